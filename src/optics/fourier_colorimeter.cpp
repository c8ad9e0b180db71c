// FourierColorimeter: the transforms of the weighted matching functions (the band tables and
// the seven nodal tables of the slopes mode) that FourierFilm sums against, and the cache of
// them per colorimeter.

#include <irid/error.h>
#include <irid/optics/fine_sum.h>
#include <irid/optics/fourier_film.h>

#include <fmt/core.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <mutex>
#include <numbers>
#include <optional>
#include <tuple>
#include <utility>

namespace irid {
namespace {

using std::numbers::pi;

/// The wavenumbers [1/nm] over which the band centres are spread: 380–780 nm, where the matching
/// functions carry all but a few 1e-4 of their weight; the outer bands take the rest.
constexpr double nu_low = 1.0 / 780.0;
constexpr double nu_high = 1.0 / 380.0;
/// The width of each band's Gaussian relative to the spacing of the centres: wide enough that
/// neighbours overlap smoothly (the normalised partition has no steps), narrow enough that a
/// band's amplitudes are close to those at its centre.
constexpr double band_sigma_per_spacing = 0.6;
/// Phasors are recomputed exactly every this many steps of τ (the recurrence in between loses
/// about one ulp per step).
constexpr int reseed_every = 256;

}  // namespace

namespace {

/// Tabulates V_k(τ_j) = Σ_i c_i T_k(x_i) e^{2πi τ_j (ν_i − ν_c)}, τ_j = j h, for the moments
/// k = 0 .. moments − 1 (basis[k][i] = T_k(x_i)) and nodes j = 0 .. nodes − 1: row j holds, per
/// moment, x, y, z as real and imaginary parts. By a phasor per wavelength, advanced by one exact rotation per node
/// and recomputed every reseed_every nodes (so blocks of nodes are independent, built in
/// parallel; the result does not depend on the number of threads).
std::vector<double> tabulate(const std::array<double, dense_sample_count>& nu, double nu_c,
                             const std::array<std::array<double, dense_sample_count>, 3>& c,
                             const std::vector<std::array<double, dense_sample_count>>& basis, int moments,
                             double step, std::size_t nodes) {
    // Wavelengths whose weights are all 0 add nothing.
    std::vector<int> used;
    for (int i = 0; i < dense_sample_count; ++i) {
        if (c[0][i] != 0.0 || c[1][i] != 0.0 || c[2][i] != 0.0) used.push_back(i);
    }
    const std::size_t n = used.size(), width = 6 * static_cast<std::size_t>(moments);
    // coefficient[(k * 3 + ch) * n + u] = c_ch T_k at the u-th used wavelength.
    std::vector<double> coefficient(static_cast<std::size_t>(moments) * 3 * n), offset(n);
    for (std::size_t u = 0; u < n; ++u) {
        offset[u] = nu[used[u]] - nu_c;
        for (int k = 0; k < moments; ++k) {
            for (int ch = 0; ch < 3; ++ch) coefficient[(k * 3 + ch) * n + u] = c[ch][used[u]] * basis[k][used[u]];
        }
    }
    std::vector<double> table(nodes * width);
    const std::size_t blocks = (nodes + reseed_every - 1) / reseed_every;
    tbb::parallel_for(std::size_t{0}, blocks, [&](std::size_t block) {
        std::vector<double> re(n), im(n), step_re(n), step_im(n);
        const std::size_t first = block * reseed_every, last = std::min(nodes, first + reseed_every);
        for (std::size_t u = 0; u < n; ++u) {
            const double angle = 2.0 * pi * step * static_cast<double>(first) * offset[u];
            re[u] = std::cos(angle);
            im[u] = std::sin(angle);
            step_re[u] = std::cos(2.0 * pi * step * offset[u]);
            step_im[u] = std::sin(2.0 * pi * step * offset[u]);
        }
        for (std::size_t j = first; j < last; ++j) {
            double* row = &table[j * width];
            for (std::size_t kc = 0; kc < 3 * static_cast<std::size_t>(moments); ++kc) {
                const double* w = &coefficient[kc * n];
                double sr = 0.0, si = 0.0;
                for (std::size_t u = 0; u < n; ++u) {
                    sr += w[u] * re[u];
                    si += w[u] * im[u];
                }
                row[2 * kc] = sr;
                row[2 * kc + 1] = si;
            }
            for (std::size_t u = 0; u < n; ++u) {
                const double r = re[u] * step_re[u] - im[u] * step_im[u];
                im[u] = re[u] * step_im[u] + im[u] * step_re[u];
                re[u] = r;
            }
        }
    });
    return table;
}

/// The Lagrange polynomials of nodes xs at x, by the barycentric formula with weights bary (a
/// node of weight 0 takes no part); exact at a node.
template <std::size_t n>
std::array<double, n> lagrange_basis(const std::array<double, n>& xs, const std::array<double, n>& bary,
                                     double x) noexcept {
    std::array<double, n> l{};
    double total = 0.0;
    for (std::size_t j = 0; j < n; ++j) {
        if (bary[j] == 0.0) continue;
        if (std::abs(x - xs[j]) < 1e-13) {
            l.fill(0.0);
            l[j] = 1.0;
            return l;
        }
        l[j] = bary[j] / (x - xs[j]);
        total += l[j];
    }
    for (double& v : l) v /= total;
    return l;
}

/// A table in single precision (header: its rounding is far below the interpolation's).
std::vector<float> to_float(const std::vector<double>& t) {
    return {t.begin(), t.end()};
}

/// The largest |V| over channels of moment k at node j of a table of `width` numbers a node.
double magnitude(const std::vector<double>& t, std::size_t width, std::size_t j, int k) {
    double m = 0.0;
    for (int ch = 0; ch < 3; ++ch) {
        const std::size_t o = j * width + 6 * static_cast<std::size_t>(k) + 2 * ch;
        m = std::max(m, std::hypot(t[o], t[o + 1]));
    }
    return m;
}

/// envelope[j] = max over nodes from j × envelope_step_nm on, and channels, of |V_k|.
std::vector<double> envelope_of(const std::vector<double>& t, std::size_t width, std::size_t nodes, int k,
                                double step_nm, double envelope_step_nm) {
    const auto per_block = static_cast<std::size_t>(envelope_step_nm / step_nm);
    std::vector<double> e((nodes + per_block - 1) / per_block, 0.0);
    double running = 0.0;
    for (std::size_t j = nodes; j-- > 0;) {
        running = std::max(running, magnitude(t, width, j, k));
        if (j % per_block == 0) e[j / per_block] = running;
    }
    return e;
}

}  // namespace

FourierColorimeter::FourierColorimeter(const Colorimeter& colorimeter, int bands, bool slopes)
    : m_colorimeter(colorimeter), m_slopes(slopes) {
    if (bands < 1 || bands > max_bands) {
        throw Error(fmt::format("Fourier film colour: {} bands; allowed 1..{}", bands, max_bands));
    }
    std::array<double, dense_sample_count> nu{};
    for (int i = 0; i < dense_sample_count; ++i) nu[i] = 1.0 / DenseSpectrum::wavelength_nm(i);
    // The partition of unity: w_b(ν) = g_b(ν) / Σ_k g_k(ν), g_b a Gaussian about the b-th centre.
    std::vector<std::array<double, dense_sample_count>> share(bands);
    if (bands == 1) {
        share[0].fill(1.0);
    } else {
        const double spacing = (nu_high - nu_low) / (bands - 1);
        const double sigma = band_sigma_per_spacing * spacing;
        for (int i = 0; i < dense_sample_count; ++i) {
            double total = 0.0;
            for (int b = 0; b < bands; ++b) {
                const double u = (nu[i] - (nu_low + b * spacing)) / sigma;
                share[b][i] = std::exp(-0.5 * u * u);
                total += share[b][i];
            }
            // total > 0: the nearest centre is within a few spacings of every grid wavenumber.
            for (int b = 0; b < bands; ++b) share[b][i] /= total;
        }
    }
    const double half_spacing = bands == 1 ? 0.5 * (nu_high - nu_low) : 0.5 * (nu_high - nu_low) / (bands - 1);
    const DenseSpectrum* weights[3] = {&colorimeter.weight_x(), &colorimeter.weight_y(),
                                       &colorimeter.weight_z()};
    const double quiet_level = cut_tolerance * colorimeter.white().Y;
    const auto max_nodes = static_cast<std::size_t>(max_opd_cap_nm / step_nm) + 1;
    const auto max_node_rows = static_cast<std::size_t>(max_node_opd_nm / step_nm) + 1;
    const auto run_nodes = static_cast<std::size_t>(cut_run_nm / step_nm);
    m_bands.resize(bands);
    for (int b = 0; b < bands; ++b) {
        Band& band = m_bands[b];
        std::array<std::array<double, dense_sample_count>, 3> c{};
        double y_sum = 0.0, nu_y = 0.0;
        for (int i = 0; i < dense_sample_count; ++i) {
            for (int ch = 0; ch < 3; ++ch) c[ch][i] = share[b][i] * (*weights[ch])[i];
            y_sum += std::abs(c[1][i]);
            nu_y += std::abs(c[1][i]) * nu[i];
        }
        band.nu_c = y_sum > 0.0 ? nu_y / y_sum : 0.5 * (nu_low + nu_high);
        // The band's interval for the Chebyshev variable: 380–780 nm for one band (the weights
        // outside it are small enough that the interpolants may extrapolate there), for several
        // the centre ± 1.5 spacings (where a band's share has fallen to 4 % of its peak), within
        // 360–830 nm where materials are validated.
        const double low = std::max(bands == 1 ? nu_low : band.nu_c - 3.0 * half_spacing, 1.0 / lambda_max_nm);
        const double high = std::min(bands == 1 ? nu_high : band.nu_c + 3.0 * half_spacing, 1.0 / lambda_min_nm);
        band.mid = 0.5 * (low + high);
        band.half = 0.5 * (high - low);
        for (int i = 0; i < dense_sample_count; ++i) {
            band.white.X += c[0][i];
            band.white.Y += c[1][i];
            band.white.Z += c[2][i];
        }
        // V: to the cap, less a quiet run at the end (a narrow band's transform dies out).
        std::vector<std::array<double, dense_sample_count>> ones(1);
        ones[0].fill(1.0);
        const std::vector<double> v = tabulate(nu, band.nu_c, c, ones, 1, step_nm, max_nodes);
        std::size_t nodes = max_nodes, quiet = 0;
        for (std::size_t j = 0; j < max_nodes; ++j) {
            const double m = magnitude(v, 6, j, 0);
            band.bound = std::max(band.bound, m);
            quiet = m < quiet_level ? quiet + 1 : 0;
            if (quiet > run_nodes) {
                nodes = j - quiet + 2;
                break;
            }
        }
        for (std::size_t j = nodes > run_nodes ? nodes - run_nodes : 0; j < nodes; ++j) {
            band.floor = std::max(band.floor, magnitude(v, 6, j, 0));
        }
        band.nodes = nodes;
        band.table.assign(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(6 * nodes));
        band.envelope = envelope_of(v, 6, nodes, 0, step_nm, envelope_step_nm);
        if (!slopes) continue;
        // The nodal transforms U_j together, as far as the dispersive films' terms reach:
        // basis[j][i] = ℓ_j(x_i), x_i = (ν_i − mid) / half.
        std::array<double, node_count> xs{}, bary{};
        for (int j = 0; j < node_count; ++j) {
            xs[j] = node_x(j);
            // The barycentric weights of the Chebyshev points of the first kind (Berrut &
            // Trefethen 2004, eq. 5.3).
            bary[j] = (j % 2 == 0 ? 1.0 : -1.0) * std::sin((2 * j + 1) * pi / (2 * node_count));
        }
        std::vector<std::array<double, dense_sample_count>> basis(node_count);
        for (int i = 0; i < dense_sample_count; ++i) {
            const auto l = lagrange_basis<node_count>(xs, bary, (nu[i] - band.mid) / band.half);
            for (int j = 0; j < node_count; ++j) {
                basis[j][i] = l[j];
                band.node_white[j].X += c[0][i] * l[j];
                band.node_white[j].Y += c[1][i] * l[j];
                band.node_white[j].Z += c[2][i] * l[j];
            }
        }
        const std::size_t rows = std::min(nodes, max_node_rows);
        band.node_table = to_float(tabulate(nu, band.nu_c, c, basis, node_count, step_nm, rows));
        band.node_rows = rows;
        // Σ_j |U_j| per row (the largest channel of each), then its envelope from each τ on.
        constexpr std::size_t width = 6 * node_count;
        const auto per_block = static_cast<std::size_t>(envelope_step_nm / step_nm);
        band.node_envelope.assign((rows + per_block - 1) / per_block, 0.0);
        double running = 0.0;
        for (std::size_t r = rows; r-- > 0;) {
            double sum = 0.0;
            for (int k = 0; k < node_count; ++k) {
                double m = 0.0;
                for (int ch = 0; ch < 3; ++ch) {
                    const std::size_t o = r * width + 6 * static_cast<std::size_t>(k) + 2 * ch;
                    m = std::max(m, static_cast<double>(std::hypot(band.node_table[o], band.node_table[o + 1])));
                }
                sum += m;
            }
            running = std::max(running, sum);
            if (r % per_block == 0) band.node_envelope[r / per_block] = running;
        }
    }
    // The quadratures: the 1 nm sums of the Lagrange polynomials through the Chebyshev–Lobatto
    // nodes x_j = cos(jπ/128) over 360–830 nm (all of the grid lies inside, so the interpolant
    // never extrapolates), every 2^(4 − L)-th of them at level L, by the barycentric formula
    // (Berrut & Trefethen 2004, §5: weights (−1)^k, halved at the ends).
    const double mid = 0.5 * (1.0 / lambda_min_nm + 1.0 / lambda_max_nm);
    const double half = 0.5 * (1.0 / lambda_min_nm - 1.0 / lambda_max_nm);
    constexpr int last = quadrature_node_count - 1;
    std::array<double, quadrature_node_count> xs{};
    for (int j = 0; j <= last; ++j) {
        xs[j] = std::cos(j * pi / last);
        m_quadrature_nu[j] = mid + half * xs[j];
    }
    for (int level = 0; level < quadrature_levels; ++level) {
        // The level's nodes are every stride-th; the others get barycentric weight 0 and drop out.
        const int stride = 1 << (quadrature_levels - 1 - level);
        std::array<double, quadrature_node_count> bary{};
        for (int j = 0; j <= last; j += stride) {
            bary[j] = ((j / stride) % 2 == 0 ? 1.0 : -1.0) * (j == 0 || j == last ? 0.5 : 1.0);
        }
        std::array<Xyz, quadrature_node_count>& out = m_quadrature_weights[level];
        for (int i = 0; i < dense_sample_count; ++i) {
            const auto l = lagrange_basis<quadrature_node_count>(xs, bary, (nu[i] - mid) / half);
            for (int j = 0; j <= last; j += stride) {
                out[j].X += l[j] * (*weights[0])[i];
                out[j].Y += l[j] * (*weights[1])[i];
                out[j].Z += l[j] * (*weights[2])[i];
            }
        }
    }
}

double FourierColorimeter::node_x(int j) noexcept {
    static const auto x = [] {
        std::array<double, node_count> out{};
        for (int k = 0; k < node_count; ++k) out[k] = std::cos((2 * k + 1) * pi / (2 * node_count));
        return out;
    }();
    return x[j];
}

double FourierColorimeter::coefficient_matrix(int k, int j) noexcept {
    // The discrete Chebyshev transform on the nodes of the first kind: c_k = (2 − δ_k0)/N Σ_j
    // v_j T_k(x_j), T_k(x_j) = cos(k (2j + 1)π / 2N).
    return (k == 0 ? 1.0 : 2.0) / node_count * std::cos(k * (2 * j + 1) * pi / (2 * node_count));
}

namespace {

/// Linear interpolation of `count` transforms (6 numbers each) from a row-major table of
/// `stride` numbers per node, at node position u; zeros outside [0, nodes − 1).
template <std::size_t count>
std::array<FourierColorimeter::Transform, count> lookup(const std::vector<float>& t, std::size_t nodes,
                                                        std::size_t stride, double u) noexcept {
    std::array<FourierColorimeter::Transform, count> out{};
    if (!(u >= 0.0) || u >= static_cast<double>(nodes) - 1.0) return out;
    const auto j = static_cast<std::size_t>(u);
    const double f = u - static_cast<double>(j);
    const float* a = &t[j * stride];
    const float* c = a + stride;
    const auto at = [&](std::size_t k) {
        return static_cast<double>(a[k]) + f * (static_cast<double>(c[k]) - static_cast<double>(a[k]));
    };
    for (std::size_t n = 0; n < count; ++n) {
        const std::size_t o = 6 * n;
        out[n] = {{at(o), at(o + 1)}, {at(o + 2), at(o + 3)}, {at(o + 4), at(o + 5)}};
    }
    return out;
}

}  // namespace

FourierColorimeter::Transform FourierColorimeter::transform(int b, double tau_nm) const noexcept {
    const Band& band = m_bands[b];
    return lookup<1>(band.table, band.nodes, 6, tau_nm / step_nm)[0];
}

std::array<FourierColorimeter::Transform, FourierColorimeter::node_count> FourierColorimeter::node_transforms(
    int b, double tau_nm) const noexcept {
    const Band& band = m_bands[b];
    return lookup<node_count>(band.node_table, band.node_rows, 6 * node_count, tau_nm / step_nm);
}

FourierColorimeter::Transform FourierColorimeter::node_sum(
    int b, double tau_nm, const std::array<std::complex<double>, node_count>& values) const noexcept {
    const Band& band = m_bands[b];
    const double u = tau_nm / step_nm;
    Transform out{};
    if (!(u >= 0.0) || u >= static_cast<double>(band.node_rows) - 1.0) return out;
    const auto row = static_cast<std::size_t>(u);
    const double f = u - static_cast<double>(row);
    constexpr std::size_t width = 6 * node_count;
    const float* a = &band.node_table[row * width];
    const float* c = a + width;
    // The rows interpolated in double, each node's six numbers against its complex value.
    double acc[6] = {};
    for (std::size_t j = 0; j < node_count; ++j) {
        const double vr = values[j].real(), vi = values[j].imag();
        for (std::size_t ch = 0; ch < 3; ++ch) {
            const std::size_t o = 6 * j + 2 * ch;
            const double re = a[o] + f * (static_cast<double>(c[o]) - a[o]);
            const double im = a[o + 1] + f * (static_cast<double>(c[o + 1]) - a[o + 1]);
            acc[2 * ch] += vr * re - vi * im;
            acc[2 * ch + 1] += vr * im + vi * re;
        }
    }
    return {{acc[0], acc[1]}, {acc[2], acc[3]}, {acc[4], acc[5]}};
}

bool fourier_needs_slopes(const SingleFilm& film) noexcept {
    return !(film.ambient.is_constant() && film.film.is_constant() && film.substrate.is_constant());
}

std::shared_ptr<const FourierColorimeter> fourier_colorimeter_for(const SingleFilm& film,
                                                                  const Colorimeter& colorimeter) {
    const bool slopes = fourier_needs_slopes(film);
    const auto same = [&](const FourierColorimeter& f) {
        const Colorimeter& c = f.colorimeter();
        const auto equal = [](const DenseSpectrum& a, const DenseSpectrum& b) {
            return std::ranges::equal(a.values(), b.values());
        };
        // The same weights, and the same linear map to RGB (FourierFilm::color takes the kept
        // colorimeter's): equal on the three unit vectors.
        const auto same_rgb = [&](const Xyz& e) {
            const Rgb p = c.linear_rgb(e), q = colorimeter.linear_rgb(e);
            return p.r == q.r && p.g == q.g && p.b == q.b;
        };
        return f.slopes() == slopes && f.bands() == 1 && equal(c.weight_x(), colorimeter.weight_x()) &&
               equal(c.weight_y(), colorimeter.weight_y()) && equal(c.weight_z(), colorimeter.weight_z()) &&
               same_rgb({1.0, 0.0, 0.0}) && same_rgb({0.0, 1.0, 0.0}) && same_rgb({0.0, 0.0, 1.0});
    };
    // Most recently used first.
    static std::mutex mutex;
    static std::vector<std::shared_ptr<const FourierColorimeter>> recent;
    constexpr std::size_t kept = 4;
    {
        const std::lock_guard lock(mutex);
        const auto hit = std::find_if(recent.begin(), recent.end(), [&](const auto& f) { return same(*f); });
        if (hit != recent.end()) {
            std::rotate(recent.begin(), hit, hit + 1);
            return recent.front();
        }
    }
    // Built outside the lock (it runs on oneTBB's threads); two threads asking at once may both
    // build, and both results are correct.
    auto built = std::make_shared<const FourierColorimeter>(colorimeter, 1, slopes);
    const std::lock_guard lock(mutex);
    recent.insert(recent.begin(), built);
    if (recent.size() > kept) recent.pop_back();
    return built;
}

}  // namespace irid
