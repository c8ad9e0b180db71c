// The continuity walk (docs/GAMUT.md, "Where a method may jump") on the ACES 2.0 display chain:
// segments through ACES2065-1 [−0.5, 64]³, every step above ΔE2000 1 bisected to its seam. A
// seam is allowed only where the published algorithm (OpenColorIO's ACES2 fixed function, which
// irid reproduces to its test vectors) forces it, and the test recognises each such seam by the
// stage that switches there:
// - black: the achromatic response A reaches 0 (the model takes A <= 0 as black);
// - the reach switch: gamut compression leaves M untouched once the gamut boundary reaches the
//   approximated reach boundary (proportion >= 1), and compresses it just below.
// Any other jump fails. docs/DISPLAY.md gives the counts.
#include <irid/color/difference.h>
#include <irid/color/spaces.h>
#include <irid/gamut/aces2_display.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>

namespace irid {
namespace {

constexpr double allowed_step = 1.0;  // ΔE2000, the bound

struct Walker {
    explicit Walker(const Aces2DisplaySpec& spec)
        : out(spec),
          white(xy_to_xyz(spec.limiting_white, spec.peak_nits / 100.0 * out.output_scale())),
          ap0_to_ap1(irid::inverse(rgb_to_xyz_matrix(ap1, aces_white), "AP1") *
                     rgb_to_xyz_matrix(ap0, aces_white)),
          ap1_to_ap0(irid::inverse(ap0_to_ap1, "AP0 to AP1")) {}

    [[nodiscard]] Lab lab(const Vec3& aces) const { return xyz_to_lab(out.forward(aces), white); }

    /// The rendering's stages for a scene colour, after the chain's AP1 clamp.
    struct Stages {
        Aces2Jmh in, toned, compressed;
    };
    [[nodiscard]] Stages stages(const Vec3& aces) const {
        Vec3 c = ap0_to_ap1 * aces;
        for (double& v : c) v = std::clamp(v, 0.0, out.rendering().forward_limit());
        const Aces2Rendering& r = out.rendering();
        Stages s;
        s.in = r.input_model().rgb_to_jmh(ap1_to_ap0 * c);
        s.toned = r.tonescale_and_chroma_forward(s.in);
        s.compressed = r.gamut_compress_forward(s.toned);
        return s;
    }

    static constexpr RgbPrimaries ap0{{0.7347, 0.2653}, {0.0, 1.0}, {0.0001, -0.0770}};
    static constexpr RgbPrimaries ap1{{0.713, 0.293}, {0.165, 0.830}, {0.128, 0.044}};
    static constexpr Xy aces_white{0.32168, 0.33767};
    Aces2Output out;
    Xyz white;
    Mat3 ap0_to_ap1, ap1_to_ap0;
};

enum class Seam { black, reach_switch, other };

/// Which stage switches between the two sides of a bisected seam.
Seam classify(const Walker& w, const Vec3& lo, const Vec3& hi) {
    const Walker::Stages a = w.stages(lo), b = w.stages(hi);
    if ((a.in.J == 0.0) != (b.in.J == 0.0)) return Seam::black;
    // The tonescale and chroma compression are continuous across the seam, and the gamut
    // compression leaves M as it is on one side and pulls it in on the other.
    const bool toned_close =
        std::abs(a.toned.J - b.toned.J) < 1e-6 && std::abs(a.toned.M - b.toned.M) < 1e-6;
    const auto untouched = [](const Walker::Stages& s) { return s.compressed.M == s.toned.M; };
    const auto pulled_in = [](const Walker::Stages& s) {
        return s.compressed.M < 0.999 * s.toned.M;
    };
    if (toned_close && ((untouched(a) && pulled_in(b)) || (untouched(b) && pulled_in(a))))
        return Seam::reach_switch;
    return Seam::other;
}

struct WalkResult {
    int black = 0, reach_switch = 0, other = 0;
    double largest = 0.0, largest_other = 0.0;
    std::string other_example;
};

WalkResult walk(const Aces2DisplaySpec& spec, int segments) {
    const Walker w(spec);
    std::mt19937 rng(20261206);
    std::uniform_real_distribution<double> cube(-0.5, 64.0), unit(0.0, 1.0);
    WalkResult result;
    constexpr int steps = 48;
    for (int s = 0; s < segments; ++s) {
        // Three families: anywhere in the cube; dark colours (exposures e^-5 to e^3), where the
        // black seam lies; colours with one negative channel, beyond AP1's faces.
        Vec3 a{}, b{};
        switch (s % 3) {
            case 0:
                a = {cube(rng), cube(rng), cube(rng)};
                b = {cube(rng), cube(rng), cube(rng)};
                break;
            case 1: {
                const double k = std::exp(unit(rng) * 8.0 - 5.0);
                a = {k * unit(rng), k * unit(rng), k * unit(rng)};
                b = {k * unit(rng), k * unit(rng), k * unit(rng)};
                break;
            }
            default: {
                const double k = std::exp(unit(rng) * 4.0);
                a = {k * (unit(rng) * 1.5 - 0.5), k * (unit(rng) * 1.5 - 0.5),
                     k * (unit(rng) * 1.5 - 0.5)};
                b = {k * (unit(rng) * 1.5 - 0.5), k * unit(rng), k * unit(rng)};
                for (double& v : a) v = std::max(v, -0.5);
                for (double& v : b) v = std::max(v, -0.5);
            }
        }
        Vec3 prev = a;
        Lab lp = w.lab(a);
        for (int i = 1; i <= steps; ++i) {
            const double t = static_cast<double>(i) / steps;
            const Vec3 c{a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]),
                         a[2] + t * (b[2] - a[2])};
            const Lab lc = w.lab(c);
            if (delta_e_2000(lp, lc) > allowed_step) {
                // Bisect toward the larger half of the change, 60 halvings (to 1e-18 of the step).
                Vec3 lo = prev, hi = c;
                Lab llo = lp, lhi = lc;
                for (int it = 0; it < 60; ++it) {
                    const Vec3 m{(lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, (lo[2] + hi[2]) / 2};
                    const Lab lm = w.lab(m);
                    if (delta_e_2000(llo, lm) >= delta_e_2000(lm, lhi)) {
                        hi = m;
                        lhi = lm;
                    } else {
                        lo = m;
                        llo = lm;
                    }
                }
                const double jump = delta_e_2000(llo, lhi);
                if (jump > allowed_step) {
                    result.largest = std::max(result.largest, jump);
                    switch (classify(w, lo, hi)) {
                        case Seam::black: ++result.black; break;
                        case Seam::reach_switch: ++result.reach_switch; break;
                        case Seam::other:
                            ++result.other;
                            if (jump > result.largest_other) {
                                result.largest_other = jump;
                                result.other_example =
                                    "ΔE2000 " + std::to_string(jump) + " between ACES2065-1 (" +
                                    std::to_string(lo[0]) + ", " + std::to_string(lo[1]) + ", " +
                                    std::to_string(lo[2]) + ") and its neighbour";
                            }
                    }
                }
            }
            prev = c;
            lp = lc;
        }
    }
    return result;
}

TEST(Aces2Continuity, EveryJumpAboveDeltaE1IsASeamThePublishedAlgorithmForces) {
    int total_black = 0, total_reach = 0;
    double largest = 0.0;
    for (const Aces2DisplaySpec& spec : aces2_displays()) {
        const WalkResult r = walk(spec, 300);
        EXPECT_EQ(r.other, 0) << spec.name << ": " << r.other_example;
        total_black += r.black;
        total_reach += r.reach_switch;
        largest = std::max(largest, r.largest);
        // At 100 cd/m² nothing jumps at all.
        if (spec.peak_nits == 100.0) {
            EXPECT_EQ(r.black + r.reach_switch, 0) << spec.name;
        }
        std::printf("%-40s black %d reach switch %d largest %.2f\n", spec.name.c_str(), r.black,
                    r.reach_switch, r.largest);
    }
    std::printf("all displays: black %d, reach switch %d, largest ΔE2000 %.2f\n", total_black,
                total_reach, largest);
}

}  // namespace
}  // namespace irid

namespace irid {
namespace {

// OpenColorIO's hue search (Aces2Rendering::hue_interval) changes interval at whole degrees of
// hue where its window misses the hue's own, and extrapolates there: the gamut compression
// steps across those degrees. Each whole degree is walked at 64 pairs of J and M, and a degree
// where that finds a step again at every J from 0.2 to 0.999 of the peak's by 0.01 and M from
// 10 to 500 by 5: the steps stay below ΔE2000 0.75 (docs/DISPLAY.md gives 0.69) unless they move
// a colour across the reach switch, and there are none on the displays up to 108 cd/m².
TEST(Aces2Continuity, OpenColorIOsHueSearchStepsOnlySlightlyAtWholeDegrees) {
    int steps = 0;
    double largest_step = 0.0;
    std::string largest_where;
    for (const Aces2DisplaySpec& spec : aces2_displays()) {
        const Aces2Output out(spec);
        const Aces2Rendering& r = out.rendering();
        const double peak = spec.peak_nits / 100.0;
        const Mat3 to_xyz = rgb_to_xyz_matrix(spec.limiting, spec.limiting_white);
        const Vec3 w = to_xyz * Vec3{peak, peak, peak};
        const Xyz white{w[0], w[1], w[2]};
        const auto lab = [&](const Aces2Jmh& jmh) {
            Vec3 rgb = r.limiting_model().jmh_to_rgb(jmh);
            for (double& v : rgb) v = std::clamp(v, 0.0, peak);
            const Vec3 x = to_xyz * rgb;
            return xyz_to_lab({x[0], x[1], x[2]}, white);
        };
        // The step across `degree` at (J, M), 0 across the reach switch.
        const auto step_at = [&](int degree, double j, double m) {
            const Aces2Jmh below = r.gamut_compress_forward({j * r.limit_j_max(), m, degree - 1e-9});
            const Aces2Jmh above = r.gamut_compress_forward({j * r.limit_j_max(), m, degree + 1e-9});
            if (below.M == m || above.M == m) return 0.0;
            return delta_e_2000(lab(below), lab(above));
        };
        int display_steps = 0;
        for (int degree = 1; degree < 360; ++degree) {
            double step = 0.0;
            for (const double j : {0.3, 0.5, 0.7, 0.8, 0.85, 0.9, 0.95, 0.99})
                for (const double m : {20.0, 50.0, 100.0, 150.0, 200.0, 250.0, 300.0, 400.0})
                    step = std::max(step, step_at(degree, j, m));
            if (step <= 1e-6) continue;
            ++display_steps;
            for (int jk = 20; jk <= 100; ++jk)
                for (int mk = 2; mk <= 100; ++mk)
                    step = std::max(step, step_at(degree, std::min(jk * 0.01, 0.999), mk * 5.0));
            if (step > largest_step) largest_step = step, largest_where = spec.name + " at " + std::to_string(degree) + "°";
            EXPECT_LE(step, 0.75) << spec.name << " at " << degree << "°";
        }
        if (spec.peak_nits * spec.linear_scale <= 108.0) {
            EXPECT_EQ(display_steps, 0) << spec.name;
        }
        steps += display_steps;
    }
    std::printf("steps at whole degrees: %d, largest ΔE2000 %.3f (%s)\n", steps, largest_step, largest_where.c_str());
}

}  // namespace
}  // namespace irid
