#pragma once

// Pieces shared by the two noise fields (private to irid_texture).

#include <irid/texture/noise.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <utility>

namespace irid::texture_detail {

/// SplitMix64's output function (Steele, Lea & Flood 2014, "Fast splittable pseudorandom number
/// generators", OOPSLA; the constants are Stafford's "Mix13"): a bijection of 64-bit words whose
/// every output bit depends on every input bit.
constexpr std::uint64_t mix64(std::uint64_t z) noexcept {
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
}

/// The SplitMix64 generator (same paper): a Weyl sequence of step 0x9e3779b97f4a7c15 (2^64
/// divided by the golden ratio, odd) passed through mix64. Period 2^64.
class SplitMix64 {
public:
    explicit constexpr SplitMix64(std::uint64_t seed) noexcept : m_state(seed) {}
    constexpr std::uint64_t next() noexcept {
        m_state += 0x9e3779b97f4a7c15ULL;
        return mix64(m_state);
    }
    /// Uniform on {0, ..., n − 1} for n ≥ 1, without modulo bias: draws below 2^64 mod n are
    /// rejected, so the accepted range is a whole number of copies of {0, ..., n − 1}.
    constexpr std::uint64_t below(std::uint64_t n) noexcept {
        const std::uint64_t threshold = (0 - n) % n;  // 2^64 mod n
        for (;;) {
            const std::uint64_t r = next();
            if (r >= threshold) return r % n;
        }
    }

private:
    std::uint64_t m_state;
};

/// A permutation of 0..N−1 repeated to `Length` entries (entry m is entry m mod N), so that
/// Perlin's nested index P[P[P[X] + Y] + Z] with X, Y, Z < N plus small offsets never needs a
/// wrap (2N entries allow an offset of 1, 2N + 2 an offset of 3). Fisher–Yates (Knuth's
/// Algorithm P): position i swaps with a uniform position in [0, i], drawn from the SplitMix64
/// generator seeded with `seed`.
template <std::size_t N, std::size_t Length = 2 * N>
std::array<std::uint16_t, Length> doubled_permutation(std::uint64_t seed) noexcept {
    static_assert(N >= 2 && N <= 65536 && (N & (N - 1)) == 0, "N must be a power of 2");
    static_assert(Length >= N, "the table must hold the permutation");
    std::array<std::uint16_t, N> p{};
    for (std::size_t i = 0; i < N; ++i) p[i] = static_cast<std::uint16_t>(i);
    SplitMix64 rng(seed);
    for (std::size_t i = N - 1; i > 0; --i) {
        const auto j = static_cast<std::size_t>(rng.below(i + 1));
        std::swap(p[i], p[j]);
    }
    std::array<std::uint16_t, Length> doubled{};
    for (std::size_t i = 0; i < Length; ++i) doubled[i] = p[i & (N - 1)];
    return doubled;
}

/// A lattice coordinate modulo N, a power of 2 (two's complement: correct for negative i).
template <std::size_t N>
std::size_t wrap(std::int64_t i) noexcept {
    return static_cast<std::size_t>(static_cast<std::uint64_t>(i) & (N - 1));
}

/// The Catmull–Rom weights of the lattice values at −1, 0, 1, 2 for t ∈ [0, 1] (Horner form;
/// exactly (0, 1, 0, 0) at t = 0).
inline std::array<double, 4> catmull_rom(double t) noexcept {
    return {0.5 * t * (t * (2.0 - t) - 1.0), 0.5 * (t * t * (3.0 * t - 5.0) + 2.0),
            0.5 * t * (t * (4.0 - 3.0 * t) + 1.0), 0.5 * t * t * (t - 1.0)};
}

/// d/dt of catmull_rom(t).
inline std::array<double, 4> catmull_rom_derivative(double t) noexcept {
    return {0.5 * (t * (4.0 - 3.0 * t) - 1.0), 0.5 * t * (9.0 * t - 10.0),
            0.5 * (t * (8.0 - 9.0 * t) + 1.0), 0.5 * t * (3.0 * t - 2.0)};
}

/// Lattice cell indices are clamped to ±2^62: far from overflowing an int64 when 2 is added,
/// and beyond 2^52 every double is an integer anyway.
inline constexpr double cell_limit = 0x1p62;

/// The lattice cell of a coordinate: floor(x) as an integer, clamped to ±cell_limit, and the
/// fraction x − floor(x) ∈ [0, 1) (exact: both have the exponent of x or less). NaN gives the
/// cell −2^62 and a NaN fraction, ±∞ a NaN fraction, so such coordinates give NaN noise and no
/// undefined conversion.
struct Cell {
    std::int64_t index;
    double fraction;
};

inline Cell cell_of(double x) noexcept {
    const double f = std::floor(x);
    const double clamped = f >= -cell_limit ? (f <= cell_limit ? f : cell_limit) : -cell_limit;
    return {static_cast<std::int64_t>(clamped), x - f};
}

/// Smits 1990, eq. 30, turb(p) = Σ_{i<octaves} noise(2^i p)/2^i, over any field with noise().
template <class Field>
double turbulence_sum(const Field& field, double x, double y, double z, int octaves) noexcept {
    octaves = std::clamp(octaves, 0, Field::max_octaves);
    double sum = 0.0;
    double scale = 1.0;  // 2^i: doubling is exact, so 2^i·x is exact too (short of overflow)
    for (int i = 0; i < octaves; ++i) {
        sum += field.noise(scale * x, scale * y, scale * z) / scale;
        scale *= 2.0;
    }
    return sum;
}

/// ∇turb(p) = Σ_{i<octaves} 2^i ∇noise(2^i p)/2^i = Σ ∇noise(2^i p).
template <class Field>
NoiseGradient turbulence_gradient_sum(const Field& field, double x, double y, double z,
                                      int octaves) noexcept {
    octaves = std::clamp(octaves, 0, Field::max_octaves);
    NoiseGradient sum;
    double scale = 1.0;
    for (int i = 0; i < octaves; ++i) {
        const NoiseGradient g = field.dnoise(scale * x, scale * y, scale * z);
        sum.x += g.x;
        sum.y += g.y;
        sum.z += g.z;
        scale *= 2.0;
    }
    return sum;
}

}  // namespace irid::texture_detail
