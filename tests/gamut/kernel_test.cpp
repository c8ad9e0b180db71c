// Every method's batch kernel against its double reference, over every built-in RGB space and an
// HDR peak (batch.h, src/gamut/kernels.h): within 1e-5 of the cube's size, finite, and the same
// bytes for any thread count. Each method's own test file checks its kernel more closely; this
// one makes sure no method is left out and the contract holds for all of them alike.

#include <irid/color/rgb.h>
#include <irid/gamut/batch.h>
#include <irid/gamut/clip.h>

#include <gtest/gtest.h>
#include <hwy/targets.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <iterator>
#include <limits>
#include <random>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace irid {
namespace {

/// Colours that exercise every path: out of gamut by a little and by far, in gamut, on faces,
/// negative, huge, NaN and ±Inf channels, greys near black and near the white, scaled to `max`.
std::vector<float> colours_for(double max, std::size_t n, std::uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> wide(-0.6f, 1.6f), unit(0.0f, 1.0f), tiny(-1e-6f, 1e-6f);
    std::uniform_int_distribution<int> kind(0, 15);
    const float m = static_cast<float>(max);
    std::vector<float> v;
    v.reserve(3 * n);
    const float specials[] = {0.0f,
                              -0.0f,
                              1.0f,
                              1e30f,
                              -1e30f,
                              std::numeric_limits<float>::quiet_NaN(),
                              std::numeric_limits<float>::infinity(),
                              -std::numeric_limits<float>::infinity(),
                              1e-38f,
                              3.0f,
                              // Near float's range, where a kernel's own arithmetic overflows
                              // (fuzz finding: oklab sent 2.55e38 to black instead of white).
                              2.55e38f,
                              -3.0e38f};
    for (std::size_t i = 0; i < n; ++i) {
        float c[3];
        const int k = kind(rng);
        for (float& x : c) {
            switch (k) {
                case 0: x = unit(rng) * m; break;                                  // inside
                case 1: x = (unit(rng) < 0.5f ? 0.0f : 1.0f) * m + tiny(rng) * m; break;  // faces
                case 2: {  // special values (near float's range: not scaled, which would overflow)
                    const float sv = specials[static_cast<std::size_t>(kind(rng)) % std::size(specials)];
                    x = std::abs(sv) > 1e37f ? sv : sv * m;
                    break;
                }
                case 3: x = wide(rng) * 4.0f * m; break;                            // far out
                default: x = wide(rng) * m; break;                                  // near out
            }
        }
        if (k == 4) c[1] = c[2] = c[0];  // greys, some outside
        v.insert(v.end(), c, c + 3);
    }
    return v;
}

TEST(Kernels, EveryMethodMatchesItsDoubleReferenceOnEverySpaceAndAnHdrPeak) {
    std::size_t checked = 0;
    for (const RgbSpace* space : builtin_rgb_spaces()) {
        for (const double max : {1.0, 4.0}) {
            const Gamut gamut(*space, max);
            const std::vector<float> in = colours_for(max, 20000, 7u + static_cast<std::uint32_t>(max));
            for (const ClipMethod method : clip_methods()) {
                if (method == ClipMethod::luv_hue) continue;  // no kernel (batch.h)
                const GamutClipper clipper(method, gamut);
                std::vector<float> simd(in.size()), reference(in.size());
                clip_batch(clipper, in, simd, {.threads = 1, .simd = true});
                clip_batch(clipper, in, reference, {.threads = 1, .simd = false});
                // The cube's size, or for an output not confined to the cube (aces-rgc without
                // clip) the colour's own size: float carries 6e-8 of any value.
                const auto scale = [&](std::size_t colour) {
                    double s = max;
                    if (clipper.confines_to_cube()) return s;
                    for (std::size_t k = 3 * colour; k < 3 * colour + 3; ++k) {
                        s = std::max({s, std::abs(finite_or_default(in[k])), std::abs(static_cast<double>(reference[k]))});
                    }
                    return s;
                };
                double worst = 0.0;  // in units of the scale × max
                std::size_t worst_at = 0;
                for (std::size_t i = 0; i < in.size(); ++i) {
                    ASSERT_TRUE(std::isfinite(simd[i]))
                        << clip_method_name(method) << " " << space->name() << " colour " << i / 3;
                    const double d =
                        std::abs(static_cast<double>(simd[i]) - reference[i]) / scale(i / 3) * max;
                    if (d > worst) worst = d, worst_at = i / 3;
                }
                const std::size_t w = 3 * worst_at;
                EXPECT_LE(worst, 1e-5 * max)
                    << clip_method_name(method) << " on " << space->name() << " max " << max
                    << ": input (" << in[w] << ", " << in[w + 1] << ", " << in[w + 2] << ") simd ("
                    << simd[w] << ", " << simd[w + 1] << ", " << simd[w + 2] << ") reference ("
                    << reference[w] << ", " << reference[w + 1] << ", " << reference[w + 2] << ")";
                ++checked;
            }
        }
    }
    EXPECT_EQ(checked, builtin_rgb_spaces().size() * 2 * (clip_methods().size() - 1));
}

// The same on every instruction set Highway compiled and this CPU runs (AVX-512, AVX2, SSE4,
// ...): the fuzz finding above showed on AVX2 only.
TEST(Kernels, EveryKernelMatchesItsReferenceOnEveryCompiledTarget) {
    for (const std::int64_t target : hwy::SupportedAndGeneratedTargets()) {
        hwy::SetSupportedTargetsForTest(target);
        for (const auto& [space, max] : {std::pair{&srgb(), 1.0}, std::pair{&display_p3(), 4.0},
                                         std::pair{&aces2065_1(), 1.0}}) {
            const Gamut gamut(*space, max);
            const std::vector<float> in = colours_for(max, 3000, 23u);
            for (const ClipMethod method : clip_methods()) {
                if (method == ClipMethod::luv_hue) continue;
                const GamutClipper clipper(method, gamut);
                if (!clipper.confines_to_cube()) continue;  // scaled tolerance: the test above
                std::vector<float> simd(in.size()), reference(in.size());
                clip_batch(clipper, in, simd, {.threads = 1, .simd = true});
                clip_batch(clipper, in, reference, {.threads = 1, .simd = false});
                double worst = 0.0;
                for (std::size_t i = 0; i < in.size(); ++i) {
                    worst = std::max(worst, std::abs(static_cast<double>(simd[i]) - reference[i]));
                }
                EXPECT_LE(worst, 1e-5 * max) << clip_method_name(method) << " on " << space->name()
                                             << " max " << max << ", " << hwy::TargetName(target);
            }
        }
    }
    hwy::SetSupportedTargetsForTest(0);
}

TEST(Kernels, ResultsAreTheSameBytesForAnyThreadCount) {
    const Gamut gamut(display_p3());
    // Several chunks (batch_chunk_colours each) and a ragged tail.
    const std::vector<float> in = colours_for(1.0, 3 * batch_chunk_colours + 37, 11u);
    for (const ClipMethod method : clip_methods()) {
        if (method == ClipMethod::luv_hue) continue;
        const GamutClipper clipper(method, gamut);
        std::vector<float> one(in.size()), two(in.size()), four(in.size());
        clip_batch(clipper, in, one, {.threads = 1, .simd = true});
        clip_batch(clipper, in, two, {.threads = 2, .simd = true});
        clip_batch(clipper, in, four, {.threads = 4, .simd = true});
        EXPECT_EQ(std::memcmp(one.data(), two.data(), one.size() * sizeof(float)), 0)
            << clip_method_name(method);
        EXPECT_EQ(std::memcmp(one.data(), four.data(), one.size() * sizeof(float)), 0)
            << clip_method_name(method);
    }
}

// A kernel that recomputes a hard lane in double must take the lane's input from its registers,
// not from memory: in place, the vector's result has already replaced it there (fuzz finding
// clip css-in-place-1: css redid such lanes from the overwritten input).
TEST(Kernels, InPlaceGivesTheSameBytesAsOutOfPlace) {
    for (const double max : {1.0, 4.0}) {
        const Gamut gamut(display_p3(), max);
        const std::vector<float> in = colours_for(max, 30000, 17u);
        for (const ClipMethod method : clip_methods()) {
            if (method == ClipMethod::luv_hue) continue;
            const GamutClipper clipper(method, gamut);
            std::vector<float> out(in.size());
            clip_batch(clipper, in, out, {.threads = 1, .simd = true});
            std::vector<float> in_place = in;
            clip_batch(clipper, in_place, {.threads = 1, .simd = true});
            EXPECT_EQ(std::memcmp(out.data(), in_place.data(), out.size() * sizeof(float)), 0)
                << clip_method_name(method) << " max " << max;
        }
    }
}

TEST(Kernels, ConfiningMethodsKeepEveryKernelOutputInsideTheCube) {
    for (const double max : {1.0, 4.0}) {
        const Gamut gamut(rec2020(), max);
        const std::vector<float> in = colours_for(max, 20000, 13u);
        for (const ClipMethod method : clip_methods()) {
            const GamutClipper clipper(method, gamut);
            if (!clipper.confines_to_cube()) continue;
            std::vector<float> out(in.size());
            clip_batch(clipper, in, out, {.threads = 2, .simd = true});
            const auto [lo, hi] = std::minmax_element(out.begin(), out.end());
            EXPECT_GE(*lo, 0.0f) << clip_method_name(method);
            EXPECT_LE(*hi, static_cast<float>(max)) << clip_method_name(method);
        }
    }
}

}  // namespace
}  // namespace irid
