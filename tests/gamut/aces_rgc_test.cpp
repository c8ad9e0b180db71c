// aces-rgc: the ACES 1.3 Reference Gamut Compression (src/gamut/aces_rgc.cpp) against its
// closed forms (LMT.Academy.ReferenceGamutCompress.ctl: the limit maps to 1, nothing moves below
// the threshold, the curve joins the identity with slope 1, the inverse undoes the forward), the
// behaviour of OpenColorIO 2.1's FixedFunctionOpCPU.cpp at ach = 0, ach < 0 and beyond the
// inverse's asymptote, its parameter ranges (FixedFunctionOpData.cpp), and its batch kernel
// (batch_simd_aces.cpp) against the double reference. The comparison with OCIO itself is in
// aces_rgc_ocio_test.cpp.

#include <irid/color/rgb.h>
#include <irid/error.h>
#include <irid/gamut/batch.h>
#include <irid/gamut/clip.h>

#include <gtest/gtest.h>
#include <hwy/targets.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <iostream>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace irid {
namespace {

/// The channel names' parameters, in clip_parameters() order.
const char* const limit_names[3] = {"limit-cyan", "limit-magenta", "limit-yellow"};
const char* const threshold_names[3] = {"threshold-cyan", "threshold-magenta",
                                        "threshold-yellow"};

double channel(const Rgb& c, int k) { return k == 0 ? c.r : (k == 1 ? c.g : c.b); }
Rgb with_channel(double ach, double v, int k) {
    Rgb c{ach, ach, ach};
    (k == 0 ? c.r : (k == 1 ? c.g : c.b)) = v;
    return c;
}

GamutClipper aces(const ClipSettings& s = {}) {
    return GamutClipper(ClipMethod::aces_rgc, Gamut(acescg()), s);
}
GamutClipper aces_inverse(ClipSettings s = {}) {
    s.inverse = true;
    return aces(s);
}

/// The compressed distance of channel k at distance d, read through clip(): a colour with
/// ach = 1 and that channel at 1 − d.
double compressed_distance(const GamutClipper& g, int k, double d) {
    return 1.0 - channel(g.clip(with_channel(1.0, 1.0 - d, k)), k);
}

TEST(AcesRgc, DefaultsAreThePublishedOnesAndRangesAreOcios) {
    // LMT.Academy.ReferenceGamutCompress.ctl (ACES 1.3): LIM_CYAN 1.147, LIM_MAGENTA 1.264,
    // LIM_YELLOW 1.312, THR_CYAN 0.815, THR_MAGENTA 0.803, THR_YELLOW 0.880, PWR 1.2.
    const double published[7] = {1.147, 1.264, 1.312, 0.815, 0.803, 0.880, 1.2};
    const auto params = clip_parameters(ClipMethod::aces_rgc);
    ASSERT_EQ(params.size(), 8u);
    for (int k = 0; k < 7; ++k) EXPECT_EQ(params[static_cast<std::size_t>(k)].default_value, published[k]);
    // OpenColorIO 2.1 FixedFunctionOpData::validate: limits [1.001, 65504], thresholds
    // [0, 0.9995], power [1, 65504].
    for (int k = 0; k < 3; ++k) {
        EXPECT_EQ(params[static_cast<std::size_t>(k)].min, 1.001);
        EXPECT_EQ(params[static_cast<std::size_t>(k)].max, 65504.0);
        EXPECT_EQ(params[static_cast<std::size_t>(3 + k)].min, 0.0);
        EXPECT_EQ(params[static_cast<std::size_t>(3 + k)].max, 0.9995);
    }
    EXPECT_EQ(params[6].min, 1.0);
    EXPECT_EQ(params[6].max, 65504.0);
    EXPECT_TRUE(params[7].boolean);
    // Beyond them the constructor refuses, naming the parameter.
    for (const auto& [name, value] : std::vector<std::pair<std::string, double>>{
             {"limit-cyan", 1.0}, {"threshold-yellow", 0.9996}, {"power", 0.99}, {"limit-magenta", 7e4}}) {
        try {
            (void)aces(ClipSettings{}.set(name, value));
            ADD_FAILURE() << name;
        } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
        }
    }
    // The ends of the ranges are accepted and give finite scales.
    const GamutClipper edge = aces(ClipSettings{}
                                       .set("limit-cyan", 1.001)
                                       .set("threshold-cyan", 0.9995)
                                       .set("limit-magenta", 65504)
                                       .set("threshold-magenta", 0)
                                       .set("power", 65504));
    for (int k = 0; k < 3; ++k) EXPECT_TRUE(std::isfinite(edge.aces_rgc_prepared().scale[static_cast<std::size_t>(k)]));
}

TEST(AcesRgc, TheLimitMapsToTheBoundaryExactly) {
    // The scale is chosen so that D(limit) = 1: a channel at distance `limit` lands on 0 (the
    // gamut's face) whatever ach, for the defaults and for other parameters.
    const std::vector<ClipSettings> settings = {
        ClipSettings{},
        ClipSettings{}.set("limit-cyan", 1.5).set("threshold-cyan", 0.6).set("power", 3.0),
        ClipSettings{}.set("limit-magenta", 2.0).set("threshold-magenta", 0.0).set("power", 1.0),
        ClipSettings{}.set("limit-yellow", 1.001).set("threshold-yellow", 0.9995).set("power", 40.0)};
    for (const ClipSettings& s : settings) {
        const GamutClipper g = aces(s);
        for (int k = 0; k < 3; ++k) {
            const double lim = g.parameter(limit_names[k]);
            EXPECT_NEAR(compressed_distance(g, k, lim), 1.0, 1e-12) << limit_names[k];
            for (const double ach : {1e-3, 0.5, 7.0, 1e4}) {
                const Rgb out = g.clip(with_channel(ach, ach * (1.0 - lim), k));
                EXPECT_NEAR(channel(out, k), 0.0, 1e-12 * ach) << ach;
            }
        }
    }
}

TEST(AcesRgc, BelowTheThresholdNothingMovesAndTheCurveJoinsWithSlopeOne) {
    const GamutClipper g = aces();
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    // Colours whose every distance is below its threshold come back bit for bit.
    int checked = 0;
    for (int i = 0; i < 20000; ++i) {
        const double ach = std::pow(10.0, 6.0 * u(rng) - 3.0) * (u(rng) < 0.2 ? -1.0 : 1.0);
        Rgb c{};
        double* v[3] = {&c.r, &c.g, &c.b};
        const int top = static_cast<int>(3 * u(rng)) % 3;
        for (int k = 0; k < 3; ++k) {
            const double d = k == top ? 0.0 : g.aces_rgc_prepared().threshold[static_cast<std::size_t>(k)] * u(rng);
            *v[k] = ach - d * std::abs(ach);
        }
        const Rgb out = g.clip(c);
        ASSERT_EQ(out.r, c.r);
        ASSERT_EQ(out.g, c.g);
        ASSERT_EQ(out.b, c.b);
        ++checked;
    }
    EXPECT_EQ(checked, 20000);
    // At the threshold the curve is continuous (D(thr) = thr) and its slope is 1 from both sides
    // (f'(0) = 1 for f(nd) = nd / (1 + nd^p)^(1/p)), so C1; farther out the slope drops below 1.
    for (int k = 0; k < 3; ++k) {
        const double thr = g.aces_rgc_prepared().threshold[static_cast<std::size_t>(k)];
        const double h = 1e-7;
        EXPECT_NEAR(compressed_distance(g, k, thr), thr, 1e-15);
        EXPECT_NEAR(compressed_distance(g, k, thr + h) - (thr + h), 0.0, 1e-14);
        const double right = (compressed_distance(g, k, thr + 2 * h) - compressed_distance(g, k, thr + h)) / h;
        const double left = (compressed_distance(g, k, thr - h) - compressed_distance(g, k, thr - 2 * h)) / h;
        EXPECT_NEAR(right, 1.0, 1e-6);
        EXPECT_NEAR(left, 1.0, 1e-6);
        const double far = (compressed_distance(g, k, 1.5 + h) - compressed_distance(g, k, 1.5)) / h;
        EXPECT_LT(far, 0.5);
        EXPECT_GT(far, 0.0);
        // Monotonic and bounded by the asymptote thr + s.
        double last = thr;
        for (double d = thr; d < 50.0; d += 0.01) {
            const double D = compressed_distance(g, k, d);
            EXPECT_GE(D, last);
            EXPECT_LT(D, g.aces_rgc_prepared().asymptote[static_cast<std::size_t>(k)]);
            last = D;
        }
    }
}

TEST(AcesRgc, InverseUndoesForwardAndForwardUndoesInverse) {
    for (const ClipSettings& s : {ClipSettings{}, ClipSettings{}.set("power", 2.5).set("limit-cyan", 1.4)}) {
        const GamutClipper fwd = aces(s), inv = aces_inverse(s);
        std::mt19937 rng(12);
        std::uniform_real_distribution<double> u(-1.5, 1.2);
        for (int i = 0; i < 50000; ++i) {
            const Rgb c{u(rng), u(rng), u(rng)};
            // |ach| >= 0.2 keeps the distances below 8.5, where the forward stays farther from
            // the asymptote than the inverse's conditioning (its slope grows without bound
            // there) allows to recover to 1e-9 in double.
            if (std::abs(std::max({c.r, c.g, c.b})) < 0.2) continue;
            const double scale = std::max({std::abs(c.r), std::abs(c.g), std::abs(c.b)});
            const Rgb back = inv.clip(fwd.clip(c));
            ASSERT_NEAR(back.r, c.r, 1e-9 * scale) << i;
            ASSERT_NEAR(back.g, c.g, 1e-9 * scale) << i;
            ASSERT_NEAR(back.b, c.b, 1e-9 * scale) << i;
        }
        // Forward ∘ inverse on colours whose distances lie below the asymptotes.
        for (int i = 0; i < 50000; ++i) {
            Rgb c{1.0, 1.0, 1.0};
            for (int k = 0; k < 3; ++k) {
                if (k == i % 3) continue;  // the achromatic axis, at 1
                const double a = fwd.aces_rgc_prepared().asymptote[static_cast<std::size_t>(k)];
                const double d = (a - 1e-3) * (0.5 + 0.5 * (u(rng) + 1.5) / 2.7);
                (k == 0 ? c.r : (k == 1 ? c.g : c.b)) = 1.0 - d;
            }
            const Rgb again = fwd.clip(inv.clip(c));
            ASSERT_NEAR(again.r, c.r, 1e-9);
            ASSERT_NEAR(again.g, c.g, 1e-9);
            ASSERT_NEAR(again.b, c.b, 1e-9);
        }
    }
}

TEST(AcesRgc, AchromaticZeroNegativeMaxAndTheAsymptoteAsOcio) {
    const GamutClipper g = aces(), inv = aces_inverse();
    // ach = 0: every channel 0 (OCIO gamut_comp returns 0; the CTL sets the distances to 0).
    for (const Rgb& c : {Rgb{0, -1, -2}, Rgb{0, 0, 0}, Rgb{-3, 0, -0.5}, Rgb{-0.0, -7, -0.0}}) {
        for (const GamutClipper* h : {&g, &inv}) {
            const Rgb out = h->clip(c);
            EXPECT_EQ(out.r, 0.0);
            EXPECT_EQ(out.g, 0.0);
            EXPECT_EQ(out.b, 0.0);
        }
    }
    // Achromatic colours, positive or negative, are unchanged (every distance 0).
    for (const double v : {-5.0, -1e-6, 1e-6, 0.18, 100.0}) {
        const Rgb out = g.clip({v, v, v});
        EXPECT_EQ(out.r, v);
        EXPECT_EQ(out.g, v);
        EXPECT_EQ(out.b, v);
    }
    // Negative max: distances against |ach|, output ach − D |ach|, so (out − ach)/|ach| is the
    // same as for the colour of the same distances around a positive ach.
    const Rgb negative{-0.1, -0.5, -2.0};
    const Rgb positive{0.1, 0.1 - 0.4, 0.1 - 1.9};  // the same distances 0, 4 and 19
    const Rgb on = g.clip(negative), op = g.clip(positive);
    for (int k = 0; k < 3; ++k) {
        EXPECT_NEAR((channel(on, k) + 0.1) / 0.1, (channel(op, k) - 0.1) / 0.1, 1e-12) << k;
    }
    EXPECT_LT(channel(on, 1), -0.1 - 0.1 * g.aces_rgc_prepared().threshold[1]);  // compressed, still below ach
    EXPECT_GT(channel(on, 1), -0.5);
    // Inverse at and beyond the asymptote thr + s: the channel is unchanged (OCIO uncompress:
    // dist >= thr + scale returns dist).
    for (int k = 0; k < 3; ++k) {
        const double a = g.aces_rgc_prepared().asymptote[static_cast<std::size_t>(k)];
        for (const double d : {a, a + 1e-9, 2.0, 50.0}) {
            const Rgb c = with_channel(2.0, 2.0 - 2.0 * d, k);
            EXPECT_EQ(channel(inv.clip(c), k), channel(c, k)) << d;
        }
        // Just below it the inverse is large but finite.
        const double below = channel(inv.clip(with_channel(1.0, 1.0 - (a - 1e-12), k)), k);
        EXPECT_TRUE(std::isfinite(below));
        EXPECT_LT(below, -10.0);
    }
}

TEST(AcesRgc, ALargePowerTendsToTheHardClipOfTheDistanceAndStaysFinite) {
    // As p → ∞, s → 1 − thr and f(nd) → min(nd, 1): D(d) → min(d, 1). OCIO's float evaluation of
    // nd^p overflows there; irid's form does not.
    const GamutClipper g = aces(ClipSettings{}.set("power", 65504));
    for (int k = 0; k < 3; ++k) {
        const double thr = g.aces_rgc_prepared().threshold[static_cast<std::size_t>(k)];
        EXPECT_NEAR(g.aces_rgc_prepared().scale[static_cast<std::size_t>(k)], 1.0 - thr, 1e-4);
        for (const double d : {thr + 0.01, 0.95, 0.999, 1.0, 1.2, 10.0, 1e20}) {
            const double D = compressed_distance(g, k, d);
            EXPECT_TRUE(std::isfinite(D));
            EXPECT_NEAR(D, std::min(d, 1.0), 2e-4) << d;
        }
    }
}

TEST(AcesRgc, OutputsAreFiniteAndClipConfinesToTheCube) {
    const double inf = std::numeric_limits<double>::infinity();
    const Rgb hostile[] = {{std::nan(""), 0.5, 0.5}, {inf, 0, 0},        {-inf, 0.2, 0.2},
                           {inf, -inf, 0.5},         {1e300, -1e300, 3}, {-1e300, -1e308, 0},
                           {1e-300, -1, 0},          {5e-324, -1e308, 0}};
    for (const bool inverse : {false, true}) {
        for (const bool clip : {false, true}) {
            ClipSettings s = ClipSettings{}.set("clip", clip ? 1.0 : 0.0);
            s.inverse = inverse;
            const GamutClipper g(ClipMethod::aces_rgc, Gamut(acescg(), 4.0), s);
            EXPECT_EQ(g.confines_to_cube(), clip);
            for (const Rgb& c : hostile) {
                const Rgb o = g.clip(c);
                EXPECT_TRUE(std::isfinite(o.r) && std::isfinite(o.g) && std::isfinite(o.b));
                if (clip) {
                    EXPECT_TRUE(g.gamut().contains(o));
                }
            }
        }
    }
    // By default a colour beyond the limit stays slightly outside the cube, as OCIO's does.
    const Rgb beyond = aces().clip({1.0, 1.0 - 1.5, 1.0});
    EXPECT_LT(beyond.g, 0.0);
    EXPECT_GT(beyond.g, -0.1);
}

// --- the batch kernel -------------------------------------------------------------------------

/// ≥ 100 000 colours of every kind: the benchmark's distribution, in-gamut, negative, large,
/// tiny, and the non-finite and huge values spread over lanes.
std::vector<float> batch_input(double max, std::uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> bench(-0.5f, 1.5f), unit(0.0f, 1.0f), wide(-3.0f, 3.0f);
    const float m = static_cast<float>(max);
    const float specials[] = {std::numeric_limits<float>::quiet_NaN(),
                              std::numeric_limits<float>::infinity(),
                              -std::numeric_limits<float>::infinity(),
                              1e30f, -1e30f, std::numeric_limits<float>::max(),
                              -std::numeric_limits<float>::max(), 0.0f, -0.0f, 1e-40f, -1e-38f,
                              1e-31f, 2e30f};
    std::vector<float> v;
    v.reserve(3 * 120000);
    for (int i = 0; i < 120000; ++i) {
        float c[3];
        switch (i % 6) {
            case 0: case 1: for (float& x : c) x = m * bench(rng); break;  // mostly out of gamut
            case 2: for (float& x : c) x = m * unit(rng); break;            // in gamut
            case 3: for (float& x : c) x = -m * 2.0f * unit(rng); break;    // all negative
            case 4: for (float& x : c) x = m * 40.0f * wide(rng); break;    // large, mixed signs
            default:
                for (float& x : c) {
                    x = unit(rng) < 0.3f ? specials[rng() % std::size(specials)] : m * wide(rng);
                }
        }
        v.insert(v.end(), c, c + 3);
    }
    return v;
}

TEST(AcesRgcBatch, SimdEqualsTheDoubleReferenceAndThreadsDoNotChangeABit) {
    const RgbSpace* spaces[] = {&srgb(), &display_p3(), &rec2020(), &acescg()};
    int cases = 0;
    double worst_of_all[2] = {0.0, 0.0};
    for (const RgbSpace* space : spaces) {
        for (const double max : {1.0, 4.0}) {
            for (const bool inverse : {false, true}) {
                for (const bool clip : {false, true}) {
                    ClipSettings s = ClipSettings{}.set("clip", clip ? 1.0 : 0.0);
                    s.inverse = inverse;
                    if (cases % 3 == 1) s.set("power", 1.7).set("threshold-yellow", 0.7);
                    const GamutClipper g(ClipMethod::aces_rgc, Gamut(*space, max), s);
                    const std::vector<float> in = batch_input(max, 100u + static_cast<unsigned>(cases));
                    std::vector<float> one(in.size()), two(in.size());
                    clip_batch(g, in, one, {.threads = 1, .simd = true});
                    clip_batch(g, in, two, {.threads = 2, .simd = true});
                    ASSERT_EQ(std::memcmp(one.data(), two.data(), one.size() * sizeof(float)), 0);
                    // Confined: within 1e-5 × max. Not confined, the output is not bounded by the
                    // cube and float carries 6e-8 of it (and of ach, from which it is computed):
                    // within 1e-5 × max(max, |ach|, |reference|).
                    double worst = 0.0;
                    std::size_t worst_at = 0;
                    for (std::size_t i = 0; i < in.size() / 3; ++i) {
                        const Rgb ref = g.clip({in[3 * i], in[3 * i + 1], in[3 * i + 2]});
                        const double ach = std::max({finite_or_default(in[3 * i]),
                                                     finite_or_default(in[3 * i + 1]),
                                                     finite_or_default(in[3 * i + 2])});
                        for (int k = 0; k < 3; ++k) {
                            const float o = one[3 * i + static_cast<std::size_t>(k)];
                            const double scale =
                                clip ? max
                                     : std::max({max, std::abs(ach), std::abs(channel(ref, k))});
                            ASSERT_TRUE(std::isfinite(o));
                            const double e = std::abs(o - channel(ref, k)) / scale;
                            if (e > worst) {
                                worst = e;
                                worst_at = i;
                            }
                        }
                    }
                    EXPECT_LE(worst, 1e-5)
                        << space->name() << " max " << max << " inverse " << inverse << " clip "
                        << clip << " at (" << in[3 * worst_at] << ", " << in[3 * worst_at + 1]
                        << ", " << in[3 * worst_at + 2] << ") -> (" << one[3 * worst_at] << ", "
                        << one[3 * worst_at + 1] << ", " << one[3 * worst_at + 2] << ")";
                    worst_of_all[clip ? 1 : 0] = std::max(worst_of_all[clip ? 1 : 0], worst);
                    // In place gives the same bytes.
                    std::vector<float> same = in;
                    clip_batch(g, same, {.threads = 1, .simd = true});
                    ASSERT_EQ(std::memcmp(same.data(), one.data(), one.size() * sizeof(float)), 0);
                    ++cases;
                }
            }
        }
    }
    EXPECT_EQ(cases, 32);
    std::cout << "aces-rgc SIMD vs double, largest error: " << worst_of_all[0]
              << " (not confined, relative) and " << worst_of_all[1] << " x max (clip)\n";
}

TEST(AcesRgcBatch, EveryCompiledTargetStaysWithinTheTolerance) {
    // The best target is what the test above checks; AVX2, SSE4 and the scalar fallback of
    // Highway's dynamic dispatch run the same code at other widths (and other Compress paths).
    int targets = 0;
    for (const std::int64_t target : hwy::SupportedAndGeneratedTargets()) {
        hwy::SetSupportedTargetsForTest(target);
        for (const bool inverse : {false, true}) {
            ClipSettings s;
            s.inverse = inverse;
            const GamutClipper g(ClipMethod::aces_rgc, Gamut(rec2020(), 4.0), s);
            const std::vector<float> in = batch_input(4.0, 77);
            std::vector<float> out(in.size());
            clip_batch(g, in, out, {.threads = 1, .simd = true});
            for (std::size_t i = 0; i < in.size() / 3; ++i) {
                const Rgb ref = g.clip({in[3 * i], in[3 * i + 1], in[3 * i + 2]});
                const double ach = std::max({finite_or_default(in[3 * i]),
                                             finite_or_default(in[3 * i + 1]),
                                             finite_or_default(in[3 * i + 2])});
                for (int k = 0; k < 3; ++k) {
                    const double scale = std::max({4.0, std::abs(ach), std::abs(channel(ref, k))});
                    ASSERT_LE(std::abs(out[3 * i + static_cast<std::size_t>(k)] - channel(ref, k)),
                              1e-5 * scale)
                        << hwy::TargetName(target) << " inverse " << inverse << " colour " << i;
                }
            }
        }
        ++targets;
    }
    hwy::SetSupportedTargetsForTest(0);
    EXPECT_GE(targets, 2);
}

TEST(AcesRgcBatch, LanesSentToTheDoubleReferenceOnTheBenchmarkInput) {
    // The kernel's criteria (batch_simd_aces.cpp), counted on the benchmark's distribution:
    // uniform in [-0.5, 1.5]^3, redrawn until outside [0, 1]^3, taken as ACEScg.
    const GamutClipper g = aces();
    std::mt19937 rng(20240613);
    std::uniform_real_distribution<float> d(-0.5f, 1.5f);
    const auto outside = [](float v) { return v < 0.0f || v > 1.0f; };
    const int colours = 1 << 18;
    int forward = 0, inverse = 0;
    for (int i = 0; i < colours; ++i) {
        float c[3];
        do {
            for (float& x : c) x = d(rng);
        } while (!(outside(c[0]) || outside(c[1]) || outside(c[2])));
        const double ach = std::max({c[0], c[1], c[2]});
        const double a = std::abs(ach);
        const bool extreme = ach != 0.0 && (a < 1e-30 || a > 1e30);
        forward += extreme;
        bool hard = extreme;
        for (std::size_t k = 0; k < 3 && ach != 0.0; ++k) {
            const double dist = (ach - c[k]) / a;
            const double thr = g.aces_rgc_prepared().threshold[k], s = g.aces_rgc_prepared().scale[k], p = g.aces_rgc_prepared().power;
            if (dist >= thr && dist < thr + s && std::pow((dist - thr) / s, p) > 1.0 - 1e-4) hard = true;
            if (dist >= thr + s && dist < (thr + s) * (1.0 + 1e-9)) hard = true;
        }
        inverse += hard;
    }
    std::cout << "aces-rgc lanes to the double reference on the benchmark input: forward "
              << forward << " of " << colours << ", inverse " << inverse << " ("
              << 100.0 * inverse / colours << " %)\n";
    EXPECT_EQ(forward, 0);
    EXPECT_LT(inverse, colours / 1000);
}

}  // namespace
}  // namespace irid
