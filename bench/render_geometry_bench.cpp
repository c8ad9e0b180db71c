// Throughput of the renderer's ray-geometry queries, in rays per second.
//
// The mesh is TriangleMesh::uv_sphere(origin, radius 1, 200 slices, 51 stacks): 20 000
// triangles. The rays (4096, std::mt19937 with a fixed seed, built before the timed loops) start
// on a sphere of radius 3 about the origin and aim at uniform random points of the cube
// [-1.25, 1.25]³, so about two thirds of them hit the unit sphere; the hit fraction is reported
// as the counter "hit". A second set, "camera", holds the 64 × 64 primary rays of a Camera at
// (0, 0, 3) looking at the origin with a 45° field of view: coherent rays, as a renderer traces.
// One item is one ray.
//
// Baselines in the same binary, so that the ratios hold on a noisy machine:
//   BM_MeshBruteForce   TriangleMesh::intersect_brute_force, every triangle tested per ray (the
//                       same watertight triangle test the BVH uses): what the BVH saves. It
//                       traces the first 64 rays per iteration (20 000 triangle tests each);
//                       items/s compare with the others all the same.
//   BM_SphereAnalytic   Sphere::intersect on the same rays: the cost of the exact surface the
//                       mesh approximates.
// Then TriangleMesh::intersect (nearest hit through the BVH) and occluded() (any hit) on the
// random rays and on the camera rays, and the BVH build of the 20 000-triangle mesh (items are
// triangles).
//
// The queries live in another translation unit, so they cannot be folded away; each result
// feeds a hit count or a sum of distances passed through DoNotOptimize.

#include <irid/render/camera.h>
#include <irid/render/geometry.h>

#include <benchmark/benchmark.h>

#include <cstddef>
#include <cstdint>
#include <random>
#include <vector>

namespace {

using irid::render::Camera;
using irid::render::Ray;
using irid::render::Sphere;
using irid::render::SurfaceHit;
using irid::render::TriangleMesh;
using irid::render::Vec3;

constexpr std::uint32_t seed = 20240614;
constexpr std::size_t ray_count = 4096;
/// Rays per iteration of the brute-force baseline.
constexpr std::size_t brute_force_rays = 64;
constexpr int slices = 200;
constexpr int stacks = 51;  // 2 · 200 · 50 = 20 000 triangles
constexpr double t_min = 1e-9;
constexpr double t_max = 1e30;

const TriangleMesh& mesh() {
    static const TriangleMesh m = TriangleMesh::uv_sphere({0, 0, 0}, 1.0, slices, stacks);
    return m;
}

const std::vector<Ray>& random_rays() {
    static const std::vector<Ray> rays = [] {
        std::mt19937 rng(seed);
        std::normal_distribution<double> g(0.0, 1.0);
        std::uniform_real_distribution<double> cube(-1.25, 1.25);
        std::vector<Ray> r;
        r.reserve(ray_count);
        while (r.size() < ray_count) {
            const Vec3 dir{g(rng), g(rng), g(rng)};
            if (length(dir) < 1e-3) continue;
            const Vec3 origin = 3.0 * normalize(dir);
            const Vec3 target{cube(rng), cube(rng), cube(rng)};
            r.push_back({origin, normalize(target - origin)});
        }
        return r;
    }();
    return rays;
}

const std::vector<Ray>& camera_rays() {
    static const std::vector<Ray> rays = [] {
        const Camera cam({0, 0, 3}, {0, 0, 0}, {0, 1, 0}, 45.0, 1.0);
        std::vector<Ray> r;
        for (int y = 0; y < 64; ++y) {
            for (int x = 0; x < 64; ++x) r.push_back(cam.ray((x + 0.5) / 64, (y + 0.5) / 64));
        }
        return r;
    }();
    return rays;
}

/// Traces `count` rays of `rays` per iteration through query(ray, hit) -> bool; reports rays/s
/// and the fraction that hit.
template <class Query>
void trace(benchmark::State& state, const std::vector<Ray>& rays, std::size_t count, Query query) {
    std::int64_t hits = 0;
    double sum_t = 0.0;
    for (auto _ : state) {
        for (std::size_t i = 0; i < count; ++i) {
            SurfaceHit hit;
            if (query(rays[i], hit)) {
                ++hits;
                sum_t += hit.t;
            }
        }
        benchmark::DoNotOptimize(hits);
        benchmark::DoNotOptimize(sum_t);
    }
    const auto traced =
        static_cast<std::int64_t>(state.iterations()) * static_cast<std::int64_t>(count);
    state.SetItemsProcessed(traced);
    state.counters["hit"] =
        traced > 0 ? static_cast<double>(hits) / static_cast<double>(traced) : 0.0;
}

void BM_MeshBruteForce(benchmark::State& state) {
    const TriangleMesh& m = mesh();
    trace(state, random_rays(), brute_force_rays, [&](const Ray& r, SurfaceHit& hit) {
        return m.intersect_brute_force(r, t_min, t_max, hit);
    });
}
BENCHMARK(BM_MeshBruteForce);

void BM_SphereAnalytic(benchmark::State& state) {
    const Sphere s({0, 0, 0}, 1.0);
    trace(state, random_rays(), ray_count,
          [&](const Ray& r, SurfaceHit& hit) { return s.intersect(r, t_min, t_max, hit); });
}
BENCHMARK(BM_SphereAnalytic);

void BM_MeshBvhIntersect(benchmark::State& state) {
    const TriangleMesh& m = mesh();
    trace(state, random_rays(), ray_count,
          [&](const Ray& r, SurfaceHit& hit) { return m.intersect(r, t_min, t_max, hit); });
    state.counters["nodes"] = static_cast<double>(m.bvh_node_count());
    state.counters["depth"] = m.bvh_depth();
}
BENCHMARK(BM_MeshBvhIntersect);

void BM_MeshBvhOccluded(benchmark::State& state) {
    const TriangleMesh& m = mesh();
    trace(state, random_rays(), ray_count,
          [&](const Ray& r, SurfaceHit&) { return m.occluded(r, t_min, t_max); });
}
BENCHMARK(BM_MeshBvhOccluded);

void BM_MeshBvhIntersectCamera(benchmark::State& state) {
    const TriangleMesh& m = mesh();
    trace(state, camera_rays(), camera_rays().size(),
          [&](const Ray& r, SurfaceHit& hit) { return m.intersect(r, t_min, t_max, hit); });
}
BENCHMARK(BM_MeshBvhIntersectCamera);

void BM_SphereAnalyticCamera(benchmark::State& state) {
    const Sphere s({0, 0, 0}, 1.0);
    trace(state, camera_rays(), camera_rays().size(),
          [&](const Ray& r, SurfaceHit& hit) { return s.intersect(r, t_min, t_max, hit); });
}
BENCHMARK(BM_SphereAnalyticCamera);

void BM_MeshBvhBuild(benchmark::State& state) {
    const TriangleMesh& m = mesh();
    const std::vector<Vec3> positions = m.positions();
    const auto triangles = m.triangles();
    for (auto _ : state) {
        TriangleMesh built(positions, triangles);
        benchmark::DoNotOptimize(built.bvh_node_count());
    }
    state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) *
                            static_cast<std::int64_t>(triangles.size()));
}
BENCHMARK(BM_MeshBvhBuild)->Unit(benchmark::kMillisecond);

}  // namespace
