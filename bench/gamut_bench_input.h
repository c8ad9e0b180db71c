#pragma once

// The input of the gamut benchmarks (gamut_bench.cpp, gamut_ocio_bench.cpp), shared so that
// every row of one run clips the same colours.
//
// Out-of-gamut colours of linear sRGB: uniform in [-0.5, 1.5]^3 (std::mt19937, fixed seed), each
// colour redrawn until at least one channel lies outside [0, 1]. Two sizes:
// - cache_colours = 2^20 colours: 12 MiB in and 12 MiB out, beyond the L2 (1 MiB per core here)
//   but inside a 32 MiB L3, so the rows show compute speed;
// - dram_colours = 2^24 colours: 192 MiB in and 192 MiB out, more than four times a 32 MiB L3,
//   so the rows show what main memory allows.
// The smaller buffer is the first cache_colours colours of the larger one.

#include <cstddef>
#include <cstdint>
#include <random>
#include <vector>

namespace irid_bench {

inline constexpr std::size_t cache_colours = std::size_t{1} << 20;
inline constexpr std::size_t dram_colours = std::size_t{1} << 24;
inline constexpr std::uint32_t input_seed = 20240613;

/// dram_colours interleaved float triples (3 × dram_colours floats), built on first use.
inline const std::vector<float>& input() {
    static const std::vector<float> in = [] {
        std::mt19937 rng(input_seed);
        std::uniform_real_distribution<float> d(-0.5f, 1.5f);
        const auto outside = [](float v) { return v < 0.0f || v > 1.0f; };
        std::vector<float> v(3 * dram_colours);
        for (std::size_t i = 0; i < dram_colours; ++i) {
            float r = 0.0f, g = 0.0f, b = 0.0f;
            do {
                r = d(rng);
                g = d(rng);
                b = d(rng);
            } while (!(outside(r) || outside(g) || outside(b)));
            v[3 * i] = r;
            v[3 * i + 1] = g;
            v[3 * i + 2] = b;
        }
        return v;
    }();
    return in;
}

}  // namespace irid_bench
