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
