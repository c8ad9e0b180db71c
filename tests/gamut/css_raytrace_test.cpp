// css-raytrace (CSS Color 4 "Ray Trace" gamut mapping, src/gamut/css_raytrace.cpp) against
// colorjs.io's published values and the method's invariants; the float SIMD kernels of css and
// css-raytrace (src/gamut/batch_simd_css.cpp) against their double references.

#include <irid/color/difference.h>
#include <irid/color/rgb.h>
#include <irid/color/spaces.h>
#include <irid/gamut/batch.h>
#include <irid/gamut/clip.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace irid {
namespace {

/// Linear Display P3 → linear sRGB through XYZ (both D65, so no adaptation).
Rgb p3_to_srgb_linear(const Rgb& p3_linear) {
    return srgb().from_xyz(display_p3().to_xyz(p3_linear));
}

bool on_a_face(const Rgb& c, double max, double tol) {
    for (const double v : {c.r, c.g, c.b}) {
        if (std::abs(v) <= tol || std::abs(v - max) <= tol) return true;
    }
    return false;
}

/// Uniform colours in [-0.5, 1.5]^3 × max outside the cube (the benchmark's input).
std::vector<Rgb> outside_colours(int count, double max, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(-0.5 * max, 1.5 * max);
    std::vector<Rgb> out;
    while (static_cast<int>(out.size()) < count) {
        const Rgb c{u(rng), u(rng), u(rng)};
        if (!Gamut(srgb(), max).contains(c)) out.push_back(c);
    }
    return out;
}

std::vector<Gamut> test_gamuts() {
    std::vector<Gamut> g;
    for (const RgbSpace* s : builtin_rgb_spaces()) g.emplace_back(*s);
    g.emplace_back(srgb(), 4.0);
    g.emplace_back(rec2020(), 4.0);
    return g;
}

// colorjs.io test/gamut.js, "P3 primaries to sRGB, Ray Trace algorithm" (toSpace srgb-linear,
// method raytrace), checked there with check.proximity({ epsilon: 0.001 }).
TEST(CssRaytrace, MatchesColorjsPublishedValuesForDisplayP3PrimariesAndSecondaries) {
    struct Case {
        Rgb p3;
        Rgb expected;
    };
    const Case cases[] = {
        {{1, 0, 0}, {1, 0.0342, 0.02168}},   {{0, 1, 0}, {0, 0.92946, 0.07742}},
        {{0, 0, 1}, {0, 0.01714, 0.97711}},  {{1, 1, 0}, {0.98002, 0.99395, 0}},
        {{0, 1, 1}, {0, 0.96255, 0.93527}},  {{1, 0, 1}, {1, 0.07188, 0.87704}},
    };
    const GamutClipper clipper(ClipMethod::css_raytrace, Gamut(srgb()));
    for (const Case& k : cases) {
        const Rgb got = clipper.clip(p3_to_srgb_linear(k.p3));
        EXPECT_NEAR(got.r, k.expected.r, 0.001) << k.p3.r << " " << k.p3.g << " " << k.p3.b;
        EXPECT_NEAR(got.g, k.expected.g, 0.001) << k.p3.r << " " << k.p3.g << " " << k.p3.b;
        EXPECT_NEAR(got.b, k.expected.b, 0.001) << k.p3.r << " " << k.p3.g << " " << k.p3.b;
    }
}

// colorjs.io test/gamut.js, "P3 to sRGB whites/blacks, Ray Trace algorithm": the P3 colours
// (encoded) 1 1 1 and 2 0 1 give white, 0 0 0 and -1 0 0 black.
TEST(CssRaytrace, MatchesColorjsPublishedWhitesAndBlacks) {
    const GamutClipper clipper(ClipMethod::css_raytrace, Gamut(srgb()));
    const auto map = [&](const Rgb& encoded) {
        return clipper.clip(p3_to_srgb_linear(display_p3().decode(encoded)));
    };
    for (const Rgb& w : {Rgb{1, 1, 1}, Rgb{2, 0, 1}}) {
        const Rgb got = map(w);
        EXPECT_NEAR(got.r, 1.0, 0.001);
        EXPECT_NEAR(got.g, 1.0, 0.001);
        EXPECT_NEAR(got.b, 1.0, 0.001);
    }
    for (const Rgb& k : {Rgb{0, 0, 0}, Rgb{-1, 0, 0}}) {
        const Rgb got = map(k);
        EXPECT_NEAR(got.r, 0.0, 0.001);
        EXPECT_NEAR(got.g, 0.0, 0.001);
        EXPECT_NEAR(got.b, 0.0, 0.001);
    }
}

TEST(CssRaytrace, LightnessAtOrBeyondWhiteGivesWhiteAndAtOrBelowZeroBlack) {
    for (const Gamut& gamut : test_gamuts()) {
        const GamutClipper clipper(ClipMethod::css_raytrace, gamut);
        const double max = gamut.max();
        int whites = 0, blacks = 0;
        for (const Rgb& c : outside_colours(3000, max, 7)) {
            const double L = clipper.to_oklab(c).L;
            const Rgb got = clipper.clip(c);
            if (L >= clipper.white_oklab_lightness()) {
                EXPECT_EQ(got.r, max);
                EXPECT_EQ(got.g, max);
                EXPECT_EQ(got.b, max);
                ++whites;
            } else if (L <= 0.0) {
                EXPECT_EQ(got.r, 0.0);
                EXPECT_EQ(got.g, 0.0);
                EXPECT_EQ(got.b, 0.0);
                ++blacks;
            }
        }
        EXPECT_GT(whites, 0) << gamut.space().name();
        EXPECT_GT(blacks, 0) << gamut.space().name();
    }
}

TEST(CssRaytrace, InGamutUnchangedOutputInTheCubeOnItsSurfaceAndIdempotent) {
    for (const Gamut& gamut : test_gamuts()) {
        const GamutClipper clipper(ClipMethod::css_raytrace, gamut);
        const double max = gamut.max();
        std::mt19937 rng(11);
        std::uniform_real_distribution<double> u(0.0, max);
        for (int k = 0; k < 500; ++k) {
            const Rgb c{u(rng), u(rng), u(rng)};
            const Rgb got = clipper.clip(c);
            EXPECT_EQ(got.r, c.r);
            EXPECT_EQ(got.g, c.g);
            EXPECT_EQ(got.b, c.b);
        }
        int on_surface = 0, mapped = 0;
        for (const Rgb& c : outside_colours(3000, max, 13)) {
            const Rgb got = clipper.clip(c);
            ASSERT_TRUE(gamut.contains(got)) << gamut.space().name();
            const Rgb again = clipper.clip(got);
            EXPECT_EQ(again.r, got.r);
            EXPECT_EQ(again.g, got.g);
            EXPECT_EQ(again.b, got.b);
            const double L = clipper.to_oklab(c).L;
            if (L > 0.0 && L < clipper.white_oklab_lightness()) {
                // The last step is a ray's intersection with the cube (then clipped): the
                // result lies on a face.
                ++mapped;
                if (on_a_face(got, max, 1e-9 * max)) ++on_surface;
            }
        }
        EXPECT_EQ(on_surface, mapped) << gamut.space().name();
    }
}

TEST(CssRaytrace, KeepsLightnessAndHueAsTheSpecificationIntends) {
    // "constant-lightness, constant-hue chroma reduction in OkLCh" (CSS Color 4 §13.2), the
    // residual after four passes removed by the final clip: the result's Oklab L and hue are
    // those of the input to within a small fraction of one JND (0.02 in ΔEOK), measured as
    // the ΔEOK between the result and OkLCh(L_in, C_out, h_in). And it is no farther from the
    // input than the binary search's result plus one JND (both reduce chroma; the binary
    // search stops up to one JND early).
    for (const Gamut& gamut : {Gamut(srgb()), Gamut(display_p3()), Gamut(rec2020())}) {
        const GamutClipper ray(ClipMethod::css_raytrace, gamut);
        const GamutClipper css(ClipMethod::css, gamut);
        std::vector<double> deviations;
        for (const Rgb& c : outside_colours(3000, 1.0, 17)) {
            const Oklch in = oklab_to_oklch(ray.to_oklab(c));
            if (!(in.L > 0.05 && in.L < 0.95) || in.C < 0.05) continue;
            const Rgb got = ray.clip(c);
            const Oklch out = oklab_to_oklch(ray.to_oklab(got));
            const double dev = delta_e_ok(oklch_to_oklab({in.L, out.C, in.h}), ray.to_oklab(got));
            deviations.push_back(dev);
            EXPECT_LT(dev, 0.02) << gamut.space().name() << " " << c.r << "," << c.g << "," << c.b;
            EXPECT_LE(out.C, in.C + 1e-9);
        }
        ASSERT_GT(deviations.size(), 500u);
        std::sort(deviations.begin(), deviations.end());
        EXPECT_LT(deviations[deviations.size() / 2], 0.002) << gamut.space().name();
    }
}

TEST(CssRaytrace, AColourWithinRoundingOfTheCubeIsClamped) {
    // clip.h's rule (css_raytrace.cpp): within oklab_rounding_tolerance × max of the cube, the
    // colour is on it to within rounding and is only clamped (after the lightness rule).
    int checked = 0;
    for (const Gamut& gamut : test_gamuts()) {
        const GamutClipper clipper(ClipMethod::css_raytrace, gamut);
        const double max = gamut.max();
        const double off = 0.5 * oklab_rounding_tolerance * max;
        for (const Rgb& c : {Rgb{max + off, 0.5 * max, 0.25 * max}, Rgb{0.3 * max, -off, 0.9 * max},
                             Rgb{max + off, max, max - 1e-3 * max}}) {
            const double L = clipper.to_oklab(c).L;
            if (!(L > 0.0 && L < clipper.white_oklab_lightness())) continue;  // white, black first
            const Rgb got = clipper.clip(c);
            EXPECT_EQ(got.r, std::clamp(c.r, 0.0, max)) << gamut.space().name();
            EXPECT_EQ(got.g, std::clamp(c.g, 0.0, max)) << gamut.space().name();
            EXPECT_EQ(got.b, std::clamp(c.b, 0.0, max)) << gamut.space().name();
            ++checked;
        }
    }
    EXPECT_GT(checked, 20);
}

// --- the float kernels -------------------------------------------------------------------------

/// ≥ 100 000 colours: out of gamut (uniform in [-0.5, 1.5]^3 × max), in gamut, negative, huge,
/// tiny, NaN and infinities, and colours next to the faces and to the neutral axis.
std::vector<float> kernel_inputs(double max) {
    std::mt19937 rng(2026);
    std::uniform_real_distribution<float> wide(-0.5f, 1.5f), unit(0.0f, 1.0f);
    std::vector<float> v;
    const auto m = static_cast<float>(max);
    constexpr float inf = std::numeric_limits<float>::infinity();
    constexpr float nan = std::numeric_limits<float>::quiet_NaN();
    for (int k = 0; k < 90000; ++k) {
        for (int c = 0; c < 3; ++c) v.push_back(m * wide(rng));
    }
    for (int k = 0; k < 6000; ++k) {
        for (int c = 0; c < 3; ++c) v.push_back(m * unit(rng));
    }
    const float specials[] = {0.0f, -0.0f, 1e30f, -1e30f, inf, -inf, nan, 1e-30f, -1e-7f,
                              m, m * 1.0000001f, -0.25f, 2.0f * m, 1e6f, -3.0f};
    for (int k = 0; k < 6000; ++k) {
        for (int c = 0; c < 3; ++c) {
            const float pick = specials[rng() % std::size(specials)];
            v.push_back((rng() % 3 == 0) ? m * wide(rng) : pick);
        }
    }
    for (int k = 0; k < 2000; ++k) {  // near the grey axis and just off a face
        const float grey = m * unit(rng);
        v.push_back(grey + 1e-4f * m * (unit(rng) - 0.5f));
        v.push_back(grey);
        v.push_back((k % 2 == 0) ? -1e-6f * m : m * (1.0f + 1e-6f));
    }
    return v;
}

void expect_kernel_matches_double(ClipMethod method) {
    // css-raytrace on ACES2065-1 too: its rgb_to_lms has negative entries (the kernel's other
    // LMS path). (css there: 2 in 2^20 colours near its imaginary blue end up to 2.8e-5 away,
    // a one-ulp difference of the origin's chroma amplified by ΔEOK's sensitivity.)
    std::vector<Gamut> gamuts{Gamut(srgb()), Gamut(display_p3()), Gamut(rec2020()),
                              Gamut(srgb(), 4.0)};
    if (method == ClipMethod::css_raytrace) gamuts.emplace_back(aces2065_1());
    for (const Gamut& gamut : gamuts) {
        const GamutClipper clipper(method, gamut);
        const std::vector<float> in = kernel_inputs(gamut.max());
        ASSERT_GE(in.size() / 3, 100000u);
        std::vector<float> simd(in.size()), simd2(in.size());
        clip_batch(clipper, in, simd, {.threads = 1, .simd = true});
        clip_batch(clipper, in, simd2, {.threads = 2, .simd = true});
        EXPECT_EQ(std::memcmp(simd.data(), simd2.data(), simd.size() * sizeof(float)), 0)
            << "thread count changed the result";
        double worst = 0.0;
        std::size_t worst_at = 0;
        for (std::size_t i = 0; i < in.size(); i += 3) {
            const Rgb c{in[i], in[i + 1], in[i + 2]};
            if (gamut.contains(c)) {  // in-gamut colours come back bit for bit
                EXPECT_EQ(simd[i], in[i]);
                EXPECT_EQ(simd[i + 1], in[i + 1]);
                EXPECT_EQ(simd[i + 2], in[i + 2]);
            }
            const Rgb ref = clipper.clip(c);
            const double r[3] = {ref.r, ref.g, ref.b};
            for (std::size_t k = 0; k < 3; ++k) {
                ASSERT_TRUE(std::isfinite(simd[i + k]));
                const double e = std::abs(simd[i + k] - r[k]);
                if (e > worst) worst = e, worst_at = i;
            }
        }
        EXPECT_LE(worst, 1e-5 * gamut.max())
            << clip_method_name(method) << " on " << gamut.space().name() << " max "
            << gamut.max() << ": input " << in[worst_at] << "," << in[worst_at + 1] << ","
            << in[worst_at + 2];
    }
}

TEST(CssKernels, RayTraceFloatKernelMatchesTheDoubleReference) {
    expect_kernel_matches_double(ClipMethod::css_raytrace);
}

TEST(CssKernels, RayTraceLaneThatFindsNoIntersectionKeepsItsLastOneAmongOthers) {
    // Display P3, L just below the white's: the anchor lies outside the cube and the second
    // ray misses it, so the spec keeps the first intersection (footnote 5) while the other
    // lanes of the same vector go on with their passes.
    const Gamut gamut(display_p3());
    const GamutClipper clipper(ClipMethod::css_raytrace, gamut);
    std::vector<float> in;
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> u(-0.5f, 1.5f);
    for (int k = 0; k < 64; ++k) {
        if (k % 16 == 5) {
            in.insert(in.end(), {0.554959655f, 1.39077878f, -0.121176034f});
        } else {
            for (int c = 0; c < 3; ++c) in.push_back(u(rng));
        }
    }
    std::vector<float> out(in.size());
    clip_batch(clipper, in, out, {.threads = 1, .simd = true});
    for (std::size_t i = 0; i < in.size(); i += 3) {
        const Rgb ref = clipper.clip({in[i], in[i + 1], in[i + 2]});
        EXPECT_NEAR(out[i], ref.r, 1e-5);
        EXPECT_NEAR(out[i + 1], ref.g, 1e-5);
        EXPECT_NEAR(out[i + 2], ref.b, 1e-5);
    }
}

TEST(CssKernels, BinarySearchFloatKernelMatchesTheDoubleReference) {
    expect_kernel_matches_double(ClipMethod::css);
}

}  // namespace
}  // namespace irid
