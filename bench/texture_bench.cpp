// Throughput of irid's procedural noise.
//
// One item is one evaluation at one point: noise, dnoise (value and gradient), turbulence and
// dturbulence (Smits 1990 eq. 30, 7 octaves, so 7 noise or dnoise calls per item), for the
// Catmull–Rom value noise (64 lattice points per call) and Perlin 2002 gradient noise (8
// corners). The points cycle through a precomputed array of 4096 pseudo-random points in
// [−100, 100)³ (std::mt19937_64, fixed seed, top 53 bits), so no result can be hoisted; the
// fields live in another translation unit, and every result goes through DoNotOptimize.
//
// Baselines in the same binary, so that the ratios hold on a noisy machine:
//   BM_SinProduct        sin x · sin y · sin z: the cheapest smooth "noise" a shader would
//                        write, three libm calls.
//   BM_LatticeValue      ValueNoise::lattice_value at the point's cell: one lattice value
//                        (three nested permutation-table lookups), of which noise() needs 64.

#include <irid/texture/noise.h>

#include <benchmark/benchmark.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <random>
#include <vector>

namespace {

constexpr std::uint64_t seed = 20240612;
/// Points cycled through, one per evaluation (a power of two: index & mask).
constexpr std::size_t point_count = 4096;
constexpr std::size_t point_mask = point_count - 1;

struct Point {
    double x, y, z;
};

const std::vector<Point>& points() {
    static const std::vector<Point> p = [] {
        std::mt19937_64 rng(seed);
        const auto uniform = [&rng] {
            return -100.0 + 200.0 * (static_cast<double>(rng() >> 11) * 0x1p-53);
        };
        std::vector<Point> v(point_count);
        for (Point& q : v) {
            q.x = uniform();
            q.y = uniform();
            q.z = uniform();
        }
        return v;
    }();
    return p;
}

void BM_SinProduct(benchmark::State& state) {
    const auto& p = points();
    std::size_t i = 0;
    for (auto _ : state) {
        const Point& q = p[i++ & point_mask];
        benchmark::DoNotOptimize(std::sin(q.x) * std::sin(q.y) * std::sin(q.z));
    }
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_SinProduct);

void BM_LatticeValue(benchmark::State& state) {
    const irid::ValueNoise field(seed);
    const auto& p = points();
    std::size_t i = 0;
    for (auto _ : state) {
        const Point& q = p[i++ & point_mask];
        benchmark::DoNotOptimize(field.lattice_value(static_cast<std::int64_t>(std::floor(q.x)),
                                                     static_cast<std::int64_t>(std::floor(q.y)),
                                                     static_cast<std::int64_t>(std::floor(q.z))));
    }
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_LatticeValue);

template <class Field>
void BM_Noise(benchmark::State& state) {
    const Field field(seed);
    const auto& p = points();
    std::size_t i = 0;
    for (auto _ : state) {
        const Point& q = p[i++ & point_mask];
        benchmark::DoNotOptimize(field.noise(q.x, q.y, q.z));
    }
    state.SetItemsProcessed(state.iterations());
}

template <class Field>
void BM_Dnoise(benchmark::State& state) {
    const Field field(seed);
    const auto& p = points();
    std::size_t i = 0;
    for (auto _ : state) {
        const Point& q = p[i++ & point_mask];
        benchmark::DoNotOptimize(field.dnoise(q.x, q.y, q.z));
    }
    state.SetItemsProcessed(state.iterations());
}

template <class Field>
void BM_Turbulence(benchmark::State& state) {
    const Field field(seed);
    const auto& p = points();
    std::size_t i = 0;
    for (auto _ : state) {
        const Point& q = p[i++ & point_mask];
        benchmark::DoNotOptimize(field.turbulence(q.x, q.y, q.z));
    }
    state.SetItemsProcessed(state.iterations());
}

template <class Field>
void BM_Dturbulence(benchmark::State& state) {
    const Field field(seed);
    const auto& p = points();
    std::size_t i = 0;
    for (auto _ : state) {
        const Point& q = p[i++ & point_mask];
        benchmark::DoNotOptimize(field.dturbulence(q.x, q.y, q.z));
    }
    state.SetItemsProcessed(state.iterations());
}

BENCHMARK(BM_Noise<irid::ValueNoise>);
BENCHMARK(BM_Dnoise<irid::ValueNoise>);
BENCHMARK(BM_Turbulence<irid::ValueNoise>);
BENCHMARK(BM_Dturbulence<irid::ValueNoise>);
BENCHMARK(BM_Noise<irid::GradientNoise>);
BENCHMARK(BM_Dnoise<irid::GradientNoise>);
BENCHMARK(BM_Turbulence<irid::GradientNoise>);
BENCHMARK(BM_Dturbulence<irid::GradientNoise>);

}  // namespace
