#pragma once

// Procedural noise for the thesis' textures (Smits 1990, Appendix A and eq. 27–30): the value
// noise of Perlin 1985 ("An Image Synthesizer", SIGGRAPH '85) as the thesis describes it, its
// analytic gradient (dnoise, for bump mapping) and turbulence (eq. 30); beside it Perlin 2002
// ("Improving Noise", SIGGRAPH '02) gradient noise with the same interface.
//
// Decisions:
// - Lattice values (ValueNoise): Perlin's seeded permutation table, as in Perlin 1985. P is a
//   permutation of 0..1023 (a Fisher–Yates shuffle driven by the SplitMix64 generator of Steele,
//   Lea and Flood 2014, "Fast Splittable Pseudorandom Number Generators", OOPSLA, seeded with
//   `seed`); the value at (i, j, k) is (P[P[P[i] + j] + k] + 1/2)/1024, indices modulo 1024:
//   uniform over the 1024 bin centres of [0, 1], so the field has period 1024 along each axis.
//   A table, not a 64-bit hash per lattice point: the 64 lattice values of one evaluation are
//   then 64 loads from a 20 KB table instead of 64 hash evaluations (~3× faster, see
//   bench/texture_bench.cpp). Integer arithmetic only, so a seed gives bit-identical values on
//   every run, compiler and thread.
// - The cubic: the interpolating Catmull–Rom spline, so the field passes through the lattice
//   values exactly (noise(i, j, k) == lattice_value(i, j, k)), as Perlin's and the thesis'
//   "values on the lattice, interpolated" say, and is C¹ (value and gradient continuous across
//   cell faces). The uniform cubic B-spline would stay inside [0, 1] and be C², but it does not
//   interpolate and it smooths the lattice away: its spatial standard deviation is 0.096
//   against Catmull–Rom's 0.212, less than half the contrast for the thesis' textures. The
//   price is overshoot, bounded as follows: per axis the negative weights w₀, w₃
//   sum to −t(1 − t)/2, at most 1/8 in magnitude (t = 1/2), the positive ones to 1 + t(1 − t)/2.
//   The worst case puts 1 where the product weight is positive and 0 where it is negative:
//   p³ + 3pn² with p = 9/8, n = 1/8 (the per-axis sums at t = 1/2), so every value lies in [−61/128, 189/128] =
//   [−0.4765625, 1.4765625] (the lower bound by the symmetry v → 1 − v). Random lattice values
//   come nowhere near the bounds (4·10⁶ random points stay within [−0.16, 1.15]); clamp where
//   a strict [0, 1] matters. The spatial mean is 1/2 and the spatial variance
//   (1/12)(57/70)³ ≈ 0.0450 (standard deviation ≈ 0.212), since ∫₀¹ Σᵢ wᵢ(t)² dt = 57/70 per
//   axis for the Catmull–Rom weights.
// - GradientNoise follows Perlin 2002: quintic fade 6t⁵ − 15t⁴ + 10t³, the 12 cube-edge
//   gradients (16-entry table, four repeated, as in Perlin's reference code), trilinear
//   blending of the 8 corner dot products. Its permutation of 0..255 is a Fisher–Yates shuffle
//   driven by the SplitMix64 generator seeded with `seed`, so the field has period 256 in each
//   of x, y and z. It is exactly 0 at lattice points, where its gradient is the lattice
//   gradient, and has mean 0. It is bounded by |n| ≤ 3/2: a corner contributes
//   |g·d| ≤ Σ_axes |d_axis|, and per axis the fade-weighted mean of |d_axis| over the corners,
//   (1 − s(u))u + s(u)(1 − u), is at most 1/2 (at u = 1/2). 4·10⁶ random points stay within
//   [−0.99, 1.0].
// - Turbulence is eq. 30 as written: turb(x) = Σ_{i=0}^{octaves−1} noise(2ⁱx)/2ⁱ; dturbulence
//   is its exact gradient Σ dnoise(2ⁱx). The hot functions are noexcept and check nothing:
//   octaves outside [0, max_octaves] are clamped (0 octaves is the empty sum, 0).
// - Coordinates: floor, not truncation, so negative coordinates continue the field without a
//   seam; lattice indices are clamped to ±2⁶², so large coordinates (|x| up to 10⁶ and far
//   beyond) cannot overflow. Non-finite coordinates give NaN.

#include <array>
#include <cstddef>
#include <cstdint>

namespace irid {

/// The gradient ∇noise = (∂/∂x, ∂/∂y, ∂/∂z) of a noise field [1/coordinate unit].
struct NoiseGradient {
    double x = 0, y = 0, z = 0;
};

/// The Catmull–Rom weights of the lattice values at −1, 0, 1, 2 for a cell fraction t ∈ [0, 1].
[[nodiscard]] std::array<double, 4> catmull_rom_weights(double t) noexcept;
/// d/dt of catmull_rom_weights(t).
[[nodiscard]] std::array<double, 4> catmull_rom_derivative_weights(double t) noexcept;

/// Perlin 1985 value noise as Smits 1990 Appendix A describes it: pseudo-random values in [0, 1] on the
/// integer lattice, interpolated with cubics over the 4×4×4 = 64 lattice points around the point.
/// The cubic is Catmull–Rom (see the file comment): values in [−61/128, 189/128], C¹.
class ValueNoise {
public:
    /// The period of the field along each axis (the size of the permutation).
    static constexpr std::size_t period = 1024;
    /// Entries of the stored permutation: repeated past `period` so that the 4×4×4 stencil's
    /// nested indices, at most (period − 1) + (period − 1) + 3, need no wrap.
    static constexpr std::size_t table_size = 2 * period + 2;
    /// Octaves above this are dropped by turbulence() and dturbulence().
    static constexpr int max_octaves = 30;

    explicit ValueNoise(std::uint64_t seed = 0);

    [[nodiscard]] double noise(double x, double y, double z) const noexcept;
    /// The analytic gradient of noise().
    [[nodiscard]] NoiseGradient dnoise(double x, double y, double z) const noexcept;
    /// Smits 1990 eq. 30: turb(x) = Σ_{i=0}^{octaves-1} noise(2^i x) / 2^i, default 7 octaves (i = 0..6).
    [[nodiscard]] double turbulence(double x, double y, double z, int octaves = 7) const noexcept;
    /// The analytic gradient of turbulence(): Σ_{i=0}^{octaves-1} dnoise(2^i x).
    [[nodiscard]] NoiseGradient dturbulence(double x, double y, double z,
                                            int octaves = 7) const noexcept;

    /// The pseudo-random value in [0, 1) at the lattice point (i, j, k).
    [[nodiscard]] double lattice_value(std::int64_t i, std::int64_t j,
                                       std::int64_t k) const noexcept;
    [[nodiscard]] std::uint64_t seed() const noexcept { return m_seed; }

private:
    std::uint64_t m_seed;
    /// The seeded permutation of 0..period−1 (Perlin 1985's table), repeated to table_size.
    std::array<std::uint16_t, table_size> m_perm;
    /// The lattice value of each entry, (m_perm[m] + 1/2)/period, read by the innermost index.
    std::array<double, table_size> m_value;
};

/// Perlin 2002 "Improving noise" gradient noise (quintic fade, 12 gradient directions, seeded
/// permutation of period 256). Values in [−3/2, 3/2], mean 0, 0 at every lattice point, C².
class GradientNoise {
public:
    /// The period of the field along each axis (the size of the permutation).
    static constexpr std::size_t period = 256;
    /// Octaves above this are dropped by turbulence() and dturbulence().
    static constexpr int max_octaves = 30;

    explicit GradientNoise(std::uint64_t seed = 0);

    [[nodiscard]] double noise(double x, double y, double z) const noexcept;
    [[nodiscard]] NoiseGradient dnoise(double x, double y, double z) const noexcept;
    /// Smits 1990 eq. 30 with this noise: Σ_{i=0}^{octaves-1} noise(2^i x) / 2^i.
    [[nodiscard]] double turbulence(double x, double y, double z, int octaves = 7) const noexcept;
    [[nodiscard]] NoiseGradient dturbulence(double x, double y, double z,
                                            int octaves = 7) const noexcept;

    /// The gradient of the lattice point (i, j, k): one of the 12 cube-edge directions.
    [[nodiscard]] NoiseGradient lattice_gradient(std::int64_t i, std::int64_t j,
                                                 std::int64_t k) const noexcept;
    [[nodiscard]] std::uint64_t seed() const noexcept { return m_seed; }

private:
    std::uint64_t m_seed;
    /// The permutation of 0..period−1, stored twice so p[p[X] + Y] needs no wrap (Perlin 2002).
    std::array<std::uint16_t, 2 * period> m_perm;
};

}  // namespace irid
