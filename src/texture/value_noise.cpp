#include <irid/texture/noise.h>

#include "noise_internal.h"

#include <array>
#include <cstddef>
#include <cstdint>

namespace irid {
namespace {

using texture_detail::Cell;
using texture_detail::cell_of;

constexpr std::size_t period = ValueNoise::period;
using texture_detail::wrap;

/// The lattice value of permutation entry p: the centre of the p-th of `period` equal bins of
/// [0, 1], (p + 1/2)/period (exact in binary: period is a power of 2).
double value_of(std::uint16_t p) noexcept {
    constexpr double scale = 1.0 / static_cast<double>(period);
    return (static_cast<double>(p) + 0.5) * scale;
}

/// Perlin's nested permutation index down to the (x, y) column: for the four x coordinates
/// cell − 1 … cell + 2 and the four y coordinates, P[P[X + a] + Y + b], to which the z
/// coordinate is added last.
using Columns = std::array<std::array<std::size_t, 4>, 4>;

Columns columns(const std::array<std::uint16_t, ValueNoise::table_size>& p, const Cell& cx,
                const Cell& cy) noexcept {
    // The stencil starts at cell − 1, wrapped, so no index is negative; the largest index,
    // (period − 1) + (period − 1) + 3, is within the table of 2·period + 2 entries.
    const std::size_t X = wrap<period>(cx.index - 1), Y = wrap<period>(cy.index - 1);
    Columns c{};
    for (std::size_t a = 0; a < 4; ++a) {
        const std::size_t A = p[X + a] + Y;
        for (std::size_t b = 0; b < 4; ++b) c[a][b] = p[A + b];
    }
    return c;
}

}  // namespace

std::array<double, 4> catmull_rom_weights(double t) noexcept {
    return texture_detail::catmull_rom(t);
}

std::array<double, 4> catmull_rom_derivative_weights(double t) noexcept {
    return texture_detail::catmull_rom_derivative(t);
}

ValueNoise::ValueNoise(std::uint64_t seed)
    : m_seed(seed),
      m_perm(texture_detail::doubled_permutation<period, table_size>(seed)),
      m_value{} {
    for (std::size_t m = 0; m < table_size; ++m) m_value[m] = value_of(m_perm[m]);
}

double ValueNoise::lattice_value(std::int64_t i, std::int64_t j, std::int64_t k) const noexcept {
    const std::size_t A = m_perm[wrap<period>(i)] + wrap<period>(j);
    return m_value[m_perm[A] + wrap<period>(k)];
}

double ValueNoise::noise(double x, double y, double z) const noexcept {
    const Cell cx = cell_of(x), cy = cell_of(y), cz = cell_of(z);
    const Columns col = columns(m_perm, cx, cy);
    const std::size_t Z = wrap<period>(cz.index - 1);
    const auto wx = texture_detail::catmull_rom(cx.fraction);
    const auto wy = texture_detail::catmull_rom(cy.fraction);
    const auto wz = texture_detail::catmull_rom(cz.fraction);
    // The 64-term tensor sum, contracted along z, then y, then x.
    double sum = 0.0;
    for (std::size_t a = 0; a < 4; ++a) {
        double sum_yz = 0.0;
        for (std::size_t b = 0; b < 4; ++b) {
            const double* v = &m_value[col[a][b] + Z];
            double sum_z = 0.0;
            for (std::size_t c = 0; c < 4; ++c) sum_z += wz[c] * v[c];
            sum_yz += wy[b] * sum_z;
        }
        sum += wx[a] * sum_yz;
    }
    return sum;
}

NoiseGradient ValueNoise::dnoise(double x, double y, double z) const noexcept {
    const Cell cx = cell_of(x), cy = cell_of(y), cz = cell_of(z);
    const Columns col = columns(m_perm, cx, cy);
    const std::size_t Z = wrap<period>(cz.index - 1);
    const auto wx = texture_detail::catmull_rom(cx.fraction);
    const auto wy = texture_detail::catmull_rom(cy.fraction);
    const auto wz = texture_detail::catmull_rom(cz.fraction);
    const auto dx = texture_detail::catmull_rom_derivative(cx.fraction);
    const auto dy = texture_detail::catmull_rom_derivative(cy.fraction);
    const auto dz = texture_detail::catmull_rom_derivative(cz.fraction);
    // ∂/∂x Σ wx wy wz v = Σ dx wy wz v, and so on: the same contraction carrying, after each
    // axis, the value and its derivative along the axes contracted so far.
    NoiseGradient g;
    for (std::size_t a = 0; a < 4; ++a) {
        double s = 0.0, s_y = 0.0, s_z = 0.0;  // Σ over (b, c) of wy wz v, dy wz v, wy dz v
        for (std::size_t b = 0; b < 4; ++b) {
            const double* v = &m_value[col[a][b] + Z];
            double t = 0.0, t_z = 0.0;  // Σ over c of wz v and dz v
            for (std::size_t c = 0; c < 4; ++c) {
                const double value = v[c];
                t += wz[c] * value;
                t_z += dz[c] * value;
            }
            s += wy[b] * t;
            s_y += dy[b] * t;
            s_z += wy[b] * t_z;
        }
        g.x += dx[a] * s;
        g.y += wx[a] * s_y;
        g.z += wx[a] * s_z;
    }
    return g;
}

double ValueNoise::turbulence(double x, double y, double z, int octaves) const noexcept {
    return texture_detail::turbulence_sum(*this, x, y, z, octaves);
}

NoiseGradient ValueNoise::dturbulence(double x, double y, double z, int octaves) const noexcept {
    return texture_detail::turbulence_gradient_sum(*this, x, y, z, octaves);
}

}  // namespace irid
