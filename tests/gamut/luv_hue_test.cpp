// luv-hue, the nearest in-gamut colour in ΔE*uv within the colour's CIELUV hue plane (Smits 1990,
// Figure 11 bottom), against a dense search written here independently: at each of 4001
// lightnesses the largest in-gamut chroma of the hue by bisection on "inside the cube", and the
// nearest of those points. luv-hue must never be farther than the dense search (beyond rounding),
// at every lightness: near black, bright, above the white's and with negative luminance.

#include <irid/color/difference.h>
#include <irid/color/rgb.h>
#include <irid/color/spaces.h>
#include <irid/gamut/clip.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace irid {
namespace {

struct Slice {
    const Gamut& gamut;
    Xyz white;
    Luv luv(const Rgb& c) const {
        const Xyz x = gamut.space().to_xyz(c);
        return xyz_to_luv(x, white);
    }
    Rgb rgb(const Luv& c) const { return gamut.space().from_xyz(luv_to_xyz(c, white)); }
};

/// The squared ΔE*uv from `in` to the nearest point of its hue plane inside the cube, by a dense
/// search over L* (4001 values) of the largest in-gamut chroma (bisection) at each.
double dense_distance2(const Slice& s, const Luv& in) {
    const double c0 = std::hypot(in.u, in.v);
    const double du = in.u / c0, dv = in.v / c0;
    const double max = s.gamut.max();
    const double tol = 1e-12 * max;
    const auto inside = [&](double L, double C) {
        const Rgb c = s.rgb({L, C * du, C * dv});
        return c.r >= -tol && c.g >= -tol && c.b >= -tol && c.r <= max + tol && c.g <= max + tol &&
               c.b <= max + tol;
    };
    double best = std::numeric_limits<double>::infinity();
    constexpr int steps = 4000;
    // L* = 0 is black whatever (u*, v*) say (they are 13 L* (u' − u'n)): its only chroma is 0.
    best = in.L * in.L + c0 * c0;
    for (int k = 1; k <= steps; ++k) {
        const double L = 100.0 * k / steps;
        double lo = 0.0, hi = c0;
        if (inside(L, c0)) {
            lo = c0;
        } else if (!inside(L, 0.0)) {
            continue;
        } else {
            for (int it = 0; it < 60; ++it) {
                const double mid = 0.5 * (lo + hi);
                (inside(L, mid) ? lo : hi) = mid;
            }
        }
        best = std::min(best, (L - in.L) * (L - in.L) + (c0 - lo) * (c0 - lo));
    }
    return best;
}

TEST(LuvHue, NeverFartherThanADenseSearchAtAnyLightness) {
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (const auto& [space, max] : {std::pair{&srgb(), 1.0}, std::pair{&rec2020(), 1.0}, std::pair{&srgb(), 100.0}}) {
        const Gamut gamut(*space, max);
        const GamutClipper clipper(ClipMethod::luv_hue, gamut);
        const Slice s{gamut, space->to_xyz({max, max, max})};
        int checked = 0;
        for (int k = 0; k < 120; ++k) {
            // Bright ([-1, 4.5]³), near black (±0.004) and beyond the white (up to 3 × max).
            const int family = k % 3;
            const double lo = family == 0 ? -1.0 : family == 1 ? -0.002 : 0.5;
            const double hi = family == 0 ? 4.5 : family == 1 ? 0.004 : 3.0;
            const Rgb c{max * (lo + (hi - lo) * u(rng)), max * (lo + (hi - lo) * u(rng)),
                        max * (lo + (hi - lo) * u(rng))};
            if (gamut.contains(c)) continue;
            const Xyz x = space->to_xyz(c);
            if (!(x.X + 15.0 * x.Y + 3.0 * x.Z > 0.0)) continue;  // no chromaticity: another rule
            const Luv in = s.luv(c);
            if (!(std::hypot(in.u, in.v) > 1e-9)) continue;
            const Rgb out = clipper.clip(c);
            ASSERT_TRUE(gamut.contains(out));
            const Luv o = s.luv(out);
            const double got = (o.L - in.L) * (o.L - in.L) +
                               (std::hypot(in.u, in.v) - std::hypot(o.u, o.v)) *
                                   (std::hypot(in.u, in.v) - std::hypot(o.u, o.v));
            const double dense = dense_distance2(s, in);
            EXPECT_LE(std::sqrt(got), std::sqrt(dense) + 1e-6 * (1.0 + std::sqrt(dense)))
                << space->name() << " max " << max << ": (" << c.r << ", " << c.g << ", " << c.b
                << ") → (" << out.r << ", " << out.g << ", " << out.b << ")";
            // Its hue is the colour's (a grey output has none).
            if (std::hypot(o.u, o.v) > 1e-6) {
                EXPECT_NEAR(std::remainder(std::atan2(o.v, o.u) - std::atan2(in.v, in.u), 2 * M_PI), 0.0, 1e-6);
            }
            ++checked;
        }
        EXPECT_GT(checked, 60);
    }
}

// A colour brighter than the white keeps its hue and lands on the boundary (no white rule), and
// the issue 23 pair no longer jumps to white.
TEST(LuvHue, BrighterThanTheWhiteIsNotWhite) {
    const GamutClipper clipper(ClipMethod::luv_hue, Gamut(srgb()));
    const Rgb a = clipper.clip({0.8327, 0.7893, 3.5785});  // Y just below the white's
    const Rgb b = clipper.clip({0.8329, 0.7895, 3.5794});  // Y just above
    EXPECT_NEAR(a.r, b.r, 1e-3);
    EXPECT_NEAR(a.g, b.g, 1e-3);
    EXPECT_NEAR(a.b, b.b, 1e-3);
    EXPECT_LT(b.r, 0.2);
    EXPECT_NEAR(b.b, 1.0, 1e-9);
}

}  // namespace
}  // namespace irid
