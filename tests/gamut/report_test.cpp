#include <irid/color/rgb.h>
#include <irid/error.h>
#include <irid/gamut/clip.h>
#include <irid/gamut/report.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
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
    // The grey of Y = 0.3 is inside sRGB: smits moves toward it at constant Y, smits-corrected
    // moves along the face at constant Y, luv-lightness-hue keeps L*.
    for (const ClipMethod m : {ClipMethod::smits, ClipMethod::smits_xyz, ClipMethod::smits_corrected,
                               ClipMethod::luv_lightness_hue}) {
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

}  // namespace
}  // namespace irid
