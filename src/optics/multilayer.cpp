#include <irid/color/numeric_table.h>
#include <irid/error.h>
#include <irid/optics/multilayer.h>

#include <algorithm>
#include <cassert>
#include <cmath>
#include <numbers>
#include <string>
#include <utility>

namespace irid {
namespace {

/// Im δ above which a layer passes less than e^-72 (< 1e-31) of the power crossing it: what lies
/// beneath it changes R by less than double precision resolves, so the layer acts as the
/// substrate and T = 0. Keeps the characteristic matrix, which grows as e^|Im δ|, finite for
/// thick metal or tunnelling layers [dimensionless, phase in radians].
inline constexpr double opaque_layer_phase_imag = 36.0;

/// The imaginary unit.
inline constexpr Complex imaginary_unit{0.0, 1.0};

/// Below this |z| sin(z)/z is its Taylor series 1 - z²/6 + z⁴/120, whose truncation error
/// (< |z|⁶/5040 < 2e-22) is below double precision.
inline constexpr double sinc_series_limit = 1e-3;

/// q = N cos θ = sqrt(N² - s²) on the branch Im q >= 0 (Re q >= 0 when q is real): a wave
/// exp(2πi q z / λ) that decays, or propagates, into +z (Born & Wolf §1.5.4 for total
/// reflection, ch. 14 for absorbing media).
Complex normal_index(Complex n, double snell_invariant) noexcept {
    Complex q = std::sqrt(n * n - snell_invariant * snell_invariant);
    if (q.imag() < 0.0 || (q.imag() == 0.0 && q.real() < 0.0)) q = -q;
    return q;
}

/// The same q in a stack lit from a lossless ambient n0 at cos θ0, written as
/// sqrt((N − n0)(N + n0) + q0²) with q0 = n0 cos θ0: equal to sqrt(N² − n0² sin²θ0), but it
/// keeps q0's precision near grazing incidence, where sin θ0 rounds to 1 and N² − s² would lose
/// every digit (an air film in air must stay invisible at 89.9999999°).
Complex normal_index_from(Complex n, double n0, double q0) noexcept {
    Complex q = std::sqrt((n - n0) * (n + n0) + q0 * q0);
    if (q.imag() < 0.0 || (q.imag() == 0.0 && q.real() < 0.0)) q = -q;
    return q;
}

/// Above this |B| + |C| the characteristic product is rescaled (r is a ratio and does not
/// change); what is transmitted is then below e^-230 of the incident power and is taken as 0.
inline constexpr double rescale_limit = 1e100;

/// The tilted admittance η = num / den of a medium (Macleod ch. 2): s: η = N cos θ = q / 1;
/// p: η = N / cos θ = N² / q. Kept as a fraction because the p admittance is infinite where
/// cos θ = 0 (exactly at the critical angle) while every physical quantity stays finite.
struct Admittance {
    Complex num;
    Complex den;
};

Admittance admittance(Complex n, Complex q, Polarization polarization) noexcept {
    assert(polarization != Polarization::unpolarized);
    if (polarization == Polarization::s) return {q, 1.0};
    return {n * n, q};
}

/// Amplitude reflection coefficient (η_a - η_b) / (η_a + η_b) going from medium a into b.
Complex reflection(const Admittance& a, const Admittance& b) noexcept {
    return (a.num * b.den - b.num * a.den) / (a.num * b.den + b.num * a.den);
}

/// Tangential-field transmission coefficient 2 η_a / (η_a + η_b) divided by b.den: finite even
/// where b.den = 0, and what flux_into() takes.
Complex transmission_over_den(const Admittance& a, const Admittance& b) noexcept {
    return 2.0 * a.num / (a.num * b.den + b.num * a.den);
}

/// Power carried towards +z by a tangential field E = den · e in a medium of admittance η:
/// Re(η) |E|² = Re(num conj(den)) |e|² (Macleod ch. 2; the common factor ½ Y_free cancels in
/// every ratio).
double flux_into(const Admittance& y, Complex e) noexcept {
    return (y.num * std::conj(y.den)).real() * std::norm(e);
}

/// sin(z) / z, 1 at z = 0.
Complex sinc(Complex z) noexcept {
    if (std::abs(z) < sinc_series_limit) {
        const Complex z2 = z * z;
        return 1.0 - z2 / 6.0 + z2 * z2 / 120.0;
    }
    return std::sin(z) / z;
}

Optics mean(const Optics& a, const Optics& b) noexcept {
    return {0.5 * (a.R + b.R), 0.5 * (a.T + b.T)};
}

/// Tangential fields (B, C) at the top of the stack from those at its bottom, by one layer's
/// characteristic matrix [[cos δ, -i sin δ / η], [-i η sin δ, cos δ]] (Born & Wolf §1.6.2),
/// δ = phase_per_q · q with phase_per_q = 2π d / λ. sin δ / η and η sin δ are written with
/// u = phase_per_q · sinc δ, so without dividing by q:
/// s: sin δ / η = u, η sin δ = u q²; p: sin δ / η = u q² / N², η sin δ = u N².
void apply_layer(Complex n, Complex q, double phase_per_q, Polarization polarization, Complex& b,
                 Complex& c) noexcept {
    const Complex delta = phase_per_q * q;
    const Complex cos_delta = std::cos(delta);
    const Complex u = phase_per_q * sinc(delta);
    const Complex q2 = q * q;
    const bool s = polarization == Polarization::s;
    const Complex sin_over_eta = s ? u : u * q2 / (n * n);
    const Complex eta_sin = s ? u * q2 : u * n * n;
    const Complex top_b = cos_delta * b - imaginary_unit * sin_over_eta * c;
    const Complex top_c = -imaginary_unit * eta_sin * b + cos_delta * c;
    b = top_b;
    c = top_c;
}

}  // namespace

void check_incidence_angle(double angle_rad) {
    if (!(angle_rad >= 0.0 && angle_rad < std::numbers::pi / 2.0)) {
        throw Error("angle of incidence " + format_shortest(angle_rad) +
                    " rad must be in [0, pi/2)");
    }
}

Complex cos_theta(Complex n, double snell_invariant) noexcept {
    return normal_index(n, snell_invariant) / n;
}

namespace {

FresnelCoefficients fresnel_of(Complex n_i, Complex n_t, Complex q_i, Complex q_t) noexcept {
    const auto coefficients = [&](Polarization polarization) {
        const Admittance a = admittance(n_i, q_i, polarization);
        const Admittance b = admittance(n_t, q_t, polarization);
        return std::pair{reflection(a, b), b.den * transmission_over_den(a, b)};
    };
    const auto [r_s, t_s] = coefficients(Polarization::s);
    const auto [r_p, t_p] = coefficients(Polarization::p);
    return {r_s, r_p, t_s, t_p};
}

}  // namespace

FresnelCoefficients fresnel(Complex n_i, Complex n_t, double snell_invariant) noexcept {
    return fresnel_of(n_i, n_t, normal_index(n_i, snell_invariant), normal_index(n_t, snell_invariant));
}

FresnelCoefficients fresnel_from(Complex n_i, Complex n_t, double n0, double q0) noexcept {
    return fresnel_of(n_i, n_t, normal_index_from(n_i, n0, q0), normal_index_from(n_t, n0, q0));
}

Optics airy_film(double n0, Complex n1, Complex n2, double thickness_nm, double lambda_nm,
                 double angle_rad, Polarization polarization) noexcept {
    if (polarization == Polarization::unpolarized) {
        return mean(airy_film(n0, n1, n2, thickness_nm, lambda_nm, angle_rad, Polarization::s),
                    airy_film(n0, n1, n2, thickness_nm, lambda_nm, angle_rad, Polarization::p));
    }
    const double q0 = n0 * std::cos(angle_rad);
    const Complex q1 = normal_index_from(n1, n0, q0);
    const Admittance y0 = admittance(n0, q0, polarization);
    const Admittance y1 = admittance(n1, q1, polarization);
    const Admittance y2 = admittance(n2, normal_index_from(n2, n0, q0), polarization);

    // One pass through the film multiplies the field by e^{iβ}; the internal reflections form a
    // geometric series in r10 r12 e^{2iβ} = -r01 r12 e^{2iβ} (Born & Wolf §7.6.1).
    const double beta_per_q = 2.0 * std::numbers::pi * thickness_nm / lambda_nm;
    const Complex pass = std::exp(imaginary_unit * beta_per_q * q1);
    const Complex r01 = reflection(y0, y1);
    const Complex r12 = reflection(y1, y2);
    const Complex round_trip = r12 * pass * pass;
    const Complex denominator = 1.0 + r01 * round_trip;
    const Complex r = (r01 + round_trip) / denominator;
    // t = t01 t12 e^{iβ} / denominator, divided by y2.den for flux_into; the incident wave
    // carries η0 (real: the ambient is lossless).
    const Complex t01 = y1.den * transmission_over_den(y0, y1);
    const Complex t_over_den = t01 * transmission_over_den(y1, y2) * pass / denominator;
    const double eta0 = (y0.num / y0.den).real();
    return {std::norm(r), flux_into(y2, t_over_den) / eta0};
}

FilmStack::FilmStack(Material ambient, std::vector<Layer> layers, Material substrate)
    : m_ambient(std::move(ambient)),
      m_layers(std::move(layers)),
      m_substrate(std::move(substrate)) {
    for (std::size_t i = 0; i < m_layers.size(); ++i) {
        const double d = m_layers[i].thickness_nm;
        const std::string what = "layer " + std::to_string(i + 1) + " thickness ";
        if (!std::isfinite(d)) throw Error(what + format_shortest(d) + " nm must be finite");
        if (d < 0.0) throw Error(what + format_shortest(d) + " nm must be >= 0");
    }
    if (!m_ambient.is_lossless()) {
        throw Error("ambient '" + m_ambient.name() +
                    "' absorbs; the ambient must be non-absorbing (k = 0) so that the angle of "
                    "incidence is real");
    }
}

Optics FilmStack::evaluate(double lambda_nm, double angle_rad,
                           Polarization polarization) const noexcept {
    if (polarization == Polarization::unpolarized) {
        return mean(evaluate(lambda_nm, angle_rad, Polarization::s),
                    evaluate(lambda_nm, angle_rad, Polarization::p));
    }
    assert(lambda_nm > 0.0 && angle_rad >= 0.0 && angle_rad < std::numbers::pi / 2.0);
    const double n0 = m_ambient.index(lambda_nm).real();
    const double q0 = n0 * std::cos(angle_rad);
    const Admittance y0 = admittance(n0, q0, polarization);
    const Complex ns = m_substrate.index(lambda_nm);
    const Admittance ys = admittance(ns, normal_index_from(ns, n0, q0), polarization);

    // (B, C) = M_1 ... M_L (1, η_s), scaled by η_s's denominator, which leaves r unchanged and
    // is undone in T by flux_into. Built from the substrate up.
    Complex b = ys.den;
    Complex c = ys.num;
    bool transmits = true;
    for (auto layer = m_layers.rbegin(); layer != m_layers.rend(); ++layer) {
        const Complex n = layer->material.index(lambda_nm);
        const Complex q = normal_index_from(n, n0, q0);
        const double phase_per_q = 2.0 * std::numbers::pi * layer->thickness_nm / lambda_nm;
        if ((phase_per_q * q).imag() > opaque_layer_phase_imag) {
            const Admittance y = admittance(n, q, polarization);
            b = y.den;
            c = y.num;
            transmits = false;
            continue;
        }
        apply_layer(n, q, phase_per_q, polarization, b, c);
        // Many absorbing or tunnelling layers together grow (B, C) as e^(Σ Im δ).
        if (std::abs(b) + std::abs(c) > rescale_limit) {
            b /= rescale_limit;
            c /= rescale_limit;
            transmits = false;
        }
    }

    const double eta0 = (y0.num / y0.den).real();
    const Complex sum = eta0 * b + c;
    // |r| <= 1 and T <= 1 physically; rounding may step past 1 under total reflection.
    const double reflectance = std::min(1.0, std::norm((eta0 * b - c) / sum));
    // T = 4 η0 Re(η_s) / |η0 B + C|²: the substrate receives the field 2 η0 / (η0 B + C), over
    // the η0 of the unit incident field.
    const double transmittance =
        transmits ? std::clamp(flux_into(ys, 2.0 * eta0 / sum) / eta0, 0.0, 1.0) : 0.0;
    return {reflectance, transmittance};
}

}  // namespace irid
