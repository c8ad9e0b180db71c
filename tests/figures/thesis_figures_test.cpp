// The numbers behind cmf-primaries, cmf-xyz, chromaticity, clip-geometry, spectrum-clip,
// film-spectra and table1 (src/figures/figure_data.h), against published values, closed forms
// and invariants; and the files draw_figure writes for them.

#include <irid/color/observer.h>
#include <irid/color/rgb.h>
#include <irid/color/spaces.h>
#include <irid/error.h>
#include <irid/figures/figures.h>
#include <irid/gamut/clip.h>
#include <irid/optics/film_color.h>
#include <irid/optics/material.h>

#include "figure_data.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <numbers>
#include <set>
#include <string>
#include <vector>

#include <unistd.h>

namespace irid::figures::detail {
namespace {

double value_at(const Series& s, double x) {
    for (std::size_t i = 0; i < s.x.size(); ++i) {
        if (s.x[i] == x) return s.y[i];
    }
    ADD_FAILURE() << s.label << " has no sample at " << x;
    return NAN;
}

// --- cmf-xyz ---------------------------------------------------------------------------------

TEST(CmfXyz, SeriesAreTheCie1931TableAtPublishedPoints) {
    const std::vector<Series> s = cmf_xyz_series(Observer::cie1931_2deg);
    ASSERT_EQ(s.size(), 3U);
    EXPECT_EQ(s[0].x.size(), static_cast<std::size_t>(dense_sample_count));
    EXPECT_EQ(s[0].x.front(), 360.0);
    EXPECT_EQ(s[0].x.back(), 830.0);
    // CIE 015:2018 Table 1 (CIE 1931 2° observer): 445 nm 0.34806, 0.02980, 1.78260;
    // 555 nm ȳ = 1.00000; 600 nm 1.06220, 0.63100, 0.00080.
    EXPECT_NEAR(value_at(s[0], 445.0), 0.34806, 1e-4);
    EXPECT_NEAR(value_at(s[1], 445.0), 0.02980, 1e-4);
    EXPECT_NEAR(value_at(s[2], 445.0), 1.78260, 1e-4);
    EXPECT_NEAR(value_at(s[1], 555.0), 1.0, 1e-4);
    EXPECT_NEAR(value_at(s[0], 600.0), 1.06220, 1e-4);
    EXPECT_NEAR(value_at(s[1], 600.0), 0.63100, 1e-4);
    EXPECT_NEAR(value_at(s[2], 600.0), 0.00080, 1e-4);
    // ȳ = V(λ) peaks at 555 nm with value 1.
    const Peak p = series_peak(s[1]);
    EXPECT_NEAR(p.x, 555.0, 1.0);
    EXPECT_NEAR(p.y, 1.0, 1e-4);
    for (const Series& f : s) EXPECT_GE(series_minimum(f).y, 0.0);
}

TEST(CmfXyz, The1964ObserverDiffers) {
    const std::vector<Series> a = cmf_xyz_series(Observer::cie1931_2deg);
    const std::vector<Series> b = cmf_xyz_series(Observer::cie1964_10deg);
    // A different table (CIE 015:2018 Table 2), also normalised to a ȳ10 peak of 1.
    EXPECT_GT(std::abs(value_at(a[0], 450.0) - value_at(b[0], 450.0)), 0.01);
    EXPECT_NEAR(series_peak(b[1]).y, 1.0, 2e-3);
}

// --- cmf-primaries ---------------------------------------------------------------------------

TEST(CmfPrimaries, EachPrimaryAloneMatchesItsOwnWavelength) {
    const PrimaryMatchingFunctions p = monochromatic_primary_matching_functions(645, 526, 444);
    const std::vector<Series> s = primary_cmf_series(p);
    ASSERT_EQ(s.size(), 3U);
    // A monochromatic stimulus at a primary's wavelength is matched by that primary alone:
    // the other two functions vanish there.
    const double r = value_at(s[0], 645.0), g = value_at(s[1], 645.0), b = value_at(s[2], 645.0);
    EXPECT_GT(r, 0.1);
    EXPECT_NEAR(g, 0.0, 1e-9 * r);
    EXPECT_NEAR(b, 0.0, 1e-9 * r);
    EXPECT_NEAR(value_at(s[0], 526.0), 0.0, 1e-9);
    EXPECT_NEAR(value_at(s[2], 526.0), 0.0, 1e-9);
    EXPECT_NEAR(value_at(s[0], 444.0), 0.0, 1e-9);
    EXPECT_NEAR(value_at(s[1], 444.0), 0.0, 1e-9);
    // Equal amounts match the equal-energy white, each with the sum of ȳ.
    const double sum_y = color_matching_functions(Observer::cie1931_2deg).y.sum();
    for (const Series& f : s) {
        double sum = 0.0;
        for (const double v : f.y) sum += v;
        EXPECT_NEAR(sum, sum_y, 1e-9 * sum_y) << f.label;
    }
    // Figure 2's point: r̄ is negative between the blue and green primaries (no real
    // primaries match the blue-greens), and its lowest point lies there.
    const Peak low = series_minimum(s[0]);
    EXPECT_LT(low.y, -0.05);
    EXPECT_GT(low.x, 444.0);
    EXPECT_LT(low.x, 526.0);
    EXPECT_EQ(s[0].label, "r̄ (645 nm)");
}

// --- chromaticity ----------------------------------------------------------------------------

TEST(Chromaticity, GamutTriangleAreasFromThePublishedPrimaries) {
    // ITU-R BT.709-6 primaries (0.64, 0.33), (0.30, 0.60), (0.15, 0.06): ½|Σ| = 0.11205.
    EXPECT_NEAR(polygon_area(gamut_triangle(srgb(), Diagram::xy)), 0.11205, 1e-6);
    // ITU-R BT.2020-2: (0.708, 0.292), (0.170, 0.797), (0.131, 0.046): 0.2118665.
    EXPECT_NEAR(polygon_area(gamut_triangle(rec2020(), Diagram::xy)), 0.2118665, 1e-6);
}

TEST(Chromaticity, LocusIsTheLibrarysAndEnclosesTheGamuts) {
    const std::vector<Point> locus = spectral_locus(Diagram::xy);
    ASSERT_EQ(locus.size(), 471U);  // 360..830 nm at 1 nm
    for (const double nm : {360.0, 520.0, 700.0}) {
        const Xy xy = spectral_locus_xy(nm);
        const Point& p = locus[static_cast<std::size_t>(nm - 360.0)];
        EXPECT_DOUBLE_EQ(p.x, xy.x);
        EXPECT_DOUBLE_EQ(p.y, xy.y);
    }
    const double area = polygon_area(locus);
    for (const RgbSpace* space : builtin_rgb_spaces()) {
        EXPECT_TRUE(inside_polygon(locus, {space->white().x, space->white().y})) << space->name();
        // ACES2065-1's AP0 primaries are imaginary by design (they enclose the whole locus,
        // Academy S-2008-001): the one built-in space whose triangle is larger.
        if (space == &aces2065_1()) {
            EXPECT_GT(polygon_area(gamut_triangle(*space, Diagram::xy)), area);
            continue;
        }
        EXPECT_LT(polygon_area(gamut_triangle(*space, Diagram::xy)), area) << space->name();
    }
    // Rec.2020's primaries are monochromatic (630, 532, 467 nm), on the locus: its triangle
    // is most of the locus' area, sRGB's about a third.
    const double rec = polygon_area(gamut_triangle(rec2020(), Diagram::xy)) / area;
    const double s = polygon_area(gamut_triangle(srgb(), Diagram::xy)) / area;
    EXPECT_GT(rec, 0.55);
    EXPECT_LT(rec, 0.75);
    EXPECT_GT(s, 0.30);
    EXPECT_LT(s, 0.40);
    EXPECT_FALSE(inside_polygon(locus, {0.8, 0.8}));
    EXPECT_FALSE(inside_polygon(locus, {0.05, 0.05}));
}

TEST(Chromaticity, UvPrimeDiagramOfD65) {
    // CIE 015:2018 Table 11.3: D65 u′ = 0.1978, v′ = 0.4683.
    const Point p = diagram_point({0.31272, 0.32903}, Diagram::uv);
    EXPECT_NEAR(p.x, 0.1978, 1e-4);
    EXPECT_NEAR(p.y, 0.4683, 1e-4);
    // Straight lines in xy stay straight in u′v′ (a projective map): the purple line's
    // midpoint maps onto the segment between the mapped ends.
    const Xy a = spectral_locus_xy(380.0), b = spectral_locus_xy(700.0);
    const Point pa = diagram_point(a, Diagram::uv), pb = diagram_point(b, Diagram::uv);
    const Point pm = diagram_point({(a.x + b.x) / 2, (a.y + b.y) / 2}, Diagram::uv);
    EXPECT_NEAR((pb.x - pa.x) * (pm.y - pa.y) - (pb.y - pa.y) * (pm.x - pa.x), 0.0, 1e-12);
}

TEST(Chromaticity, FillColoursAreExactInsideSrgb) {
    const GamutClipper clipper(ClipMethod::smits, Gamut(srgb()));
    const Color white = chromaticity_fill_color(srgb().white(), clipper);
    EXPECT_NEAR(white.r, 1.0, 1e-9);
    EXPECT_NEAR(white.g, 1.0, 1e-9);
    EXPECT_NEAR(white.b, 1.0, 1e-9);
    const Color red = chromaticity_fill_color(srgb().primaries().red, clipper);
    EXPECT_NEAR(red.r, 1.0, 1e-9);
    EXPECT_NEAR(red.g, 0.0, 1e-6);
    EXPECT_NEAR(red.b, 0.0, 1e-6);
    // Outside the triangle the colour is clipped into the cube.
    const Color green = chromaticity_fill_color(spectral_locus_xy(520.0), clipper);
    for (const double v : {green.r, green.g, green.b}) {
        EXPECT_GE(v, 0.0);
        EXPECT_LE(v, 1.0);
    }
    EXPECT_GT(green.g, green.r);
}

// --- clip-geometry ---------------------------------------------------------------------------

TEST(ClipGeometry, SliceShapesFollowTheCubesCornerLuminances) {
    // sRGB corner luminances: B 0.0722, R 0.2126, R+B 0.2848, G 0.7152, G+B 0.7874,
    // R+G 0.9278 (IEC 61966-2-1 / BT.709 luminance row). The plane Y cuts the edges between the
    // corners below and above it.
    const Gamut gamut(srgb());
    EXPECT_EQ(luminance_slice(gamut, 0.05).size(), 3U);  // below: black
    EXPECT_EQ(luminance_slice(gamut, 0.10).size(), 4U);  // black, B
    EXPECT_EQ(luminance_slice(gamut, 0.25).size(), 5U);  // black, B, R
    EXPECT_EQ(luminance_slice(gamut, 0.50).size(), 4U);  // black, B, R, R+B
    EXPECT_EQ(luminance_slice(gamut, 0.75).size(), 5U);  // ... and G
    EXPECT_EQ(luminance_slice(gamut, 0.95).size(), 3U);  // all but white
    EXPECT_TRUE(luminance_slice(gamut, 0.0).empty());
    EXPECT_TRUE(luminance_slice(gamut, 1.0).empty());
    EXPECT_TRUE(luminance_slice(gamut, -1.0).empty());
}

TEST(ClipGeometry, SliceVerticesLieOnCubeEdgesAtTheLuminanceAndFormAConvexPolygon) {
    const Gamut gamut(srgb());
    for (const double Y : {0.03, 0.2, 0.4, 0.7152, 0.8, 0.97}) {
        const std::vector<Rgb> slice = luminance_slice(gamut, Y);
        ASSERT_GE(slice.size(), 3U) << Y;
        std::vector<Point> xy;
        for (const Rgb& c : slice) {
            EXPECT_NEAR(srgb().to_xyz(c).Y, Y, 1e-12);
            int on_face = 0;
            for (const double v : {c.r, c.g, c.b}) {
                EXPECT_GE(v, -1e-12);
                EXPECT_LE(v, 1.0 + 1e-12);
                on_face += (std::abs(v) < 1e-12 || std::abs(v - 1.0) < 1e-12) ? 1 : 0;
            }
            EXPECT_GE(on_face, 2) << "a vertex lies on an edge of the cube";
            const Xy p = xyz_to_xy(srgb().to_xyz(c));
            xy.push_back({p.x, p.y});
        }
        double sign = 0.0;
        for (std::size_t i = 0; i < xy.size(); ++i) {
            const Point& a = xy[i];
            const Point& b = xy[(i + 1) % xy.size()];
            const Point& c = xy[(i + 2) % xy.size()];
            const double cross = (b.x - a.x) * (c.y - b.y) - (b.y - a.y) * (c.x - b.x);
            if (sign == 0.0) sign = cross;
            EXPECT_GT(cross * sign, 0.0) << "Y = " << Y << " vertex " << i;
        }
        // The white's chromaticity (the neutral point) is inside every slice.
        EXPECT_TRUE(inside_polygon(xy, {srgb().white().x, srgb().white().y})) << Y;
    }
}

TEST(ClipGeometry, SmitsLandsOnTheSliceEdgeOnTheLineToTheNeutralPoint) {
    const Gamut gamut(srgb());
    const Xy g = spectral_locus_xy(520.0);
    const Xyz input = xyy_to_xyz({g.x, g.y, 0.25});
    const std::vector<ClipMethod> methods{ClipMethod::smits, ClipMethod::clamp};
    const std::vector<ClipLanding> l = clip_landings(gamut, input, methods);
    ASSERT_EQ(l.size(), 2U);
    const ClipLanding& s = l[0];
    EXPECT_NEAR(s.xyy.Y, 0.25, 1e-12);  // constant luminance
    EXPECT_NEAR(s.hue_shift_deg, 0.0, 1e-6);
    // Collinear with the input and the white, between them.
    const Xy w = srgb().white();
    const double cross = (g.x - w.x) * (s.xyy.y - w.y) - (g.y - w.y) * (s.xyy.x - w.x);
    EXPECT_NEAR(cross, 0.0, 1e-9);
    EXPECT_GT(s.xyy.y, w.y);
    EXPECT_LT(s.xyy.y, g.y);
    // On the boundary: one channel on a face.
    EXPECT_NEAR(std::min({s.rgb.r, s.rgb.g, s.rgb.b}), 0.0, 1e-12);
    // Clamping changes the luminance (it is not a move at constant Y).
    EXPECT_GT(std::abs(l[1].xyy.Y - 0.25), 0.01);
}

// --- spectrum-clip ---------------------------------------------------------------------------

TEST(SpectrumClip, EqualLuminanceSpectrumIsTheLocusAtOneLuminance) {
    const std::vector<Rgb> s = equal_luminance_spectrum(srgb(), 380.0, 700.0, 1.0, 0.2);
    ASSERT_EQ(s.size(), 321U);
    for (std::size_t i = 0; i < s.size(); i += 20) {
        const Xyz c = srgb().to_xyz(s[i]);
        EXPECT_NEAR(c.Y, 0.2, 1e-12);
        const Xy xy = xyz_to_xy(c);
        const Xy locus = spectral_locus_xy(380.0 + static_cast<double>(i));
        EXPECT_NEAR(xy.x, locus.x, 1e-9);
        EXPECT_NEAR(xy.y, locus.y, 1e-9);
        // No spectral colour is inside sRGB.
        EXPECT_FALSE(Gamut(srgb()).contains(s[i])) << 380 + i;
    }
}

TEST(SpectrumClip, BatchClipEqualsTheScalarClipperAndSmitsKeepsLuminance) {
    const std::vector<Rgb> s = equal_luminance_spectrum(srgb(), 380.0, 700.0, 5.0, 0.2);
    const Gamut gamut(srgb());
    for (const ClipMethod m : clip_methods()) {
        const GamutClipper clipper(m, gamut);
        const std::vector<Rgb> batch = clip_colors_batch(clipper, s);
        ASSERT_EQ(batch.size(), s.size());
        for (std::size_t i = 0; i < s.size(); ++i) {
            // The batch runs in float: equal to the double clip of the float input to ~1e-5.
            const Rgb in{static_cast<float>(s[i].r), static_cast<float>(s[i].g),
                         static_cast<float>(s[i].b)};
            const Rgb scalar = clipper.clip(in);
            EXPECT_NEAR(batch[i].r, scalar.r, 2e-5) << clip_method_name(m) << " " << i;
            EXPECT_NEAR(batch[i].g, scalar.g, 2e-5) << clip_method_name(m) << " " << i;
            EXPECT_NEAR(batch[i].b, scalar.b, 2e-5) << clip_method_name(m) << " " << i;
            if (m == ClipMethod::smits) {
                EXPECT_NEAR(srgb().to_xyz(batch[i]).Y, 0.2, 1e-5);
            }
        }
    }
}

TEST(SpectrumClip, DefaultOrderIsTheThesisThreeThenTheRest) {
    const std::vector<ClipMethod> m = spectrum_clip_default_methods();
    ASSERT_GE(m.size(), 3U);
    EXPECT_EQ(m[0], ClipMethod::clamp);
    EXPECT_EQ(m[1], ClipMethod::smits);
    EXPECT_EQ(m[2], ClipMethod::luv_hue);
    EXPECT_EQ(m.size(), clip_methods().size());
    EXPECT_EQ(std::set<ClipMethod>(m.begin(), m.end()).size(), m.size());
}

// --- film-spectra ----------------------------------------------------------------------------

TEST(FilmSpectra, ParsesFilmItems) {
    EXPECT_DOUBLE_EQ(parse_film_spec("250").thickness_nm, 250.0);
    EXPECT_EQ(parse_film_spec("250").material, "");
    const FilmSpec f = parse_film_spec("400.5@mineral-oil");
    EXPECT_DOUBLE_EQ(f.thickness_nm, 400.5);
    EXPECT_EQ(f.material, "mineral-oil");
    for (const char* bad : {"", "abc", "-5", "20000", "5@", "1e400", "nan"}) {
        EXPECT_THROW((void)parse_film_spec(bad), Error) << bad;
    }
}

TEST(FilmSpectra, ExactSeriesIsTheAiryFormulaOfALosslessFilmInAir) {
    const SingleFilm film{*find_material("air"), *find_material("soap-film"), *find_material("air")};
    for (const double t : {100.0, 500.0}) {
        const Series s = film_reflectance_series(film, t, 0.0, false, 1.0);
        ASSERT_EQ(s.x.size(), 401U);
        for (std::size_t i = 0; i < s.x.size(); i += 25) {
            // Normal incidence, Born & Wolf §7.6.1: r01 = (n0 − n)/(n0 + n),
            // r12 = (n − n2)/(n + n2), R = (r01² + r12² + 2 r01 r12 cos δ)/
            // (1 + r01² r12² + 2 r01 r12 cos δ), δ = 4π n t / λ (air's n0 = n2 ≈ 1.0003).
            const double lambda = s.x[i];
            const double n = film.film.index(lambda).real();
            const double n0 = film.ambient.index(lambda).real();
            const double n2 = film.substrate.index(lambda).real();
            const double r01 = (n0 - n) / (n0 + n);
            const double r12 = (n - n2) / (n + n2);
            const double cd = std::cos(4.0 * std::numbers::pi * n * t / lambda);
            const double expected = (r01 * r01 + r12 * r12 + 2.0 * r01 * r12 * cd) /
                                    (1.0 + r01 * r01 * r12 * r12 + 2.0 * r01 * r12 * cd);
            EXPECT_NEAR(s.y[i], expected, 1e-12) << t << " nm at " << lambda;
        }
    }
}

TEST(FilmSpectra, ThesisSeriesIsEquation21) {
    const SingleFilm film{*find_material("air"), *find_material("soap-film"), *find_material("air")};
    const double k = thesis_matched_k(film);
    const Series s = film_reflectance_series(film, 300.0, 0.0, true, k);
    for (std::size_t i = 0; i < s.x.size(); i += 40) {
        // Smits 1990 eq. 21 at normal incidence (one phase change): [K cos(2π t n/λ + π/2)]².
        const double lambda = s.x[i];
        const double n = film.film.index(lambda).real();
        const double a = k * std::cos(2.0 * std::numbers::pi * 300.0 * n / lambda + std::numbers::pi / 2);
        EXPECT_NEAR(s.y[i], a * a, 1e-12) << lambda;
    }
}

// --- table1 ----------------------------------------------------------------------------------

TEST(Table1, MarkdownRowsCarryTheCountsAndTheThesisRow) {
    const Table1 t = count_smits_operations();
    // The thesis' clip divides once per crossed plane and multiplies 7 times whatever the
    // case (Smits 1990, Table 1: 7 multiplications, 1–3 divisions). irid's compares the
    // planes' parameters by cross-multiplication and divides once: two more multiplications
    // per plane after the first (clip.h, smits_clip_rgb).
    for (const OperationCounts* c : {&t.one_plane, &t.two_planes, &t.three_planes}) {
        EXPECT_EQ(c->divisions, 1);
    }
    EXPECT_EQ(t.one_plane.multiplications, 7);
    EXPECT_EQ(t.two_planes.multiplications, 9);
    EXPECT_EQ(t.three_planes.multiplications, 11);
    EXPECT_TRUE(thesis_multiplications.contains(t.one_plane.multiplications));
    const std::string md = table1_markdown(t);
    const auto row = [](const char* name, const OperationCounts& c) {
        return std::string("| ") + name + " | " + std::to_string(c.comparisons);
    };
    EXPECT_NE(md.find(row("in gamut", t.in_gamut)), std::string::npos) << md;
    EXPECT_NE(md.find(row("1 plane crossed", t.one_plane)), std::string::npos) << md;
    EXPECT_NE(md.find(row("3 planes crossed", t.three_planes)), std::string::npos) << md;
    EXPECT_NE(md.find("| thesis, Table 1 (per clipped colour) | 5–7 | 9–11 | 7 | 1–3 |"),
              std::string::npos) << md;
    // A markdown table: every table line has the same number of cells.
    std::size_t lines = 0;
    std::size_t start = 0;
    while (true) {
        const std::size_t end = md.find('\n', start);
        const std::string line = md.substr(start, end - start);
        if (line.rfind("| ", 0) == 0) {
            ++lines;
            EXPECT_EQ(std::count(line.begin(), line.end(), '|'), 6) << line;
        }
        if (end == std::string::npos) break;
        start = end + 1;
    }
    EXPECT_EQ(lines, 7U);  // header, rule, 4 cases, thesis
}

TEST(Table1, HtmlPageAndFragment) {
    const Table1 t = count_smits_operations();
    const std::string page = table1_html(t, true);
    const std::string fragment = table1_html(t, false);
    EXPECT_EQ(page.rfind("<!DOCTYPE html>", 0), 0U);
    EXPECT_NE(page.find(fragment), std::string::npos);
    EXPECT_EQ(fragment.rfind("<section", 0), 0U);
    EXPECT_EQ(std::count(fragment.begin(), fragment.end(), '<') -
                  std::count(fragment.begin(), fragment.end(), '>'),
              0);
    std::size_t rows = 0;
    for (std::size_t at = fragment.find("<tr"); at != std::string::npos;
         at = fragment.find("<tr", at + 1)) {
        ++rows;
    }
    EXPECT_EQ(rows, 6U);  // header, 4 cases, thesis
}

// --- the written files -------------------------------------------------------------------------

class Written : public ::testing::Test {
protected:
    void SetUp() override {
        m_dir = std::filesystem::temp_directory_path() /
                ("irid_figures_test_" + std::to_string(::getpid()));
        std::filesystem::create_directories(m_dir);
    }
    void TearDown() override { std::filesystem::remove_all(m_dir); }
    std::filesystem::path m_dir;
};

std::string read_file(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

long be32(const std::string& b, std::size_t at) {
    long v = 0;
    for (std::size_t i = 0; i < 4; ++i) v = v * 256 + static_cast<unsigned char>(b[at + i]);
    return v;
}

const std::vector<std::string> figures_a{"cmf-primaries", "cmf-xyz", "chromaticity",
                                         "clip-geometry", "spectrum-clip", "film-spectra"};

TEST_F(Written, EveryFigureWritesAPngOfTheRequestedSizeAndAnSvg) {
    for (const std::string& name : figures_a) {
        FigureRequest r{name, m_dir / (name + ".png"), 480, 300, {}};
        const FigureResult result = draw_figure(r);
        const std::string png = read_file(r.output);
        ASSERT_GT(png.size(), 24U) << name;
        EXPECT_EQ(png.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8)) << name;
        EXPECT_EQ(be32(png, 16), 480) << name;
        EXPECT_EQ(be32(png, 20), 300) << name;
        EXPECT_EQ(result.width_px, 480);
        EXPECT_EQ(result.height_px, 300);
        EXPECT_FALSE(result.caption.empty()) << name;
        EXPECT_NE(result.caption.find("Options:"), std::string::npos) << name;
        EXPECT_FALSE(result.measurements.empty()) << name;

        r.output = m_dir / (name + ".svg");
        (void)draw_figure(r);
        const std::string svg = read_file(r.output);
        EXPECT_EQ(svg.rfind("<?xml", 0), 0U) << name;
        EXPECT_NE(svg.find("<svg"), std::string::npos) << name;
        EXPECT_NE(svg.find("</svg>"), std::string::npos) << name;
    }
    std::size_t files = 0;
    for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(m_dir)) ++files;
    EXPECT_EQ(files, 2 * figures_a.size());  // no temporary file left
}

TEST_F(Written, Table1WritesMarkdownAndHtmlWithTheCounts) {
    const FigureResult md = draw_figure({"table1", m_dir / "t.md", 960, 600, {}});
    EXPECT_EQ(md.width_px, 0);
    EXPECT_EQ(read_file(m_dir / "t.md"), table1_markdown(count_smits_operations()));
    const Table1 t = count_smits_operations();
    ASSERT_EQ(md.measurements.size(), 5U);
    EXPECT_EQ(md.measurements[1].second.rfind(std::to_string(t.one_plane.comparisons) + " comparisons", 0), 0U);
    (void)draw_figure({"table1", m_dir / "t.html", 960, 600, {{"html", "fragment"}}});
    EXPECT_EQ(read_file(m_dir / "t.html"), table1_html(t, false));
    EXPECT_THROW((void)draw_figure({"table1", m_dir / "t.png", 960, 600, {}}), FigureRequestError);
}

TEST_F(Written, MeasurementsMatchTheData) {
    const FigureResult r = draw_figure({"chromaticity", m_dir / "c.svg", 960, 600,
                                        {{"spaces", "srgb,rec2020-linear"}}});
    ASSERT_EQ(r.measurements.size(), 3U);
    EXPECT_EQ(r.measurements[1].first, "srgb triangle area (xy)");
    EXPECT_EQ(r.measurements[1].second.rfind("0.1121", 0), 0U) << r.measurements[1].second;
    EXPECT_EQ(r.measurements[2].first, "rec2020 triangle area (xy)");

    const FigureResult g = draw_figure({"clip-geometry", m_dir / "g.svg", 960, 600, {}});
    EXPECT_EQ(g.measurements.front().first, "slice vertices");
    EXPECT_EQ(g.measurements.front().second.rfind("5 ", 0), 0U);  // Y = 0.25: a pentagon
}

TEST_F(Written, RequestErrorsNameWhatIsAllowedAndLeaveNoFile) {
    struct Case {
        FigureRequest request;
        std::vector<std::string> expected;
    };
    const std::filesystem::path out = m_dir / "x.png";
    const std::vector<Case> cases{
        {{"no-such-figure", out, 960, 600, {}}, {"cmf-primaries", "table1"}},
        {{"cmf-xyz", m_dir / "x.jpg", 960, 600, {}}, {".svg, .png"}},
        {{"cmf-xyz", out, 10, 600, {}}, {"64..8192"}},
        {{"cmf-xyz", out, 960, 600, {{"observer", "cie2000"}}}, {"observer=cie2000", "cie1964"}},
        {{"cmf-primaries", out, 960, 600, {{"primaries", "444,526"}}}, {"primaries", "3"}},
        {{"cmf-primaries", out, 960, 600, {{"primaries", "500,500,600"}}}, {"distinct"}},
        {{"chromaticity", out, 960, 600, {{"spaces", "srgb,prophoto"}}}, {"prophoto", "display-p3"}},
        {{"chromaticity", out, 960, 600, {{"diagram", "lab"}}}, {"diagram", "xy, uv"}},
        {{"clip-geometry", out, 960, 600, {{"method", "magic"}}}, {"method", "smits-xyz", "all"}},
        {{"clip-geometry", out, 960, 600, {{"color", "0.7,0.7,0.5"}}}, {"color", "x + y <= 1"}},
        {{"spectrum-clip", out, 960, 600, {{"methods", "smits,nope"}}}, {"nope", "luv-hue"}},
        {{"spectrum-clip", out, 960, 600, {{"luminance", "2"}}}, {"luminance", "[0.01, 0.99]"}},
        {{"film-spectra", out, 960, 600, {{"films", "100,abc"}}}, {"films", "thickness"}},
        {{"film-spectra", out, 960, 600, {{"film", "unobtainium"}}}, {"film", "mineral-oil"}},
        {{"film-spectra", out, 960, 600, {{"model", "fast"}}}, {"model", "exact, thesis, both"}},
        {{"film-spectra", out, 960, 600, {{"thickness", "5"}}}, {"thickness", "films"}},
    };
    for (const Case& c : cases) {
        try {
            (void)draw_figure(c.request);
            ADD_FAILURE() << c.request.name << ": no exception";
        } catch (const FigureRequestError& e) {
            for (const std::string& s : c.expected) {
                EXPECT_NE(std::string(e.what()).find(s), std::string::npos)
                    << "'" << s << "' missing from: " << e.what();
            }
        }
        EXPECT_FALSE(std::filesystem::exists(c.request.output));
    }
    std::size_t files = 0;
    for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(m_dir)) ++files;
    EXPECT_EQ(files, 0U);
}

TEST_F(Written, WriteFailureIsAnErrorButNotARequestError) {
    try {
        (void)draw_figure({"cmf-xyz", m_dir / "missing" / "x.png", 960, 600, {}});
        FAIL() << "no exception";
    } catch (const FigureRequestError& e) {
        FAIL() << "a write failure reported as a request error: " << e.what();
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("missing"), std::string::npos) << e.what();
    }
}

TEST(Catalog, NamesAreUniqueAndEntriesComplete) {
    std::set<std::string> names;
    for (const FigureInfo& info : figure_catalog()) {
        EXPECT_TRUE(names.insert(info.name).second) << info.name;
        EXPECT_FALSE(info.title.empty()) << info.name;
        EXPECT_FALSE(info.extensions.empty()) << info.name;
        EXPECT_EQ(find_figure(info.name), &info);
    }
    EXPECT_EQ(find_figure("nope"), nullptr);
    EXPECT_EQ(find_figure("cmf-primaries")->thesis_figure, "Figure 2");
    EXPECT_EQ(find_figure("cmf-xyz")->thesis_figure, "Figure 3");
    EXPECT_EQ(find_figure("chromaticity")->thesis_figure, "Figure 4");
    EXPECT_EQ(find_figure("clip-geometry")->thesis_figure, "Figure 10");
    EXPECT_EQ(find_figure("spectrum-clip")->thesis_figure, "Figure 11");
    EXPECT_EQ(find_figure("table1")->thesis_figure, "Table 1");
    EXPECT_EQ(find_figure("table1")->extensions, (std::vector<std::string>{".md", ".html"}));
}

}  // namespace
}  // namespace irid::figures::detail
