// bake_display_lut: the ACES 2.0 display transform as a LUT, and how closely the LUT, interpolated
// as OpenColorIO interpolates a .clf, stands for the transform (docs/DISPLAY.md, "LUTs and
// OpenColorIO 2.1").
#include <irid/color/convert.h>
#include <irid/color/difference.h>
#include <irid/color/spaces.h>
#include <irid/error.h>
#include <irid/exchange/display_lut.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

namespace irid {
namespace {

DisplayTransform transform_to(const char* display, const char* target) {
    return DisplayTransform(display_lut_options("aces2", display, "aces2065-1", target));
}

TEST(DisplayLut, TheTargetDefaultsToTheDisplaysEncoding) {
    EXPECT_EQ(display_lut_options("aces2", "sdr-100nit-rec709", "aces2065-1", "").target, "srgb");
    EXPECT_EQ(display_lut_options("aces2", "hdr-1000nit-p3-d65", "aces2065-1", "").target, "p3-d65-pq");
    EXPECT_EQ(display_lut_options("aces2", "sdr-100nit-rec709", "acescg", "xyz").target, "xyz");
    EXPECT_THROW((void)display_lut_options("aces2", "sdr-100nit-p3-d60-in-xyz-e", "aces2065-1", ""), Error);
    EXPECT_THROW((void)display_lut_options("aces2", "no-such-display", "aces2065-1", ""), UnknownNameError);
}

TEST(DisplayLut, TheDefaultClfDomainIsLog2UpToTheForwardLimit) {
    const DisplayTransform sdr = transform_to("sdr-100nit-rec709", "srgb");
    const LutDomain d = display_lut_domain(sdr, LutFormat::clf);
    EXPECT_EQ(d.shaper, LutShaper::log2);
    EXPECT_EQ(d.min, 0.0);
    // 8 (128 + 768 log(peak/100) / log(100)) of ACES 2.0 (issue 27): 1024 at 100 cd/m², 4096 at 1000.
    EXPECT_NEAR(d.max, 1024.0, 1e-9);
    EXPECT_EQ(d.stops, display_lut_stops);
    EXPECT_NEAR(display_lut_domain(transform_to("hdr-1000nit-p3-d65", "p3-d65-pq"), LutFormat::clf).max,
                4096.0, 1e-9);
    // A .cube (no shaper) over linear scene values is refused, and over another encoding than
    // ACEScct; over ACEScct it is uniform over the code values [0, 1], for .clf too.
    EXPECT_THROW((void)display_lut_domain(sdr, LutFormat::cube), Error);
    const DisplayTransform srgb_source(display_lut_options("aces2", "sdr-100nit-rec709", "srgb", "srgb"));
    EXPECT_THROW((void)display_lut_domain(srgb_source, LutFormat::cube), Error);
    const DisplayTransform cct(display_lut_options("aces2", "sdr-100nit-rec709", "acescct", "srgb"));
    for (const LutFormat f : {LutFormat::cube, LutFormat::clf}) {
        const LutDomain u = display_lut_domain(cct, f);
        EXPECT_EQ(u.shaper, LutShaper::none);
        EXPECT_EQ(u.min, 0.0);
        EXPECT_EQ(u.max, 1.0);
    }
}

TEST(DisplayLut, EveryNodeHoldsTheTransformOfItsInput) {
    const DisplayTransform t = transform_to("sdr-100nit-rec709", "srgb");
    const Lut3D lut = bake_display_lut(t, 9, display_lut_domain(t, LutFormat::clf), 2);
    EXPECT_EQ(lut.source, "aces2065-1");
    EXPECT_EQ(lut.destination, "srgb");
    for (const char* word : {"--view aces2", "--display sdr-100nit-rec709", "--size 9", "log2 shaper"}) {
        EXPECT_NE(lut.title.find(word), std::string::npos) << lut.title;
    }
    for (int b = 0; b < 9; b += 4) {
        for (int g = 0; g < 9; ++g) {
            for (int r = 0; r < 9; r += 2) {
                const Vec3 expected = t({lut.node(r), lut.node(g), lut.node(b)});
                const float* v = &lut.values[3 * static_cast<std::size_t>(r + 9 * (g + 9 * b))];
                for (int c = 0; c < 3; ++c) EXPECT_NEAR(v[c], expected[c], 2e-5) << r << ' ' << g << ' ' << b;
            }
        }
    }
    DisplayTransformOptions inverse = t.options();
    inverse.inverse = true;
    std::swap(inverse.source, inverse.target);
    EXPECT_THROW((void)bake_display_lut(DisplayTransform(inverse), 9, {}, 1), Error);
    EXPECT_THROW((void)bake_display_lut(t, 1, {}, 1), Error);
}

/// Scene colours spanning ACES2065-1 [0, limit]: greys and 12 hues at three saturations, at
/// exposures every half stop from 2^-12 to the limit.
std::vector<Vec3> scene_colours(double limit) {
    std::vector<Vec3> out;
    for (double stop = -12.0; std::exp2(stop) <= limit; stop += 0.5) {
        const double e = std::exp2(stop);
        out.push_back({e, e, e});
        for (int h = 0; h < 12; ++h) {
            const double angle = 2.0 * std::numbers::pi * h / 12.0;
            for (const double s : {0.3, 0.6, 0.9}) {
                Vec3 c{};
                for (int k = 0; k < 3; ++k) {
                    c[k] = e * (1.0 - s + s * 0.5 * (1.0 + std::cos(angle - 2.0 * std::numbers::pi * k / 3.0)));
                }
                out.push_back(c);
            }
        }
    }
    return out;
}

struct Stats {
    double mean = 0.0, p95 = 0.0, max = 0.0;
};

/// ΔE2000 of the LUT (tetrahedral, as OCIO applies irid's .clf) against the transform, both
/// display signals decoded to XYZ and taken to CIELAB relative to the display's white at its peak.
Stats lut_delta_e(const char* display, const char* target, int size, LutFormat format) {
    const DisplayTransform t = transform_to(display, target);
    // The .cube takes ACEScct code values (the scene colours are encoded on the way in), whose
    // [0, 1] reaches 222.86 (2^7.8): the colours measured stop there.
    const char* source = format == LutFormat::cube ? "acescct" : "aces2065-1";
    const double limit = format == LutFormat::cube ? acescct().transfer().decode(1.0)
                                                   : display_lut_domain(t, LutFormat::clf).max;
    const DisplayTransform baked(display_lut_options("aces2", display, source, target));
    const Lut3D lut = bake_display_lut(baked, size, display_lut_domain(baked, format), 0);
    const Converter to_source(color_space("aces2065-1"), color_space(source));
    const Converter to_xyz(color_space(target), color_space("xyz"));
    const double peak = t.output().spec().peak_nits * t.output().spec().linear_scale / 100.0;
    const Xyz white = xy_to_xyz(d65_xy);
    const auto lab = [&](const Vec3& signal) {
        const Vec3 x = to_xyz(signal);
        return xyz_to_lab({x[0] / peak, x[1] / peak, x[2] / peak}, white);
    };
    std::vector<double> de;
    for (const Vec3& c : scene_colours(limit)) {
        const Rgb l = apply_lut(lut, to_source(c), lut_format_interpolation(format));
        de.push_back(delta_e_2000(lab(t(c)), lab({l.r, l.g, l.b})));
    }
    std::sort(de.begin(), de.end());
    Stats s;
    for (const double d : de) s.mean += d / static_cast<double>(de.size());
    s.p95 = de[static_cast<std::size_t>(std::ceil(0.95 * static_cast<double>(de.size()))) - 1];
    s.max = de.back();
    std::printf("%s %s %s size %d, %zu colours: mean %.3f p95 %.3f max %.3f\n", display, target,
                format == LutFormat::cube ? ".cube over ACEScct" : ".clf log2", size, de.size(), s.mean,
                s.p95, s.max);
    return s;
}

TEST(DisplayLut, TheLutStandsForTheTransformWithinItsMeasuredDeltaE) {
    struct Case {
        const char* display;
        const char* target;
        int size;
        LutFormat format;
        Stats bound;
    };
    // docs/DISPLAY.md's table (apply_lut: tetrahedral for the .clf, trilinear for the .cube, as
    // OpenColorIO reads them), with a margin of about 10 %.
    const std::array<Case, 8> cases{{
        {"sdr-100nit-rec709", "srgb", 33, LutFormat::clf, {0.24, 1.0, 2.6}},
        {"sdr-100nit-rec709", "srgb", 65, LutFormat::clf, {0.065, 0.29, 0.81}},
        {"sdr-100nit-rec709", "srgb", 33, LutFormat::cube, {0.21, 0.82, 1.95}},
        {"sdr-100nit-rec709", "srgb", 65, LutFormat::cube, {0.065, 0.28, 1.15}},
        {"hdr-1000nit-p3-d65", "p3-d65-pq", 33, LutFormat::clf, {0.19, 0.78, 3.0}},
        {"hdr-1000nit-p3-d65", "p3-d65-pq", 65, LutFormat::clf, {0.052, 0.26, 1.05}},
        {"hdr-1000nit-p3-d65", "p3-d65-pq", 33, LutFormat::cube, {0.145, 0.57, 4.0}},
        {"hdr-1000nit-p3-d65", "p3-d65-pq", 65, LutFormat::cube, {0.047, 0.2, 0.83}},
    }};
    for (const Case& c : cases) {
        const Stats s = lut_delta_e(c.display, c.target, c.size, c.format);
        EXPECT_LE(s.mean, c.bound.mean) << c.display << ' ' << c.size;
        EXPECT_LE(s.p95, c.bound.p95) << c.display << ' ' << c.size;
        EXPECT_LE(s.max, c.bound.max) << c.display << ' ' << c.size;
    }
}

}  // namespace
}  // namespace irid
