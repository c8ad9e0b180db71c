// FourierFilm: a single film's colour as a Fourier series against the FourierColorimeter's
// tables, with the quadratures and the 1 nm sum where the series does not apply (docs/OPTICS.md).

#include <irid/error.h>
#include <irid/optics/fine_sum.h>
#include <irid/optics/fourier_film.h>
#include <irid/optics/multilayer.h>

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <utility>

namespace irid {
namespace {

using std::numbers::pi;

/// coefficient_matrix, tabulated.
const std::array<std::array<double, FourierColorimeter::node_count>, FourierColorimeter::node_count>&
chebyshev_matrix() noexcept {
    static const auto matrix = [] {
        std::array<std::array<double, FourierColorimeter::node_count>, FourierColorimeter::node_count> m{};
        for (int k = 0; k < FourierColorimeter::node_count; ++k) {
            for (int j = 0; j < FourierColorimeter::node_count; ++j) m[k][j] = FourierColorimeter::coefficient_matrix(k, j);
        }
        return m;
    }();
    return matrix;
}

/// The Chebyshev coefficients of the interpolant through values at the nodes.
template <typename T>
std::array<T, FourierColorimeter::node_count> chebyshev_coefficients(
    const std::array<T, FourierColorimeter::node_count>& v) noexcept {
    const auto& m = chebyshev_matrix();
    std::array<T, FourierColorimeter::node_count> c{};
    for (int k = 0; k < FourierColorimeter::node_count; ++k) {
        T sum{};
        for (int j = 0; j < FourierColorimeter::node_count; ++j) sum += m[k][j] * v[j];
        c[k] = sum;
    }
    return c;
}

/// Σ_k c_k T_k(x), by the three-term recurrence.
double chebyshev_value(const std::array<double, FourierColorimeter::node_count>& c, double x) noexcept {
    double t_prev = 1.0, t = x, sum = c[0] + c[1] * x;
    for (int k = 2; k < FourierColorimeter::node_count; ++k) {
        const double next = 2.0 * x * t - t_prev;
        sum += c[k] * next;
        t_prev = t;
        t = next;
    }
    return sum;
}

}  // namespace

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
            for (int k = 0; k < FourierColorimeter::node_count; ++k) {
                m.nodes[k] = media_at(1.0 / m_colorimeter->node_wavenumber(b, k));
            }
        }
    }
    if (m_colorimeter->slopes()) {
        // The media must be as smooth as the nodes: each index (real and imaginary parts) within
        // max_index_misfit of its interpolant through them, on the 1 nm grid inside each band.
        for (int b = 0; b < bands && !m_sum_only; ++b) {
            std::array<std::array<double, FourierColorimeter::node_count>, 4> at{};
            for (int k = 0; k < FourierColorimeter::node_count; ++k) {
                const Media& n = m_media[b].nodes[k];
                at[0][k] = n.n0;
                at[1][k] = n.n1;
                at[2][k] = n.n2.real();
                at[3][k] = n.n2.imag();
            }
            std::array<std::array<double, FourierColorimeter::node_count>, 4> c{};
            for (int q = 0; q < 4; ++q) c[q] = chebyshev_coefficients(at[q]);
            const double mid = m_colorimeter->band_mid(b), half = m_colorimeter->band_half_width(b);
            for (int lambda = lambda_min_nm; lambda <= lambda_max_nm && !m_sum_only; ++lambda) {
                const double x = (1.0 / lambda - mid) / half;
                if (std::abs(x) > 1.0) continue;
                const Media n = media_at(lambda);
                const double exact[4] = {n.n0, n.n1, n.n2.real(), n.n2.imag()};
                for (int q = 0; q < 4; ++q) {
                    if (!(std::abs(exact[q] - chebyshev_value(c[q], x)) <= max_index_misfit)) m_sum_only = true;
                }
            }
        }
    } else {
        // Without slopes the coefficients are held at each band's centre: a dispersive absorbing
        // substrate (a metal's table) turns too sharply for that (docs/OPTICS.md).
        m_sum_only = !film.substrate.is_lossless() && !film.substrate.is_constant();
    }
    for (int lambda = lambda_min_nm; lambda <= lambda_max_nm; ++lambda) m_dense.push_back(media_at(lambda));
    for (int j = 0; j < FourierColorimeter::quadrature_node_count; ++j) {
        m_quadrature_media[j] = media_at(1.0 / m_colorimeter->quadrature_wavenumber(j));
    }
    m_critical_ratios.fill({std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()});
    for (double lambda = lambda_min_nm; lambda <= lambda_max_nm; lambda += 10.0) {
        const Media at = media_at(lambda);
        // n1²/n0² and, for a lossless substrate, n2²/n0²: their ranges over the rows.
        const double ratios[2] = {at.n1 * at.n1 / (at.n0 * at.n0),
                                  at.n2.imag() == 0.0 ? at.n2.real() * at.n2.real() / (at.n0 * at.n0)
                                                      : std::numeric_limits<double>::quiet_NaN()};
        for (int k = 0; k < 2; ++k) {
            auto& [low, high] = m_critical_ratios[static_cast<std::size_t>(k)];
            // (An absorbing substrate's NaN leaves an empty range: no crossing.)
            if (std::isnan(ratios[k])) continue;
            low = std::min(low, ratios[k]);
            high = std::max(high, ratios[k]);
        }
        m_barrier.push_back({lambda, at.n0 * at.n0, at.n1 * at.n1});
    }
}

std::optional<Xyz> FourierFilm::total_reflection(double thickness_nm, double cos_theta, double sin2) const noexcept {
    // Past its critical angle the film carries an evanescent field, κ = 2π sqrt(n0² sin²θ − n1²)/λ,
    // and what tunnels through is of order e^{−2κd}. The wavelengths every 10 nm must all be past
    // the critical angle with a margin, n0² sin²θ − n1² >= 1e-3 n1², that the indices' change
    // over 10 nm stays inside (water's n² changes by 6e-4 from 360 to 370 nm); the smallest κ
    // among them bounds the tunnelling.
    double kappa = std::numeric_limits<double>::infinity();
    for (const auto& [lambda, n0_sq, n1_sq] : m_barrier) {
        const double g = n0_sq * sin2 - n1_sq;
        if (!(g >= 1e-3 * n1_sq)) return std::nullopt;
        kappa = std::min(kappa, 2.0 * pi * std::sqrt(g) / lambda);
    }
    // e^{-23} = 1e-10; otherwise the evanescent reflectance, analytic in wavenumber (no cycles).
    if (!(2.0 * kappa * thickness_nm > 23.0)) return quadrature(thickness_nm, cos_theta, 0.0);
    return m_colorimeter->colorimeter().white();
}

bool FourierFilm::critical_inside(double sin2) const noexcept {
    // A sign change of n² − n0² sin²θ between the rows every 10 nm (they include 360 and 830 nm,
    // so every crossing inside the spectrum is bracketed), for the film and for a lossless
    // substrate: some row has n²/n0² below sin²θ and another not (the ratios' range is found
    // once, at construction). Near a crossing just outside the spectrum the reflectance bends
    // without a kink: the series' tail checks and the quadratures' agreement see that.
    for (const auto& [low, high] : m_critical_ratios) {
        if (low < sin2 && high >= sin2) return true;
    }
    return false;
}

std::optional<Xyz> FourierFilm::quadrature(double thickness_nm, double cos_theta, double cycles) const noexcept {
    // Each level's nodes are the previous level's and the points between them: a reflectance is
    // computed once, when a level first needs it.
    const FourierColorimeter& fc = *m_colorimeter;
    constexpr int levels = FourierColorimeter::quadrature_levels;
    constexpr int last = FourierColorimeter::quadrature_node_count - 1;
    std::array<double, FourierColorimeter::quadrature_node_count> r{};
    const auto reflectance = [&](int j) {
        const Media& m = m_quadrature_media[j];
        bool at_critical = false;
        const PreparedFilm::Sample sample =
            PreparedFilm::prepare_media(m.n0, m.n1, m.n2, cos_theta, 1.0 / fc.quadrature_wavenumber(j), at_critical);
        // At the film's own critical angle the Airy form loses its digits: no quadrature (NaN
        // fails the comparison below).
        return at_critical ? std::numeric_limits<double>::quiet_NaN() : PreparedFilm::airy_reflectance(sample, thickness_nm);
    };
    const double white = fc.colorimeter().white().Y;
    Xyz previous;
    double previous_difference = 0.0;
    for (int level = 0; level < levels; ++level) {
        const int stride = 1 << (levels - 1 - level);
        // New nodes: the odd multiples of the stride (all of them at level 0).
        for (int j = level == 0 ? 0 : stride; j <= last; j += level == 0 ? stride : 2 * stride) r[j] = reflectance(j);
        Xyz q;
        for (int j = 0; j <= last; j += stride) {
            const Xyz& w = fc.quadrature_weights(level, j);
            q = {q.X + r[j] * w.X, q.Y + r[j] * w.Y, q.Z + r[j] * w.Z};
        }
        if (level > 0) {
            const double difference =
                std::max({std::abs(q.X - previous.X), std::abs(q.Y - previous.Y), std::abs(q.Z - previous.Z)});
            // The tolerance is relative for dark colours (where ΔE2000 is sensitive to small
            // differences). Unless the reflectance is known to be analytic (an evanescent film),
            // the agreement must be established: the level before must have been close as well
            // (within √tolerance of the white), or two rules that both miss a feature can agree
            // by coincidence.
            // A level is taken only once it has nodes enough for the reflectance's cycles: N
            // intervals space their nodes by up to π/N of the interval at its middle, and the
            // interpolant converges once a cycle has π of those, so N >= π² cycles / 2, about
            // five intervals a cycle.
            const double tolerance = max_quadrature_disagreement * std::min(white, std::max(100.0 * q.Y, 1e-6 * white));
            const bool resolved = (8 << level) >= 5.0 * cycles;
            if (difference <= tolerance && resolved &&
                (cycles == 0.0 || (level > 1 && previous_difference <= std::sqrt(tolerance * white)))) {
                return q;
            }
            // Converging geometrically, e_N ~ ρ^−N, the next difference is about d³ / d_prev²:
            // where that is still a hundred times the tolerance, the next level (twice the
            // reflectances) would fail too, so the sum is started now. A colour that goes to the
            // sum then costs about what the 1 nm sum from scratch costs (docs/PERFORMANCE.md).
            if (level > 1 && previous_difference > 0.0 &&
                !(difference * difference * difference <= 100.0 * tolerance * previous_difference * previous_difference)) {
                return std::nullopt;
            }
            previous_difference = difference;
        }
        previous = q;
    }
    return std::nullopt;
}

std::optional<Xyz> FourierFilm::fast(double thickness_nm, double cos_theta) const noexcept {
    // Where the film or the substrate reaches its critical angle inside the spectrum, the
    // reflectance has a kink at that wavelength: neither the nodes nor the quadratures follow it.
    if (critical_inside(1.0 - cos_theta * cos_theta)) return std::nullopt;
    if (const std::optional<Xyz> c = series(thickness_nm, cos_theta)) return c;
    // A metal's table has kinks the polynomials converge on too slowly to be worth trying.
    if (m_sum_only) return std::nullopt;
    // Where the 1 nm grid aliases, its sum is not the colour, and neither is a quadrature of it.
    const double angle = std::min(std::acos(std::clamp(cos_theta, 0.0, 1.0)), std::nextafter(pi / 2.0, 0.0));
    const AliasReach reach = alias_reach(m_film, angle);
    if (!(alias_free_step_nm(reach, thickness_nm) >= 1.0)) return std::nullopt;
    // The reflections that count reach d × reach_per_nm of path: the reflectance makes that many
    // cycles over 360–830 nm. The finest level (128 intervals) takes at most 25 of them
    // (quadrature()); past that it would compute 129 reflectances to fail. Never below one cycle,
    // so that a smooth-looking film still needs established agreement.
    const double cycles = std::max(1.0, thickness_nm * reach.reach_per_nm * (1.0 / lambda_min_nm - 1.0 / lambda_max_nm));
    if (!(5.0 * cycles <= FourierColorimeter::quadrature_node_count - 1)) return std::nullopt;
    return quadrature(thickness_nm, cos_theta, cycles);
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
    const Colorimeter& colorimeter = m_colorimeter->colorimeter();
    if (step < 1.0) {
        if (optical_path_difference_nm(m_film, thickness_nm, angle) < incoherent_opd_nm) {
            return finely_summed_film_xyz(m_film, thickness_nm, angle, colorimeter, std::max(step, fallback_min_step_nm));
        }
        return exact_film_color(m_film, thickness_nm, angle, colorimeter).xyz;
    }
    // The 1 nm sum, as exact_film_color sums it, from the media's indices read once at
    // construction; a wavelength where the film sits at its own critical angle (rare) sends the
    // colour to exact_film_color, which takes the transfer matrix there.
    bool degenerate = false;
    const Xyz xyz = colorimeter.xyz_of([&](double lambda) {
        const Media& m = m_dense[static_cast<std::size_t>(static_cast<int>(lambda) - lambda_min_nm)];
        bool at_critical = false;
        const PreparedFilm::Sample s = PreparedFilm::prepare_media(m.n0, m.n1, m.n2, cos_theta, lambda, at_critical);
        degenerate = degenerate || at_critical;
        return at_critical ? 0.0 : PreparedFilm::airy_reflectance(s, thickness_nm);
    });
    return degenerate ? exact_film_color(m_film, thickness_nm, angle, colorimeter).xyz : xyz;
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

namespace {

/// cos θ = 0 carries no light into the film: the colour there is the limit, taken at the largest
/// angle below π/2 (cos θ 6e-17), where the amplitudes are still defined.
double grazing_limit(double cos_theta) noexcept {
    static const double smallest = std::cos(std::nextafter(pi / 2.0, 0.0));
    return std::max(cos_theta, smallest);
}

}  // namespace

Xyz FourierFilm::xyz(double thickness_nm, double cos_theta) const noexcept {
    // Outside the preconditions (a thickness that is not finite and >= 0, cos θ outside [0, 1]):
    // NaN, never a colour that looks valid.
    if (!(std::isfinite(thickness_nm) && thickness_nm >= 0.0 && cos_theta >= 0.0 && cos_theta <= 1.0)) {
        const double nan = std::numeric_limits<double>::quiet_NaN();
        return {nan, nan, nan};
    }
    cos_theta = grazing_limit(cos_theta);
    if (const std::optional<Xyz> c = fast(thickness_nm, cos_theta)) {
        // Reflectances lie in [0, 1] and the weights are >= 0, so each channel lies in [0, the
        // white's]; the series' rounding (1e-8 at grazing incidence) and the quadrature's
        // departures (within max_quadrature_disagreement) are clamped to that.
        const Xyz& w = m_colorimeter->colorimeter().white();
        return {std::clamp(c->X, 0.0, w.X), std::clamp(c->Y, 0.0, w.Y), std::clamp(c->Z, 0.0, w.Z)};
    }
    return exact_sum(thickness_nm, cos_theta);
}

bool FourierFilm::summed_at(double thickness_nm, double cos_theta) const noexcept {
    if (!(std::isfinite(thickness_nm) && thickness_nm >= 0.0 && cos_theta >= 0.0 && cos_theta <= 1.0)) {
        return false;
    }
    return !fast(thickness_nm, grazing_limit(cos_theta));
}

std::optional<Xyz> FourierFilm::series(double thickness_nm, double cos_theta) const noexcept {
    if (m_sum_only) return std::nullopt;
    const FourierColorimeter& fc = *m_colorimeter;
    const double d = thickness_nm;
    const double sin2 = std::max(0.0, 1.0 - cos_theta * cos_theta);
    Xyz out;
    for (int b = 0; b < fc.bands(); ++b) {
        if (fc.slopes()) {
            // Where a node has no series (the film past its critical angle there, or |q| too
            // large): total reflection if every wavelength is past it, else the sum.
            bool no_series = false;
            if (!add_interpolated_band(b, d, cos_theta, sin2, out, no_series)) {
                return no_series ? total_reflection(d, cos_theta, sin2) : std::nullopt;
            }
            continue;
        }
        const BandMedia& m = m_media[b];
        std::array<Series, 2> set;
        double q1 = 0.0;
        if (!series_of(m.centre.n0, m.centre.n1, m.centre.n2, cos_theta, sin2, max_ratio, set, q1)) {
            return total_reflection(d, cos_theta, sin2);
        }
        const double dc = set[0].dc + set[1].dc;
        const Xyz& white = fc.band_white(b);
        out.X += dc * white.X;
        out.Y += dc * white.Y;
        out.Z += dc * white.Z;
        // The phase about the band's centre, φ = 4π d f(ν), f = ν q1, is linear: φ_c + 2π τ1
        // (ν − ν_c) with τ1 = 2 d f'(ν_c), f' the group value q1 − λ dq1/dλ from the indices'
        // slopes per nm; e^{imφ} W(...) = e^{imφ_c} V(m τ1).
        const double dq1 = (m.centre.n1 * m.dn1 - m.centre.n0 * m.dn0 * sin2) / q1;
        const double f1 = q1 - m.lambda_c * dq1;
        if (!(f1 > 0.0)) return std::nullopt;
        const double tau1 = 2.0 * d * f1;
        const std::complex<double> u = std::polar(1.0, 4.0 * pi * d * q1 / m.lambda_c);
        // term[p] = G q^{k-1} u^k at the k-th step of the loop. After k terms, what the rest can
        // add is at most 2 Σ_p |term_{k+1}| E(τ) / (1 − |q|), E the largest |V| from (k+1) τ1 on
        // (the table's envelope): with |term_{k+1}| <= |term_1| |q|max^k, one running product
        // decides when to stop.
        std::complex<double> term[2], ratio[2];
        double a_v = 0.0, q_max = 0.0;
        for (int p = 0; p < 2; ++p) {
            term[p] = set[p].g * u;
            ratio[p] = set[p].q * u;
            const double q_abs = std::sqrt(std::norm(set[p].q));
            a_v += std::sqrt(std::norm(term[p])) / (1.0 - q_abs);
            q_max = std::max(q_max, q_abs);
        }
        const double max_tau = fc.max_opd_nm(b);
        double q_power = 1.0;
        for (int k = 1; 2.0 * q_power * a_v * fc.envelope(b, k * tau1) > series_tolerance; ++k) {
            const double tau = k * tau1;
            if (tau >= max_tau) {
                // The terms past the table's end are dropped. What they can add is bounded by the
                // transform's level at the table's end: where that matters for a film whose first
                // terms are in the table (grazing incidence, |q| → 1), the sum is used instead. A
                // film whose first term is already past the table (OPD >= max_opd_nm) is the
                // incoherent sum of its faces, within 2 |G| × the floor.
                if (k > 1 && 2.0 * q_power * a_v * fc.band_floor(b) > max_dropped_tail) return std::nullopt;
                break;
            }
            const std::complex<double> t = term[0] + term[1];
            const auto v = fc.transform(b, tau);
            out.X += 2.0 * (t * v.x).real();
            out.Y += 2.0 * (t * v.y).real();
            out.Z += 2.0 * (t * v.z).real();
            for (int p = 0; p < 2; ++p) term[p] *= ratio[p];
            q_power *= q_max;
        }
    }
    return out;
}


bool FourierFilm::add_interpolated_band(int b, double thickness_nm, double cos_theta, double sin2, Xyz& out,
                                        bool& no_series) const noexcept {
    constexpr int n_nodes = FourierColorimeter::node_count;
    const FourierColorimeter& fc = *m_colorimeter;
    const BandMedia& m = m_media[b];
    const double d = thickness_nm;
    const double half = fc.band_half_width(b), nu_c = fc.band_wavenumber(b);
    // The series' coefficients and f = ν q1 at the nodes.
    std::array<std::array<Series, 2>, n_nodes> set;
    std::array<double, n_nodes> f{}, dc{};
    for (int j = 0; j < n_nodes; ++j) {
        double q1 = 0.0;
        if (!series_of(m.nodes[j].n0, m.nodes[j].n1, m.nodes[j].n2, cos_theta, sin2, max_ratio, set[j], q1)) {
            no_series = true;
            return false;
        }
        f[j] = fc.node_wavenumber(b, j) * q1;
        dc[j] = set[j][0].dc + set[j][1].dc;
    }
    // A0 and the phase must be as smooth as the nodes: their Chebyshev series converged by the
    // last coefficient.
    const auto a = chebyshev_coefficients(f);
    if (std::abs(chebyshev_coefficients(dc)[n_nodes - 1]) > max_amplitude_tail) return false;
    if (4.0 * pi * d * std::abs(a[n_nodes - 1]) > max_phase_tail) return false;
    // The carrier: φ's Chebyshev fit to first order, slope 4π d a_1 / half in ν, so τ1 = 2 d a_1 /
    // half; the residual ρ_j = 4π d (f_j − a_0 − a_1 x_j) is what the nodes interpolate, and
    // the group delay departs from τ1 by at most 2d Σ_{k>=2} k² |a_k| / half (|T_k'| <= k²).
    if (!(a[1] > 0.0)) return false;
    const double tau1 = 2.0 * d * a[1] / half;
    double residual = 0.0, spread = 0.0;
    for (int j = 0; j < n_nodes; ++j) {
        residual = std::max(residual, 4.0 * pi * d * std::abs(f[j] - a[0] - a[1] * FourierColorimeter::node_x(j)));
    }
    for (int k = 2; k < n_nodes; ++k) spread += 2.0 * d * k * k * std::abs(a[k]) / half;
    // The constant term: Σ_j A0(x_j) U_j(0). Its Y sets the scale of the budgets below: dark
    // films (index-matched ones reflect 1e-5 of the white) need absolute errors as small, in
    // proportion, as bright ones.
    double incoherent_y = 0.0;
    for (int j = 0; j < n_nodes; ++j) {
        const Xyz& w = fc.node_white(b, j);
        out.X += dc[j] * w.X;
        out.Y += dc[j] * w.Y;
        out.Z += dc[j] * w.Z;
        incoherent_y += dc[j] * w.Y;
    }
    const double scale = std::clamp(relative_budget * incoherent_y, 1e-3 * max_dropped_tail, 1.0);
    const double dropped_budget = std::min(max_dropped_tail, scale);
    const double interpolation_budget = std::min(max_interpolation_error, scale);
    // term[j][p] = G q^{k-1} z^k at node j for the k-th term, z = e^{i(φ − 2π τ1 (ν − ν_c))}.
    std::array<std::array<std::complex<double>, 2>, n_nodes> term, ratio;
    double a_sum = 0.0, q_max = 0.0;
    for (int j = 0; j < n_nodes; ++j) {
        const double nu = fc.node_wavenumber(b, j);
        const std::complex<double> z = std::polar(1.0, 4.0 * pi * d * f[j] - 2.0 * pi * tau1 * (nu - nu_c));
        double a_node = 0.0;
        for (int p = 0; p < 2; ++p) {
            term[j][p] = set[j][p].g * z;
            ratio[j][p] = set[j][p].q * z;
            const double q_abs = std::sqrt(std::norm(set[j][p].q));
            a_node += std::sqrt(std::norm(set[j][p].g)) / (1.0 - q_abs);
            q_max = std::max(q_max, q_abs);
        }
        a_sum = std::max(a_sum, a_node);
    }
    // What the terms from the k-th on can add: each is Σ_j P(x_j) U_j with |P(x_j)| <= the
    // largest node's, against transforms bounded by the envelopes from k (τ1 − spread) on (past
    // the nodal tables, V times the mean of the P(x_j)).
    const auto remaining = [&](int k, double q_power) {
        const double tau = std::max(0.0, k * (tau1 - spread));
        return 2.0 * q_power * a_sum * std::max(fc.envelope(b, tau), fc.node_envelope(b, tau));
    };
    const double max_tau = fc.max_opd_nm(b);
    const double node_tau = std::min(max_tau, FourierColorimeter::max_node_opd_nm);
    double q_power = 1.0, interpolation_error = 0.0;
    for (int k = 1; remaining(k, q_power) > series_tolerance; ++k) {
        const double tau = k * tau1;
        if (tau >= max_tau) {
            // Past the table's end, as for constant indices (series()).
            if (k > 1 && remaining(k, q_power) > dropped_budget) return false;
            break;
        }
        const double r = k * residual;
        if (r > max_residual_phase) {
            // Past what the nodes resolve: the sum, unless this term and the rest are negligible.
            if (remaining(k, q_power) > dropped_budget) return false;
            break;
        }
        std::array<std::complex<double>, n_nodes> values;
        double largest = 0.0;
        for (int j = 0; j < n_nodes; ++j) {
            values[j] = term[j][0] + term[j][1];
            largest = std::max(largest, std::norm(values[j]));
        }
        // The interpolant of e^{ikρ} (ρ the residual phase, of amplitude r at the nodes) through
        // seven nodes errs by up to about 0.06 r³ of the term inside the band where ρ holds a
        // third-order part up to 0.3 of its second (docs/OPTICS.md). Its transform's share at
        // this delay is bounded by the envelope.
        static_assert(n_nodes == 7, "the estimate's constant is for seven nodes");
        interpolation_error += 2.0 * std::sqrt(largest) * 0.06 * r * r * r *
                               fc.envelope(b, std::max(0.0, k * (tau1 - spread)));
        if (interpolation_error > interpolation_budget) return false;
        std::complex<double> x, y, z;
        if (tau < node_tau) {
            const auto v = fc.node_sum(b, tau, values);
            x = v.x;
            y = v.y;
            z = v.z;
        } else {
            std::complex<double> mean;
            for (int j = 0; j < n_nodes; ++j) mean += chebyshev_matrix()[0][j] * values[j];
            const auto v = fc.transform(b, tau);
            x = mean * v.x;
            y = mean * v.y;
            z = mean * v.z;
        }
        out.X += 2.0 * x.real();
        out.Y += 2.0 * y.real();
        out.Z += 2.0 * z.real();
        for (int j = 0; j < n_nodes; ++j) {
            for (int pol = 0; pol < 2; ++pol) term[j][pol] *= ratio[j][pol];
        }
        q_power *= q_max;
    }
    return true;
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
