// No floating-point contraction: the scalar reference must perform the same IEEE operations
// as the SIMD kernels (batch_simd.cpp), also when built with -march and FMA available.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC optimize("fp-contract=off")
#endif

#include <irid/color/rgb.h>
#include <irid/error.h>
#include <irid/gamut/batch.h>
#include <irid/gamut/clip.h>

#include <gtest/gtest.h>
#include <hwy/targets.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <span>
#include <string>
#include <vector>

namespace irid {
namespace {

constexpr float inf = std::numeric_limits<float>::infinity();
constexpr float nan = std::numeric_limits<float>::quiet_NaN();
constexpr float flt_max = std::numeric_limits<float>::max();

/// SIMD against the scalar reference, absolute, per channel (both are float).
constexpr float simd_tolerance = 1e-6f;

/// The scalar reference, colour by colour: the non-finite rule of clip.h, smits_clip_rgb<float>
/// on the gamut's parameters rounded to float, and GamutClipper::clip's final clamp to [0, max]
/// (batch.h). `smits` = false gives the clamp method.
std::vector<float> reference(const Gamut& gamut, std::span<const float> in, bool smits = true) {
    const Vec3& l = gamut.luminance_row();
    const std::array<float, 3> lum{static_cast<float>(l[0]), static_cast<float>(l[1]),
                                   static_cast<float>(l[2])};
    const auto inv = static_cast<float>(1.0 / (l[0] + l[1] + l[2]));
    const auto max = static_cast<float>(gamut.max());
    std::vector<float> out(in.size());
    for (std::size_t i = 0; i < in.size(); i += 3) {
        std::array<float, 3> c{};
        for (std::size_t k = 0; k < 3; ++k) c[k] = static_cast<float>(finite_or_default(in[i + k]));
        if (smits) c = smits_clip_rgb<float>(c, lum, inv, max);
        for (std::size_t k = 0; k < 3; ++k) out[i + k] = std::clamp(c[k], 0.0f, max);
    }
    return out;
}

std::vector<float> batch(const GamutClipper& clipper, std::span<const float> in,
                         const BatchOptions& options = {}) {
    std::vector<float> out(in.size(), -7.0f);
    clip_batch(clipper, in, out, options);
    return out;
}

/// The largest absolute difference, +Inf when either side has a NaN or the sizes differ.
float max_difference(std::span<const float> a, std::span<const float> b) {
    if (a.size() != b.size()) return inf;
    float d = 0.0f;
    for (std::size_t i = 0; i < a.size(); ++i) {
        if (std::isnan(a[i]) || std::isnan(b[i])) return inf;
        d = std::max(d, std::abs(a[i] - b[i]));
    }
    return d;
}

bool bitwise_equal(std::span<const float> a, std::span<const float> b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size_bytes()) == 0;
}

/// Every output finite and inside [0, max]³.
bool finite_and_inside(std::span<const float> out, double max) {
    const auto m = static_cast<float>(max);
    return std::all_of(out.begin(), out.end(),
                       [m](float v) { return std::isfinite(v) && v >= 0.0f && v <= m; });
}

std::vector<float> random_colours(std::size_t colours, float lo, float hi, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(lo, hi);
    std::vector<float> v(3 * colours);
    for (float& x : v) x = u(rng);
    return v;
}

/// Runs `check` once on every Highway target compiled and supported here (AVX3 = AVX-512, AVX2,
/// SSE4, SSSE3 and SCALAR on an AVX-512 machine), then restores the normal choice.
template <class F>
void for_each_simd_target(F check) {
    for (const std::int64_t target : hwy::SupportedAndGeneratedTargets()) {
        hwy::SetSupportedTargetsForTest(target);
        SCOPED_TRACE(hwy::TargetName(target));
        EXPECT_EQ(simd_target_name(), hwy::TargetName(target));
        check();
    }
    hwy::SetSupportedTargetsForTest(0);
}

/// Boundary cases for a gamut: channels exactly 0 and max (in gamut and beside out-of-range
/// channels), -0, and the float neighbourhoods where the grey reaches exactly max and where the
/// luminance is exactly 0, found by stepping one channel ulp by ulp.
std::vector<float> boundary_colours(const Gamut& gamut) {
    const auto max = static_cast<float>(gamut.max());
    const Vec3& l = gamut.luminance_row();
    const float a = static_cast<float>(l[0]), b = static_cast<float>(l[1]),
                c = static_cast<float>(l[2]);
    const auto inv = static_cast<float>(1.0 / (l[0] + l[1] + l[2]));
    std::vector<float> v;
    const float values[] = {0.0f,
                            -0.0f,
                            max,
                            0.5f * max,
                            -0.25f * max,
                            1.25f * max,
                            std::nextafter(0.0f, -1.0f),
                            std::nextafter(max, 2.0f * max)};
    for (const float r : values)
        for (const float g : values)
            for (const float bl : values) v.insert(v.end(), {r, g, bl});
    // Grey exactly at max: (1.5 max, g, 0.5 max) with g stepped across the value where w = max.
    {
        float g = (max * (a + b + c) - a * 1.5f * max - c * 0.5f * max) / b;
        for (int k = 0; k < 64; ++k) g = std::nextafter(g, -inf);
        int at_max = 0, below = 0;
        for (int k = 0; k < 128; ++k, g = std::nextafter(g, inf)) {
            const float y = a * (1.5f * max) + b * g + c * (0.5f * max);
            const float w = y * inv;
            at_max += w == max;
            below += w < max;
            v.insert(v.end(), {1.5f * max, g, 0.5f * max});
        }
        EXPECT_GT(below, 0);
        EXPECT_GT(128 - below, 0);  // both sides of the white rule are covered
        EXPECT_GT(at_max, 0);       // and the grey lands exactly on max
    }
    // Luminance exactly 0: (0.5 max, 0, bl) with bl stepped across -a r / c.
    {
        const float r = 0.5f * max;
        float bl = -a * r / c;
        for (int k = 0; k < 64; ++k) bl = std::nextafter(bl, -inf);
        int zero = 0, positive = 0;
        for (int k = 0; k < 128; ++k, bl = std::nextafter(bl, inf)) {
            const float y = a * r + b * 0.0f + c * bl;
            zero += y == 0.0f;
            positive += y > 0.0f;
            v.insert(v.end(), {r, 0.0f, bl});
        }
        EXPECT_GT(zero, 0);
        EXPECT_GT(positive, 0);
        EXPECT_GT(128 - zero - positive, 0);
    }
    return v;
}

TEST(ClipBatch, SimdTargetNameNamesARealTarget) {
    const std::string_view name = simd_target_name();
    EXPECT_FALSE(name.empty());
    EXPECT_NE(name, "Unknown");
}

TEST(ClipBatch, SmitsSimdEqualsScalarReferenceOnAMillionRandomColours) {
    const Gamut gamut(srgb());
    const GamutClipper clipper(ClipMethod::smits, gamut);
    const std::vector<float> in = random_colours(1'000'000, -1.0f, 2.0f, 20261122);
    const std::vector<float> expected = reference(gamut, in);
    for_each_simd_target([&] {
        const std::vector<float> out = batch(clipper, in);
        EXPECT_LE(max_difference(out, expected), simd_tolerance);
        EXPECT_TRUE(finite_and_inside(out, gamut.max()));
    });
}

TEST(ClipBatch, ClampSimdEqualsScalarReferenceOnRandomColours) {
    const Gamut gamut(srgb());
    const GamutClipper clipper(ClipMethod::clamp, gamut);
    const std::vector<float> in = random_colours(100'003, -1.0f, 2.0f, 7);
    const std::vector<float> expected = reference(gamut, in, false);
    for_each_simd_target(
        [&] { EXPECT_LE(max_difference(batch(clipper, in), expected), simd_tolerance); });
}

TEST(ClipBatch, SmitsSimdEqualsScalarReferenceOnFacesGreyAtMaxAndZeroLuminance) {
    const Gamut gamut(srgb());
    const GamutClipper clipper(ClipMethod::smits, gamut);
    const std::vector<float> in = boundary_colours(gamut);
    const std::vector<float> expected = reference(gamut, in);
    for_each_simd_target([&] {
        const std::vector<float> out = batch(clipper, in);
        EXPECT_LE(max_difference(out, expected), simd_tolerance);
        EXPECT_TRUE(finite_and_inside(out, gamut.max()));
    });
}

TEST(ClipBatch, InGamutColoursAreUnchangedBitForBit) {
    for (const double max : {1.0, 4.0}) {
        const Gamut gamut(srgb(), max);
        std::vector<float> in = random_colours(10'000, 0.0f, static_cast<float>(max), 3);
        const auto m = static_cast<float>(max);
        const float faces[] = {0.0f, -0.0f, m, 0.5f * m};
        for (const float r : faces)
            for (const float g : faces)
                for (const float b : faces) in.insert(in.end(), {r, g, b});
        for (const ClipMethod method : {ClipMethod::smits, ClipMethod::clamp}) {
            const GamutClipper clipper(method, gamut);
            for_each_simd_target([&] {
                EXPECT_TRUE(bitwise_equal(batch(clipper, in), in));
                EXPECT_TRUE(bitwise_equal(batch(clipper, in, {.threads = 1, .simd = false}), in));
            });
        }
    }
}

TEST(ClipBatch, NonFiniteAndHugeInputsFollowTheRuleAndMatchTheReference) {
    const Gamut gamut(srgb());
    const float specials[] = {nan,      -nan,  inf,    -inf,    1e30f, -1e30f, flt_max,
                              -flt_max, 3e38f, 1e-40f, -1e-40f, 0.5f,  -0.5f,  1.5f};
    std::vector<float> in;
    for (const float r : specials)
        for (const float g : specials)
            for (const float b : specials) in.insert(in.end(), {r, g, b});
    // Huge channels whose luminance cancels to a small positive value: the clip then runs with
    // t close to 1 on 1e30-sized values (the result is arbitrary, but defined and finite).
    const Vec3& l = gamut.luminance_row();
    const auto ratio = static_cast<float>(l[0] / l[1]);
    for (const float r : {1e30f, 3e20f, 1e10f}) in.insert(in.end(), {r, -r * ratio, 0.5f});
    for (const ClipMethod method : {ClipMethod::smits, ClipMethod::clamp}) {
        const GamutClipper clipper(method, gamut);
        const std::vector<float> expected = reference(gamut, in, method == ClipMethod::smits);
        for_each_simd_target([&] {
            const std::vector<float> out = batch(clipper, in);
            EXPECT_LE(max_difference(out, expected), simd_tolerance);
            EXPECT_TRUE(finite_and_inside(out, gamut.max()));
        });
    }
    // NaN is 0 and ±Inf is ±1e30, exactly.
    const GamutClipper smits(ClipMethod::smits, gamut);
    const std::vector<float> with_nan{nan, 0.5f, 1.5f, inf, -0.2f, 0.3f, 0.4f, -inf, 0.9f};
    const std::vector<float> replaced{0.0f, 0.5f, 1.5f, 1e30f, -0.2f, 0.3f, 0.4f, -1e30f, 0.9f};
    EXPECT_TRUE(bitwise_equal(batch(smits, with_nan), batch(smits, replaced)));
}

TEST(ClipBatch, HdrMaximumAndOtherGamutsMatchTheReference) {
    struct Case {
        const RgbSpace& space;
        double max;
    };
    const Case cases[] = {{srgb(), 4.0}, {rec2020(), 1.0}, {rec2020(), 4.0}, {ntsc1953(), 1.0}};
    for (const Case& c : cases) {
        const Gamut gamut(c.space, c.max);
        SCOPED_TRACE(std::string(c.space.name()) + " max " + std::to_string(c.max));
        const auto m = static_cast<float>(c.max);
        std::vector<float> in = random_colours(200'000, -m, 2.0f * m, 11);
        const std::vector<float> edges = boundary_colours(gamut);
        in.insert(in.end(), edges.begin(), edges.end());
        for (const ClipMethod method : {ClipMethod::smits, ClipMethod::clamp}) {
            const GamutClipper clipper(method, gamut);
            const std::vector<float> expected = reference(gamut, in, method == ClipMethod::smits);
            for_each_simd_target([&] {
                const std::vector<float> out = batch(clipper, in);
                EXPECT_LE(max_difference(out, expected), simd_tolerance);
                EXPECT_TRUE(finite_and_inside(out, c.max));
            });
        }
    }
}

TEST(ClipBatch, OddLengthsUseTheScalarTailAndWriteNothingElse) {
    const Gamut gamut(srgb());
    for (const ClipMethod method : {ClipMethod::smits, ClipMethod::clamp}) {
        const GamutClipper clipper(method, gamut);
        for (const std::size_t colours : {1u, 7u, 17u, 33u}) {
            SCOPED_TRACE(colours);
            const std::vector<float> in =
                random_colours(colours, -1.0f, 2.0f, static_cast<unsigned>(colours));
            const std::vector<float> expected = reference(gamut, in, method == ClipMethod::smits);
            for_each_simd_target([&] {
                // Out of place, with guard values after the output.
                std::vector<float> out(in.size() + 8, -7.0f);
                clip_batch(clipper, in, std::span<float>(out).first(in.size()));
                EXPECT_LE(max_difference(std::span<const float>(out).first(in.size()), expected),
                          simd_tolerance);
                EXPECT_TRUE(std::all_of(out.begin() + static_cast<std::ptrdiff_t>(in.size()),
                                        out.end(), [](float v) { return v == -7.0f; }));
                // In place gives the same bits.
                std::vector<float> in_place = in;
                clip_batch(clipper, in_place);
                EXPECT_TRUE(bitwise_equal(in_place, std::span<const float>(out).first(in.size())));
            });
        }
    }
}

TEST(ClipBatch, ResultDoesNotDependOnTheThreadCount) {
    const Gamut gamut(rec2020());
    // 19 chunks of 16384 colours and a partial one.
    const std::vector<float> in = random_colours(18 * batch_chunk_colours + 1001, -1.0f, 2.0f, 5);
    const std::vector<float> oklab_in(in.begin(), in.begin() + 3 * (2 * batch_chunk_colours + 17));
    for (const ClipMethod method : {ClipMethod::smits, ClipMethod::clamp, ClipMethod::oklab}) {
        SCOPED_TRACE(std::string(clip_method_name(method)));
        const GamutClipper clipper(method, gamut);
        const std::vector<float>& input = method == ClipMethod::oklab ? oklab_in : in;
        for (const bool simd : {true, false}) {
            const std::vector<float> one = batch(clipper, input, {.threads = 1, .simd = simd});
            for (const int threads : {2, 3, 8, 0}) {
                SCOPED_TRACE(threads);
                EXPECT_TRUE(
                    bitwise_equal(batch(clipper, input, {.threads = threads, .simd = simd}), one));
            }
        }
    }
}

TEST(ClipBatch, ScalarPathEqualsSimdPath) {
    const Gamut gamut(display_p3(), 2.0);
    std::vector<float> in = random_colours(300'001, -2.0f, 4.0f, 9);
    const std::vector<float> edges = boundary_colours(gamut);
    in.insert(in.end(), edges.begin(), edges.end());
    for (const ClipMethod method : {ClipMethod::smits, ClipMethod::clamp}) {
        const GamutClipper clipper(method, gamut);
        EXPECT_LE(
            max_difference(batch(clipper, in, {.simd = false}), batch(clipper, in, {.simd = true})),
            simd_tolerance);
    }
}

TEST(ClipBatch, OtherMethodsEqualGamutClipperClipPerColour) {
    const Gamut gamut(srgb());
    std::vector<float> in = random_colours(5000, -1.0f, 2.0f, 13);
    in.insert(in.end(), {nan, 0.5f, 0.5f, inf, 0.0f, 0.0f, 0.2f, 0.3f, 0.4f});
    for (const ClipMethod method : {ClipMethod::luv_hue}) {  // the one method without a kernel
        SCOPED_TRACE(std::string(clip_method_name(method)));
        const GamutClipper clipper(method, gamut);
        // The scalar path: these methods' SIMD kernels are tested against clip to 1e-5 max in
        // their own tests (oklab: oklab_projection_test.cpp).
        const std::vector<float> out = batch(clipper, in, {.simd = false});
        for (std::size_t i = 0; i < in.size(); i += 3) {
            const Rgb expected = clipper.clip({in[i], in[i + 1], in[i + 2]});
            // The double result rounded once to float: within half an ulp of float.
            const double got[] = {out[i], out[i + 1], out[i + 2]};
            const double want[] = {expected.r, expected.g, expected.b};
            for (int k = 0; k < 3; ++k) {
                EXPECT_LE(std::abs(got[k] - want[k]),
                          0.5 * std::numeric_limits<float>::epsilon() * std::abs(want[k]) +
                              std::numeric_limits<float>::denorm_min())
                    << "colour " << i / 3 << " channel " << k;
            }
        }
    }
}

TEST(ClipBatch, FloatSimdAgreesWithTheDoubleClipperToFloatPrecision) {
    // The batch computes in float; GamutClipper::clip in double. On the same float inputs they
    // agree to a few float roundings of y, w and t (each ~6e-8 relative), amplified by
    // 1/(c − w) near grazing crossings: measured 1.6e-6 of the cube's size; bound 3e-6.
    for (const double max : {1.0, 4.0}) {
        const GamutClipper clipper(ClipMethod::smits, Gamut(srgb(), max));
        const std::vector<float> in = random_colours(200'000, -1.0f, 2.0f * static_cast<float>(max), 5);
        std::vector<float> out(in.size());
        clip_batch(clipper, in, out);
        double worst = 0.0;
        for (std::size_t i = 0; i < in.size(); i += 3) {
            const Rgb d = clipper.clip({in[i], in[i + 1], in[i + 2]});
            worst = std::max({worst, std::abs(out[i] - d.r), std::abs(out[i + 1] - d.g),
                              std::abs(out[i + 2] - d.b)});
        }
        EXPECT_LE(worst, 3e-6 * max) << max;
    }
}

TEST(ClipBatch, BadSpansAndThreadCountsThrow) {
    const GamutClipper clipper(ClipMethod::smits, Gamut(srgb()));
    std::vector<float> four(4, 0.5f), six(6, 0.5f), nine(9, 0.5f);
    EXPECT_THROW(clip_batch(clipper, four), Error);                               // not RGB triples
    EXPECT_THROW(clip_batch(clipper, std::span<const float>(six), nine), Error);  // sizes differ
    EXPECT_THROW(clip_batch(clipper, std::span<const float>(four), four), Error);  // not triples
    EXPECT_THROW(clip_batch(clipper, six, {.threads = -1}), Error);
    // Partly overlapping input and output.
    std::vector<float> big(12, 0.5f);
    EXPECT_THROW(
        clip_batch(clipper, std::span<const float>(big).first(9), std::span<float>(big).last(9)),
        Error);
    // Nothing was written by the calls that threw.
    EXPECT_TRUE(std::all_of(big.begin(), big.end(), [](float v) { return v == 0.5f; }));
    // Empty spans and the same span in and out are fine.
    EXPECT_NO_THROW(clip_batch(clipper, std::span<float>()));
    EXPECT_NO_THROW(clip_batch(clipper, std::span<const float>(six), six));
    try {
        clip_batch(clipper, four);
        FAIL();
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("multiple of 3"), std::string::npos);
    }
}

}  // namespace
// --- the float kernels of smits-xyz, luv-lightness-hue, smits-soft ------------------------------

/// The inputs of the kernel tests: uniform in [-1, 2 max]^3 (in and out of gamut), in-gamut
/// colours, negative ones, channels of ±1e30 and ±1e20 beside ordinary ones, NaN and ±Inf, the
/// boundary cases of boundary_colours, and colours within 1e-6 of the cube's faces.
std::vector<float> kernel_inputs(const Gamut& gamut, unsigned seed) {
    const auto max = static_cast<float>(gamut.max());
    std::vector<float> in = random_colours(100'000, -1.0f * max, 2.0f * max, seed);
    const std::vector<float> inside = random_colours(5'000, 0.0f, max, seed + 1);
    const std::vector<float> negative = random_colours(2'000, -2.0f * max, 0.0f, seed + 2);
    in.insert(in.end(), inside.begin(), inside.end());
    in.insert(in.end(), negative.begin(), negative.end());
    std::mt19937 rng(seed + 3);
    std::uniform_int_distribution<int> pick(0, 9);
    const float specials[] = {1e30f, -1e30f, 1e20f, -1e20f, nan, inf, -inf, 0.0f, -0.0f, max};
    for (int k = 0; k < 3000; ++k) {
        for (int c = 0; c < 3; ++c) {
            const int p = pick(rng);
            in.push_back(p < 7 ? specials[p] : 0.3f * static_cast<float>(p) * max - max);
        }
    }
    const std::vector<float> edges = boundary_colours(gamut);
    in.insert(in.end(), edges.begin(), edges.end());
    std::uniform_real_distribution<float> u(0.0f, max), hair(-1e-6f * max, 1e-6f * max);
    for (int k = 0; k < 3000; ++k) {
        float c[3] = {u(rng), u(rng), u(rng)};
        c[k % 3] = (k % 2 ? max : 0.0f) + hair(rng);
        in.insert(in.end(), c, c + 3);
    }
    return in;
}

/// The largest difference between the SIMD batch and the double GamutClipper::clip per colour.
double max_difference_to_double(const GamutClipper& clipper, std::span<const float> in,
                                std::span<const float> out) {
    double worst = 0.0;
    for (std::size_t i = 0; i < in.size(); i += 3) {
        const Rgb e = clipper.clip({in[i], in[i + 1], in[i + 2]});
        // Compared in float, as the batch's output is (what the double path would store).
        worst = std::max({worst, std::abs(static_cast<double>(out[i]) - static_cast<float>(e.r)),
                          std::abs(static_cast<double>(out[i + 1]) - static_cast<float>(e.g)),
                          std::abs(static_cast<double>(out[i + 2]) - static_cast<float>(e.b))});
    }
    return worst;
}

struct KernelCase {
    ClipMethod method;
    bool inverse;
};
constexpr KernelCase smits_family_kernels[] = {
    {ClipMethod::smits_xyz, false},  {ClipMethod::luv_lightness_hue, false},
    {ClipMethod::smits_soft, false}, {ClipMethod::smits_soft, true},
};

TEST(SmitsFamilyKernels, FloatSimdIsWithin1e5OfTheDoubleReferenceOnEveryGamut) {
    // The issue: every kernel equal to its double reference within 1e-5 of the cube's size,
    // outputs finite, on sRGB, Display P3, Rec.2020 and an HDR peak.
    const Gamut gamuts[] = {Gamut(srgb()), Gamut(display_p3()), Gamut(rec2020()), Gamut(srgb(), 4.0)};
    unsigned seed = 41;
    for (const Gamut& gamut : gamuts) {
        const std::vector<float> in = kernel_inputs(gamut, seed++);
        for (const KernelCase& k : smits_family_kernels) {
            SCOPED_TRACE(std::string(clip_method_name(k.method)) + (k.inverse ? " inverse" : "") +
                         " on " + gamut.space().name() + " max " + std::to_string(gamut.max()));
            const GamutClipper clipper(k.method, gamut, ClipSettings{.values = {}, .inverse = k.inverse});
            const std::vector<float> out = batch(clipper, in, {.threads = 1, .simd = true});
            EXPECT_LE(max_difference_to_double(clipper, in, out), 1e-5 * gamut.max());
            EXPECT_TRUE(std::all_of(out.begin(), out.end(), [](float v) { return std::isfinite(v); }));
            if (clipper.confines_to_cube()) {
                EXPECT_TRUE(finite_and_inside(out, gamut.max()));
            }
        }
    }
}

TEST(SmitsFamilyKernels, EveryTargetAndThreadCountGivesTheSameBits) {
    const Gamut gamut(rec2020());
    // 7 chunks and a partial one, so that 2 threads split them.
    const std::vector<float> base = kernel_inputs(gamut, 77);
    std::vector<float> in;
    while (in.size() < 3 * (7 * batch_chunk_colours + 999)) in.insert(in.end(), base.begin(), base.end());
    in.resize(3 * (7 * batch_chunk_colours + 999));
    for (const KernelCase& k : smits_family_kernels) {
        SCOPED_TRACE(std::string(clip_method_name(k.method)) + (k.inverse ? " inverse" : ""));
        const GamutClipper clipper(k.method, gamut, ClipSettings{.values = {}, .inverse = k.inverse});
        const std::vector<float> one = batch(clipper, in, {.threads = 1});
        EXPECT_TRUE(bitwise_equal(batch(clipper, in, {.threads = 2}), one));
        // In place gives the same bits.
        std::vector<float> in_place = in;
        clip_batch(clipper, in_place, {.threads = 2});
        EXPECT_TRUE(bitwise_equal(in_place, one));
        // Every Highway target is within the tolerance of the double reference too.
        const std::vector<float> small(in.begin(), in.begin() + 3 * 20'000);
        for_each_simd_target([&] {
            EXPECT_LE(max_difference_to_double(clipper, small, batch(clipper, small)), 1e-5);
        });
    }
}

TEST(SmitsFamilyKernels, TheKernelsRunInSimdAndDifferFromTheDoublePathOnlyByRounding) {
    // A kernel that returned 0 (no SIMD) would give the double results rounded once, exactly;
    // the float kernels differ from them somewhere, by rounding only.
    const Gamut gamut(srgb());
    const std::vector<float> in = random_colours(20'000, -0.5f, 1.5f, 5);
    for (const KernelCase& k : smits_family_kernels) {
        SCOPED_TRACE(std::string(clip_method_name(k.method)));
        const GamutClipper clipper(k.method, gamut, ClipSettings{.values = {}, .inverse = k.inverse});
        const std::vector<float> simd = batch(clipper, in, {.simd = true});
        const std::vector<float> dbl = batch(clipper, in, {.simd = false});
        EXPECT_FALSE(bitwise_equal(simd, dbl));
        EXPECT_LE(max_difference(simd, dbl), 1e-5f);
    }
}

}  // namespace irid
