// The numbers behind the figures hue-shift, clip-claims, film-error, newton and morpho-angle
// (src/figures/film_clip_data.h), checked against the library by independent paths and against
// closed forms; and the files those figures write.

#include <irid/color/difference.h>
#include <irid/color/observer.h>
#include <irid/color/rgb.h>
#include <irid/color/spaces.h>
#include <irid/error.h>
#include <irid/figures/figures.h>
#include <irid/gamut/analysis.h>
#include <irid/optics/film_color.h>
#include <irid/optics/film_error_study.h>
#include <irid/optics/material.h>
#include <irid/optics/thesis_models.h>

#include "film_clip_data.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <numbers>
#include <string>
#include <vector>

namespace irid::figures::detail {
namespace {

constexpr double radians_per_degree = std::numbers::pi / 180.0;

std::string read_file(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::filesystem::path temp_path(const std::string& name) {
    return std::filesystem::temp_directory_path() / ("irid_figb_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "_" + name);
}

// --- hue-shift ----------------------------------------------------------------------------

TEST(HueShiftFigure, CurvesAreTheAnalysisAtEveryWavelength) {
    const std::vector<ClipMethod> methods{ClipMethod::clamp, ClipMethod::smits, ClipMethod::oklab};
    const HueShiftData d = hue_shift_data(methods, HueMeasure::lab, 0.25);
    ASSERT_EQ(d.wavelength_nm.size(), 401u);
    ASSERT_EQ(d.curves.size(), 3u);
    const ColorSet set = monochromatic_color_set(0.25);
    for (std::size_t k = 0; k < methods.size(); ++k) {
        EXPECT_EQ(d.curves[k].method, methods[k]);
        const ClipAnalysis a = analyse_clip(set, Gamut(srgb()), methods[k]);
        double largest = 0.0;
        for (std::size_t i = 0; i < 401; ++i) {
            const double v = d.curves[k].shift_deg[i];
            if (std::isnan(a.colors[i].hue_shift_ab)) {
                EXPECT_TRUE(std::isnan(v));
            } else {
                EXPECT_EQ(v, a.colors[i].hue_shift_ab);
                largest = std::max(largest, std::abs(v));
            }
        }
        EXPECT_EQ(d.curves[k].abs_shift.max, largest);
    }
}

TEST(HueShiftFigure, ClampAtOneWavelengthByHand) {
    // 600 nm at Y = 0.3, clamped channel by channel, measured in Oklab: no analysis code involved.
    const HueShiftData d = hue_shift_data(std::vector<ClipMethod>{ClipMethod::clamp}, HueMeasure::oklab, 0.3);
    const Xyz m = monochromatic_xyz(600.0);
    const Xyz in{m.X * 0.3 / m.Y, 0.3, m.Z * 0.3 / m.Y};
    const Rgb rgb = srgb().from_xyz(in);
    const auto c01 = [](double v) { return std::clamp(v, 0.0, 1.0); };
    const Rgb out{c01(rgb.r), c01(rgb.g), c01(rgb.b)};
    const Oklch a = oklab_to_oklch(xyz_to_oklab(srgb().to_xyz(rgb)));
    const Oklch b = oklab_to_oklch(xyz_to_oklab(srgb().to_xyz(out)));
    double expected = b.h - a.h;
    if (expected > 180.0) expected -= 360.0;
    if (expected <= -180.0) expected += 360.0;
    EXPECT_NEAR(d.curves[0].shift_deg[600 - 380], expected, 1e-9);
    EXPECT_GT(std::abs(expected), 1.0);  // the clamp does move it
}

TEST(HueShiftFigure, SmitsKeepsTheCieluvHueAndOklabLosesTheVioletsToWhite) {
    const HueShiftData luv =
        hue_shift_data(std::vector<ClipMethod>{ClipMethod::smits, ClipMethod::oklab}, HueMeasure::luv, 0.3);
    for (const double v : luv.curves[0].shift_deg) {
        ASSERT_FALSE(std::isnan(v));
        EXPECT_NEAR(v, 0.0, 1e-9);
    }
    // At Y = 0.3 the violet end has Oklab L >= 1, which oklab (as CSS) sends to white: no hue.
    EXPECT_TRUE(std::isnan(luv.curves[1].shift_deg[0]));
    EXPECT_FALSE(std::isnan(luv.curves[1].shift_deg[600 - 380]));
    EXPECT_THROW((void)parse_hue_measure("hsv"), Error);
    EXPECT_EQ(parse_hue_measure("luv"), HueMeasure::luv);
}

// --- clip-claims --------------------------------------------------------------------------

TEST(ClipClaimsTable, VerdictsForSmitsAndClampOnTheSpectrum) {
    const ColorSet set = clip_claims_set("spectrum");
    const auto smits = clip_claim_verdicts(analyse_clip(set, Gamut(srgb()), ClipMethod::smits).summary, HueMeasure::oklab);
    ASSERT_EQ(smits.size(), 4u);
    EXPECT_TRUE(smits[0].holds);   // constant lightness
    EXPECT_TRUE(smits[1].holds);   // saturation lower
    EXPECT_TRUE(smits[2].holds);   // CIELUV hue kept
    const auto clamp = clip_claim_verdicts(analyse_clip(set, Gamut(srgb()), ClipMethod::clamp).summary, HueMeasure::oklab);
    EXPECT_FALSE(clamp[0].holds);
    EXPECT_FALSE(clamp[2].holds);
}

TEST(ClipClaimsTable, TheParallelFaceVerdictFollowsItsDefinition) {
    ClipClaimsSummary s;
    s.clipped = 10;
    s.angle_bins.resize(6);
    for (std::size_t b = 0; b < 6; ++b) {
        s.angle_bins[b].min_deg = 15.0 * static_cast<double>(b);
        s.angle_bins[b].max_deg = 15.0 * static_cast<double>(b + 1);
    }
    // The nearest-parallel occupied bin (15-30°) has the largest mean, and r < -0.1: holds.
    s.angle_bins[1].hue.oklab = {.mean = 8.0, .p95 = 9.0, .max = 9.0, .count = 4};
    s.angle_bins[4].hue.oklab = {.mean = 2.0, .p95 = 3.0, .max = 3.0, .count = 6};
    s.correlation_oklab = -0.8;
    EXPECT_TRUE(clip_claim_verdicts(s, HueMeasure::oklab)[3].holds);
    // A weak correlation does not.
    s.correlation_oklab = -0.05;
    EXPECT_FALSE(clip_claim_verdicts(s, HueMeasure::oklab)[3].holds);
    // Nor a larger mean on a face farther from parallel.
    s.correlation_oklab = -0.8;
    s.angle_bins[4].hue.oklab.mean = 8.5;
    EXPECT_FALSE(clip_claim_verdicts(s, HueMeasure::oklab)[3].holds);
    // Undefined correlation (a constant |Δh|): does not.
    s.angle_bins[4].hue.oklab.mean = 2.0;
    s.correlation_oklab = std::nan("");
    EXPECT_FALSE(clip_claim_verdicts(s, HueMeasure::oklab)[3].holds);
}

TEST(ClipClaimsTable, MarkdownAndHtmlHaveEveryMethodAndTheVerdicts) {
    const ColorSet set = clip_claims_set("rec2020");
    std::vector<ClipAnalysis> analyses;
    for (const ClipMethod m : clip_methods()) analyses.push_back(analyse_clip(set, Gamut(srgb()), m));
    const std::string md = clip_claims_markdown(analyses, set, HueMeasure::oklab, ClipMethod::smits);
    const std::string html = clip_claims_html(analyses, set, HueMeasure::oklab, ClipMethod::smits);
    for (const ClipMethod m : clip_methods()) {
        const std::string name(clip_method_name(m));
        EXPECT_NE(md.find("| " + name + " |"), std::string::npos) << name;
        EXPECT_NE(html.find("<td>" + name + "</td>"), std::string::npos) << name;
    }
    EXPECT_NE(md.find("1. lightness is constant"), std::string::npos);
    EXPECT_NE(md.find("Set rec2020: 729 colours, 488 out of the sRGB gamut"), std::string::npos);
    EXPECT_EQ(html.rfind("<!DOCTYPE html>", 0), 0u);
    EXPECT_NE(html.find("</html>"), std::string::npos);
    // Three tables, each closed; no raw '<' from the text (escaped as &lt;).
    std::size_t tables = 0;
    for (std::size_t p = html.find("<table>"); p != std::string::npos; p = html.find("<table>", p + 1)) ++tables;
    EXPECT_EQ(tables, 3u);
    EXPECT_EQ(html.find("r < "), std::string::npos);
    // The report's catalogue: spectrum, interference, rec2020 and ramps.
    EXPECT_EQ(clip_claims_set("all").colors.size(), 2936u + 36864u);
    EXPECT_THROW((void)clip_claims_set("nothing"), Error);
}

// --- film-error ---------------------------------------------------------------------------

TEST(FilmErrorFigure, GridStatisticsAreThoseOfTheErrorStudy) {
    const Colorimeter colorimeter;
    for (const char* name : {"soap", "oil"}) {
        SCOPED_TRACE(name);
        const SingleFilm film = film_by_name(name);
        const double k = thesis_matched_k(film);
        // 41 × 9 = 369 samples: an odd count, so both medians are the middle value.
        const FilmErrorGrid g = film_error_grid(film, colorimeter, k, 1000.0, 25.0, 80.0, 10.0);
        ASSERT_EQ(g.thickness_nm.size(), 41u);
        ASSERT_EQ(g.angle_deg.size(), 9u);
        ASSERT_EQ(g.delta_e.size(), 369u);
        const ErrorStudyResult study = thesis_error_study(name, film, colorimeter, {1000.0, 25.0, 80.0, 10.0, std::nullopt});
        EXPECT_EQ(study.samples, g.delta_e.size());
        EXPECT_NEAR(g.mean, study.mean, 1e-9);
        EXPECT_NEAR(g.median, study.median, 1e-9);
        EXPECT_NEAR(g.max, study.max, 1e-9);
        EXPECT_EQ(g.worst_thickness_nm, study.worst_thickness_nm);
        EXPECT_EQ(g.worst_angle_deg, study.worst_angle_deg);
        EXPECT_NEAR(study.k, k, 1e-15);
        // Each row's mean is the study's mean at that angle.
        for (std::size_t j = 0; j < g.angle_deg.size(); ++j) {
            double sum = 0.0;
            for (std::size_t i = 0; i < g.thickness_nm.size(); ++i) sum += g.delta_e[j * g.thickness_nm.size() + i];
            EXPECT_NEAR(sum / static_cast<double>(g.thickness_nm.size()), study.mean_by_angle[j], 1e-9);
        }
    }
}

TEST(FilmErrorFigure, OneCellByAnotherPathAndZeroThicknessIsExact) {
    const Colorimeter colorimeter;
    const SingleFilm soap = film_by_name("soap");
    const double k = thesis_matched_k(soap);
    const FilmErrorGrid g = film_error_grid(soap, colorimeter, k, 600.0, 100.0, 60.0, 30.0);
    // The cell at 300 nm, 30°: thesis spectrum → colour, exact colour by exact_film_color.
    const double theta = 30.0 * radians_per_degree;
    const Xyz thesis = colorimeter.xyz(thesis_single_film_spectrum(soap, 300.0, theta, k));
    const Xyz exact = exact_film_color(soap, 300.0, theta, colorimeter).xyz;
    EXPECT_NEAR(g.delta_e[1 * g.thickness_nm.size() + 3],
                delta_e_2000(colorimeter.lab(thesis), colorimeter.lab(exact)), 1e-6);
    // A soap film of zero thickness is air | air: both models reflect nothing.
    for (std::size_t j = 0; j < g.angle_deg.size(); ++j) EXPECT_NEAR(g.delta_e[j * g.thickness_nm.size()], 0.0, 1e-9);
    EXPECT_THROW((void)film_by_name("glass"), Error);
    EXPECT_THROW((void)film_error_grid(soap, colorimeter, k, 100.0, 0.0, 10.0, 1.0), Error);
    EXPECT_THROW((void)film_error_grid(soap, colorimeter, k, 100.0, 5.0, 90.0, 1.0), Error);
}

// --- newton -------------------------------------------------------------------------------

TEST(NewtonFigure, OrderBoundariesAreHalfWavesOfThePath) {
    // n = 1.5, λ = 600 nm: one order is λ/(2n) = 200 nm.
    const std::vector<double> with = order_boundaries_nm(1.5, true, 600.0, 1000.0);
    const std::vector<double> without = order_boundaries_nm(1.5, false, 600.0, 1000.0);
    ASSERT_EQ(with.size(), 5u);  // 200, 400, 600, 800, 1000
    ASSERT_EQ(without.size(), 5u);  // 100, 300, 500, 700, 900
    for (std::size_t m = 0; m < 5; ++m) {
        EXPECT_NEAR(with[m], 200.0 * static_cast<double>(m + 1), 1e-9);
        EXPECT_NEAR(without[m], 200.0 * static_cast<double>(m) + 100.0, 1e-9);
    }
    EXPECT_THROW((void)order_boundaries_nm(0.0, true, 600.0, 1000.0), Error);
}

TEST(NewtonFigure, BoundariesAreWhereTheReferenceWavelengthIsExtinguished) {
    const Colorimeter colorimeter;
    const NewtonData d = newton_data(1500.0, 10.0, 550.0, true, Brightness::off, colorimeter);
    ASSERT_EQ(d.strips.size(), 4u);
    EXPECT_TRUE(d.strips[0].phase_change && d.strips[1].phase_change);
    EXPECT_FALSE(d.strips[2].phase_change || d.strips[3].phase_change);
    const double n_water = find_material("water")->index(550.0).real();
    for (const NewtonStrip& s : d.strips) {
        EXPECT_EQ(s.n_at_reference, n_water);
        ASSERT_FALSE(s.boundaries_nm.empty());
        const SingleFilm film = newton_film(s.phase_change);
        const PreparedFilm exact(film, 0.0);
        for (const double t : s.boundaries_nm) {
            // The thesis' model is exactly dark there at 550 nm.
            EXPECT_NEAR(thesis_single_film_reflectance(film, t, 550.0, 0.0, 1.0, s.phase_change), 0.0, 1e-20);
            // The exact film too: a soap film's two beams are equal and opposite (R = 0), water on
            // n = 1.77 nearly (|r01| and |r12| differ by 0.004).
            EXPECT_LT(exact.reflectance(550 - 360, t), s.phase_change ? 1e-20 : 1e-4);
        }
    }
    EXPECT_EQ(d.strips[0].boundaries_nm.size(), 7u);  // 206, 412, ..., 1442 nm
    EXPECT_NEAR(d.strips[0].boundaries_nm[0], 550.0 / (2.0 * n_water), 1e-9);
}

TEST(NewtonFigure, StripColoursAreTheColorimetersAtSamplePoints) {
    const Colorimeter colorimeter;
    const NewtonData d = newton_data(1500.0, 5.0, 550.0, true, Brightness::off, colorimeter);
    ASSERT_EQ(d.thickness_nm.size(), 301u);
    for (const double t : {0.0, 250.0, 500.0, 1225.0}) {
        const auto i = static_cast<std::size_t>(t / 5.0);
        ASSERT_EQ(d.thickness_nm[i], t);
        for (std::size_t r = 0; r < 4; ++r) {
            const NewtonStrip& s = d.strips[r];
            const SingleFilm film = newton_film(s.phase_change);
            const Xyz expected = s.exact ? exact_film_color(film, t, 0.0, colorimeter).xyz
                                         : colorimeter.xyz(thesis_single_film_spectrum(
                                               film, t, 0.0, thesis_matched_k(film), s.phase_change));
            EXPECT_NEAR(s.raw[i].X, expected.X, 1e-12) << r << " " << t;
            EXPECT_NEAR(s.raw[i].Y, expected.Y, 1e-12) << r << " " << t;
            EXPECT_NEAR(s.raw[i].Z, expected.Z, 1e-12) << r << " " << t;
            EXPECT_EQ(s.shown[i].Y, s.raw[i].Y);  // brightness off
        }
    }
    // With the phase change a film of no thickness is black; without, it reflects.
    EXPECT_NEAR(d.strips[0].raw[0].Y, 0.0, 1e-15);
    EXPECT_NEAR(d.strips[1].raw[0].Y, 0.0, 1e-15);
    EXPECT_GT(d.strips[2].raw[0].Y, 0.01);
    EXPECT_GT(d.strips[3].raw[0].Y, 0.01);
}

TEST(NewtonFigure, BrightnessRules) {
    std::vector<Xyz> strip{{0.0, 0.0, 0.0}, {0.1, 0.2, 0.3}, {0.05, 0.05, 0.05}, {0.2, 0.1, 0.0}};
    std::vector<Xyz> s = strip;
    normalise_brightness(s, Brightness::strip);
    EXPECT_NEAR(s[1].Y, strip_peak_luminance, 1e-15);
    EXPECT_NEAR(s[1].X / s[1].Y, 0.5, 1e-15);  // chromaticity kept
    EXPECT_NEAR(s[3].Y, 0.1 * strip_peak_luminance / 0.2, 1e-15);
    s = strip;
    normalise_brightness(s, Brightness::each);
    EXPECT_EQ(s[0].Y, 0.0);
    for (std::size_t i = 1; i < s.size(); ++i) EXPECT_NEAR(s[i].Y, each_luminance, 1e-15);
    EXPECT_NEAR(s[3].X, 2.0 * each_luminance, 1e-15);
    s = strip;
    normalise_brightness(s, Brightness::off);
    EXPECT_EQ(s[1].Y, 0.2);
    EXPECT_THROW((void)parse_brightness("auto"), Error);
}

// --- morpho-angle -------------------------------------------------------------------------

TEST(MorphoFigure, ExactStackIsTheThesisGeometry) {
    const MorphoParameters wing;
    const FilmStack stack = morpho_exact_stack(wing);
    ASSERT_EQ(stack.layers().size(), 23u);  // 12 chitin layers, 11 air gaps
    for (std::size_t i = 0; i < stack.layers().size(); ++i) {
        const Layer& layer = stack.layers()[i];
        EXPECT_EQ(layer.thickness_nm, i % 2 == 0 ? wing.d2_nm : wing.d1_nm);
        EXPECT_EQ(layer.material.index(500.0).real(), i % 2 == 0 ? wing.n : 1.0);
    }
}

TEST(MorphoFigure, DominantPeak) {
    EXPECT_EQ(dominant_peak_nm(DenseSpectrum::from_function([](double nm) { return -std::abs(nm - 500.0); })), 500.0);
    // The largest value at an end of the grid, or outside 380-780 nm: no visible peak.
    EXPECT_TRUE(std::isnan(dominant_peak_nm(DenseSpectrum::from_function([](double nm) { return -nm; }))));
    EXPECT_TRUE(std::isnan(dominant_peak_nm(DenseSpectrum::from_function([](double nm) { return -std::abs(nm - 800.0); }))));
}

TEST(MorphoFigure, RowsAreTheModelsAndPeaksFollowBragg) {
    const Colorimeter colorimeter;
    const MorphoAngleData d = morpho_angle_data(10.0, Brightness::off, colorimeter, 3);
    ASSERT_EQ(d.angle_deg.size(), 9u);  // 5, 15, ..., 85
    EXPECT_EQ(d.angle_deg.front(), 5.0);
    EXPECT_EQ(d.angle_deg.back(), 85.0);
    ASSERT_EQ(d.rows.size(), 4u);
    EXPECT_NEAR(d.wing.K, 2.0 / 169.0, 1e-15);
    for (std::size_t j = 0; j < d.angle_deg.size(); ++j) {
        const double angle = d.angle_deg[j];
        const Xyz thesis = colorimeter.xyz(morpho_spectrum(d.wing, angle));
        EXPECT_NEAR(d.rows[0].raw[j].Y, thesis.Y, 1e-12);
        const Xyz blend = colorimeter.xyz(morpho_blend_spectrum(d.wing, d.blend, angle));
        EXPECT_NEAR(d.rows[1].raw[j].Y, blend.Y, 1e-12);
        const Xyz exact = colorimeter.xyz(exact_reflectance_spectrum(morpho_exact_stack(d.wing), angle * radians_per_degree));
        EXPECT_NEAR(d.rows[2].raw[j].Y, exact.Y, 1e-12);
        // Bragg: both the thesis' eq. 25 and the exact stack reflect most at λ = 2 t_θ (first
        // order), t_θ = d₁ cos θ + d₂ (n² − sin²θ)^½ the optical path of one period (eq. 29).
        const double bragg = 2.0 * morpho_effective_thickness_nm(d.wing, angle * radians_per_degree);
        if (bragg >= 400.0) {
            EXPECT_NEAR(d.rows[0].peak_nm[j], bragg, 1.0) << angle;
            EXPECT_NEAR(d.rows[2].peak_nm[j], bragg, 5.0) << angle;
        }
    }
    EXPECT_THROW((void)morpho_angle_data(7.0, Brightness::off, colorimeter, 3), Error);
    EXPECT_THROW((void)morpho_angle_data(10.0, Brightness::off, colorimeter, 1), Error);
}

// --- the files ----------------------------------------------------------------------------

std::uint32_t be32(const std::string& s, std::size_t at) {
    return (static_cast<std::uint32_t>(static_cast<unsigned char>(s[at])) << 24) |
           (static_cast<std::uint32_t>(static_cast<unsigned char>(s[at + 1])) << 16) |
           (static_cast<std::uint32_t>(static_cast<unsigned char>(s[at + 2])) << 8) |
           static_cast<std::uint32_t>(static_cast<unsigned char>(s[at + 3]));
}

TEST(FilmClipFigureFiles, PngOfTheRequestedSizeSvgAndTables) {
    for (const char* name : {"hue-shift", "newton", "film-error"}) {
        SCOPED_TRACE(name);
        const auto png = temp_path(std::string(name) + ".png");
        const FigureResult r = draw_figure({name, png, 321, 203, {}});
        const std::string bytes = read_file(png);
        ASSERT_GT(bytes.size(), 33u);
        EXPECT_EQ(bytes.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
        EXPECT_EQ(bytes.substr(12, 4), "IHDR");
        EXPECT_EQ(be32(bytes, 16), 321u);
        EXPECT_EQ(be32(bytes, 20), 203u);
        EXPECT_EQ(r.width_px, 321);
        EXPECT_FALSE(r.caption.empty());
        EXPECT_FALSE(r.measurements.empty());
        std::filesystem::remove(png);
        const auto svg = temp_path(std::string(name) + ".svg");
        (void)draw_figure({name, svg, 640, 400, {}});
        const std::string text = read_file(svg);
        EXPECT_EQ(text.rfind("<?xml", 0), 0u);
        EXPECT_NE(text.find("<svg"), std::string::npos);
        EXPECT_NE(text.find("</svg>"), std::string::npos);
        std::filesystem::remove(svg);
    }
    for (const char* ext : {".md", ".html"}) {
        const auto table = temp_path(std::string("claims") + ext);
        const FigureResult r = draw_figure({"clip-claims", table, 960, 600, {{"set", "interference"}}});
        EXPECT_EQ(r.width_px, 0);
        const std::string text = read_file(table);
        EXPECT_NE(text.find("Set interference: 1806 colours"), std::string::npos);
        EXPECT_EQ(r.measurements.size(), 4u);
        std::filesystem::remove(table);
    }
}

TEST(FilmClipFigureFiles, BadOptionsNameTheKeyAndTheAllowedValues) {
    const auto out = temp_path("bad.png");
    const auto message = [&](const std::string& name, std::string key, std::string value) {
        try {
            (void)draw_figure({name, out, 200, 200, {{std::move(key), std::move(value)}}});
        } catch (const Error& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    std::string m = message("hue-shift", "hue", "hsv");
    EXPECT_NE(m.find("hue"), std::string::npos) << m;
    EXPECT_NE(m.find("oklab"), std::string::npos) << m;
    m = message("hue-shift", "methods", "smits,foo");
    EXPECT_NE(m.find("foo"), std::string::npos) << m;
    EXPECT_NE(m.find("luv-lightness-hue"), std::string::npos) << m;
    m = message("film-error", "film", "glass");
    EXPECT_NE(m.find("soap"), std::string::npos) << m;
    m = message("newton", "reference", "100");
    EXPECT_NE(m.find("reference"), std::string::npos) << m;
    m = message("morpho-angle", "angle", "3");
    EXPECT_NE(m.find("angle"), std::string::npos) << m;
    EXPECT_FALSE(std::filesystem::exists(out));
    EXPECT_THROW((void)draw_figure({"clip-claims", temp_path("claims.png"), 200, 200, {}}), Error);
    EXPECT_THROW((void)draw_figure({"newton", temp_path("newton.md"), 200, 200, {}}), Error);
}

// --- hue-shift's defaults and the ramps figure ---------------------------------------------

TEST(HueShiftFigure, DefaultsShowEveryMethodButTheTwoThatDrawSmitsCurve) {
    const auto png = temp_path("hue-default.png");
    const FigureResult r = draw_figure({"hue-shift", png, 480, 300, {}});
    std::vector<std::string> want;
    for (const ClipMethod m : clip_methods()) {
        if (m != ClipMethod::smits_xyz && m != ClipMethod::luv_lightness_hue) want.push_back(std::string(clip_method_name(m)) + " |Δh|");
    }
    ASSERT_EQ(r.measurements.size(), want.size());
    for (std::size_t k = 0; k < want.size(); ++k) EXPECT_EQ(r.measurements[k].first, want[k]);
    // methods=all brings them back: every method is selectable.
    const FigureResult all = draw_figure({"hue-shift", png, 480, 300, {{"methods", "all"}}});
    EXPECT_EQ(all.measurements.size(), clip_methods().size());
    std::filesystem::remove(png);
}

TEST(RampsFigure, OnePanelPerMethodWithTheReportsMeasures) {
    const auto png = temp_path("ramps.png");
    const FigureResult r = draw_figure({"ramps", png, 640, 400, {}});
    const std::string bytes = read_file(png);
    ASSERT_GT(bytes.size(), 24u);
    EXPECT_EQ(bytes.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
    EXPECT_EQ(be32(bytes, 16), 640u);
    EXPECT_EQ(be32(bytes, 20), 400u);
    ASSERT_EQ(r.measurements.size(), clip_methods().size());
    for (std::size_t k = 0; k < clip_methods().size(); ++k) {
        EXPECT_EQ(r.measurements[k].first, clip_method_name(clip_methods()[k]));
        EXPECT_EQ(r.measurements[k].second.rfind("banding mean ", 0), 0u) << r.measurements[k].second;
    }
    EXPECT_NE(r.caption.find("end=locus"), std::string::npos);
    // smits stops every ramp's tail at one point of the boundary: at Y = 0.3 toward the locus
    // every hue leaves sRGB, and each of its out-of-gamut steps collapses.
    EXPECT_NE(r.measurements[1].second.find("collapse 1.000"), std::string::npos) << r.measurements[1].second;
    std::filesystem::remove(png);
    const auto svg = temp_path("ramps.svg");
    const FigureResult some = draw_figure(
        {"ramps", svg, 640, 400, {{"methods", "clamp,aces-rgc"}, {"end", "rec2020"}, {"luminance", "0.6"}, {"boundary", "off"}}});
    ASSERT_EQ(some.measurements.size(), 2u);
    EXPECT_EQ(some.measurements[1].first, "aces-rgc");
    EXPECT_NE(read_file(svg).find("</svg>"), std::string::npos);
    std::filesystem::remove(svg);
    for (const auto& [key, value] : std::vector<std::pair<std::string, std::string>>{
             {"methods", "smits,nope"}, {"end", "edge"}, {"luminance", "1"}, {"boundary", "maybe"}}) {
        try {
            (void)draw_figure({"ramps", png, 640, 400, {{key, value}}});
            ADD_FAILURE() << key << "=" << value;
        } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find(key), std::string::npos) << e.what();
        }
    }
    EXPECT_FALSE(std::filesystem::exists(png));
}

}  // namespace
}  // namespace irid::figures::detail
