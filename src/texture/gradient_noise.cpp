#include <irid/texture/noise.h>

#include "noise_internal.h"

#include <array>
#include <cstddef>
#include <cstdint>

namespace irid {
namespace {

using texture_detail::Cell;
using texture_detail::cell_of;

/// Perlin 2002's gradients, indexed by the low 4 bits of the hash: the 12 vectors from the
/// centre of a cube to its edges' midpoints, and (1, 1, 0), (0, −1, 1), (−1, 1, 0), (0, −1, −1)
/// a second time to make 16 (the cases 12–15 of his grad()).
struct Gradient {
    double x, y, z;
};
constexpr std::array<Gradient, 16> gradients{{
    {1, 1, 0}, {-1, 1, 0}, {1, -1, 0}, {-1, -1, 0},  //
    {1, 0, 1}, {-1, 0, 1}, {1, 0, -1}, {-1, 0, -1},  //
    {0, 1, 1}, {0, -1, 1}, {0, 1, -1}, {0, -1, -1},  //
    {1, 1, 0}, {0, -1, 1}, {-1, 1, 0}, {0, -1, -1},  //
}};

constexpr std::size_t period_mask = GradientNoise::period - 1;
static_assert((GradientNoise::period & period_mask) == 0, "the period must be a power of 2");

/// The lattice coordinate modulo the period (two's complement: correct for negative indices).
std::size_t wrap(std::int64_t i) noexcept {
    return static_cast<std::size_t>(static_cast<std::uint64_t>(i) & period_mask);
}

/// Perlin 2002's fade 6t⁵ − 15t⁴ + 10t³ and its derivative 30t²(t − 1)².
double fade(double t) noexcept {
    return t * t * t * (t * (t * 6.0 - 15.0) + 10.0);
}
double fade_derivative(double t) noexcept {
    const double s = t * (t - 1.0);
    return 30.0 * s * s;
}

double lerp(double t, double a, double b) noexcept {
    return a + t * (b - a);
}

}  // namespace

GradientNoise::GradientNoise(std::uint64_t seed)
    : m_seed(seed), m_perm(texture_detail::doubled_permutation<period>(seed)) {}

NoiseGradient GradientNoise::lattice_gradient(std::int64_t i, std::int64_t j,
                                              std::int64_t k) const noexcept {
    const std::size_t h = m_perm[m_perm[m_perm[wrap(i)] + wrap(j)] + wrap(k)];
    const Gradient& g = gradients[h & 15];
    return {g.x, g.y, g.z};
}

namespace {

/// The eight corners of a cell: their gradients, and the corner values g·(p − corner).
struct Corners {
    std::array<const Gradient*, 8> g;  // index bit 0: x + 1, bit 1: y + 1, bit 2: z + 1
    std::array<double, 8> n;
};

Corners corners(const std::array<std::uint16_t, 2 * GradientNoise::period>& p, const Cell& cx,
                const Cell& cy, const Cell& cz) noexcept {
    const std::size_t X = wrap(cx.index), Y = wrap(cy.index), Z = wrap(cz.index);
    // Perlin's nested hash P[P[P[X] + Y] + Z], with the +1 of the far corners inside.
    const std::size_t A = p[X] + Y, B = p[X + 1] + Y;
    const std::size_t AA = p[A] + Z, AB = p[A + 1] + Z, BA = p[B] + Z, BB = p[B + 1] + Z;
    const std::array<std::size_t, 8> hash{p[AA],     p[BA],     p[AB],     p[BB],
                                          p[AA + 1], p[BA + 1], p[AB + 1], p[BB + 1]};
    Corners c{};
    const double fx = cx.fraction, fy = cy.fraction, fz = cz.fraction;
    for (std::size_t i = 0; i < 8; ++i) {
        const Gradient& g = gradients[hash[i] & 15];
        const double dx = (i & 1) != 0 ? fx - 1.0 : fx;
        const double dy = (i & 2) != 0 ? fy - 1.0 : fy;
        const double dz = (i & 4) != 0 ? fz - 1.0 : fz;
        c.g[i] = &g;
        c.n[i] = g.x * dx + g.y * dy + g.z * dz;
    }
    return c;
}

/// Trilinear interpolation of eight corner values (indexed as in Corners) at (u, v, w).
double trilinear(const std::array<double, 8>& c, double u, double v, double w) noexcept {
    return lerp(w, lerp(v, lerp(u, c[0], c[1]), lerp(u, c[2], c[3])),
                lerp(v, lerp(u, c[4], c[5]), lerp(u, c[6], c[7])));
}

}  // namespace

double GradientNoise::noise(double x, double y, double z) const noexcept {
    const Cell cx = cell_of(x), cy = cell_of(y), cz = cell_of(z);
    const Corners c = corners(m_perm, cx, cy, cz);
    return trilinear(c.n, fade(cx.fraction), fade(cy.fraction), fade(cz.fraction));
}

NoiseGradient GradientNoise::dnoise(double x, double y, double z) const noexcept {
    const Cell cx = cell_of(x), cy = cell_of(y), cz = cell_of(z);
    const Corners c = corners(m_perm, cx, cy, cz);
    const double u = fade(cx.fraction), v = fade(cy.fraction), w = fade(cz.fraction);
    const double du = fade_derivative(cx.fraction), dv = fade_derivative(cy.fraction),
                 dw = fade_derivative(cz.fraction);
    const auto& n = c.n;
    // noise = Σ W_c n_c with W_c the product of the fade weights (1 − u or u, ...), and
    // n_c = g_c·(p − c), so ∂noise/∂x = Σ (∂W_c/∂x) n_c + Σ W_c g_c.x: the fade's derivative
    // times the x-difference of the corner values interpolated in (v, w), plus the corner
    // gradients' x components interpolated in (u, v, w).
    std::array<double, 8> gx{}, gy{}, gz{};
    for (std::size_t i = 0; i < 8; ++i) {
        gx[i] = c.g[i]->x;
        gy[i] = c.g[i]->y;
        gz[i] = c.g[i]->z;
    }
    NoiseGradient g;
    g.x = du * lerp(w, lerp(v, n[1] - n[0], n[3] - n[2]), lerp(v, n[5] - n[4], n[7] - n[6])) +
          trilinear(gx, u, v, w);
    g.y = dv * lerp(w, lerp(u, n[2] - n[0], n[3] - n[1]), lerp(u, n[6] - n[4], n[7] - n[5])) +
          trilinear(gy, u, v, w);
    g.z = dw * lerp(v, lerp(u, n[4] - n[0], n[5] - n[1]), lerp(u, n[6] - n[2], n[7] - n[3])) +
          trilinear(gz, u, v, w);
    return g;
}

double GradientNoise::turbulence(double x, double y, double z, int octaves) const noexcept {
    return texture_detail::turbulence_sum(*this, x, y, z, octaves);
}

NoiseGradient GradientNoise::dturbulence(double x, double y, double z,
                                         int octaves) const noexcept {
    return texture_detail::turbulence_gradient_sum(*this, x, y, z, octaves);
}

}  // namespace irid
