#include <irid/color/adaptation.h>
#include <irid/color/difference.h>
#include <irid/color/observer.h>
#include <irid/color/rgb.h>
#include <irid/color/spaces.h>
#include <irid/error.h>
#include <irid/gamut/clip.h>
#include <irid/gamut/report.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

namespace irid {
namespace {

/// The report of a set on sRGB, with a single timed pass (speed is checked only for > 0).
ClipReport quick_report(const ColorSet& set, const RgbSpace& space = srgb()) {
    return measure_clip_report(set, Gamut(space), ClipReportOptions{0.0});
}

const ClipReport& spectrum_report() {
    static const ClipReport report = quick_report(spectrum_color_set());
    return report;
}

const MethodClipReport& of(const ClipReport& report, ClipMethod method) {
    const auto it = std::find_if(report.methods.begin(), report.methods.end(),
                                 [&](const MethodClipReport& m) { return m.method == method; });
    EXPECT_NE(it, report.methods.end());
    return *it;
}

bool outside(const RgbSpace& space, const Xyz& c) {
    const Rgb r = space.from_xyz(c);
    const double tol = 1e-9;
    return r.r < -tol || r.g < -tol || r.b < -tol || r.r > 1 + tol || r.g > 1 + tol || r.b > 1 + tol;
}

TEST(ClipReportSets, SpectrumIsTheLocusAtOneLuminanceAndAlmostAllOutsideSrgb) {
    const ColorSet set = spectrum_color_set();
    ASSERT_EQ(set.colors.size(), 401u);  // 380..780 nm at 1 nm
    int out = 0;
    for (const Xyz& c : set.colors) {
        EXPECT_EQ(c.Y, 0.3);
        EXPECT_TRUE(std::isfinite(c.X) && std::isfinite(c.Z));
        out += outside(srgb(), c) ? 1 : 0;
    }
    // Monochromatic light lies on the spectral locus, outside every gamut of real primaries.
    EXPECT_GE(out, 395);
    EXPECT_EQ(spectrum_report().size, 401u);
    EXPECT_EQ(static_cast<int>(spectrum_report().out_of_gamut), out);
}

TEST(ClipReportSets, Rec2020GridIsInsideRec2020AndPartlyOutsideSrgb) {
    const ColorSet to_srgb = rec2020_color_set(srgb());
    ASSERT_EQ(to_srgb.colors.size(), 729u);
    EXPECT_NEAR(to_srgb.colors.front().Y, 0.0, 1e-15);
    EXPECT_NEAR(to_srgb.colors.back().Y, 1.0, 1e-12);  // (1, 1, 1): the shared D65 white
    const ClipReport in_rec2020 = quick_report(rec2020_color_set(rec2020()), rec2020());
    EXPECT_EQ(in_rec2020.out_of_gamut, 0u);
    const ClipReport in_srgb = quick_report(to_srgb);
    EXPECT_GT(in_srgb.out_of_gamut, 0u);
    EXPECT_LT(in_srgb.out_of_gamut, 729u);
    EXPECT_THROW((void)rec2020_color_set(srgb(), 1), Error);
}

TEST(ClipReportSets, UnionConcatenates) {
    const ColorSet sets[] = {spectrum_color_set(), rec2020_color_set(srgb(), 3)};
    const ColorSet all = union_color_set(sets);
    EXPECT_EQ(all.name, "all");
    ASSERT_EQ(all.colors.size(), 401u + 27u);
    EXPECT_EQ(all.colors[401].Y, sets[1].colors[0].Y);
}

TEST(ClipReport, EveryMethodInOrder) {
    const ClipReport& r = spectrum_report();
    ASSERT_EQ(r.methods.size(), clip_methods().size());
    for (std::size_t i = 0; i < r.methods.size(); ++i) EXPECT_EQ(r.methods[i].method, clip_methods()[i]);
}

TEST(ClipReport, LuminanceKeepingMethodsKeepYOnTheSpectrum) {
    // The grey of Y = 0.3 is inside sRGB: smits moves toward it at constant Y, luv-lightness-hue
    // keeps L*.
    for (const ClipMethod m : {ClipMethod::smits, ClipMethod::smits_xyz, ClipMethod::luv_lightness_hue}) {
        EXPECT_LT(of(spectrum_report(), m).delta_y.max, 1e-9) << clip_method_name(m);
    }
    EXPECT_GT(of(spectrum_report(), ClipMethod::clamp).delta_y.max, 1e-3);
}

TEST(ClipReport, HueKeepingMethodsKeepTheirHue) {
    const MethodClipReport& oklab = of(spectrum_report(), ClipMethod::oklab);
    EXPECT_GT(oklab.hue_oklab.count, 300u);
    EXPECT_LT(oklab.hue_oklab.max, 1e-6);
    // luv-lightness-hue keeps the CIELUV hue, which is neither the CIELAB nor the Oklab hue.
    const MethodClipReport& luv = of(spectrum_report(), ClipMethod::luv_lightness_hue);
    EXPECT_GT(luv.hue_luv.count, 300u);
    EXPECT_LT(luv.hue_luv.max, 1e-6);
    EXPECT_GT(luv.hue_lab.mean, 0.1);
    EXPECT_GT(luv.hue_oklab.mean, 0.1);
}

TEST(ClipReport, StatisticsAreOrderedAndChromaKeptIsAFraction) {
    for (const MethodClipReport& m : spectrum_report().methods) {
        SCOPED_TRACE(std::string(clip_method_name(m.method)));
        EXPECT_EQ(m.delta_e2000.count, 401u);
        for (const ClipStatistics* s : {&m.delta_e2000, &m.hue_lab, &m.hue_oklab, &m.delta_y}) {
            EXPECT_GE(s->mean, 0.0);
            EXPECT_LE(s->mean, s->max + 1e-12);
            EXPECT_LE(s->p95, s->max);
        }
        EXPECT_LE(m.hue_lab.max, 180.0);
        EXPECT_GT(m.delta_e2000.mean, 1.0);  // every colour of the locus had to move
        EXPECT_EQ(m.chroma_kept_count, 401u);
        EXPECT_GT(m.chroma_kept, 0.0);
        EXPECT_LE(m.chroma_kept, 1.0);
        EXPECT_GT(m.colors_per_second, 0.0);
        EXPECT_GE(m.timed_colors, 401u);
    }
}

TEST(ClipReport, InGamutColoursMeasureZero) {
    ColorSet inside{"inside", "the interior of the sRGB cube", {}};
    for (double r = 0.05; r < 1.0; r += 0.15) {
        for (double g = 0.05; g < 1.0; g += 0.15) {
            for (double b = 0.05; b < 1.0; b += 0.15) inside.colors.push_back(srgb().to_xyz({r, g, b}));
        }
    }
    const ClipReport report = quick_report(inside);
    EXPECT_EQ(report.out_of_gamut, 0u);
    for (const MethodClipReport& m : report.methods) {
        if (moves_in_gamut_colours(m.method)) continue;  // the soft methods move them by design
        SCOPED_TRACE(std::string(clip_method_name(m.method)));
        EXPECT_GT(m.colors_per_second, 0.0);
        // The soft methods (aces-rgc, smits-soft) move colours inside the gamut by design.
        if (moves_in_gamut_colours(m.method)) continue;
        EXPECT_EQ(m.delta_e2000.max, 0.0);
        EXPECT_EQ(m.hue_lab.max, 0.0);
        EXPECT_EQ(m.delta_y.max, 0.0);
        EXPECT_EQ(m.chroma_kept, 1.0);
        EXPECT_GT(m.colors_per_second, 0.0);
    }
}

TEST(ClipReport, SpeedRunsForAtLeastTheRequestedTime) {
    const ColorSet set = rec2020_color_set(srgb(), 3);
    const ClipReport report = measure_clip_report(set, Gamut(srgb()), ClipReportOptions{0.01});
    for (const MethodClipReport& m : report.methods) {
        EXPECT_GE(m.timed_seconds, 0.01);
        EXPECT_EQ(m.timed_colors % set.colors.size(), 0u);
        // Every round ran at least one whole pass; the rate is the median of the rounds'.
        EXPECT_GT(m.colors_per_second, 0.0);
        EXPECT_GE(m.timed_colors, static_cast<std::size_t>(clip_report_timing_rounds) * set.colors.size());
    }
    EXPECT_THROW((void)measure_clip_report(set, Gamut(srgb()), ClipReportOptions{-1.0}), Error);
    EXPECT_THROW((void)measure_clip_report(ColorSet{}, Gamut(srgb())), Error);
}

TEST(ClipReport, MarkdownHasTheSetLineAndOneRowPerMethod) {
    const std::string md = clip_report_markdown(spectrum_report());
    EXPECT_EQ(md.rfind("Set spectrum: 401 colours, ", 0), 0u) << md;
    EXPECT_NE(md.find("out of the srgb gamut"), std::string::npos);
    EXPECT_NE(md.find("| method | ΔE00 mean | ΔE00 p95 | ΔE00 max |"), std::string::npos);
    for (const ClipMethod m : clip_methods()) {
        const std::string row = "| " + std::string(clip_method_name(m)) + " |";
        const auto at = md.find(row);
        ASSERT_NE(at, std::string::npos) << row;
        const std::string line = md.substr(at, md.find('\n', at) - at);
        // 9 columns: 10 unescaped bars.
        int bars = 0;
        for (std::size_t i = 0; i < line.size(); ++i) bars += line[i] == '|' && (i == 0 || line[i - 1] != '\\');
        EXPECT_EQ(bars, 10) << line;
    }
}


// --- the ramps set and the gradient measures ------------------------------------------------

/// The destinations the ramps are checked on: two D65 spaces and one with another white (ACEScg,
/// the ACES white), whose Rec.2020 cube and Oklab hue need the Bradford adaptation.
std::vector<const RgbSpace*> ramp_destinations() { return {&srgb(), &display_p3(), &acescg()}; }

/// Linear Rec.2020 of XYZ relative to the destination's white.
Rgb rec2020_of(const RgbSpace& destination, const Xyz& c) {
    const Mat3 to_xyz = destination.white().x == rec2020().white().x && destination.white().y == rec2020().white().y
                            ? rec2020().to_xyz_matrix()
                            : adaptation_matrix(rec2020().white_xyz(), destination.white_xyz()) *
                                  rec2020().to_xyz_matrix();
    const Vec3 v = inverse(to_xyz) * Vec3{c.X, c.Y, c.Z};
    return {v[0], v[1], v[2]};
}

/// Distance in xy from a chromaticity to the spectral locus polygon (380-780 nm at 1 nm and the
/// purple line).
double distance_to_locus(const Xy& p) {
    const auto xy_of = [](int nm) {
        const Xyz m = monochromatic_xyz(nm);
        const double sum = m.X + m.Y + m.Z;
        return Xy{m.X / sum, m.Y / sum};
    };
    double best = std::numeric_limits<double>::infinity();
    for (int nm = 380; nm <= 780; ++nm) {
        const Xy a = xy_of(nm), b = xy_of(nm < 780 ? nm + 1 : 380);
        const double dx = b.x - a.x, dy = b.y - a.y;
        const double len2 = dx * dx + dy * dy;
        const double t = len2 > 0.0 ? std::clamp(((p.x - a.x) * dx + (p.y - a.y) * dy) / len2, 0.0, 1.0) : 0.0;
        best = std::min(best, std::hypot(p.x - (a.x + t * dx), p.y - (a.y + t * dy)));
    }
    return best;
}

TEST(ClipReportRamps, TheSetIs144RampsOf256StepsInOrder) {
    const ColorSet set = ramps_color_set(srgb());
    EXPECT_EQ(set.name, "ramps");
    ASSERT_EQ(set.colors.size(), 36864u);
    ASSERT_EQ(set.ramps.size(), 144u);
    for (std::size_t r = 0; r < set.ramps.size(); ++r) {
        EXPECT_EQ(set.ramps[r].first, 256u * r);
        EXPECT_EQ(set.ramps[r].size, 256u);
    }
    // Luminance outermost, then the end, then the hue (h = 15° k).
    EXPECT_EQ(set.ramps[0].label, "Y 0.1, h 0°, to rec2020");
    EXPECT_EQ(set.ramps[25].label, "Y 0.1, h 15°, to the locus");
    EXPECT_EQ(set.ramps[143].label, "Y 0.6, h 345°, to the locus");
    const std::vector<Xyz> one = color_ramp(srgb(), 0.3, 45.0, RampEnd::locus);
    for (std::size_t i = 0; i < one.size(); ++i) {
        EXPECT_EQ(one[i].X, set.colors[set.ramps[48 + 24 + 3].first + i].X);
        EXPECT_EQ(one[i].Z, set.colors[set.ramps[48 + 24 + 3].first + i].Z);
    }
}

TEST(ClipReportRamps, EveryStepHasTheRampsLuminanceAndTheFirstIsItsGrey) {
    for (const RgbSpace* space : ramp_destinations()) {
        SCOPED_TRACE(space->name());
        const Xyz white = space->white_xyz();
        for (const double y : ramp_set_luminances) {
            for (const RampEnd end : {RampEnd::rec2020, RampEnd::locus}) {
                for (const double h : {0.0, 100.0, 265.0}) {
                    const std::vector<Xyz> ramp = color_ramp(*space, y, h, end);
                    ASSERT_EQ(ramp.size(), 256u);
                    EXPECT_EQ(ramp[0].X, white.X * y);
                    EXPECT_EQ(ramp[0].Y, y);
                    EXPECT_EQ(ramp[0].Z, white.Z * y);
                    for (const Xyz& c : ramp) EXPECT_EQ(c.Y, y);
                }
            }
        }
    }
}

TEST(ClipReportRamps, Rec2020EndsAreOnTheRec2020Boundary) {
    for (const RgbSpace* space : ramp_destinations()) {
        SCOPED_TRACE(space->name());
        for (const double y : ramp_set_luminances) {
            for (int k = 0; k < ramp_set_hues; ++k) {
                const std::vector<Xyz> ramp = color_ramp(*space, y, 15.0 * k, RampEnd::rec2020);
                const Rgb e = rec2020_of(*space, ramp.back());
                const double lo = std::min({e.r, e.g, e.b}), hi = std::max({e.r, e.g, e.b});
                EXPECT_GE(lo, -1e-9);
                EXPECT_LE(hi, 1.0 + 1e-9);
                EXPECT_LT(std::min(std::abs(lo), std::abs(hi - 1.0)), 1e-9) << y << " " << 15 * k;
                // Every step before the end is inside Rec.2020.
                const Rgb before = rec2020_of(*space, ramp[254]);
                EXPECT_GT(std::min({before.r, before.g, before.b}), 0.0);
                EXPECT_LT(std::max({before.r, before.g, before.b}), 1.0);
            }
        }
    }
}

TEST(ClipReportRamps, LocusEndsAreOnTheSpectralLocus) {
    for (const RgbSpace* space : ramp_destinations()) {
        SCOPED_TRACE(space->name());
        for (const double y : ramp_set_luminances) {
            for (int k = 0; k < ramp_set_hues; ++k) {
                const std::vector<Xyz> ramp = color_ramp(*space, y, 15.0 * k, RampEnd::locus);
                const Xyz e = ramp.back();
                const double sum = e.X + e.Y + e.Z;
                EXPECT_LT(distance_to_locus({e.X / sum, e.Y / sum}), 1e-9) << y << " " << 15 * k;
                // Physical: no tristimulus value below 0 (to rounding), and farther than the
                // Rec.2020 end, which lies inside the locus.
                EXPECT_GE(std::min(e.X, e.Z), -1e-12);
                const RampGeometry locus = ramp_geometry(*space, y, 15.0 * k, RampEnd::locus);
                const RampGeometry gamut = ramp_geometry(*space, y, 15.0 * k, RampEnd::rec2020);
                EXPECT_GE(locus.end, gamut.end);
            }
        }
    }
}

TEST(ClipReportRamps, RampsLeaveTheGreyAlongTheirOklabHueAndStepEvenlyInCiede2000) {
    for (const RgbSpace* space : {&srgb(), &display_p3()}) {  // D65: Oklab needs no adaptation
        for (int k = 0; k < ramp_set_hues; ++k) {
            const double h = 15.0 * k;
            const std::vector<Xyz> ramp = color_ramp(*space, 0.3, h, RampEnd::locus);
            // The direction is the hue's at the grey: a small step from the grey moves Oklab
            // (a, b) along (cos h, sin h). (The grey itself has Oklab C ≈ 1.3e-4 with the
            // published matrices, so the step's direction, not its hue, is what is h.)
            const RampGeometry g = ramp_geometry(*space, 0.3, h, RampEnd::locus);
            const double s = 1e-6 * g.end;
            const Oklab grey = xyz_to_oklab(g.grey);
            const Oklab near =
                xyz_to_oklab({g.grey.X + s * g.direction[0], g.grey.Y, g.grey.Z + s * g.direction[2]});
            const double step_h = std::atan2(near.b - grey.b, near.a - grey.a) * 180.0 / std::numbers::pi;
            double dh = std::fmod(std::abs(step_h - h) + 720.0, 360.0);
            dh = std::min(dh, 360.0 - dh);
            EXPECT_LT(dh, 0.05) << h;
            // Equal ΔE2000 between neighbours, to the resolution of the arc-length table.
            std::vector<Lab> lab;
            for (const Xyz& c : ramp) lab.push_back(xyz_to_lab(c, space->white_xyz()));
            EXPECT_LT(ramp_banding(lab), 1.05) << h;
        }
    }
}

TEST(ClipReportRamps, BadRampRequestsThrow) {
    EXPECT_THROW((void)ramp_geometry(srgb(), 0.0, 0.0, RampEnd::locus), Error);
    EXPECT_THROW((void)ramp_geometry(srgb(), 1.0, 0.0, RampEnd::locus), Error);
    EXPECT_THROW((void)ramp_geometry(srgb(), 0.3, std::numeric_limits<double>::quiet_NaN(), RampEnd::locus), Error);
    EXPECT_THROW((void)color_ramp(srgb(), 0.3, 0.0, RampEnd::rec2020, 1), Error);
    ColorSet bad{"bad", "a ramp past the end", {srgb().white_xyz()}};
    bad.ramps.push_back({0, 2, "too long"});
    EXPECT_THROW((void)quick_report(bad), Error);
}

/// Two CIELAB colours and a ramp alternating between them: every neighbouring pair is the same
/// pair, so every step has the same ΔE2000.
const Lab lab_a{50.0, 10.0, -5.0}, lab_b{52.0, 14.0, -3.0};
std::vector<Lab> alternating(std::size_t n) {
    std::vector<Lab> out;
    for (std::size_t i = 0; i < n; ++i) out.push_back(i % 2 == 0 ? lab_a : lab_b);
    return out;
}

TEST(ClipReportMeasures, EvenStepsGiveBandingOneAndAKneeItsClosedForm) {
    EXPECT_NEAR(ramp_banding(alternating(256)), 1.0, 1e-12);
    // k equal steps, then the output stops: max d over mean k d / 255 = 255 / k.
    for (const std::size_t k : {1u, 51u, 200u, 255u}) {
        std::vector<Lab> knee = alternating(k + 1);
        knee.resize(256, knee.back());
        EXPECT_NEAR(ramp_banding(knee), 255.0 / static_cast<double>(k), 1e-12) << k;
    }
    // One colour throughout: no step to see; fewer than two colours likewise.
    EXPECT_EQ(ramp_banding(std::vector<Lab>(10, lab_a)), 1.0);
    EXPECT_EQ(ramp_banding(std::vector<Lab>(1, lab_a)), 1.0);
    ASSERT_GT(delta_e_2000(lab_a, lab_b), clip_report_collapse_delta_e);
}

TEST(ClipReportMeasures, CollapseCountsOutOfGamutStepsThatStopMoving) {
    // 10 steps, the last 6 out of gamut; of steps 4..8 (9 has no next) those within 0.5 count.
    std::vector<Lab> lab = alternating(10);
    std::unique_ptr<bool[]> out = std::make_unique<bool[]>(10);
    for (int i = 4; i < 10; ++i) out[static_cast<std::size_t>(i)] = true;
    const std::span<const bool> flags(out.get(), 10);
    EXPECT_EQ(ramp_collapse(lab, flags), 0.0);  // every step moves by more than 0.5
    for (std::size_t i = 6; i < 10; ++i) lab[i] = lab[5];  // steps 5..8 map to one output
    EXPECT_DOUBLE_EQ(*ramp_collapse(lab, flags), 4.0 / 5.0);
    // A larger threshold takes every step.
    EXPECT_EQ(ramp_collapse(alternating(10), flags, 100.0), 1.0);
    // No out-of-gamut step, or only the last: nothing to measure.
    const std::unique_ptr<bool[]> none = std::make_unique<bool[]>(10);
    EXPECT_FALSE(ramp_collapse(lab, std::span<const bool>(none.get(), 10)).has_value());
    none[9] = true;
    EXPECT_FALSE(ramp_collapse(lab, std::span<const bool>(none.get(), 10)).has_value());
    EXPECT_THROW((void)ramp_collapse(lab, std::span<const bool>(none.get(), 9)), Error);
}

/// A set of a few ramps of the ramps set's construction.
ColorSet some_ramps(const RgbSpace& space, double y, std::initializer_list<double> hues, RampEnd end) {
    ColorSet set{"some-ramps", "a few ramps", {}};
    for (const double h : hues) {
        const std::vector<Xyz> r = color_ramp(space, y, h, end);
        set.ramps.push_back({set.colors.size(), r.size(), "h " + std::to_string(h)});
        set.colors.insert(set.colors.end(), r.begin(), r.end());
    }
    return set;
}

TEST(ClipReportMeasures, HardClipsCollapseTheTailOfARampThatEndsFarOutside) {
    // Toward violet the locus at Y = 0.3 is far outside sRGB (most of the ramp is outside).
    const ClipReport report = quick_report(some_ramps(srgb(), 0.3, {270.0, 300.0}, RampEnd::locus));
    EXPECT_EQ(report.ramps, 2u);
    EXPECT_GT(report.out_of_gamut, 200u);
    EXPECT_LT(report.input_banding.max, 1.05);
    const MethodClipReport& clamp = of(report, ClipMethod::clamp);
    EXPECT_EQ(clamp.collapse.count, 2u);
    EXPECT_GT(clamp.collapse.mean, 0.0);
    EXPECT_GT(clamp.collapse_relative.mean, 0.0);
    EXPECT_GT(clamp.banding.mean, 1.05);
    // smits moves every colour along the ramp's own line to where it meets the cube: the whole
    // tail lands on one point, every out-of-gamut step collapses.
    for (const ClipMethod m : {ClipMethod::smits, ClipMethod::smits_xyz, ClipMethod::luv_lightness_hue}) {
        SCOPED_TRACE(std::string(clip_method_name(m)));
        EXPECT_EQ(of(report, m).collapse.mean, 1.0);
        EXPECT_EQ(of(report, m).collapse_relative.mean, 1.0);
        EXPECT_GT(of(report, m).banding.mean, 1.5);
    }
}

TEST(ClipReportMeasures, MethodsThatLeaveInGamutColoursAloneMoveThemByZero) {
    const ColorSet set = ramps_color_set(srgb());
    const ClipReport report = quick_report(set);
    EXPECT_EQ(report.ramps, 144u);
    EXPECT_GT(report.out_of_gamut, 0u);
    EXPECT_LT(report.out_of_gamut, set.colors.size());
    EXPECT_LT(report.input_banding.max, 1.05);
    for (const MethodClipReport& m : report.methods) {
        SCOPED_TRACE(std::string(clip_method_name(m.method)));
        EXPECT_EQ(m.in_gamut_moved.count, report.size - report.out_of_gamut);
        if (!moves_in_gamut_colours(m.method)) {
            EXPECT_EQ(m.in_gamut_moved.max, 0.0);
        }
        EXPECT_EQ(m.banding.count, 144u);
        EXPECT_GE(m.banding.mean, 1.0);
        EXPECT_LE(m.banding.mean, m.banding.max);
        EXPECT_GE(m.collapse.mean, 0.0);
        EXPECT_LE(m.collapse.max, 1.0);
        EXPECT_LE(m.collapse_relative.mean, m.collapse.mean + 1e-12);  // a smaller threshold
        EXPECT_GT(m.colors_per_second, 0.0);
    }
}

TEST(ClipReportMeasures, ARampAboveTheWhitesLuminanceGoesToTheWhiteWhole) {
    // A gamut whose white has Y = 0.5: the grey of Y = 0.6 is outside, so is every step.
    const ColorSet set = some_ramps(srgb(), 0.6, {0.0, 180.0}, RampEnd::rec2020);
    const ClipReport report = measure_clip_report(set, Gamut(srgb(), 0.5), ClipReportOptions{0.0});
    EXPECT_EQ(report.out_of_gamut, set.colors.size());
    const MethodClipReport& smits = of(report, ClipMethod::smits);
    EXPECT_EQ(smits.banding.max, 1.0);  // one colour: the white
    EXPECT_EQ(smits.collapse.mean, 1.0);
    EXPECT_EQ(smits.in_gamut_moved.count, 0u);
}

TEST(ClipReportMeasures, UnionKeepsTheRampsAtTheirNewPlaces) {
    const ColorSet sets[] = {spectrum_color_set(), some_ramps(srgb(), 0.3, {0.0, 90.0}, RampEnd::locus)};
    const ColorSet all = union_color_set(sets);
    ASSERT_EQ(all.ramps.size(), 2u);
    EXPECT_EQ(all.ramps[0].first, 401u);
    EXPECT_EQ(all.ramps[1].first, 401u + 256u);
    EXPECT_EQ(all.colors[all.ramps[1].first].X, sets[1].colors[256].X);
}

TEST(ClipReportMeasures, EveryClipperOfTheReportConfinesToTheCube) {
    for (const ClipMethod m : clip_methods()) {
        const GamutClipper clipper = report_clipper(m, Gamut(srgb()));
        EXPECT_TRUE(clipper.confines_to_cube()) << clip_method_name(m);
        EXPECT_EQ(clipper.method(), m);
    }
}

TEST(ClipReportMeasures, MarkdownHasTheSecondTableWithDashesWhereNothingIsMeasured) {
    const std::string md = clip_report_markdown(spectrum_report());
    EXPECT_NE(md.find("| method | in-gamut ΔE00 mean / max | banding mean / max | collapse | collapse ½ step |"),
              std::string::npos);
    EXPECT_NE(md.find("over 0 ramps."), std::string::npos);
    for (const ClipMethod m : clip_methods()) {
        // The spectrum has no ramps and no colour inside sRGB: every measure is a dash.
        const std::string row = "| " + std::string(clip_method_name(m)) + " | – | – | – | – |\n";
        EXPECT_NE(md.find(row), std::string::npos) << row;
    }
    const std::string ramps = clip_report_markdown(quick_report(some_ramps(srgb(), 0.3, {0.0}, RampEnd::locus)));
    EXPECT_NE(ramps.find("| smits | 0.00 / 0.00 | "), std::string::npos) << ramps;
    EXPECT_NE(ramps.find("the input ramps' own banding is 1.0"), std::string::npos) << ramps;
}

}  // namespace
}  // namespace irid
