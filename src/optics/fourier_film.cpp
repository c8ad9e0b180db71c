#include <irid/error.h>
#include <irid/optics/fourier_film.h>

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
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

/// Tabulates V(τ_j) = Σ_i c_i e^{2πi τ_j (ν_i − ν_c)}, τ_j = j h, by a phasor per wavelength,
/// until |V| has stayed below `quiet_level` for `run_nodes` nodes or `max_nodes` are made.
/// Returns the table (the quiet run dropped but for its first node) and max |V| over it.
std::pair<std::vector<std::array<double, 6>>, double> tabulate(
    const std::array<double, dense_sample_count>& nu, double nu_c,
    const std::array<std::array<double, dense_sample_count>, 3>& c, double step, double quiet_level,
    std::size_t run_nodes, std::size_t max_nodes) {
    // Wavelengths whose weights are all 0 add nothing.
    std::vector<int> used;
    for (int i = 0; i < dense_sample_count; ++i) {
        if (c[0][i] != 0.0 || c[1][i] != 0.0 || c[2][i] != 0.0) used.push_back(i);
    }
    std::vector<std::complex<double>> phasor(used.size()), advance(used.size());
    for (std::size_t k = 0; k < used.size(); ++k) {
        advance[k] = std::polar(1.0, 2.0 * pi * step * (nu[used[k]] - nu_c));
    }
    std::vector<std::array<double, 6>> table;
    table.reserve(4096);
    double bound = 0.0;
    std::size_t quiet = 0;
    for (std::size_t j = 0; j < max_nodes && quiet <= run_nodes; ++j) {
        if (j % reseed_every == 0) {
            const double tau = step * static_cast<double>(j);
            for (std::size_t k = 0; k < used.size(); ++k) {
                phasor[k] = std::polar(1.0, 2.0 * pi * tau * (nu[used[k]] - nu_c));
            }
        }
        std::complex<double> v[3];
        for (std::size_t k = 0; k < used.size(); ++k) {
            const int i = used[k];
            for (int ch = 0; ch < 3; ++ch) v[ch] += c[ch][i] * phasor[k];
            phasor[k] *= advance[k];
        }
        table.push_back({v[0].real(), v[0].imag(), v[1].real(), v[1].imag(), v[2].real(), v[2].imag()});
        const double largest = std::max({std::abs(v[0]), std::abs(v[1]), std::abs(v[2])});
        bound = std::max(bound, largest);
        quiet = largest < quiet_level ? quiet + 1 : 0;
    }
    if (quiet > run_nodes) table.resize(table.size() - quiet + 1);
    table.shrink_to_fit();
    return {std::move(table), bound};
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
            band.delta = std::min({half_spacing, band.nu_c - 1.0 / lambda_max_nm, 1.0 / lambda_min_nm - band.nu_c});
        }
        for (int i = 0; i < dense_sample_count; ++i) {
            band.white.X += c[0][i];
            band.white.Y += c[1][i];
            band.white.Z += c[2][i];
        }
        std::vector<std::array<double, 6>> v, v1, v2;
        std::tie(v, band.bound) = tabulate(nu, band.nu_c, c, step_nm, quiet_level, run_nodes, max_nodes);
        for (std::size_t j = v.size() > run_nodes ? v.size() - run_nodes : 0; j < v.size(); ++j) {
            for (int ch = 0; ch < 3; ++ch) band.floor = std::max(band.floor, std::hypot(v[j][2 * ch], v[j][2 * ch + 1]));
        }
        const auto store = [&] {
            band.nodes = v.size();
            band.table.assign(band.nodes * stride(), 0.0);
            for (std::size_t j = 0; j < band.nodes; ++j) {
                double* row = &band.table[j * stride()];
                std::copy(v[j].begin(), v[j].end(), row);
                if (j < v1.size()) std::copy(v1[j].begin(), v1[j].end(), row + 6);
                if (j < v2.size()) std::copy(v2[j].begin(), v2[j].end(), row + 12);
            }
        };
        if (!slopes) {
            store();
            continue;
        }
        for (int i = 0; i < dense_sample_count; ++i) {
            for (int ch = 0; ch < 3; ++ch) c[ch][i] *= nu[i] - band.nu_c;
            band.moment.X += c[0][i];
            band.moment.Y += c[1][i];
            band.moment.Z += c[2][i];
        }
        // The moments' values are about δ and δ² times smaller: so are their quiet levels.
        std::tie(v1, band.moment_bound) =
            tabulate(nu, band.nu_c, c, step_nm, quiet_level * band.delta, run_nodes, max_nodes);
        for (int i = 0; i < dense_sample_count; ++i) {
            for (int ch = 0; ch < 3; ++ch) c[ch][i] *= nu[i] - band.nu_c;
        }
        std::tie(v2, band.second_moment_bound) = tabulate(
            nu, band.nu_c, c, step_nm, quiet_level * band.delta * band.delta, run_nodes, max_nodes);
        store();
    }
}

namespace {

/// Linear interpolation of `count` transforms (6 doubles each) from a row-major table of
/// `stride` doubles per node, at node position u; zeros outside [0, nodes − 1).
template <std::size_t count>
std::array<FourierColorimeter::Transform, count> lookup(const std::vector<double>& t, std::size_t nodes,
                                                        std::size_t stride, double u) noexcept {
    std::array<FourierColorimeter::Transform, count> out{};
    if (!(u >= 0.0) || u >= static_cast<double>(nodes) - 1.0) return out;
    const auto j = static_cast<std::size_t>(u);
    const double f = u - static_cast<double>(j);
    const double* a = &t[j * stride];
    const double* c = a + stride;
    const auto at = [&](std::size_t k) { return a[k] + f * (c[k] - a[k]); };
    for (std::size_t n = 0; n < count; ++n) {
        const std::size_t o = 6 * n;
        out[n] = {{at(o), at(o + 1)}, {at(o + 2), at(o + 3)}, {at(o + 4), at(o + 5)}};
    }
    return out;
}

}  // namespace

FourierColorimeter::Transform FourierColorimeter::transform(int b, double tau_nm) const noexcept {
    const Band& band = m_bands[b];
    return lookup<1>(band.table, band.nodes, stride(), tau_nm / step_nm)[0];
}

std::array<FourierColorimeter::Transform, 3> FourierColorimeter::transforms(int b, double tau_nm) const noexcept {
    const Band& band = m_bands[b];
    if (!m_slopes) return {transform(b, tau_nm), Transform{}, Transform{}};
    return lookup<3>(band.table, band.nodes, stride(), tau_nm / step_nm);
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
            const double delta = m_colorimeter->slope_step(b);
            m.below = media_at(1.0 / (nu_c - delta));
            m.above = media_at(1.0 / (nu_c + delta));
        }
    }
}

Xyz FourierFilm::exact_sum(double thickness_nm, double cos_theta) const noexcept {
    // The 1 nm sum (exact_film_color: the Airy sum per wavelength, the transfer matrix where the
    // film is exactly at its own critical angle). Its arguments are valid here: the ambient was
    // checked lossless at construction, and the angle stays just below π/2 (cos θ = 0 carries no
    // light into the film; the colour there is the limit).
    const double angle = std::min(std::acos(std::clamp(cos_theta, 0.0, 1.0)), std::nextafter(pi / 2.0, 0.0));
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
    if (m_sum_only) return exact_sum(thickness_nm, cos_theta);
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
            return exact_sum(thickness_nm, cos_theta);
        }
        const int sets = slopes ? 3 : 1;
        if (slopes && (!series_of(m.below.n0, m.below.n1, m.below.n2, cos_theta, sin2, max_ratio, set[1], q1_below) ||
                       !series_of(m.above.n0, m.above.n1, m.above.n2, cos_theta, sin2, max_ratio, set[2], q1_above))) {
            return exact_sum(thickness_nm, cos_theta);
        }
        const double inv_2delta = slopes ? 0.5 / fc.slope_step(b) : 0.0;
        // The band's model holds only while the media change little through it: near the film's
        // critical angle q1 = n1 cos θ1 changes fast with the indices' dispersion (and the
        // coefficients with it), so where q1 varies by more than max_q1_variation across the
        // band, or the coefficients bend (their second difference above max_bend), the 1 nm sum
        // is used.
        if (slopes) {
            const double dc_below = set[1][0].dc + set[1][1].dc, dc_c = set[0][0].dc + set[0][1].dc;
            const double dc_above = set[2][0].dc + set[2][1].dc;
            if (std::abs(q1_above - q1_below) > max_q1_variation * q1 ||
                std::abs(dc_above - 2.0 * dc_c + dc_below) > max_bend) {
                return exact_sum(thickness_nm, cos_theta);
            }
        }
        add(set[0][0].dc + set[0][1].dc, fc.band_white(b));
        if (slopes) add((set[2][0].dc + set[2][1].dc - set[1][0].dc - set[1][1].dc) * inv_2delta, fc.band_moment(b));
        // The phase about the band's centre, φ = 4π d f(ν), f = ν q1: φ(ν) ≈ φ_c + 2π τ1 (ν − ν_c)
        // (+ ψ), τ1 = 2 d f'(ν_c); e^{imφ} W(...) = e^{imφ_c} V(m τ1). Without slopes f' is the
        // group value q1 − λ dq1/dλ from the indices' slopes per nm; with them, f' and f'' come
        // from f at ν_c and ν_c ± δ, and ψ = 2π d f'' (ν − ν_c)² enters as i m ψ against V2.
        const double nu_c = 1.0 / m.lambda_c;
        double f1 = 0.0, psi2 = 0.0;
        if (slopes) {
            const double delta = fc.slope_step(b);
            const double f_below = (nu_c - delta) * q1_below, f_c = nu_c * q1, f_above = (nu_c + delta) * q1_above;
            f1 = (f_above - f_below) / (2.0 * delta);
            psi2 = 2.0 * pi * d * (f_above - 2.0 * f_c + f_below) / (delta * delta);
            // The quadratic term enters to first order: past max_quadratic_phase at the band's
            // edges (thick films of strongly dispersive media) the expansion fails.
            if (std::abs(psi2) * delta * delta > max_quadratic_phase) return exact_sum(thickness_nm, cos_theta);
        } else {
            const double dq1 = (m.centre.n1 * m.dn1 - m.centre.n0 * m.dn0 * sin2) / q1;
            f1 = q1 - m.lambda_c * dq1;
        }
        if (!(f1 > 0.0)) return exact_sum(thickness_nm, cos_theta);
        const double tau1 = 2.0 * d * f1;
        const std::complex<double> u = std::polar(1.0, 4.0 * pi * d * q1 * nu_c);
        // term[s][p] = G q^{k-1} u^k for set s, polarisation p, at the k-th step of the loop.
        std::complex<double> term[3][2], ratio[3][2];
        const double bounds[3] = {fc.band_bound(b), fc.band_moment_bound(b) * inv_2delta,
                                  fc.band_moment_bound(b) * inv_2delta};
        // After k terms, what the rest can add is at most 2 Σ |term_1| |q|^k bound / (1 − |q|)
        // ≤ 2 A |q|max^k (|V| <= bound; the quadratic term's own tail is at most m|ψ| times the
        // linear one's): the number of terms follows once, not per term.
        double a = 0.0, q_max = 0.0;
        for (int s = 0; s < sets; ++s) {
            for (int p = 0; p < 2; ++p) {
                term[s][p] = set[s][p].g * u;
                ratio[s][p] = set[s][p].q * u;
                const double q_abs = std::sqrt(std::norm(set[s][p].q));
                a += std::sqrt(std::norm(term[s][p])) * bounds[s] / (1.0 - q_abs);
                q_max = std::max(q_max, q_abs);
            }
        }
        const double wanted = series_tolerance / (2.0 * a);
        int terms = 0;
        if (!(wanted >= 1.0)) {
            terms = q_max > 0.0 ? static_cast<int>(std::ceil(std::log(wanted) / std::log(q_max))) : 1;
            terms = std::max(terms, 1);
        }
        const double max_tau = fc.max_opd_nm(b);
        for (int k = 1; k <= terms; ++k) {
            const double tau = k * tau1;
            if (tau >= max_tau) {
                // The terms past the table's end are dropped. What they can add is bounded by the
                // transform's level at the table's end: where that matters for a film whose first
                // terms are in the table (grazing incidence, |q| → 1), the 1 nm sum is used
                // instead. A film whose first term is already past the table (OPD >= 20 µm) is
                // the incoherent sum of its faces, within 2 |G| × the floor.
                double tail = 0.0;
                for (int s = 0; s < sets; ++s) {
                    for (int p = 0; p < 2; ++p) {
                        tail += std::sqrt(std::norm(term[s][p])) / (1.0 - std::sqrt(std::norm(set[s][p].q)));
                    }
                }
                if (k > 1 && 2.0 * tail * fc.band_floor(b) > max_dropped_tail) {
                    return exact_sum(thickness_nm, cos_theta);
                }
                break;
            }
            const std::complex<double> t = term[0][0] + term[0][1];
            if (slopes) {
                const auto v = fc.transforms(b, tau);
                const std::complex<double> ts = (term[2][0] + term[2][1] - term[1][0] - term[1][1]) * inv_2delta;
                const std::complex<double> tq = t * std::complex<double>(0.0, k * psi2);
                // 2 Re(t V + ts V1 + i k ψ2 t V2) per channel.
                out.X += 2.0 * (t * v[0].x + ts * v[1].x + tq * v[2].x).real();
                out.Y += 2.0 * (t * v[0].y + ts * v[1].y + tq * v[2].y).real();
                out.Z += 2.0 * (t * v[0].z + ts * v[1].z + tq * v[2].z).real();
            } else {
                const auto v = fc.transform(b, tau);
                out.X += 2.0 * (t.real() * v.x.real() - t.imag() * v.x.imag());
                out.Y += 2.0 * (t.real() * v.y.real() - t.imag() * v.y.imag());
                out.Z += 2.0 * (t.real() * v.z.real() - t.imag() * v.z.imag());
            }
            for (int s = 0; s < sets; ++s) {
                for (int p = 0; p < 2; ++p) term[s][p] *= ratio[s][p];
            }
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
