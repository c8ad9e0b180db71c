#include <irid/error.h>
#include <irid/render/geometry.h>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <numbers>
#include <random>
#include <string>
#include <vector>

namespace irid::render {
namespace {

constexpr double pi = std::numbers::pi;

/// The message of the irid::Error that f throws, or "" when it throws none.
template <class F>
std::string error_message(F&& f) {
    try {
        f();
    } catch (const Error& e) {
        return e.what();
    }
    return {};
}

void expect_near(Vec3 a, Vec3 b, double tol, const std::string& what = {}) {
    EXPECT_NEAR(a.x, b.x, tol) << what;
    EXPECT_NEAR(a.y, b.y, tol) << what;
    EXPECT_NEAR(a.z, b.z, tol) << what;
}

Vec3 random_unit(std::mt19937& rng) {
    std::normal_distribution<double> g(0.0, 1.0);
    while (true) {
        const Vec3 v{g(rng), g(rng), g(rng)};
        if (length(v) > 1e-6) return normalize(v);
    }
}

Vec3 random_point(std::mt19937& rng, double lo, double hi) {
    std::uniform_real_distribution<double> u(lo, hi);
    return {u(rng), u(rng), u(rng)};
}

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

// --- Triangles ------------------------------------------------------------------------------

TEST(TriangleMesh, BarycentricsPositionAndWindingNormal) {
    const Vec3 p0{1, 0, 0}, p1{0, 2, 0}, p2{0, 0, 3};
    const TriangleMesh mesh({p0, p1, p2}, {{0, 1, 2}});
    const Vec3 winding = normalize(cross(p1 - p0, p2 - p0));
    std::mt19937 rng(2);
    std::uniform_real_distribution<double> u01(0.0, 1.0);
    for (int i = 0; i < 500; ++i) {
        double b1 = u01(rng), b2 = u01(rng);
        if (b1 + b2 > 1.0) {
            b1 = 1.0 - b1;
            b2 = 1.0 - b2;
        }
        const Vec3 target = (1.0 - b1 - b2) * p0 + b1 * p1 + b2 * p2;
        const Vec3 d = random_unit(rng);
        const double dist = 2.0 + 3.0 * u01(rng);
        SurfaceHit hit;
        ASSERT_TRUE(mesh.intersect({target - dist * d, d}, 0.0, 100.0, hit));
        // Rounding of the ray's origin (~1e-16 × 5) moves the hit along the plane by that over
        // the cosine of incidence.
        const double tol = 1e-14 / std::abs(dot(d, winding));
        EXPECT_NEAR(hit.t, dist, tol);
        EXPECT_NEAR(hit.u, b1, tol);
        EXPECT_NEAR(hit.v, b2, tol);
        expect_near(hit.position, target, tol);
        // By winding, whichever side the ray comes from.
        expect_near(hit.normal, winding, 1e-15);
        EXPECT_EQ(hit.shading_normal, hit.normal);
        EXPECT_EQ(hit.primitive, 0);
    }
    SurfaceHit hit;
    // The triangle's plane is x + y/2 + z/3 = 1. This line meets it at about (−0.55, 1.45, 2.45),
    // outside the triangle (x = b0 < 0): miss.
    EXPECT_FALSE(mesh.intersect({{-1, 1, 2}, normalize({1, 1, 1})}, 0, 100, hit));
    // In the plane z = 0 and pointing away from it: misses. Toward it: hits at z = 2.1.
    EXPECT_FALSE(mesh.intersect({{0.2, 0.2, 5}, {0, 0, 1}}, 0, 100, hit));
    ASSERT_TRUE(mesh.intersect({{0.2, 0.2, 5}, {0, 0, -1}}, 0, 100, hit));
    EXPECT_NEAR(hit.t, 5.0 - 3.0 * (1.0 - 0.2 - 0.1), 1e-14);
}

TEST(TriangleMesh, InterpolatesVertexNormalsAndUvs) {
    const Vec3 p0{0, 0, 0}, p1{1, 0, 0}, p2{0, 1, 0};
    const Vec3 n0 = normalize({-1, -1, 1}), n1 = normalize({1, 0, 1}), n2{0, 3, 3};
    const TriangleMesh mesh({p0, p1, p2}, {{0, 1, 2}}, {n0, n1, n2},
                            {{{0.5, 0.5}}, {{1.0, 0.25}}, {{0.0, 1.0}}});
    const double b1 = 0.2, b2 = 0.5, b0 = 0.3;
    SurfaceHit hit;
    ASSERT_TRUE(mesh.intersect({{b1, b2, 2}, {0, 0, -1}}, 0, 100, hit));
    expect_near(hit.normal, {0, 0, 1}, 0.0);
    expect_near(hit.shading_normal, normalize(b0 * n0 + b1 * n1 + b2 * normalize(n2)), 1e-14);
    EXPECT_NEAR(hit.u, b0 * 0.5 + b1 * 1.0 + b2 * 0.0, 1e-14);
    EXPECT_NEAR(hit.v, b0 * 0.5 + b1 * 0.25 + b2 * 1.0, 1e-14);
    // At a vertex the shading normal is that vertex's (stored unit) normal.
    ASSERT_TRUE(mesh.intersect({{1, 0, 2}, {0, 0, -1}}, 0, 100, hit));
    expect_near(hit.shading_normal, n1, 1e-14);
    expect_near(mesh.normals()[2], normalize(n2), 1e-15);
}

TEST(TriangleMesh, IsWatertightAlongASharedEdge) {
    // A skew quad split along its diagonal p0–p2: rays through points a hair off the diagonal,
    // on both sides, all hit one of the two triangles, unless they see the fold edge-on (one
    // triangle from the front, the other from the back), when both triangles lie on one side of
    // the edge and a ray on the other side rightly misses.
    const Vec3 p0{0.1, -0.3, 0.2}, p1{1.3, 0.1, -0.4}, p2{1.1, 1.2, 0.3}, p3{-0.2, 0.9, 0.1};
    const TriangleMesh mesh({p0, p1, p2, p3}, {{0, 1, 2}, {0, 2, 3}});
    const Vec3 n1 = cross(p1 - p0, p2 - p0), n2 = cross(p2 - p0, p3 - p0);
    std::mt19937 rng(9);
    std::uniform_real_distribution<double> along(0.01, 0.99), off(-1e-13, 1e-13);
    const Vec3 side = normalize(cross(p2 - p0, n1));
    int misses = 0, tested = 0;
    for (int i = 0; i < 20000; ++i) {
        const Vec3 target = p0 + along(rng) * (p2 - p0) + off(rng) * side;
        const Vec3 d = random_unit(rng);
        if (!(dot(d, n1) * dot(d, n2) > 0.0)) continue;
        SurfaceHit hit;
        ++tested;
        if (!mesh.intersect({target - 3.0 * d, d}, 0.0, 100.0, hit)) ++misses;
    }
    EXPECT_GT(tested, 10000);
    EXPECT_EQ(misses, 0) << "of " << tested << " rays through the shared edge";
}

TEST(TriangleMesh, RejectsBadInput) {
    const std::vector<Vec3> p{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    EXPECT_NE(error_message([&] { TriangleMesh(p, {}); }).find("at least one triangle"),
              std::string::npos);
    EXPECT_NE(error_message([&] {
                  TriangleMesh(p, {{0, 1, 3}});
              }).find("triangles[0] index 3 is out of range; allowed 0 to 2"),
              std::string::npos);
    EXPECT_NE(error_message([&] {
                  TriangleMesh(p, {{0, -1, 2}});
              }).find("index -1"),
              std::string::npos);
    EXPECT_NE(error_message([&] {
                  TriangleMesh(p, {{0, 1, 2}}, {{0, 0, 1}});
              }).find("normals has 1 entries"),
              std::string::npos);
    EXPECT_NE(error_message([&] {
                  TriangleMesh(p, {{0, 1, 2}}, {{0, 0, 1}, {0, 0, 0}, {0, 0, 1}});
              }).find("normals[1] must be finite and non-zero"),
              std::string::npos);
    EXPECT_NE(error_message([&] {
                  TriangleMesh(p, {{0, 1, 2}}, {}, {{{0, 0}}});
              }).find("uvs has 1 entries"),
              std::string::npos);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    EXPECT_NE(error_message([&] {
                  TriangleMesh({{0, 0, 0}, {1, nan, 0}, {0, 1, 0}}, {{0, 1, 2}});
              }).find("positions[1] must be finite"),
              std::string::npos);
}

// --- The BVH against the brute-force loop -----------------------------------------------------

/// Random rays: half from random origins toward random points of the mesh's box (enlarged), half
/// with random origins and directions; and a random sub-range (t_min, t_max) for some of them.
struct RandomRay {
    Ray ray;
    double t_min, t_max;
};

std::vector<RandomRay> random_rays(const Aabb& box, int count, std::uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u01(0.0, 1.0);
    const Vec3 size = box.extent();
    const double scale = length(size);
    std::vector<RandomRay> rays;
    for (int i = 0; i < count; ++i) {
        const Vec3 o = box.centroid() + random_unit(rng) * (scale * (0.1 + 1.5 * u01(rng)));
        Vec3 d;
        if (i % 2 == 0) {
            const Vec3 target =
                box.lo + Vec3{u01(rng) * size.x, u01(rng) * size.y, u01(rng) * size.z};
            if (length(target - o) < 1e-9) continue;
            d = normalize(target - o);
        } else {
            d = random_unit(rng);
        }
        double t_min = 1e-9 * scale, t_max = std::numeric_limits<double>::infinity();
        if (i % 5 == 0) {
            t_min = u01(rng) * scale;
            t_max = t_min + u01(rng) * scale;
        }
        rays.push_back({{o, d}, t_min, t_max});
    }
    return rays;
}

/// BVH and brute force agree exactly (same t, same triangle, same hit record); occluded() agrees
/// with intersect(). Returns how many rays hit.
int expect_bvh_matches_brute_force(const TriangleMesh& mesh, const std::vector<RandomRay>& rays) {
    int hits = 0;
    for (std::size_t i = 0; i < rays.size(); ++i) {
        const RandomRay& r = rays[i];
        SurfaceHit bvh, brute;
        const bool a = mesh.intersect(r.ray, r.t_min, r.t_max, bvh);
        const bool b = mesh.intersect_brute_force(r.ray, r.t_min, r.t_max, brute);
        EXPECT_EQ(a, b) << "ray " << i;
        EXPECT_EQ(mesh.occluded(r.ray, r.t_min, r.t_max), b) << "ray " << i;
        if (!a || !b) continue;
        ++hits;
        EXPECT_EQ(bvh.t, brute.t) << "ray " << i;
        EXPECT_EQ(bvh.primitive, brute.primitive) << "ray " << i;
        EXPECT_EQ(bvh.u, brute.u) << "ray " << i;
        EXPECT_EQ(bvh.v, brute.v) << "ray " << i;
        EXPECT_EQ(bvh.normal, brute.normal) << "ray " << i;
        EXPECT_GT(bvh.t, r.t_min);
        EXPECT_LT(bvh.t, r.t_max);
        // Nothing nearer: a shadow ray up to just before the hit is unoccluded.
        EXPECT_FALSE(mesh.occluded(r.ray, r.t_min, bvh.t * (1.0 - 1e-12))) << "ray " << i;
    }
    return hits;
}

TEST(TriangleMeshBvh, AgreesWithBruteForceOnARandomTriangleSoup) {
    std::mt19937 rng(2024);
    std::uniform_real_distribution<double> size(0.01, 0.6);
    std::vector<Vec3> positions;
    std::vector<std::array<int, 3>> triangles;
    for (int i = 0; i < 3000; ++i) {
        const Vec3 c = random_point(rng, -4, 4);
        const double s = size(rng);
        const int base = static_cast<int>(positions.size());
        for (int k = 0; k < 3; ++k) positions.push_back(c + s * random_unit(rng));
        triangles.push_back({base, base + 1, base + 2});
    }
    const TriangleMesh mesh(positions, triangles);
    EXPECT_EQ(mesh.triangle_count(), 3000u);
    EXPECT_GT(mesh.bvh_node_count(), 3000u / 8);
    EXPECT_LT(mesh.bvh_depth(), 40);
    const Aabb b = mesh.bounds();
    for (const Vec3& p : positions) EXPECT_TRUE(b.contains(p));
    const int hits = expect_bvh_matches_brute_force(mesh, random_rays(b, 5000, 17));
    EXPECT_GT(hits, 1500);  // a test that mostly misses would prove little
}

TEST(TriangleMeshBvh, AgreesWithBruteForceOnATessellatedSphere) {
    const TriangleMesh mesh = TriangleMesh::uv_sphere({0.5, -1, 2}, 2.0, 64, 32);
    EXPECT_EQ(mesh.triangle_count(), 2u * 64 * 31);
    const int hits = expect_bvh_matches_brute_force(mesh, random_rays(mesh.bounds(), 5000, 23));
    EXPECT_GT(hits, 2000);
}

TEST(TriangleMeshBvh, CoincidentAndCoplanarTrianglesStillAgree) {
    // A grid of coplanar triangles with every triangle duplicated: equal-t ties everywhere, which
    // both searches must settle on the lowest index.
    std::vector<Vec3> positions;
    std::vector<std::array<int, 3>> triangles;
    const int n = 20;
    for (int j = 0; j <= n; ++j) {
        for (int i = 0; i <= n; ++i) positions.push_back({i * 0.1, j * 0.1, 0.0});
    }
    for (int j = 0; j < n; ++j) {
        for (int i = 0; i < n; ++i) {
            const int a = j * (n + 1) + i, b = a + 1, c = a + n + 2, d = a + n + 1;
            triangles.push_back({a, b, c});
            triangles.push_back({a, c, d});
            triangles.push_back({a, b, c});
        }
    }
    const TriangleMesh mesh(positions, triangles);
    std::mt19937 rng(31);
    std::uniform_real_distribution<double> u(-0.1, 2.1);
    std::vector<RandomRay> rays;
    for (int i = 0; i < 3000; ++i) {
        const Vec3 target{u(rng), u(rng), 0.0};
        Vec3 d = random_unit(rng);
        if (std::abs(d.z) < 0.1) d = normalize(d + Vec3{0, 0, 0.5});
        rays.push_back({{target - 2.0 * d, d}, 0.0, 10.0});
    }
    const int hits = expect_bvh_matches_brute_force(mesh, rays);
    EXPECT_GT(hits, 2000);
    for (const RandomRay& r : rays) {
        SurfaceHit hit;
        if (mesh.intersect(r.ray, r.t_min, r.t_max, hit)) {
            EXPECT_NE(hit.primitive % 3, 2);  // the duplicate never wins a tie
        }
    }
}

TEST(TriangleMeshBvh, ExponentiallySpacedTrianglesStayShallowAndExact) {
    // Triangles in the planes x = 2^k, k = 0..399: binned SAH peels off a few per level, so the
    // build reaches its depth limit and finishes with median splits. Rays along ±x from between
    // two planes must meet the next plane in their direction, at an exactly known distance.
    const int count = 400;
    std::vector<Vec3> positions;
    std::vector<std::array<int, 3>> triangles;
    for (int k = 0; k < count; ++k) {
        const double x = std::ldexp(1.0, k);
        positions.insert(positions.end(), {{x, -1, -1}, {x, 2, -1}, {x, -1, 2}});
        triangles.push_back({3 * k, 3 * k + 1, 3 * k + 2});
    }
    const TriangleMesh mesh(positions, triangles);
    EXPECT_GE(mesh.bvh_depth(), 48);
    EXPECT_LE(mesh.bvh_depth(), 48 + 10);
    std::vector<RandomRay> rays;
    for (int j = 0; j + 1 < count; ++j) {
        const Vec3 o{1.5 * std::ldexp(1.0, j), 0.1, 0.2};
        SurfaceHit hit;
        ASSERT_TRUE(mesh.intersect({o, {1, 0, 0}}, 0.0, 1e300, hit));
        EXPECT_EQ(hit.primitive, j + 1);
        EXPECT_EQ(hit.t, 0.5 * std::ldexp(1.0, j));
        ASSERT_TRUE(mesh.intersect({o, {-1, 0, 0}}, 0.0, 1e300, hit));
        EXPECT_EQ(hit.primitive, j);
        EXPECT_EQ(hit.t, 0.5 * std::ldexp(1.0, j));
        // Slightly oblique: a slope of at most 0.3 / 2^j drifts at most 0.15 before the next plane.
        const double slope = 0.1 * std::ldexp(1.0, -j);
        rays.push_back({{o, normalize({1, slope * (j % 7 - 3), slope * (j % 5 - 2)})}, 0.0, 1e300});
        // Steeper: these miss once the planes are far apart.
        rays.push_back({{o, normalize({-1, 1e-2 * (j % 3 - 1), 1e-2 * (j % 4 - 2)})}, 0.0, 1e300});
    }
    EXPECT_GT(expect_bvh_matches_brute_force(mesh, rays), count / 2);
}

TEST(TriangleMesh, UvSphereApproximatesTheSphereFromInsideIt) {
    const Vec3 c{1, 2, 3};
    const double r = 1.5;
    const int slices = 48, stacks = 24;
    const TriangleMesh mesh = TriangleMesh::uv_sphere(c, r, slices, stacks);
    for (std::size_t i = 0; i < mesh.positions().size(); ++i) {
        EXPECT_NEAR(length(mesh.positions()[i] - c), r, 1e-14);
        expect_near(mesh.normals()[i], (mesh.positions()[i] - c) / r, 1e-14);
    }
    const Sphere sphere(c, r);
    // Vertices lie on the sphere, so the mesh is inside it: radial rays from outside meet the
    // mesh no sooner than the sphere and no later than the sagitta r (1 − cos α) of the largest
    // triangle's angular half-size α ≤ (2π/slices + π/stacks)/2.
    const double alpha = 0.5 * (2.0 * pi / slices + pi / stacks);
    const double sagitta = r * (1.0 - std::cos(alpha));
    std::mt19937 rng(4);
    for (int i = 0; i < 2000; ++i) {
        const Vec3 out = random_unit(rng);
        const Ray ray{c + 5.0 * out, -out};
        SurfaceHit m, s;
        ASSERT_TRUE(mesh.intersect(ray, 0.0, 100.0, m));
        ASSERT_TRUE(sphere.intersect(ray, 0.0, 100.0, s));
        EXPECT_GE(m.t, s.t - 1e-12);
        EXPECT_LE(m.t - s.t, sagitta);
        EXPECT_GT(dot(m.normal, out), std::cos(2.0 * alpha));  // outward winding
        EXPECT_GT(dot(m.shading_normal, out), std::cos(alpha));
        // The interpolated uv follows Sphere's convention to within a triangle.
        EXPECT_NEAR(m.v, s.v, 1.0 / stacks);
        double du = std::abs(m.u - s.u);
        du = std::min(du, 1.0 - du);  // across the seam
        EXPECT_LT(du, 1.0 / slices + 1e-12);
    }
    EXPECT_NE(error_message([] {
                  (void)TriangleMesh::uv_sphere({0, 0, 0}, 1.0, 2, 5);
              }).find("slices 2 and stacks 5 must be >= 3 and >= 2"),
              std::string::npos);
}

TEST(TriangleMesh, TransformedMovesHitsAndMirroringKeepsNormalsOutward) {
    const TriangleMesh unit = TriangleMesh::uv_sphere({0, 0, 0}, 1.0, 32, 16);
    const Transform t = Transform::scale({2, 1, 0.5}).then(Transform::translate({10, 0, 0}));
    const TriangleMesh ellipsoid = unit.transformed(t);
    EXPECT_EQ(ellipsoid.triangle_count(), unit.triangle_count());
    SurfaceHit hit;
    ASSERT_TRUE(ellipsoid.intersect({{0, 0, 0}, {1, 0, 0}}, 0.0, 100.0, hit));
    EXPECT_NEAR(hit.t, 8.0, 1e-12);  // the vertex at (−2, 0, 0) + (10, 0, 0)
    expect_near(hit.shading_normal, {-1, 0, 0}, 1e-12);
    EXPECT_GT(dot(hit.normal, Vec3{-1, 0, 0}), 0.9);
    // A mirror: winding normals still point outward, and agree with the vertex normals.
    const TriangleMesh mirrored = unit.transformed(Transform::scale({-1, 1, 1}));
    std::mt19937 rng(8);
    for (int i = 0; i < 200; ++i) {
        const Vec3 out = random_unit(rng);
        ASSERT_TRUE(mirrored.intersect({5.0 * out, -out}, 0.0, 100.0, hit));
        EXPECT_GT(dot(hit.normal, out), 0.8);
        EXPECT_GT(dot(hit.normal, hit.shading_normal), 0.8);
    }
}

}  // namespace
}  // namespace irid::render
