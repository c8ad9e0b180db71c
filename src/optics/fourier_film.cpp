#include <irid/error.h>
#include <irid/optics/fine_sum.h>
#include <irid/optics/fourier_film.h>

#include <fmt/core.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>
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

// --- FourierColorimeter -----------------------------------------------------------------------

namespace {

/// Tabulates V_k(τ_j) = Σ_i c_i (ν_i − ν_c)^k e^{2πi τ_j (ν_i − ν_c)}, τ_j = j h, for the
/// moments k = 0 .. moments − 1 and nodes j = 0 .. nodes − 1: row j holds, per moment, x, y, z as
/// real and imaginary parts. By a phasor per wavelength, advanced by one exact rotation per node
/// and recomputed every reseed_every nodes (so blocks of nodes are independent, built in
/// parallel; the result does not depend on the number of threads).
std::vector<double> tabulate(const std::array<double, dense_sample_count>& nu, double nu_c,
                             const std::array<std::array<double, dense_sample_count>, 3>& c, int moments,
                             double step, std::size_t nodes) {
    // Wavelengths whose weights are all 0 add nothing.
    std::vector<int> used;
    for (int i = 0; i < dense_sample_count; ++i) {
        if (c[0][i] != 0.0 || c[1][i] != 0.0 || c[2][i] != 0.0) used.push_back(i);
    }
    const std::size_t n = used.size(), width = 6 * static_cast<std::size_t>(moments);
    // coefficient[(k * 3 + ch) * n + u] = c_ch (ν − ν_c)^k at the u-th used wavelength.
    std::vector<double> coefficient(static_cast<std::size_t>(moments) * 3 * n), offset(n);
    for (std::size_t u = 0; u < n; ++u) {
        offset[u] = nu[used[u]] - nu_c;
        double power = 1.0;
        for (int k = 0; k < moments; ++k) {
            for (int ch = 0; ch < 3; ++ch) coefficient[(k * 3 + ch) * n + u] = c[ch][used[u]] * power;
            power *= offset[u];
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
    const auto max_moment_nodes = static_cast<std::size_t>(max_moment_opd_nm / step_nm) + 1;
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
        if (slopes) {
            // The band's reach: the wavenumbers its weights cover (380–780 nm for one band, the
            // centre ± half the spacing for several). The coefficients are sampled at the outer
            // Chebyshev nodes of that interval, mid ± cos(π/6) × half its width (a parabola
            // through them errs least over it), kept inside 360–830 nm where materials are
            // validated.
            const double low = bands == 1 ? nu_low : band.nu_c - half_spacing;
            const double high = bands == 1 ? nu_high : band.nu_c + half_spacing;
            const double mid = 0.5 * (low + high), half = 0.5 * (high - low);
            band.node_below = std::max(mid - std::cos(pi / 6.0) * half, 1.0 / lambda_max_nm) - band.nu_c;
            band.node_above = std::min(mid + std::cos(pi / 6.0) * half, 1.0 / lambda_min_nm) - band.nu_c;
            band.delta = std::max(band.nu_c - low, high - band.nu_c);
        }
        for (int i = 0; i < dense_sample_count; ++i) {
            double power = 1.0;
            for (int k = 0; k < moment_count; ++k) {
                band.moments[k].X += c[0][i] * power;
                band.moments[k].Y += c[1][i] * power;
                band.moments[k].Z += c[2][i] * power;
                power *= nu[i] - band.nu_c;
            }
        }
        // V: to the cap, less a quiet run at the end (a narrow band's transform dies out).
        const std::vector<double> v = tabulate(nu, band.nu_c, c, 1, step_nm, max_nodes);
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
        // V1 .. V4 together, as far as the dispersive films' terms reach.
        const std::size_t moment_nodes = std::min(nodes, max_moment_nodes);
        const std::vector<double> vm = tabulate(nu, band.nu_c, c, moment_count, step_nm, moment_nodes);
        constexpr std::size_t width = 6 * moment_count;
        band.moment_nodes = moment_nodes;
        band.moment_table.resize(moment_nodes * (width - 6));
        for (std::size_t j = 0; j < moment_nodes; ++j) {
            std::copy(vm.begin() + static_cast<std::ptrdiff_t>(j * width + 6),
                      vm.begin() + static_cast<std::ptrdiff_t>((j + 1) * width),
                      band.moment_table.begin() + static_cast<std::ptrdiff_t>(j * (width - 6)));
        }
        // The moments' envelope in units of the band's half-width: max_k |V_k| / δ^k.
        const auto per_block = static_cast<std::size_t>(envelope_step_nm / step_nm);
        band.moment_envelope.assign((moment_nodes + per_block - 1) / per_block, 0.0);
        double scale = 1.0;
        for (int k = 1; k < moment_count; ++k) {
            scale *= band.delta;
            const std::vector<double> e = envelope_of(vm, width, moment_nodes, k, step_nm, envelope_step_nm);
            for (std::size_t j = 0; j < e.size(); ++j) {
                band.moment_envelope[j] = std::max(band.moment_envelope[j], e[j] / scale);
            }
        }
    }
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

std::array<FourierColorimeter::Transform, FourierColorimeter::moment_count - 1> FourierColorimeter::moment_transforms(
    int b, double tau_nm) const noexcept {
    const Band& band = m_bands[b];
    return lookup<moment_count - 1>(band.moment_table, band.moment_nodes, 6 * (moment_count - 1), tau_nm / step_nm);
}

bool fourier_needs_slopes(const SingleFilm& film) noexcept {
    return !(film.ambient.is_constant() && film.film.is_constant() && film.substrate.is_constant());
}

std::shared_ptr<const FourierColorimeter> fourier_colorimeter_for(const SingleFilm& film,
                                                                  const Colorimeter& colorimeter) {
    return std::make_shared<const FourierColorimeter>(colorimeter, 1, fourier_needs_slopes(film));
}

// --- FourierFilm --------------------------------------------------------------------------------

FourierFilm::FourierFilm(const SingleFilm& film, std::shared_ptr<const FourierColorimeter> colorimeter)
    : m_film(film), m_colorimeter(std::move(colorimeter)) {
    if (!m_colorimeter) throw Error("Fourier film colour: no colorimeter");
    if (!film.ambient.is_lossless()) {
        throw Error("Fourier film colour: the ambient '" + film.ambient.name() +
                    "' absorbs (k > 0); the angle of incidence needs a lossless ambient");
    }
    if (!film.film.is_lossless()) {
        throw Error("Fourier film colour: the film '" + film.film.name() +
                    "' absorbs (k > 0); the series needs a lossless film (use the 1 nm sum)");
    }
    m_sum_only = !film.substrate.is_lossless() && !film.substrate.is_constant();
    const auto media_at = [&](double lambda) {
        return Media{film.ambient.index(lambda).real(), film.film.index(lambda).real(),
                     film.substrate.index(lambda)};
    };
    // Each band's media at its centre (and at ν_c ± δ); the slopes of the real indices by central
    // differences over ±0.5 nm (the materials are smooth on that scale: fits, or tables linear
    // between samples at least 5 nm apart).
    const int bands = m_colorimeter->bands();
    m_media.resize(bands);
    for (int b = 0; b < bands; ++b) {
        BandMedia& m = m_media[b];
        const double nu_c = m_colorimeter->band_wavenumber(b);
        m.lambda_c = 1.0 / nu_c;
        m.centre = media_at(m.lambda_c);
        const Media lo = media_at(m.lambda_c - 0.5), hi = media_at(m.lambda_c + 0.5);
        m.dn0 = hi.n0 - lo.n0;
        m.dn1 = hi.n1 - lo.n1;
        if (m_colorimeter->slopes()) {
            m.below = media_at(1.0 / (nu_c + m_colorimeter->node_below(b)));
            m.above = media_at(1.0 / (nu_c + m_colorimeter->node_above(b)));
            const double delta = m_colorimeter->slope_step(b);
            m.edge_x0 = std::max(-delta, 1.0 / lambda_max_nm - nu_c);
            m.edge_x2 = std::min(delta, 1.0 / lambda_min_nm - nu_c);
            m.edge_below = media_at(1.0 / (nu_c + m.edge_x0));
            m.edge_above = media_at(1.0 / (nu_c + m.edge_x2));
        }
    }
    for (double lambda = lambda_min_nm; lambda <= lambda_max_nm; lambda += 10.0) {
        const Media at = media_at(lambda);
        m_barrier.push_back({lambda, at.n0 * at.n0, at.n1 * at.n1});
    }
}

std::optional<Xyz> FourierFilm::total_reflection(double thickness_nm, double sin2) const noexcept {
    // Past its critical angle the film carries an evanescent field, κ = 2π sqrt(n0² sin²θ − n1²)/λ,
    // and what tunnels through is of order e^{−2κd}. The wavelengths every 10 nm must all be well
    // past the critical angle (n0² sin²θ − n1² >= 1 % of n1²: the indices are smooth on that
    // scale); the smallest κ among them bounds the tunnelling.
    double kappa = std::numeric_limits<double>::infinity();
    for (const auto& [lambda, n0_sq, n1_sq] : m_barrier) {
        const double g = n0_sq * sin2 - n1_sq;
        if (!(g >= 0.01 * n1_sq)) return std::nullopt;
        kappa = std::min(kappa, 2.0 * pi * std::sqrt(g) / lambda);
    }
    if (!(2.0 * kappa * thickness_nm > 23.0)) return std::nullopt;  // e^{-23} = 1e-10
    return m_colorimeter->colorimeter().white();
}

Xyz FourierFilm::exact_sum(double thickness_nm, double cos_theta) const noexcept {
    // The exact colour by summation: exact_film_color (the Airy sum per wavelength, the transfer
    // matrix where the film is exactly at its own critical angle, the incoherent colour past
    // 100 µm of path), or where the 1 nm grid aliases under that path (high finesse near grazing
    // incidence) a sum fine enough, down to fallback_min_step_nm. Its arguments are valid here:
    // the ambient was checked lossless at construction, and the angle stays just below π/2
    // (cos θ = 0 carries no light into the film; the colour there is the limit).
    const double angle = std::min(std::acos(std::clamp(cos_theta, 0.0, 1.0)), std::nextafter(pi / 2.0, 0.0));
    const double step = alias_free_step_nm(m_film, thickness_nm, angle);
    if (step < 1.0 && optical_path_difference_nm(m_film, thickness_nm, angle) < incoherent_opd_nm) {
        return finely_summed_film_xyz(m_film, thickness_nm, angle, m_colorimeter->colorimeter(),
                                      std::max(step, fallback_min_step_nm));
    }
    return exact_film_color(m_film, thickness_nm, angle, m_colorimeter->colorimeter()).xyz;
}

namespace {

/// The series' coefficients of one polarisation (header): A0, and G q^{m-1} for m >= 1.
struct Series {
    double dc = 0.0;
    std::complex<double> g, q;
};

/// s and p at one set of media; false where the series does not apply (the film at or past its
/// own critical angle, or |q| > max_ratio).
bool series_of(double n0, double n1, std::complex<double> n2, double cos_theta, double sin2,
               double max_ratio, std::array<Series, 2>& out, double& q1_out) noexcept {
    const double q0 = n0 * cos_theta;
    const double q1_sq = n1 * n1 - n0 * n0 * sin2;
    if (!(q1_sq > 1e-6 * n1 * n1)) return false;
    const double q1 = std::sqrt(q1_sq);
    // Fresnel amplitudes as PreparedFilm::prepare writes them (tangential fields).
    const double a0 = n0 * n0, a1 = n1 * n1;
    const double r01[2] = {(q0 - q1) / (q0 + q1), (a0 * q1 - a1 * q0) / (a0 * q1 + a1 * q0)};
    std::complex<double> r12[2];
    const double q2_sq = n2.real() * n2.real() - n0 * n0 * sin2;
    if (n2.imag() == 0.0 && q2_sq > 0.0) {
        // A lossless substrate below its critical angle: real amplitudes (no complex division).
        const double q2 = std::sqrt(q2_sq), a2 = n2.real() * n2.real();
        r12[0] = (q1 - q2) / (q1 + q2);
        r12[1] = (a1 * q2 - a2 * q1) / (a1 * q2 + a2 * q1);
    } else {
        std::complex<double> q2 = std::sqrt(n2 * n2 - n0 * n0 * sin2);
        if (q2.imag() < 0.0 || (q2.imag() == 0.0 && q2.real() < 0.0)) q2 = -q2;
        const std::complex<double> a2 = n2 * n2;
        r12[0] = (q1 - q2) / (q1 + q2);
        r12[1] = (a1 * q2 - a2 * q1) / (a1 * q2 + a2 * q1);
    }
    for (int p = 0; p < 2; ++p) {
        const double a = r01[p];
        const std::complex<double> b = r12[p] * (1.0 - a * a);
        const std::complex<double> q = -a * r12[p];
        if (std::norm(q) > max_ratio * max_ratio) return false;
        const double denom = 1.0 - std::norm(q);
        // Unpolarised: the mean of s and p, so each carries half.
        out[p] = {0.5 * (a * a + std::norm(b) / denom), 0.5 * (a * b + std::norm(b) * q / denom), q};
    }
    q1_out = q1;
    return true;
}

}  // namespace

Xyz FourierFilm::xyz(double thickness_nm, double cos_theta) const noexcept {
    // Outside the preconditions (a thickness that is not finite and >= 0, cos θ outside [0, 1]):
    // NaN, never a colour that looks valid.
    if (!(std::isfinite(thickness_nm) && thickness_nm >= 0.0 && cos_theta >= 0.0 && cos_theta <= 1.0)) {
        const double nan = std::numeric_limits<double>::quiet_NaN();
        return {nan, nan, nan};
    }
    if (const std::optional<Xyz> c = series(thickness_nm, cos_theta)) {
        // Reflectances lie in [0, 1] and the weights are >= 0, so each channel lies in [0, the
        // white's]; the series' rounding (1e-8 at grazing incidence) is clamped to that.
        const Xyz& w = m_colorimeter->colorimeter().white();
        return {std::clamp(c->X, 0.0, w.X), std::clamp(c->Y, 0.0, w.Y), std::clamp(c->Z, 0.0, w.Z)};
    }
    return exact_sum(thickness_nm, cos_theta);
}

bool FourierFilm::summed_at(double thickness_nm, double cos_theta) const noexcept {
    if (!(std::isfinite(thickness_nm) && thickness_nm >= 0.0 && cos_theta >= 0.0 && cos_theta <= 1.0)) {
        return false;
    }
    return !series(thickness_nm, cos_theta);
}

std::optional<Xyz> FourierFilm::series(double thickness_nm, double cos_theta) const noexcept {
    if (m_sum_only) return std::nullopt;
    const FourierColorimeter& fc = *m_colorimeter;
    const double d = thickness_nm;
    const double sin2 = std::max(0.0, 1.0 - cos_theta * cos_theta);
    const bool slopes = fc.slopes();
    Xyz out;
    const auto add = [&out](double k, const Xyz& c) {
        out.X += k * c.X;
        out.Y += k * c.Y;
        out.Z += k * c.Z;
    };
    for (int b = 0; b < fc.bands(); ++b) {
        const BandMedia& m = m_media[b];
        // Sets of coefficients: 0 at the centre, 1 and 2 at ν_c − δ and ν_c + δ (slopes).
        std::array<Series, 2> set[3];
        double q1 = 0.0, q1_below = 0.0, q1_above = 0.0;
        if (!series_of(m.centre.n0, m.centre.n1, m.centre.n2, cos_theta, sin2, max_ratio, set[0], q1)) {
            return total_reflection(d, sin2);
        }
        const int sets = slopes ? 3 : 1;
        if (slopes && (!series_of(m.below.n0, m.below.n1, m.below.n2, cos_theta, sin2, max_ratio, set[1], q1_below) ||
                       !series_of(m.above.n0, m.above.n1, m.above.n2, cos_theta, sin2, max_ratio, set[2], q1_above))) {
            return std::nullopt;
        }
        const double delta = slopes ? fc.slope_step(b) : 0.0;
        const double x0 = slopes ? fc.node_below(b) : -1.0, x2 = slopes ? fc.node_above(b) : 1.0;
        // Through the band a coefficient c(ν) is the parabola through its values at the nodes
        // ν_c + x0, ν_c, ν_c + x2: c0 + c1 Δ + c2 Δ², Δ = ν − ν_c, against the moments V0, V1, V2.
        const auto parabola = [x0, x2](auto below, auto centre, auto above) {
            using T = decltype(centre);
            const T s0 = (below - centre) / x0, s2 = (above - centre) / x2;
            const T c2 = (s2 - s0) / (x2 - x0);
            return std::array<T, 3>{centre, s2 - c2 * x2, c2};
        };
        // The model holds while the media change little through the band: near the film's
        // critical angle q1 = n1 cos θ1 changes fast with the indices' dispersion, and there (q1
        // varying by more than max_q1_variation across the band) the 1 nm sum is used.
        if (slopes && std::abs(q1_above - q1_below) > max_q1_variation * q1) return std::nullopt;
        // With slopes, the parabolas (of A0 and of the phase) are checked at the band's edges.
        std::array<Series, 2> edge[2];
        double q1_edge[2] = {0.0, 0.0};
        if (slopes &&
            (!series_of(m.edge_below.n0, m.edge_below.n1, m.edge_below.n2, cos_theta, sin2, max_ratio, edge[0], q1_edge[0]) ||
             !series_of(m.edge_above.n0, m.edge_above.n1, m.edge_above.n2, cos_theta, sin2, max_ratio, edge[1], q1_edge[1]))) {
            return std::nullopt;
        }
        if (slopes) {
            const auto dc = parabola(set[1][0].dc + set[1][1].dc, set[0][0].dc + set[0][1].dc,
                                     set[2][0].dc + set[2][1].dc);
            const double xs[2] = {m.edge_x0, m.edge_x2};
            for (int e = 0; e < 2; ++e) {
                const double x = xs[e];
                if (std::abs(edge[e][0].dc + edge[e][1].dc - (dc[0] + x * (dc[1] + x * dc[2]))) > max_bend) {
                    return std::nullopt;
                }
            }
            for (int k = 0; k < 3; ++k) add(dc[k], fc.band_moment(b, k));
        } else {
            add(set[0][0].dc + set[0][1].dc, fc.band_white(b));
        }
        // The phase about the band's centre, φ = 4π d f(ν), f = ν q1: φ(ν) ≈ φ_c + 2π τ1 (ν − ν_c)
        // + ψ, τ1 = 2 d f'(ν_c), ψ = β (ν − ν_c)², β = 2π d f''(ν_c); e^{imφ} W(...) =
        // e^{imφ_c} V(m τ1) but for ψ. Without slopes f' is the group value q1 − λ dq1/dλ from the
        // indices' slopes per nm; with them f' and f'' come from f at ν_c and ν_c ± δ.
        const double nu_c = 1.0 / m.lambda_c;
        double f1 = 0.0, f2 = 0.0;
        if (slopes) {
            const auto f = parabola((nu_c + x0) * q1_below, nu_c * q1, (nu_c + x2) * q1_above);
            f1 = f[1];
            f2 = 2.0 * f[2];
            const double xs[2] = {m.edge_x0, m.edge_x2};
            for (int e = 0; e < 2; ++e) {
                const double x = xs[e];
                const double departure = (nu_c + x) * q1_edge[e] - (f[0] + x * (f[1] + x * f[2]));
                if (4.0 * pi * d * std::abs(departure) > max_phase_departure) return std::nullopt;
            }
        } else {
            const double dq1 = (m.centre.n1 * m.dn1 - m.centre.n0 * m.dn0 * sin2) / q1;
            f1 = q1 - m.lambda_c * dq1;
        }
        if (!(f1 > 0.0)) return std::nullopt;
        const double tau1 = 2.0 * d * f1;
        const double beta = 2.0 * pi * d * f2;
        // The m-th term's chirp e^{imψ} enters to second order, 1 + imψ − (mψ)²/2: its error at the
        // band's edges is (m |β| δ²)³ / 6. The term's group delays spread over m · 2d |f''| δ on
        // either side of m τ1, so the envelope bounding it is taken that much earlier.
        const double edge_phase = std::abs(beta) * delta * delta;
        const double spread = 2.0 * d * std::abs(f2) * delta;
        const std::complex<double> u = std::polar(1.0, 4.0 * pi * d * q1 * nu_c);
        // term[s][p] = G q^{k-1} u^k for set s, polarisation p, at the k-th step of the loop.
        std::complex<double> term[3][2], ratio[3][2];
        // After k terms, what the rest can add is at most 2 Σ |term_{k+1}| E(τ) / (1 − |q|), E the
        // largest |V| from (k+1) τ1 on (the table's envelope): with |term_{k+1}| <= |term_1|
        // |q|max^k, one running product decides when to stop.
        double a_v = 0.0, a_m = 0.0, q_max = 0.0;
        for (int s = 0; s < sets; ++s) {
            for (int p = 0; p < 2; ++p) {
                term[s][p] = set[s][p].g * u;
                ratio[s][p] = set[s][p].q * u;
                const double q_abs = std::sqrt(std::norm(set[s][p].q));
                (s == 0 ? a_v : a_m) += std::sqrt(std::norm(term[s][p])) / (1.0 - q_abs);
                q_max = std::max(q_max, q_abs);
            }
        }
        const auto remaining = [&](int k, double q_power) {
            const double tau = std::max(0.0, k * (tau1 - spread));
            const double chirp = 1.0 + k * edge_phase * (1.0 + k * edge_phase);
            return 2.0 * q_power * (a_v * chirp * fc.envelope(b, tau) + (a_m + a_v * chirp) * fc.moment_envelope(b, tau));
        };
        const double max_tau = fc.max_opd_nm(b);
        double q_power = 1.0;
        for (int k = 1; remaining(k, q_power) > series_tolerance; ++k) {
            const double tau = k * tau1;
            if (tau >= max_tau) {
                // The terms past the table's end are dropped. What they can add is bounded by the
                // transform's level at the table's end: where that matters for a film whose first
                // terms are in the table (grazing incidence, |q| → 1), the 1 nm sum is used
                // instead. A film whose first term is already past the table (OPD >= max_opd_nm)
                // is the incoherent sum of its faces, within 2 |G| × the floor.
                double tail = 0.0;
                for (int s = 0; s < sets; ++s) {
                    for (int p = 0; p < 2; ++p) {
                        tail += std::sqrt(std::norm(term[s][p])) / (1.0 - std::sqrt(std::norm(set[s][p].q)));
                    }
                }
                if (k > 1 && 2.0 * tail * fc.band_floor(b) > max_dropped_tail) return std::nullopt;
                break;
            }
            const double psi = k * edge_phase;
            if (slopes && psi > max_quadratic_phase) {
                // Past the second-order chirp's reach: the 1 nm sum, unless this term and the rest
                // are negligible.
                if (remaining(k, q_power) > max_dropped_tail) return std::nullopt;
                break;
            }
            const std::complex<double> t0 = term[0][0] + term[0][1];
            const auto transform = fc.transform(b, tau);
            std::complex<double> x = t0 * transform.x, y = t0 * transform.y, z = t0 * transform.z;
            if (slopes) {
                // Σ_i w_i c(ν_i) (1 + iβ_k Δ² − β_k² Δ⁴/2) e^{2πi kτ1 Δ}, Δ = ν_i − ν_c:
                // c0 V0 + c1 V1 + (c2 + iβ c0) V2 + iβ c1 V3 + (iβ c2 − β²/2 c0) V4.
                const auto c = parabola(term[1][0] + term[1][1], t0, term[2][0] + term[2][1]);
                const std::complex<double> ib(0.0, k * beta);
                const std::complex<double> w[4] = {c[1], c[2] + ib * c[0], ib * c[1],
                                                   ib * c[2] + 0.5 * ib * ib * c[0]};
                const auto v = fc.moment_transforms(b, tau);
                for (int n = 0; n < 4; ++n) {
                    x += w[n] * v[n].x;
                    y += w[n] * v[n].y;
                    z += w[n] * v[n].z;
                }
            }
            out.X += 2.0 * x.real();
            out.Y += 2.0 * y.real();
            out.Z += 2.0 * z.real();
            for (int s = 0; s < sets; ++s) {
                for (int p = 0; p < 2; ++p) term[s][p] *= ratio[s][p];
            }
            q_power *= q_max;
        }
    }
    return out;
}

FilmColor FourierFilm::color(double thickness_nm, double cos_theta) const noexcept {
    const Xyz c = xyz(thickness_nm, cos_theta);
    return {c, m_colorimeter->colorimeter().linear_rgb(c)};
}

std::string_view film_integration_name(FilmIntegration integration) noexcept {
    return integration == FilmIntegration::fourier ? "fourier" : "sum";
}

FilmIntegration parse_film_integration(std::string_view name) {
    if (name == "sum") return FilmIntegration::sum;
    if (name == "fourier") return FilmIntegration::fourier;
    throw UnknownNameError(fmt::format("integration '{}' is unknown; valid: sum, fourier", name),
                           {"sum", "fourier"});
}

SingleFilm fourier_single_film(const FilmModel& model) {
    const auto* exact = dynamic_cast<const ExactFilm*>(&model);
    if (exact == nullptr) {
        throw Error(fmt::format("the Fourier integration is for the exact film; the model is {}",
                                model.name()));
    }
    if (exact->layers().size() != 1) {
        throw Error(fmt::format("the Fourier integration needs one layer; the stack has {}",
                                exact->layers().size()));
    }
    if (exact->polarization() != Polarization::unpolarized) {
        throw Error("the Fourier integration gives unpolarised colour; the film is polarised");
    }
    const Material& film = exact->layers().front().material;
    if (!film.is_lossless()) {
        throw Error("the Fourier integration needs a lossless film; '" + film.name() +
                    "' absorbs (k > 0)");
    }
    return {exact->ambient(), film, exact->substrate()};
}

}  // namespace irid
