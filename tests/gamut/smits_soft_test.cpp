// smits-soft (smits_soft.cpp): constant-luminance soft compression toward the grey of equal
// luminance. Checked against its definition's invariants (luminance and direction kept, nothing
// inside the threshold moved, the boundary reached exactly at the limit and smits' answer
// beyond), the closed form of ACES' power curve at power 1, and round trips with the inverse.

#include <irid/color/rgb.h>
#include <irid/error.h>
#include <irid/gamut/clip.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <string>
#include <vector>

namespace irid {
namespace {

double luminance(const Gamut& g, const Rgb& c) {
    const Vec3& l = g.luminance_row();
    return l[0] * c.r + l[1] * c.g + l[2] * c.b;
}

/// The grey of c's luminance and c's relative distance r from it (1 on the cube's boundary).
struct Ray {
    double w, r;
};
Ray ray(const Gamut& g, const Rgb& c) {
    const Vec3& l = g.luminance_row();
    const double w = luminance(g, c) / (l[0] + l[1] + l[2]);
    const double max = g.max();
    double r = 0.0;
    for (const double v : {c.r, c.g, c.b})
        r = std::max(r, v > w ? (v - w) / (max - w) : (w - v) / w);
    return {w, r};
}

/// The point of relative distance `r` on the ray from the grey of level w toward direction d
/// (d of zero luminance), found by scaling: r is linear in the offset.
Rgb at_distance(const Gamut& g, double w, const Vec3& d, double r) {
    const Rgb unit{w + d[0], w + d[1], w + d[2]};
    const double k = r / ray(g, unit).r;
    return {w + k * d[0], w + k * d[1], w + k * d[2]};
}

/// Random directions of zero luminance (a colour minus its grey).
std::vector<Vec3> directions(const Gamut& g, int count, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    const Vec3& l = g.luminance_row();
    const double sum = l[0] + l[1] + l[2];
    std::vector<Vec3> out;
    while (static_cast<int>(out.size()) < count) {
        const Vec3 v{u(rng), u(rng), u(rng)};
        const double y = (l[0] * v[0] + l[1] * v[1] + l[2] * v[2]) / sum;
        const Vec3 d{v[0] - y, v[1] - y, v[2] - y};
        if (std::abs(d[0]) + std::abs(d[1]) + std::abs(d[2]) > 0.1) out.push_back(d);
    }
    return out;
}

TEST(SmitsSoft, KeepsLuminanceAndDirectionAndMovesNothingInsideTheThreshold) {
    for (const Gamut& gamut : {Gamut(srgb()), Gamut(rec2020()), Gamut(display_p3(), 4.0)}) {
        const GamutClipper clipper(ClipMethod::smits_soft, gamut);
        const double threshold = clipper.parameter("threshold");
        std::mt19937 rng(3);
        std::uniform_real_distribution<double> level(0.02, 0.98), dist(0.0, 3.0);
        int inside = 0, moved = 0;
        for (const Vec3& d : directions(gamut, 3000, 11)) {
            const double w = level(rng) * gamut.max();
            const Rgb c = at_distance(gamut, w, d, dist(rng));
            const Rgb o = clipper.clip(c);
            const Ray rc = ray(gamut, c), ro = ray(gamut, o);
            if (rc.r <= threshold) {
                // Bitwise unchanged.
                EXPECT_EQ(o.r, c.r);
                EXPECT_EQ(o.g, c.g);
                EXPECT_EQ(o.b, c.b);
                ++inside;
                continue;
            }
            ++moved;
            EXPECT_NEAR(luminance(gamut, o), luminance(gamut, c), 1e-12 * gamut.max());
            EXPECT_TRUE(gamut.contains(o));
            // o − w = k (c − w) with 0 < k <= 1: the direction is kept.
            const Vec3 a{c.r - rc.w, c.g - rc.w, c.b - rc.w}, b{o.r - rc.w, o.g - rc.w, o.b - rc.w};
            const double k = (a[0] * b[0] + a[1] * b[1] + a[2] * b[2]) /
                             (a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
            EXPECT_GT(k, 0.0);
            EXPECT_LE(k, 1.0 + 1e-12);
            for (int i = 0; i < 3; ++i) EXPECT_NEAR(b[i], k * a[i], 1e-12 * gamut.max());
            // Compressed, never beyond the boundary, never below the threshold.
            EXPECT_LE(ro.r, std::min(rc.r, 1.0) + 1e-12);
            EXPECT_GE(ro.r, threshold - 1e-12);
        }
        EXPECT_GT(inside, 300);
        EXPECT_GT(moved, 1500);
    }
}

TEST(SmitsSoft, ReachesTheBoundaryExactlyAtTheLimitAndIsSmitsBeyond) {
    const Gamut gamut(srgb());
    const GamutClipper soft(ClipMethod::smits_soft, gamut);
    const GamutClipper smits(ClipMethod::smits, gamut);
    const double limit = soft.parameter("limit");
    for (const Vec3& d : directions(gamut, 500, 5)) {
        for (const double r : {limit, limit * 1.01, 2.0 * limit, 50.0}) {
            const Rgb c = at_distance(gamut, 0.4, d, r);
            const Rgb o = soft.clip(c), s = smits.clip(c);
            EXPECT_NEAR(ray(gamut, o).r, 1.0, 1e-12);
            EXPECT_NEAR(o.r, s.r, 1e-12);
            EXPECT_NEAR(o.g, s.g, 1e-12);
            EXPECT_NEAR(o.b, s.b, 1e-12);
        }
        // Just below the limit the colour is still strictly inside.
        EXPECT_LT(ray(gamut, soft.clip(at_distance(gamut, 0.4, d, 0.99 * limit))).r, 1.0);
    }
}

TEST(SmitsSoft, FollowsTheClosedFormOfTheCurveAtPowerOne) {
    // At power 1 ACES' curve is rational: f(r) = t + s x/(1 + x), x = (r − t)/s, with
    // s = (l − t)(1 − t)/(l − 1) (from f(l) = 1); e.g. t = 0.5, l = 2: s = 0.75 and
    // f(1.25) = 0.5 + 0.75 · 1/2 = 0.875.
    const Gamut gamut(srgb());
    const GamutClipper clipper(
        ClipMethod::smits_soft, gamut,
        ClipSettings{}.set("threshold", 0.5).set("limit", 2.0).set("power", 1.0));
    for (const Vec3& d : directions(gamut, 200, 9)) {
        EXPECT_NEAR(ray(gamut, clipper.clip(at_distance(gamut, 0.5, d, 1.25))).r, 0.875, 1e-12);
        for (const double r : {0.6, 0.9, 1.3, 1.9}) {
            const double x = (r - 0.5) / 0.75;
            EXPECT_NEAR(ray(gamut, clipper.clip(at_distance(gamut, 0.5, d, r))).r,
                        0.5 + 0.75 * x / (1.0 + x), 1e-12);
        }
    }
}

TEST(SmitsSoft, CurveIsContinuousIncreasingAndSmoothAtTheThreshold) {
    const Gamut gamut(rec2020());
    const GamutClipper clipper(ClipMethod::smits_soft, gamut);
    const double t = clipper.parameter("threshold"), l = clipper.parameter("limit");
    const Vec3 d = directions(gamut, 1, 21)[0];
    const auto f = [&](double r) {
        return ray(gamut, clipper.clip(at_distance(gamut, 0.3, d, r))).r;
    };
    double last = 0.0;
    for (int k = 1; k <= 2000; ++k) {
        const double r = 2.0 * l * k / 2000.0;
        const double v = f(r);
        EXPECT_GE(v, last - 1e-12) << r;
        last = v;
    }
    // Slope 1 on both sides of the threshold (ACES' curve has f'(t) = 1), below 1 after it.
    const double h = 1e-6;
    EXPECT_NEAR((f(t + h) - f(t)) / h, 1.0, 1e-4);
    EXPECT_NEAR((f(t) - f(t - h)) / h, 1.0, 1e-6);
    EXPECT_LT((f(0.5 * (t + l) + h) - f(0.5 * (t + l))) / h, 0.9);
    // Continuous at the limit: f(l − h) → 1.
    EXPECT_NEAR(f(l - h), 1.0, 1e-5);
}

TEST(SmitsSoft, InverseUndoesTheCompressionAndMapsTheBoundaryToTheLimit) {
    for (const Gamut& gamut : {Gamut(srgb()), Gamut(display_p3(), 4.0)}) {
        ClipSettings inverse_settings;
        inverse_settings.inverse = true;
        const GamutClipper forward(ClipMethod::smits_soft, gamut);
        const GamutClipper inverse(ClipMethod::smits_soft, gamut, inverse_settings);
        EXPECT_FALSE(inverse.confines_to_cube());
        EXPECT_TRUE(forward.confines_to_cube());
        const double limit = forward.parameter("limit");
        const double max = gamut.max();
        std::mt19937 rng(8);
        std::uniform_real_distribution<double> level(0.05, 0.95), frac(0.0, 0.999);
        for (const Vec3& d : directions(gamut, 1000, 13)) {
            const double w = level(rng) * max;
            // Forward then inverse: back where it was, for every r < limit.
            const Rgb c = at_distance(gamut, w, d, frac(rng) * limit);
            const Rgb back = inverse.clip(forward.clip(c));
            EXPECT_NEAR(back.r, c.r, 1e-9 * max);
            EXPECT_NEAR(back.g, c.g, 1e-9 * max);
            EXPECT_NEAR(back.b, c.b, 1e-9 * max);
            // Inverse then forward: every in-gamut colour off the boundary.
            const Rgb o = at_distance(gamut, w, d, frac(rng));
            const Rgb again = forward.clip(inverse.clip(o));
            EXPECT_NEAR(again.r, o.r, 1e-9 * max);
            EXPECT_NEAR(again.g, o.g, 1e-9 * max);
            EXPECT_NEAR(again.b, o.b, 1e-9 * max);
            // The boundary, and anything beyond it on the ray, goes to the limit.
            for (const double r : {1.0, 1.7, 30.0}) {
                EXPECT_NEAR(ray(gamut, inverse.clip(at_distance(gamut, w, d, r))).r, limit, 1e-9);
            }
        }
    }
}

TEST(SmitsSoft, BlackAndWhiteAndNonFiniteInputs) {
    const Gamut gamut(srgb(), 2.0);
    for (const bool inv : {false, true}) {
        ClipSettings s;
        s.inverse = inv;
        const GamutClipper clipper(ClipMethod::smits_soft, gamut, s);
        const Rgb black = clipper.clip({-0.5, 0.1, 0.1});  // Y < 0
        EXPECT_EQ(black.r + black.g + black.b, 0.0);
        const Rgb white = clipper.clip({3.0, 2.5, 2.2});  // grey above max
        EXPECT_EQ(white.r, 2.0);
        EXPECT_EQ(white.g, 2.0);
        EXPECT_EQ(white.b, 2.0);
        const Rgb grey = clipper.clip({0.7, 0.7, 0.7});
        EXPECT_EQ(grey.r, 0.7);
        const Rgb n = clipper.clip({std::nan(""), INFINITY, 0.2});
        EXPECT_TRUE(std::isfinite(n.r) && std::isfinite(n.g) && std::isfinite(n.b));
    }
}

TEST(SmitsSoft, InconsistentParametersThrowNamingThem) {
    // Each value is in its range, but ((1 − 0.9999)/(1000 − 0.9999))^−100 overflows.
    try {
        const GamutClipper c(
            ClipMethod::smits_soft, Gamut(srgb()),
            ClipSettings{}.set("threshold", 0.9999).set("limit", 1000.0).set("power", 100.0));
        FAIL() << "no throw";
    } catch (const Error& e) {
        const std::string m = e.what();
        EXPECT_NE(m.find("threshold"), std::string::npos) << m;
        EXPECT_NE(m.find("limit"), std::string::npos) << m;
        EXPECT_NE(m.find("power"), std::string::npos) << m;
    }
    EXPECT_THROW(
        GamutClipper(ClipMethod::smits_soft, Gamut(srgb()), ClipSettings{}.set("limit", 1.0)),
        Error);
    EXPECT_NO_THROW(GamutClipper(
        ClipMethod::smits_soft, Gamut(srgb()),
        ClipSettings{}.set("threshold", 0.0).set("limit", 1000.0).set("power", 100.0)));
}

}  // namespace
}  // namespace irid
