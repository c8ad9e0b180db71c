#include "geometry_test_util.h"

#include <irid/error.h>
#include <irid/render/geometry.h>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace irid::render {
namespace {

using namespace test;  // NOLINT(google-build-using-namespace): the tests' helpers

// --- Vectors --------------------------------------------------------------------------------

TEST(Vec3, ArithmeticAndProducts) {
    constexpr Vec3 a{1, 2, 3}, b{4, -5, 6};
    static_assert(dot(a, b) == 4 - 10 + 18);
    static_assert(a + b == Vec3{5, -3, 9});
    static_assert(a - b == Vec3{-3, 7, -3});
    static_assert(-a == Vec3{-1, -2, -3});
    static_assert(a * 2.0 == Vec3{2, 4, 6} && 2.0 * a == a * 2.0);
    static_assert(a / 2.0 == Vec3{0.5, 1, 1.5});
    static_assert(a * b == Vec3{4, -10, 18} && mul(a, b) == a * b);
    static_assert(cross(Vec3{1, 0, 0}, Vec3{0, 1, 0}) == Vec3{0, 0, 1});
    Vec3 c = a;
    c += b;
    EXPECT_EQ(c, (Vec3{5, -3, 9}));
    // The cross product is perpendicular to both factors, with |a × b|² = |a|²|b|² − (a·b)².
    const Vec3 x = cross(a, b);
    EXPECT_EQ(dot(x, a), 0.0);
    EXPECT_EQ(dot(x, b), 0.0);
    EXPECT_NEAR(dot(x, x), dot(a, a) * dot(b, b) - dot(a, b) * dot(a, b), 1e-12);
    EXPECT_NEAR(length(normalize(b)), 1.0, 1e-15);
    EXPECT_DOUBLE_EQ(length(Vec3{3, 4, 12}), 13.0);
}

TEST(Vec3, ReflectMirrorsAboutTheNormal) {
    const Vec3 n{0, 1, 0};
    EXPECT_EQ(reflect(Vec3{1, -1, 0}, n), (Vec3{1, 1, 0}));
    std::mt19937 rng(1);
    for (int i = 0; i < 100; ++i) {
        const Vec3 d = random_unit(rng), m = random_unit(rng);
        const Vec3 r = reflect(d, m);
        EXPECT_NEAR(length(r), 1.0, 1e-14);                        // length kept
        EXPECT_NEAR(dot(r, m), -dot(d, m), 1e-14);                 // normal component flipped
        expect_near(r - dot(r, m) * m, d - dot(d, m) * m, 1e-14);  // tangential kept
    }
}

// --- Aabb -----------------------------------------------------------------------------------

TEST(Aabb, SlabTestHitsMissesAndRespectsTheRange) {
    const Aabb box{{-1, -1, -1}, {1, 2, 3}};
    EXPECT_TRUE(box.intersect({{-5, 0, 0}, {1, 0, 0}}, 0.0, 100.0));
    EXPECT_FALSE(box.intersect({{-5, 0, 0}, {-1, 0, 0}}, 0.0, 100.0));  // pointing away
    EXPECT_FALSE(box.intersect({{-5, 0, 0}, {1, 0, 0}}, 0.0, 3.9));     // ends before it (t = 4)
    EXPECT_FALSE(box.intersect({{-5, 0, 0}, {1, 0, 0}}, 6.1, 100.0));   // starts after (t = 6)
    EXPECT_TRUE(box.intersect({{0, 0, 0}, {0, 0, 1}}, 0.0, 0.5));       // origin inside
    // Parallel to the x slabs: inside them hits, outside misses.
    EXPECT_TRUE(box.intersect({{0.5, -5, 0}, {0, 1, 0}}, 0.0, 100.0));
    EXPECT_FALSE(box.intersect({{1.5, -5, 0}, {0, 1, 0}}, 0.0, 100.0));
    // A diagonal ray in the plane z = 2.5 passing 0.001 outside the edge x = 1, y = 2 misses;
    // moved 0.001 inside, it hits.
    const Vec3 d = normalize({1, -1, 0});
    EXPECT_FALSE(box.intersect({Vec3{1, 2.001, 2.5} - 5.0 * d, d}, 0.0, 100.0));
    EXPECT_TRUE(box.intersect({Vec3{0.999, 1.999, 2.5} - 5.0 * d, d}, 0.0, 100.0));
    EXPECT_TRUE(Aabb{}.empty());
    EXPECT_EQ(Aabb{}.surface_area(), 0.0);
    EXPECT_DOUBLE_EQ(box.surface_area(), 2.0 * (2 * 3 + 3 * 4 + 4 * 2));
}

// --- Transform ------------------------------------------------------------------------------

TEST(Transform, QuarterTurnsMapAxesOntoAxesExactly) {
    const Transform rz = Transform::rotate_deg({0, 0, 1}, 90);
    EXPECT_EQ(rz.vector({1, 0, 0}), (Vec3{0, 1, 0}));  // counter-clockwise about +z
    EXPECT_EQ(rz.vector({0, 1, 0}), (Vec3{-1, 0, 0}));
    const Transform ry = Transform::rotate_deg({0, 2, 0}, 90);  // axis need not be unit
    EXPECT_EQ(ry.vector({0, 0, 1}), (Vec3{1, 0, 0}));
    EXPECT_EQ(ry.vector({1, 0, 0}), (Vec3{0, 0, -1}));
    EXPECT_EQ(Transform::rotate_deg({1, 0, 0}, 450).vector({0, 1, 0}), (Vec3{0, 0, 1}));
}

TEST(Transform, RotationPreservesLengthsAndAngles) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> deg(-720.0, 720.0);
    for (int i = 0; i < 200; ++i) {
        const Vec3 axis = random_unit(rng) * 3.0;
        const double angle = deg(rng);
        const Transform r = Transform::rotate_deg(axis, angle);
        const Vec3 a = random_point(rng, -10, 10), b = random_point(rng, -10, 10);
        EXPECT_NEAR(length(r.vector(a)), length(a), 1e-12 * length(a));
        EXPECT_NEAR(dot(r.vector(a), r.vector(b)), dot(a, b), 1e-11);
        EXPECT_NEAR(r.determinant(), 1.0, 1e-14);
        // The axis is fixed, and a perpendicular vector turns by the angle.
        expect_near(r.vector(axis), axis, 1e-13);
        const Vec3 k = normalize(axis);
        const Vec3 p = normalize(cross(k, random_unit(rng)));
        const double cos_expected = std::cos(angle * pi / 180.0);
        const double sin_expected = std::sin(angle * pi / 180.0);
        EXPECT_NEAR(dot(r.vector(p), p), cos_expected, 1e-12);
        EXPECT_NEAR(dot(r.vector(p), cross(k, p)), sin_expected, 1e-12);  // right-hand rule
    }
}

TEST(Transform, ThenAppliesThisFirst) {
    const Transform move = Transform::translate({1, 0, 0});
    const Transform turn = Transform::rotate_deg({0, 0, 1}, 90);
    // Move then turn: (0,0,0) → (1,0,0) → (0,1,0). Turn then move: (0,0,0) → (0,0,0) → (1,0,0).
    EXPECT_EQ(move.then(turn).point({0, 0, 0}), (Vec3{0, 1, 0}));
    EXPECT_EQ(turn.then(move).point({0, 0, 0}), (Vec3{1, 0, 0}));
    const Transform grow = Transform::scale({2, 3, 4});
    std::mt19937 rng(3);
    for (int i = 0; i < 50; ++i) {
        const Vec3 p = random_point(rng, -5, 5);
        const Transform all = grow.then(turn).then(move);
        expect_near(all.point(p), move.point(turn.point(grow.point(p))), 1e-13);
        expect_near(all.vector(p), turn.vector(grow.vector(p)), 1e-13);  // no translation
        expect_near(all.inverse().point(all.point(p)), p, 1e-13);
        expect_near(all.point(all.inverse().point(p)), p, 1e-13);
    }
}

TEST(Transform, NormalsStayPerpendicularUnderNonUniformScale) {
    const Transform t = Transform::scale({3, 0.5, -2})
                            .then(Transform::rotate_deg({1, 1, 0}, 37))
                            .then(Transform::translate({4, 5, 6}));
    std::mt19937 rng(11);
    double naive_worst = 0.0;
    for (int i = 0; i < 200; ++i) {
        const Vec3 n = random_unit(rng);
        const Vec3 tangent = normalize(cross(n, random_unit(rng)));  // ⟂ n
        const Vec3 tt = t.vector(tangent);
        const Vec3 nn = t.normal(n);
        EXPECT_NEAR(dot(normalize(tt), normalize(nn)), 0.0, 1e-13);
        // Transforming the normal like a vector would not do: the test can tell.
        naive_worst = std::max(naive_worst, std::abs(dot(normalize(tt), normalize(t.vector(n)))));
    }
    EXPECT_GT(naive_worst, 0.3);
}

TEST(Transform, FactoriesRejectDegenerateParameters) {
    const double inf = std::numeric_limits<double>::infinity();
    EXPECT_NE(error_message([] {
                  (void)Transform::scale({1, 0, 1});
              }).find("non-zero"),
              std::string::npos);
    EXPECT_NE(error_message([] {
                  (void)Transform::rotate_deg({0, 0, 0}, 10);
              }).find("axis"),
              std::string::npos);
    EXPECT_NE(error_message([&] {
                  (void)Transform::rotate_deg({0, 1, 0}, inf);
              }).find("degrees"),
              std::string::npos);
    EXPECT_NE(error_message([&] {
                  (void)Transform::translate({inf, 0, 0});
              }).find("finite"),
              std::string::npos);
    EXPECT_NE(error_message([] {
                  (void)Transform::from_matrix({{{1, 2, 3}, {2, 4, 6}, {0, 0, 1}}}, {});
              }).find("invertible"),
              std::string::npos);
    const Transform m = Transform::from_matrix({{{2, 1, 0}, {0, 1, 0}, {1, 0, 3}}}, {1, 2, 3});
    expect_near(m.inverse().point(m.point({0.3, -0.7, 2})), {0.3, -0.7, 2}, 1e-14);
    EXPECT_DOUBLE_EQ(m.determinant(), 6.0);  // 2 (1·3 − 0·0) − 1 (0·3 − 0·1) + 0
}

// --- Sphere ---------------------------------------------------------------------------------

/// The two roots of |o + t d − c|² = r² for unit d, by the plain quadratic formula.
std::array<double, 2> sphere_roots(Vec3 o, Vec3 d, Vec3 c, double r) {
    const double b = dot(o - c, d);
    const double disc = b * b - (dot(o - c, o - c) - r * r);
    return {-b - std::sqrt(disc), -b + std::sqrt(disc)};
}

TEST(Sphere, OutsideHitsTheNearRootOfTheQuadratic) {
    const Vec3 c{1, 2, 3};
    const double r = 2.0;
    const Sphere s(c, r);
    std::mt19937 rng(5);
    int hits = 0;
    for (int i = 0; i < 1000; ++i) {
        const Vec3 o = c + random_unit(rng) * 10.0;
        // Aim at a random point within the sphere's bounding ball so that most rays hit.
        const Vec3 target = c + random_unit(rng) * 1.9;
        const Vec3 d = normalize(target - o);
        const auto roots = sphere_roots(o, d, c, r);
        SurfaceHit hit;
        ASSERT_TRUE(s.intersect({o, d}, 1e-9, 100.0, hit));
        ++hits;
        EXPECT_NEAR(hit.t, roots[0], 1e-12);
        EXPECT_NEAR(length(hit.position - c), r, 1e-12);
        expect_near(hit.normal, (hit.position - c) / r, 1e-12);
        EXPECT_LT(dot(hit.normal, d), 0.0);  // outward, facing the ray
        EXPECT_EQ(hit.shading_normal, hit.normal);
        EXPECT_EQ(hit.primitive, -1);
    }
    EXPECT_EQ(hits, 1000);
}

// --- Ellipsoid ------------------------------------------------------------------------------

TEST(Ellipsoid, HitsLieOnTheSurfaceWithTheGradientAsNormal) {
    const Vec3 c{0.5, -1, 2}, s{2.0, 0.5, 1.0};
    const Ellipsoid e(c, s);
    std::mt19937 rng(11);
    for (int i = 0; i < 1000; ++i) {
        const Vec3 o = c + random_unit(rng) * 8.0;
        // A point strictly inside: the ray enters, so the near root is the hit.
        const Vec3 u = random_unit(rng) * 0.9;
        const Vec3 target = c + Vec3{u.x * s.x, u.y * s.y, u.z * s.z};
        const Vec3 d = normalize(target - o);
        SurfaceHit hit;
        ASSERT_TRUE(e.intersect({o, d}, 1e-9, 100.0, hit));
        const Vec3 p = hit.position - c;
        // On the implicit surface.
        EXPECT_NEAR(p.x * p.x / (s.x * s.x) + p.y * p.y / (s.y * s.y) + p.z * p.z / (s.z * s.z), 1.0, 1e-10);
        // The normal is the implicit function's gradient (x/a², y/b², z/c²), unit, facing out.
        const Vec3 g = normalize(Vec3{p.x / (s.x * s.x), p.y / (s.y * s.y), p.z / (s.z * s.z)});
        expect_near(hit.normal, g, 1e-12);
        EXPECT_LT(dot(hit.normal, d), 0.0);
        // Nothing on the segment before the hit is inside (the near root).
        const Vec3 q = o + 0.5 * hit.t * d - c;
        EXPECT_GT(q.x * q.x / (s.x * s.x) + q.y * q.y / (s.y * s.y) + q.z * q.z / (s.z * s.z), 1.0);
    }
}

TEST(Ellipsoid, EqualAxesAreTheSphereAndMissesMiss) {
    const Vec3 c{1, 2, 3};
    const Ellipsoid e(c, {1.5, 1.5, 1.5});
    const Sphere sphere(c, 1.5);
    std::mt19937 rng(12);
    for (int i = 0; i < 200; ++i) {
        const Ray r{c + random_unit(rng) * 5.0, random_unit(rng)};
        SurfaceHit a, b;
        const bool hit_e = e.intersect(r, 1e-9, 100.0, a);
        ASSERT_EQ(hit_e, sphere.intersect(r, 1e-9, 100.0, b));
        if (hit_e) {
            EXPECT_NEAR(a.t, b.t, 1e-12);
            expect_near(a.normal, b.normal, 1e-12);
        }
    }
    // A ray passing above the top of a flat ellipsoid misses it.
    SurfaceHit h;
    EXPECT_FALSE(Ellipsoid({0, 0, 0}, {2, 0.1, 1}).intersect({{-5, 0.11, 0}, {1, 0, 0}}, 0.0, 100.0, h));
    EXPECT_THROW(Ellipsoid({0, 0, 0}, {1, 0, 1}), irid::Error);
}

TEST(Sphere, InsideHitsTheFarRootWithAnOutwardNormal) {
    const Vec3 c{-3, 0.5, 7};
    const Sphere s(c, 1.5);
    std::mt19937 rng(6);
    for (int i = 0; i < 500; ++i) {
        const Vec3 o = c + random_point(rng, -0.8, 0.8);
        const Vec3 d = random_unit(rng);
        const auto roots = sphere_roots(o, d, c, 1.5);
        ASSERT_LT(roots[0], 0.0);
        SurfaceHit hit;
        ASSERT_TRUE(s.intersect({o, d}, 1e-9, 100.0, hit));
        EXPECT_NEAR(hit.t, roots[1], 1e-12);
        EXPECT_GT(dot(hit.normal, d), 0.0);  // outward: the ray leaves along it
    }
}

TEST(Sphere, MissTangentAndTheRangeLimits) {
    const Sphere s({0, 0, 0}, 1.0);
    SurfaceHit hit;
    // Passes at distance 1.000001: miss. At exactly 1: the tangent point, t = 5.
    EXPECT_FALSE(s.intersect({{-5, 1.000001, 0}, {1, 0, 0}}, 0.0, 100.0, hit));
    ASSERT_TRUE(s.intersect({{-5, 1, 0}, {1, 0, 0}}, 0.0, 100.0, hit));
    EXPECT_DOUBLE_EQ(hit.t, 5.0);
    expect_near(hit.position, {0, 1, 0}, 0.0);
    expect_near(hit.normal, {0, 1, 0}, 0.0);
    // Pointing away: miss.
    EXPECT_FALSE(s.intersect({{-5, 0, 0}, {-1, 0, 0}}, 0.0, 100.0, hit));
    // Roots at t = 4 and 6 along +x from (-5, 0, 0).
    const Ray ray{{-5, 0, 0}, {1, 0, 0}};
    ASSERT_TRUE(s.intersect(ray, 0.0, 100.0, hit));
    EXPECT_DOUBLE_EQ(hit.t, 4.0);
    ASSERT_TRUE(s.intersect(ray, 4.5, 100.0, hit));  // t_min beyond the near root
    EXPECT_DOUBLE_EQ(hit.t, 6.0);
    EXPECT_FALSE(s.intersect(ray, 0.0, 3.99, hit));   // t_max before the near root
    EXPECT_FALSE(s.intersect(ray, 6.0, 100.0, hit));  // the interval is open: (6, 100)
    EXPECT_FALSE(s.intersect(ray, 0.0, 4.0, hit));    // and (0, 4)
    ASSERT_TRUE(s.intersect(ray, 4.0, 6.5, hit));
    EXPECT_DOUBLE_EQ(hit.t, 6.0);
    EXPECT_FALSE(s.intersect(ray, 4.1, 5.9, hit));  // between the roots
}

TEST(Sphere, FarOriginsKeepTheirPrecision) {
    // 1e6 radii away, the plain formula b² − c loses ~12 digits; the result must still lie on
    // the sphere to 1e-9 of its radius.
    const Sphere s({0, 0, 0}, 1.0);
    SurfaceHit hit;
    ASSERT_TRUE(s.intersect({{-1e6, 0.5, 0.25}, {1, 0, 0}}, 0.0, 2e6, hit));
    EXPECT_NEAR(length(hit.position), 1.0, 1e-9);
    EXPECT_NEAR(hit.position.x, -std::sqrt(1.0 - 0.25 - 0.0625), 1e-9);
}

TEST(Sphere, UvAtThePolesEquatorAndAzimuths) {
    const Vec3 c{2, -1, 4};
    const double r = 3.0;
    const Sphere s(c, r);
    SurfaceHit hit;
    ASSERT_TRUE(s.intersect({c + Vec3{0, 10, 0}, {0, -1, 0}}, 0.0, 100.0, hit));  // top pole
    EXPECT_DOUBLE_EQ(hit.v, 1.0);
    ASSERT_TRUE(s.intersect({c + Vec3{0, -10, 0}, {0, 1, 0}}, 0.0, 100.0, hit));  // bottom
    EXPECT_DOUBLE_EQ(hit.v, 0.0);
    // The equator at four azimuths, right-handed about +y from +x: +x 0, −z 1/4, −x 1/2, +z 3/4.
    const std::array<Vec3, 4> dirs{{{1, 0, 0}, {0, 0, -1}, {-1, 0, 0}, {0, 0, 1}}};
    for (int k = 0; k < 4; ++k) {
        const Vec3 out = dirs[static_cast<std::size_t>(k)];
        ASSERT_TRUE(s.intersect({c + 10.0 * out, -out}, 0.0, 100.0, hit));
        EXPECT_NEAR(hit.u, 0.25 * k, 1e-15) << k;
        EXPECT_NEAR(hit.v, 0.5, 1e-15) << k;
    }
    // Latitude 30° north: v = (1 + sin 30°)/2 = 0.75; u stays in [0, 1) just below +x.
    const Vec3 n{std::cos(pi / 6) * std::cos(-1e-12), std::sin(pi / 6),
                 -std::cos(pi / 6) * std::sin(-1e-12)};
    ASSERT_TRUE(s.intersect({c + 10.0 * n, -n}, 0.0, 100.0, hit));
    EXPECT_NEAR(hit.v, 0.75, 1e-12);
    EXPECT_GE(hit.u, 0.0);
    EXPECT_LT(hit.u, 1.0);
}

TEST(Sphere, RejectsBadParametersAndReportsItsBounds) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    EXPECT_NE(error_message([] {
                  Sphere({0, 0, 0}, 0.0);
              }).find("radius 0 must be finite and > 0"),
              std::string::npos);
    EXPECT_NE(error_message([] { Sphere({0, 0, 0}, -1.0); }).find("radius"), std::string::npos);
    EXPECT_NE(error_message([&] { Sphere({0, 0, 0}, nan); }).find("radius"), std::string::npos);
    EXPECT_NE(error_message([&] { Sphere({nan, 0, 0}, 1.0); }).find("center"), std::string::npos);
    const Sphere s({1, 2, 3}, 0.5);
    EXPECT_EQ(s.bounds().lo, (Vec3{0.5, 1.5, 2.5}));
    EXPECT_EQ(s.bounds().hi, (Vec3{1.5, 2.5, 3.5}));
    EXPECT_EQ(s.center(), (Vec3{1, 2, 3}));
    EXPECT_EQ(s.radius(), 0.5);
}

// --- Plane ----------------------------------------------------------------------------------

TEST(Plane, HitsAtTheDistanceWithTangentCoordinates) {
    // The ground y = 1, u along +x (given with a normal component that must be removed).
    const Plane ground({3, 1, -2}, {0, 2, 0}, {1, 0.5, 0});
    EXPECT_EQ(ground.normal(), (Vec3{0, 1, 0}));
    expect_near(ground.u_axis(), {1, 0, 0}, 1e-15);
    expect_near(ground.v_axis(), {0, 0, -1}, 1e-15);  // v = n × u
    SurfaceHit hit;
    const Vec3 d = normalize({1, -2, 2});  // from (0, 7, 0): reaches y = 1 after 6 / (2/3) = 9
    ASSERT_TRUE(ground.intersect({{0, 7, 0}, d}, 0.0, 100.0, hit));
    EXPECT_NEAR(hit.t, 9.0, 1e-14);
    expect_near(hit.position, {3, 1, 6}, 1e-14);
    EXPECT_EQ(hit.normal, (Vec3{0, 1, 0}));
    EXPECT_NEAR(hit.u, 0.0, 1e-14);   // (3,1,6) − (3,1,−2) = (0, 0, 8)
    EXPECT_NEAR(hit.v, -8.0, 1e-14);  // along v = −z
    // Two-sided: from below too, normal unchanged.
    ASSERT_TRUE(ground.intersect({{0, -1, 0}, {0, 1, 0}}, 0.0, 100.0, hit));
    EXPECT_DOUBLE_EQ(hit.t, 2.0);
    EXPECT_EQ(hit.normal, (Vec3{0, 1, 0}));
}

TEST(Plane, ParallelAndBackwardRaysMissAndTheRangeIsOpen) {
    const Plane p({0, 0, 0}, {0, 0, 1});
    SurfaceHit hit;
    EXPECT_FALSE(p.intersect({{0, 0, 1}, {1, 0, 0}}, 0.0, 100.0, hit));   // parallel, above
    EXPECT_FALSE(p.intersect({{0, 0, 0}, {0, 1, 0}}, -1.0, 100.0, hit));  // parallel, in it
    EXPECT_FALSE(p.intersect({{0, 0, 1}, {0, 0, 1}}, 0.0, 100.0, hit));   // pointing away
    EXPECT_FALSE(p.intersect({{0, 0, 1}, {0, 0, -1}}, 0.0, 1.0, hit));    // t = 1 not < 1
    EXPECT_TRUE(p.intersect({{0, 0, 1}, {0, 0, -1}}, 0.0, 1.0 + 1e-12, hit));
    EXPECT_FALSE(p.intersect({{0, 0, 1}, {0, 0, -1}}, 1.0, 2.0, hit));  // t = 1 not > 1
}

TEST(Plane, RejectsDegenerateAxes) {
    EXPECT_NE(error_message([] { Plane({0, 0, 0}, {0, 0, 0}); }).find("normal"), std::string::npos);
    EXPECT_NE(error_message([] {
                  Plane({0, 0, 0}, {1, 0, 0});
              }).find("parallel"),
              std::string::npos);  // default u_axis = +x
    EXPECT_NE(error_message([] {
                  Plane({0, 0, 0}, {0, 1, 0}, {0, 0, 0});
              }).find("u_axis"),
              std::string::npos);
    const double inf = std::numeric_limits<double>::infinity();
    EXPECT_NE(error_message([&] {
                  Plane({inf, 0, 0}, {0, 1, 0});
              }).find("point"),
              std::string::npos);
    EXPECT_NO_THROW(Plane({0, 0, 0}, {1, 0, 0}, {0, 0, 1}));
}

}  // namespace
}  // namespace irid::render
