#include <irid/color/numeric_table.h>
#include <irid/error.h>
#include <irid/optics/thesis_models.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <numbers>
#include <span>
#include <string>
#include <string_view>

namespace irid {
namespace {

constexpr double pi = std::numbers::pi;

double radians(double degrees) noexcept {
    return degrees * pi / 180.0;
}

// --- Validation: every message names the model, the parameter, its value and what is allowed.

[[noreturn]] void reject(std::string_view model, std::string_view name, double value,
                         std::string_view unit, std::string_view allowed) {
    std::string message =
        std::string(model) + ": " + std::string(name) + " " + format_shortest(value);
    if (!unit.empty()) message += " " + std::string(unit);
    throw Error(message + " must be " + std::string(allowed));
}

void require_at_least(std::string_view model, std::string_view name, double value,
                      std::string_view unit, double minimum) {
    if (!(std::isfinite(value) && value >= minimum))
        reject(model, name, value, unit, "finite and >= " + format_shortest(minimum));
}

void require_positive(std::string_view model, std::string_view name, double value) {
    if (!(std::isfinite(value) && value > 0.0)) reject(model, name, value, "", "finite and > 0");
}

void require_periods(std::string_view model, int periods) {
    try {
        check_thesis_periods(periods);
    } catch (const Error& e) {
        throw Error(std::string(model) + ": " + e.what());
    }
}

/// Angles are in the ambient medium, measured from the normal: grazing (90°) is excluded.
void require_angle(std::string_view model, double angle_deg) {
    if (!(angle_deg >= 0.0 && angle_deg < 90.0))
        reject(model, "angle", angle_deg, "deg", "in [0, 90) deg");
}

// --- Colour tables: XYZ at equal steps of one variable, linear in between.

/// Number of equal intervals of at most `step` covering [0, range]; a quotient like
/// 90 / 0.1 = 900.0000000000001 is taken as the whole number it rounds from.
std::size_t interval_count(double range, double step) noexcept {
    return static_cast<std::size_t>(std::ceil(range / step - 1e-9));
}

Xyz mix(const Xyz& a, const Xyz& b, double f) noexcept {
    return {a.X + f * (b.X - a.X), a.Y + f * (b.Y - a.Y), a.Z + f * (b.Z - a.Z)};
}

Xyz scaled(const Xyz& c, double k) noexcept {
    return {k * c.X, k * c.Y, k * c.Z};
}

/// Linear interpolation in a table sampled at 0, step, 2 step, ...; clamped to its ends.
Xyz interpolate(std::span<const Xyz> table, double step, double x) noexcept {
    const double u = x / step;
    if (!(u > 0.0)) return table.front();  // also NaN
    const double last = static_cast<double>(table.size() - 1);
    if (u >= last) return table.back();
    const auto i = static_cast<std::size_t>(u);
    return mix(table[i], table[i + 1], u - static_cast<double>(i));
}

// --- Eq. 25 near its removable singularities.

/// |sin(N x) / sin(x)| for x = π u, N ≥ 1: the amplitude of N equal beams each delayed by 2x.
/// Writing x = mπ + δ with m the integer nearest u, sin(Nx)/sin(x) = ±sin(Nδ)/sin(δ), and
/// δ = π(u − m) is computed without cancellation (u − m is exact), so the ratio keeps full
/// precision up to the pole. Where Nδ is tiny the series N[1 − (N² − 1)δ²/6 + O(N⁴δ⁴)] gives the
/// limit N at δ = 0 (the O(N⁴δ⁴) term is below rounding for N|δ| < 1e-4). The sign is
/// irrelevant: eq. 25 squares the ratio.
double beam_sum_ratio(int beams, double u) noexcept {
    const double n = static_cast<double>(beams);
    const double delta = pi * (u - std::nearbyint(u));
    if (std::abs(n * delta) < 1e-4) return n * (1.0 - (n * n - 1.0) * delta * delta / 6.0);
    return std::abs(std::sin(n * delta) / std::sin(delta));
}

/// The root (n² − sin²θ)^½ shared by eq. 26 and 29: n cos θ_film for a film in air. Kept ≥ 0 so
/// that an index below 1 (rejected by validation) cannot produce a NaN.
double cos_term(double n, double theta_rad) noexcept {
    const double s = std::sin(theta_rad);
    return std::sqrt(std::max(0.0, n * n - s * s));
}

}  // namespace

// --- One film ------------------------------------------------------------------------------

void validate_thesis_film(const ThesisFilmParameters& film) {
    constexpr std::string_view model = "thesis film";
    require_positive(model, "n_film", film.n_film);
    require_positive(model, "n_ambient", film.n_ambient);
    require_at_least(model, "K", film.K, "", 0.0);
}

bool thesis_phase_change(double n_ambient, double n_film, double n_substrate) noexcept {
    const bool shift_at_top = n_film > n_ambient;       // ambient → film
    const bool shift_at_bottom = n_substrate > n_film;  // film → substrate
    return shift_at_top != shift_at_bottom;
}

double thesis_film_reflectance(double lambda_nm, double thickness_nm, double n_film,
                               bool phase_change, double K) noexcept {
    // Two beams whose paths differ by 2tn: their phase difference (eq. 19) is 2π·2tn/λ, plus π
    // with a phase change, and their sum's intensity is cos² of half of it. With the phase
    // change, cos(a + π/2) = −sin(a), which is exactly 0 at t = 0.
    const double half_phase = 2.0 * pi * thickness_nm * n_film / lambda_nm;
    const double amplitude = K * (phase_change ? std::sin(half_phase) : std::cos(half_phase));
    return amplitude * amplitude;
}

double thesis_film_angle_rad(double theta_ambient_rad, double n_film, double n_ambient) noexcept {
    const double sin_film = n_ambient * std::sin(theta_ambient_rad) / n_film;
    return sin_film >= 1.0 ? pi / 2.0 : std::asin(sin_film);
}

double thesis_effective_thickness_nm(double thickness_nm, double n_film,
                                     double theta_film_rad) noexcept {
    return thickness_nm * n_film * std::cos(theta_film_rad);
}

DenseSpectrum thesis_film_spectrum(const ThesisFilmParameters& film, double thickness_nm,
                                   double angle_deg) {
    validate_thesis_film(film);
    require_at_least("thesis film", "thickness", thickness_nm, "nm", 0.0);
    require_angle("thesis film", angle_deg);
    const double theta_film =
        thesis_film_angle_rad(radians(angle_deg), film.n_film, film.n_ambient);
    const double t_eff = thesis_effective_thickness_nm(thickness_nm, film.n_film, theta_film);
    return DenseSpectrum::from_function([&](double lambda_nm) {
        return thesis_film_reflectance(lambda_nm, t_eff, 1.0, film.phase_change, film.K);
    });
}

ThesisFilmTable::ThesisFilmTable(bool phase_change, double max_effective_thickness_nm,
                                 double step_nm, const DenseSpectrum& illuminant, Observer observer)
    : m_phase_change(phase_change) {
    constexpr std::string_view model = "thesis film table";
    if (!(max_effective_thickness_nm > 0.0 && max_effective_thickness_nm <= 1e6))
        reject(model, "max effective thickness", max_effective_thickness_nm, "nm",
               "in (0, 1e6] nm");
    if (!(step_nm > 0.0 && step_nm <= max_effective_thickness_nm))
        reject(model, "step", step_nm, "nm",
               "in (0, " + format_shortest(max_effective_thickness_nm) + "] nm");
    if (max_effective_thickness_nm / step_nm > 1e7)
        reject(model, "step", step_nm, "nm",
               ">= " + format_shortest(max_effective_thickness_nm / 1e7) +
                   " nm (at most 1e7 entries)");
    (void)illuminant_white(illuminant, observer);  // throws when the illuminant has no luminance

    const std::size_t intervals = interval_count(max_effective_thickness_nm, step_nm);
    m_step_nm = max_effective_thickness_nm / static_cast<double>(intervals);
    m_colors.reserve(intervals + 1);
    for (std::size_t i = 0; i <= intervals; ++i) {
        const double t_eff = m_step_nm * static_cast<double>(i);
        const DenseSpectrum rho = DenseSpectrum::from_function([&](double lambda_nm) {
            return thesis_film_reflectance(lambda_nm, t_eff, 1.0, phase_change);
        });
        m_colors.push_back(reflectance_to_xyz(rho, illuminant, observer));
    }
}

Xyz ThesisFilmTable::at(double effective_thickness_nm, double K) const noexcept {
    return scaled(interpolate(m_colors, m_step_nm, effective_thickness_nm), K * K);
}

double ThesisFilmTable::max_effective_thickness_nm() const noexcept {
    return m_step_nm * static_cast<double>(m_colors.size() - 1);
}

// --- Multiple films ------------------------------------------------------------------------

void check_thesis_periods(int periods) {
    if (periods < thesis_min_periods || periods > thesis_max_periods) {
        throw Error("periods " + std::to_string(periods) + " must be in " + std::to_string(thesis_min_periods) +
                    ".." + std::to_string(thesis_max_periods) + " (l, the number of films of eq. 25)");
    }
}

void check_thesis_air_index(double n, std::string_view what) {
    if (!(std::isfinite(n) && n >= 1.0)) {
        throw Error("eq. 26 needs the film's index >= 1 (air around it); " + std::string(what) + " has " +
                    format_shortest(n));
    }
}

void validate_thesis_multilayer(const ThesisMultilayerParameters& stack) {
    constexpr std::string_view model = "thesis multilayer";
    require_at_least(model, "n", stack.n, "", 1.0);
    require_periods(model, stack.periods);
    require_at_least(model, "K", stack.K, "", 0.0);
}

double thesis_multilayer_reflectance(double lambda_nm, double effective_thickness_nm, int periods,
                                     double K) noexcept {
    // 2πt/λ = π u with u = 2t/λ: the poles are at whole u, where 2t = mλ.
    const double ratio = beam_sum_ratio(periods + 1, 2.0 * effective_thickness_nm / lambda_nm);
    return 0.5 * K * ratio * ratio;
}

double thesis_unit_peak_k(int periods) noexcept {
    const double beams = static_cast<double>(periods) + 1.0;
    return 2.0 / (beams * beams);
}

double thesis_multilayer_effective_thickness_nm(double thickness_nm, double n,
                                                double theta_rad) noexcept {
    return thickness_nm * cos_term(n, theta_rad);
}

DenseSpectrum thesis_multilayer_spectrum(const ThesisMultilayerParameters& stack,
                                         double thickness_nm, double angle_deg) {
    validate_thesis_multilayer(stack);
    require_at_least("thesis multilayer", "thickness", thickness_nm, "nm", 0.0);
    require_angle("thesis multilayer", angle_deg);
    const double t_eff =
        thesis_multilayer_effective_thickness_nm(thickness_nm, stack.n, radians(angle_deg));
    return DenseSpectrum::from_function([&](double lambda_nm) {
        return thesis_multilayer_reflectance(lambda_nm, t_eff, stack.periods, stack.K);
    });
}

// --- The Morpho wing -----------------------------------------------------------------------

void validate_morpho(const MorphoParameters& wing) {
    constexpr std::string_view model = "morpho";
    require_at_least(model, "d1", wing.d1_nm, "nm", 0.0);
    require_at_least(model, "d2", wing.d2_nm, "nm", 0.0);
    require_at_least(model, "n", wing.n, "", 1.0);
    require_periods(model, wing.periods);
    require_at_least(model, "K", wing.K, "", 0.0);
}

void validate_morpho_blend(const MorphoBlend& blend) {
    constexpr std::string_view model = "morpho blend";
    require_at_least(model, "min", blend.min_nm, "nm", 0.0);
    require_at_least(model, "max", blend.max_nm, "nm", blend.min_nm);
    if (blend.samples < 2 || blend.samples > 100'000)
        reject(model, "samples", blend.samples, "", "in [2, 100000]");
}

double morpho_effective_thickness_nm(const MorphoParameters& wing, double theta_rad) noexcept {
    return wing.d1_nm * std::cos(theta_rad) + wing.d2_nm * cos_term(wing.n, theta_rad);
}

double morpho_reflectance(const MorphoParameters& wing, double lambda_nm,
                          double theta_rad) noexcept {
    return thesis_multilayer_reflectance(lambda_nm, morpho_effective_thickness_nm(wing, theta_rad),
                                         wing.periods, wing.K);
}

namespace {

/// Eq. 25 with eq. 29 on the 1 nm grid, for a validated wing, at θ [rad] in air.
DenseSpectrum wing_spectrum(const MorphoParameters& wing, double theta_rad) {
    return DenseSpectrum::from_function(
        [&](double lambda_nm) { return morpho_reflectance(wing, lambda_nm, theta_rad); });
}

/// The blended wing on the 1 nm grid, for a validated wing and blend.
DenseSpectrum blended_wing_spectrum(const MorphoParameters& wing, const MorphoBlend& blend,
                                    double theta_rad) {
    return DenseSpectrum::from_function([&](double lambda_nm) {
        return morpho_blend_reflectance(wing, blend, lambda_nm, theta_rad);
    });
}

}  // namespace

double morpho_blend_reflectance(const MorphoParameters& wing, const MorphoBlend& blend,
                                double lambda_nm, double theta_rad) noexcept {
    const double step = (blend.max_nm - blend.min_nm) / static_cast<double>(blend.samples - 1);
    MorphoParameters sample = wing;
    double& varied = blend.varies == MorphoBlendThickness::d1 ? sample.d1_nm : sample.d2_nm;
    double sum = 0.0;
    for (int i = 0; i < blend.samples; ++i) {
        varied = blend.min_nm + step * static_cast<double>(i);
        sum += morpho_reflectance(sample, lambda_nm, theta_rad);
    }
    return sum * (1.0 / static_cast<double>(blend.samples));
}

double morpho_blend_reflectance_continuous(const MorphoParameters& wing, const MorphoBlend& blend,
                                           double lambda_nm, double theta_rad) noexcept {
    MorphoParameters lo = wing, hi = wing;
    double& lo_varied = blend.varies == MorphoBlendThickness::d1 ? lo.d1_nm : lo.d2_nm;
    double& hi_varied = blend.varies == MorphoBlendThickness::d1 ? hi.d1_nm : hi.d2_nm;
    lo_varied = blend.min_nm;
    hi_varied = blend.max_nm;
    const double to_x = 2.0 * std::numbers::pi / lambda_nm;
    const double xa = to_x * morpho_effective_thickness_nm(lo, theta_rad);
    const double xb = to_x * morpho_effective_thickness_nm(hi, theta_rad);
    // A range too narrow to average over (grazing incidence with d₁ varied, or min = max).
    if (std::abs(xb - xa) < 1e-9) return morpho_reflectance(lo, lambda_nm, theta_rad);
    const int l = wing.periods;
    double mean = l + 1.0;
    for (int k = 1; k <= l; ++k) {
        const double twice_k = 2.0 * k;
        mean += 2.0 * (l + 1.0 - k) * (std::sin(twice_k * xb) - std::sin(twice_k * xa)) /
                (twice_k * (xb - xa));
    }
    return 0.5 * wing.K * mean;
}

DenseSpectrum morpho_spectrum(const MorphoParameters& wing, double angle_deg) {
    validate_morpho(wing);
    require_angle("morpho", angle_deg);
    return wing_spectrum(wing, radians(angle_deg));
}

DenseSpectrum morpho_blend_spectrum(const MorphoParameters& wing, const MorphoBlend& blend,
                                    double angle_deg) {
    validate_morpho(wing);
    validate_morpho_blend(blend);
    require_angle("morpho", angle_deg);
    return blended_wing_spectrum(wing, blend, radians(angle_deg));
}

MorphoTable::MorphoTable(const MorphoParameters& wing, const DenseSpectrum& illuminant,
                         Observer observer, double step_deg,
                         const std::optional<MorphoBlend>& blend) {
    validate_morpho(wing);
    if (blend) validate_morpho_blend(*blend);
    if (!(step_deg > 0.0 && step_deg <= 90.0))
        reject("morpho table", "step", step_deg, "deg", "in (0, 90] deg");
    (void)illuminant_white(illuminant, observer);  // throws when the illuminant has no luminance

    const std::size_t intervals = interval_count(90.0, step_deg);
    m_step_deg = 90.0 / static_cast<double>(intervals);
    m_colors.reserve(intervals + 1);
    for (std::size_t i = 0; i <= intervals; ++i) {
        // The last node is grazing incidence, which the spectrum helpers do not accept.
        const double theta = radians(m_step_deg * static_cast<double>(i));
        const DenseSpectrum rho =
            blend ? blended_wing_spectrum(wing, *blend, theta) : wing_spectrum(wing, theta);
        m_colors.push_back(reflectance_to_xyz(rho, illuminant, observer));
    }
}

Xyz MorphoTable::at(double angle_deg) const noexcept {
    return interpolate(m_colors, m_step_deg, angle_deg);
}

}  // namespace irid
