// oklab-adaptive and oklab-cusp (Ottosson 2021, "sRGB gamut clipping",
// bottosson.github.io/posts/gamutclipping/) and the float kernels of oklab, oklab-adaptive and
// oklab-cusp.
//
// What is checked, on every built-in RGB space and on HDR peaks:
// - in-gamut colours are unchanged; there is no black or white rule (Ottosson's L0 applies at
//   every lightness);
// - an out-of-gamut colour comes back inside the cube with a channel at 0 or max (to 1e-12 max),
//   its Oklab hue kept, on the segment from (L0, 0) to itself in its hue plane, where L0 is
//   Ottosson's formula (written out here from the article) around half the white's L or around
//   the cusp's L; the cusp is found here independently, as the largest chroma of the hue on the
//   cube's edges where one channel is 0 and another max (the article: the cusp is where the
//   hue's "triangle" has its corner, at the most saturated colour of the hue at full intensity),
//   by scanning those six edges;
// - the segment's points beyond the result are outside (the result is where it last leaves);
// - alpha's limits (the article's formulas): alpha = 0 gives L0 = L (constant lightness, as the
//   oklab method); as alpha grows L0 moves monotonically to the centre (0.5 or the cusp's L);
// - a colour within 1e-9 max of the cube comes back within 1e-6 max of itself;
// - the SIMD kernels equal the double reference within 1e-5 max on over 100 000 colours
//   (in-gamut, out-of-gamut, negative, huge, NaN and Inf) and give the same bytes on 1 and 2
//   threads.

#include <irid/color/rgb.h>
#include <irid/color/spaces.h>
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
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace irid {
namespace {

std::vector<Gamut> gamuts() {
    std::vector<Gamut> g;
    for (const RgbSpace* space : builtin_rgb_spaces()) g.emplace_back(*space);
    g.emplace_back(srgb(), 4.0);
    g.emplace_back(rec2020(), 4.0);
    g.emplace_back(display_p3(), 2.5);
    return g;
}

std::string name(const Gamut& g) {
    std::ostringstream s;
    s << g.space().name() << " [0, " << g.max() << "]";
    return s.str();
}

double chroma(const Oklab& c) { return std::hypot(c.a, c.b); }

/// Ottosson 2021, gamut_clip_adaptive_L0_L_cusp's L0 (with l_centre = 0.5: ..._L0_0_5), in
/// lightness relative to the white's (his white has L = 1).
double ottosson_l0(double l, double c, double l_centre, double l_white, double alpha) {
    l /= l_white;
    c /= l_white;
    l_centre /= l_white;
    const double ld = l - l_centre;
    const double k = 2.0 * (ld > 0.0 ? 1.0 - l_centre : l_centre);
    const double e1 = 0.5 * k + std::abs(ld) + alpha * c / k;
    const double sign = ld > 0.0 ? 1.0 : (ld < 0.0 ? -1.0 : 0.0);
    return l_white * (l_centre + 0.5 * sign * (e1 - std::sqrt(e1 * e1 - 2.0 * k * std::abs(ld))));
}

/// The signed angle from hue direction (a, b) to (a2, b2), in radians.
double hue_angle(double a, double b, double a2, double b2) {
    return std::atan2(a * b2 - b * a2, a * a2 + b * b2);
}

/// The cusp's L of the hue (a, b) found independently: the largest chroma, among the points of
/// that hue and L > 0 on the six cube edges from a primary to a secondary (one channel 0, one at max),
/// each edge scanned in 1024 steps and the crossings of the hue refined by bisection.
double edge_cusp_l(const GamutClipper& clipper, double a, double b) {
    const double max = clipper.gamut().max();
    double best_c = -1.0, best_l = 0.0;
    for (int zero = 0; zero < 3; ++zero) {
        for (int full = 0; full < 3; ++full) {
            if (full == zero) continue;
            const int free = 3 - zero - full;
            const auto point = [&](double x) {
                std::array<double, 3> c{};
                c[static_cast<std::size_t>(zero)] = 0.0;
                c[static_cast<std::size_t>(full)] = max;
                c[static_cast<std::size_t>(free)] = x;
                return clipper.to_oklab({c[0], c[1], c[2]});
            };
            const auto side = [&](double x) {
                const Oklab p = point(x);
                return hue_angle(a, b, p.a, p.b);
            };
            constexpr int steps = 1024;
            double prev = side(0.0);
            for (int k = 1; k <= steps; ++k) {
                const double x = max * k / steps;
                const double cur = side(x);
                if ((prev < 0.0) != (cur < 0.0) && std::abs(prev - cur) < 1.0) {
                    double lo = max * (k - 1) / steps, hi = x;
                    const bool neg_lo = prev < 0.0;
                    for (int it = 0; it < 100; ++it) {
                        const double mid = 0.5 * (lo + hi);
                        ((side(mid) < 0.0) == neg_lo ? lo : hi) = mid;
                    }
                    const Oklab p = point(0.5 * (lo + hi));
                    if (p.L > 0.0 && chroma(p) > best_c && p.a * a + p.b * b > 0.0) {
                        best_c = chroma(p);
                        best_l = p.L;
                    }
                }
                prev = cur;
            }
        }
    }
    return best_l;
}

/// Out-of-gamut colours: uniform in [-0.5, 1.5]³ max (the benchmark's range) and in [-3, 3]³ max.
/// Out-of-gamut colours of six kinds in turn: uniform in [−0.5, 1.5]³ (twice), wide
/// ([−3, 3]³), near the white (a level of 0.95 to 4 with tints of ±0.03: lightness around and
/// above the white's), near black ([−0.004, 0.004]³: lightness around 0, negative too) and HDR
/// ([−5, 100]³), all × max.
std::vector<Rgb> out_of_gamut(const Gamut& g, int count, unsigned seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(-0.5, 1.5), w(-3.0, 3.0), level(0.95, 4.0),
        tint(-0.03, 0.03), dark(-0.004, 0.004), hdr(-5.0, 100.0);
    std::vector<Rgb> out;
    while (static_cast<int>(out.size()) < count) {
        Rgb c{};
        switch (out.size() % 6) {
            case 2: c = {w(rng), w(rng), w(rng)}; break;
            case 3: {
                const double l = level(rng);
                c = {l + tint(rng), l + tint(rng), l + tint(rng)};
                break;
            }
            case 4: c = {dark(rng), dark(rng), dark(rng)}; break;
            case 5: c = {hdr(rng), hdr(rng), hdr(rng)}; break;
            default: c = {u(rng), u(rng), u(rng)}; break;
        }
        c = {c.r * g.max(), c.g * g.max(), c.b * g.max()};
        if (!g.contains(c)) out.push_back(c);
    }
    return out;
}

bool on_boundary(const Rgb& c, double max) {
    const double e = 1e-12 * max;
    for (const double v : {c.r, c.g, c.b}) {
        if (std::abs(v) <= e || std::abs(v - max) <= e) return true;
    }
    return false;
}

/// How far outside the cube (0 inside).
double outside_by(const Rgb& c, double max) {
    return std::max({0.0, -c.r, -c.g, -c.b, c.r - max, c.g - max, c.b - max});
}

/// The L0 implied by a result: where the line through the colour and the result in the hue
/// plane meets the neutral axis.
double implied_l0(const Oklab& in, const Oklab& out) {
    const double c = chroma(in), co = chroma(out);
    return in.L - (in.L - out.L) * c / (c - co);
}

void check_projection(ClipMethod method, double alpha, int count) {
    for (const Gamut& g : gamuts()) {
        SCOPED_TRACE(name(g) + " " + std::string(clip_method_name(method)) + " alpha " +
                     std::to_string(alpha));
        const GamutClipper clipper(method, g, ClipSettings{}.set("alpha", alpha));
        const double max = g.max(), lw = clipper.white_oklab_lightness();
        int checked_l0 = 0, failures = 0;
        for (const Rgb& c : out_of_gamut(g, count, 7)) {
            const Rgb o = clipper.clip(c);
            const Oklab in = clipper.to_oklab(c), out = clipper.to_oklab(o);
            ASSERT_TRUE(g.contains(o));
            // Every lightness, below 0 and above the white's too, takes Ottosson's formula: no
            // black or white rule.
            if (outside_by(c, max) <= oklab_rounding_tolerance * max) continue;
            if (!on_boundary(o, max) && ++failures < 5) {
                ADD_FAILURE() << "not on the boundary: " << o.r << " " << o.g << " " << o.b;
            }
            // Hue kept: (a, b) of the result parallel to the colour's, same direction.
            const double cin = chroma(in), cout = chroma(out);
            if (cout > 1e-6 * lw) {
                EXPECT_NEAR(hue_angle(in.a, in.b, out.a, out.b), 0.0, 1e-8);
            }
            // On the segment from (L0, 0) toward the colour, L0 as Ottosson's formula.
            const double t = cout / cin;
            EXPECT_LE(t, 1.0 + 1e-9);
            // oklab-cusp's centre is the cusp's L kept within [0.01, 0.99] × the white's
            // (ACES2065-1 has hues whose cusp is lighter than its white).
            const double centre = method == ClipMethod::oklab_adaptive
                                      ? 0.5 * lw
                                      : std::clamp(edge_cusp_l(clipper, in.a / cin, in.b / cin),
                                                   0.01 * lw, 0.99 * lw);
            // The edge scan finds the cusp only where it lies on an edge of the cube; on
            // ACES2065-1, whose imaginary blue puts some hues' cusps elsewhere, the colours
            // brighter than its white (which the former white rule kept from here) reach such
            // hues: their L0 is not checked against the scan.
            if (method == ClipMethod::oklab_cusp && g.space().name() == "aces2065-1" && in.L >= lw) continue;
            const double l0 = ottosson_l0(in.L, cin, centre, lw, alpha);
            EXPECT_NEAR(out.L, l0 + t * (in.L - l0), 2e-9 * lw)
                << "colour " << c.r << " " << c.g << " " << c.b;
            if (t < 0.9) {
                EXPECT_NEAR(implied_l0(in, out), l0, 1e-7 * lw);
                ++checked_l0;
            }
            // Beyond the result the segment is outside (it is where the segment last leaves).
            for (const double f : {0.25, 0.5, 0.75, 1.0}) {
                const double s = t + f * (1.0 - t);
                if (s - t < 1e-6) continue;
                const Rgb p = clipper.from_oklab({l0 + s * (in.L - l0), s * in.a, s * in.b});
                EXPECT_GT(outside_by(p, max), 0.0) << "s " << s << " t " << t;
            }
        }
        EXPECT_GT(checked_l0, count / 10);
    }
}

TEST(OklabAdaptive, StopsOnTheBoundaryTowardOttossonsL0KeepingHue) {
    check_projection(ClipMethod::oklab_adaptive, 0.05, 400);
    check_projection(ClipMethod::oklab_adaptive, 1.0, 100);
}

TEST(OklabCusp, StopsOnTheBoundaryTowardOttossonsL0AroundTheEdgeCusp) {
    check_projection(ClipMethod::oklab_cusp, 0.05, 150);
    check_projection(ClipMethod::oklab_cusp, 2.0, 50);
}

TEST(OklabProjection, InGamutColoursUnchangedAndNoBlackOrWhiteRule) {
    for (const Gamut& g : gamuts()) {
        for (const ClipMethod m : {ClipMethod::oklab_adaptive, ClipMethod::oklab_cusp}) {
            const GamutClipper clipper(m, g);
            std::mt19937_64 rng(3);
            std::uniform_real_distribution<double> u(0.0, g.max());
            for (int k = 0; k < 200; ++k) {
                const Rgb c{u(rng), u(rng), u(rng)};
                const Rgb o = clipper.clip(c);
                EXPECT_EQ(o.r, c.r);
                EXPECT_EQ(o.g, c.g);
                EXPECT_EQ(o.b, c.b);
            }
            // No black or white rule (Ottosson's projections move every lightness toward L0):
            // a colour of negative lightness lands near black, and one brighter than the white
            // on an upper face with its yellow tint, not on white.
            const double max = g.max();
            const Rgb dark = clipper.clip({-0.2 * max, -0.1 * max, -0.3 * max});
            EXPECT_TRUE(g.contains(dark));
            EXPECT_LT(std::max({dark.r, dark.g, dark.b}), 1e-3 * max);
            const Rgb bright = clipper.clip({2.0 * max, 2.0 * max, 1.5 * max});
            EXPECT_EQ(std::max(bright.r, bright.g), max);
            EXPECT_LT(bright.b, 0.999 * max);
            EXPECT_GT(bright.b, 0.5 * max);
        }
    }
}

TEST(OklabProjection, AlphaZeroIsConstantLightnessAndLargeAlphaApproachesTheCentre) {
    for (const Gamut& g : {Gamut(srgb()), Gamut(rec2020()), Gamut(display_p3(), 4.0)}) {
        SCOPED_TRACE(name(g));
        const GamutClipper oklab(ClipMethod::oklab, g);
        for (const ClipMethod m : {ClipMethod::oklab_adaptive, ClipMethod::oklab_cusp}) {
            const GamutClipper zero(m, g, ClipSettings{}.set("alpha", 0.0));
            const double lw = zero.white_oklab_lightness();
            for (const Rgb& c : out_of_gamut(g, 300, 11)) {
                // alpha = 0: L0 = L, Ottosson's e1 − sqrt(e1² − 2 k |ΔL|) = 2 |ΔL|.
                const Rgb a = zero.clip(c), b = oklab.clip(c);
                EXPECT_NEAR(a.r, b.r, 1e-9 * g.max());
                EXPECT_NEAR(a.g, b.g, 1e-9 * g.max());
                EXPECT_NEAR(a.b, b.b, 1e-9 * g.max());
            }
            // Growing alpha: L0 moves monotonically toward the centre, reaching it in the limit.
            const Oklab in = zero.to_oklab({1.3 * g.max(), -0.2 * g.max(), 0.1 * g.max()});
            const double cin = chroma(in);
            const double centre = m == ClipMethod::oklab_adaptive
                                      ? 0.5 * lw
                                      : edge_cusp_l(zero, in.a / cin, in.b / cin);
            double previous = std::abs(in.L - centre);
            for (const double alpha : {0.01, 0.05, 0.5, 5.0, 100.0}) {
                const GamutClipper clipper(m, g, ClipSettings{}.set("alpha", alpha));
                const Rgb c = clipper.from_oklab(in);
                const Oklab out = clipper.to_oklab(clipper.clip(c));
                const double l0 = implied_l0(in, out);
                EXPECT_NEAR(l0, ottosson_l0(in.L, cin, centre, lw, alpha), 1e-7);
                EXPECT_LT(std::abs(l0 - centre), previous) << "alpha " << alpha;
                previous = std::abs(l0 - centre);
            }
            // L0 − centre ≈ k |ΔL| / (2 e1), e1 ≈ alpha C / k: a few per cent of ΔL at 100.
            EXPECT_LT(previous, 0.05 * std::abs(in.L - centre));
        }
    }
}

TEST(OklabProjection, ColoursJustOutsideComeBackClose) {
    for (const Gamut& g : gamuts()) {
        SCOPED_TRACE(name(g));
        const double max = g.max();
        std::mt19937_64 rng(5);
        std::uniform_real_distribution<double> u(0.0, max);
        for (const ClipMethod m : {ClipMethod::oklab_adaptive, ClipMethod::oklab_cusp}) {
            const GamutClipper clipper(m, g);
            for (int k = 0; k < 600; ++k) {
                std::array<double, 3> c{u(rng), u(rng), u(rng)};
                const int face = k % 3;
                const bool high = (k / 3) % 2 == 1;
                c[static_cast<std::size_t>(face)] = high ? max * (1.0 + 1e-9) : -1e-9 * max;
                if (k % 7 == 0) c[static_cast<std::size_t>((face + 1) % 3)] = high ? max : 0.0;
                const Rgb o = clipper.clip({c[0], c[1], c[2]});
                EXPECT_NEAR(o.r, c[0], 1e-6 * max);
                EXPECT_NEAR(o.g, c[1], 1e-6 * max);
                EXPECT_NEAR(o.b, c[2], 1e-6 * max);
            }
        }
    }
}

/// Colours for the kernels: the benchmark's range, in-gamut, negative, huge, NaN and Inf.
std::vector<float> kernel_input(double max, std::size_t colours) {
    std::mt19937_64 rng(99);
    std::uniform_real_distribution<float> u(-0.5f, 1.5f), in(0.0f, 1.0f), wide(-50.0f, 50.0f);
    std::uniform_int_distribution<int> kind(0, 99);
    const float m = static_cast<float>(max);
    const float specials[] = {std::numeric_limits<float>::quiet_NaN(),
                              std::numeric_limits<float>::infinity(),
                              -std::numeric_limits<float>::infinity(), 1e30f, -1e30f, 0.0f, m};
    std::vector<float> v(3 * colours);
    for (std::size_t i = 0; i < colours; ++i) {
        const int k = kind(rng);
        for (std::size_t j = 0; j < 3; ++j) {
            float x = u(rng) * m;
            if (k < 15) x = in(rng) * m;
            else if (k < 20) x = wide(rng) * m;
            else if (k < 23) x = specials[std::uniform_int_distribution<int>(0, 6)(rng)];
            else if (k < 26 && j == i % 3) x = -1e-7f * m;  // just outside a face
            v[3 * i + j] = x;
        }
    }
    return v;
}

TEST(OklabKernels, SimdEqualsTheDoubleReferenceAndIsThreadInvariant) {
    const std::size_t colours = 120000;
    // (A peak of 1e-7: the kernels leave it to the double reference, float's range being short.)
    for (const Gamut& g : {Gamut(srgb()), Gamut(display_p3()), Gamut(rec2020()), Gamut(srgb(), 4.0),
                           Gamut(aces2065_1()), Gamut(adobe_rgb()), Gamut(display_p3(), 1e-7)}) {
        const std::vector<float> input = kernel_input(g.max(), colours);
        struct Case {
            ClipMethod method;
            double alpha;  // for the projections; oklab has no parameter
        };
        for (const Case& k : {Case{ClipMethod::oklab, 0.0}, Case{ClipMethod::oklab_adaptive, 0.05},
                              Case{ClipMethod::oklab_cusp, 0.05},
                              Case{ClipMethod::oklab_adaptive, 1.0},
                              Case{ClipMethod::oklab_cusp, 1.0}}) {
            const ClipMethod m = k.method;
            SCOPED_TRACE(name(g) + " " + std::string(clip_method_name(m)) + " alpha " +
                         std::to_string(k.alpha));
            const GamutClipper clipper(
                m, g, m == ClipMethod::oklab ? ClipSettings{} : ClipSettings{}.set("alpha", k.alpha));
            std::vector<float> one(input.size()), two(input.size());
            clip_batch(clipper, input, one, {.threads = 1, .simd = true});
            clip_batch(clipper, input, two, {.threads = 2, .simd = true});
            EXPECT_EQ(std::memcmp(one.data(), two.data(), one.size() * sizeof(float)), 0);
            double worst = 0.0;
            std::size_t worst_at = 0;
            for (std::size_t i = 0; i < colours; ++i) {
                const Rgb ref = clipper.clip({input[3 * i], input[3 * i + 1], input[3 * i + 2]});
                const double e = std::max({std::abs(one[3 * i] - ref.r),
                                           std::abs(one[3 * i + 1] - ref.g),
                                           std::abs(one[3 * i + 2] - ref.b)});
                ASSERT_TRUE(std::isfinite(one[3 * i]) && std::isfinite(one[3 * i + 1]) &&
                            std::isfinite(one[3 * i + 2]));
                if (e > worst) worst = e, worst_at = i;
            }
            EXPECT_LE(worst, 1e-5 * g.max())
                << "at " << input[3 * worst_at] << " " << input[3 * worst_at + 1] << " "
                << input[3 * worst_at + 2];
        }
    }
}

TEST(OklabKernels, EveryCompiledTargetAgreesWithTheDoubleReference) {
    // Every instruction set Highway compiled and this CPU supports (AVX-512, AVX2, SSE4, ...):
    // the kernels' vector length and approximate reciprocals differ between them.
    const std::size_t colours = 30000;
    const std::vector<std::int64_t> targets = hwy::SupportedAndGeneratedTargets();
    std::set<std::string> ran;
    for (const std::int64_t target : targets) {
        hwy::SetSupportedTargetsForTest(target);
        ran.insert(std::string(simd_target_name()));
        SCOPED_TRACE(std::string(simd_target_name()));
        for (const Gamut& g : {Gamut(srgb()), Gamut(rec2020(), 4.0)}) {
            const std::vector<float> input = kernel_input(g.max(), colours);
            for (const ClipMethod m :
                 {ClipMethod::oklab, ClipMethod::oklab_adaptive, ClipMethod::oklab_cusp}) {
                SCOPED_TRACE(name(g) + " " + std::string(clip_method_name(m)));
                const GamutClipper clipper(m, g);
                std::vector<float> out(input.size());
                clip_batch(clipper, input, out, {.threads = 1, .simd = true});
                double worst = 0.0;
                for (std::size_t i = 0; i < colours; ++i) {
                    const Rgb ref =
                        clipper.clip({input[3 * i], input[3 * i + 1], input[3 * i + 2]});
                    worst = std::max({worst, std::abs(out[3 * i] - ref.r),
                                      std::abs(out[3 * i + 1] - ref.g),
                                      std::abs(out[3 * i + 2] - ref.b)});
                }
                EXPECT_LE(worst, 1e-5 * g.max());
            }
        }
    }
    hwy::SetSupportedTargetsForTest(0);
    EXPECT_EQ(ran.size(), targets.size());  // each target really ran
}

}  // namespace
}  // namespace irid
