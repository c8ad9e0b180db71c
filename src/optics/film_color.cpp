#include <irid/color/difference.h>
#include <irid/color/numeric_table.h>
#include <irid/color/spaces.h>
#include <irid/error.h>
#include <irid/optics/film_color.h>
#include <irid/optics/fine_sum.h>
#include <irid/optics/thesis_models.h>


#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

namespace irid {
namespace {

/// The most entries a colour table may have: 10⁷ colours are 480 MB.
constexpr double max_table_entries = 1e7;

FilmColor color_of(const Colorimeter& colorimeter, const Xyz& xyz) {
    return {xyz, colorimeter.linear_rgb(xyz)};
}

}  // namespace

// --- spectra --------------------------------------------------------------------------------

DenseSpectrum exact_reflectance_spectrum(const FilmStack& stack, double angle_rad,
                                         Polarization polarization) {
    return DenseSpectrum::from_function(
        [&](double lambda) { return stack.evaluate(lambda, angle_rad, polarization).R; });
}

PreparedFilm::Sample PreparedFilm::prepare(const SingleFilm& film, double cos_theta0, int i,
                                           bool& degenerate) noexcept {
    return prepare_at(film, cos_theta0, DenseSpectrum::wavelength_nm(i), degenerate);
}

PreparedFilm::Sample PreparedFilm::prepare_at(const SingleFilm& film, double cos_theta0, double lambda,
                                              bool& degenerate) noexcept {
    return prepare_media(film.ambient.index(lambda).real(), film.film.index(lambda), film.substrate.index(lambda),
                         cos_theta0, lambda, degenerate);
}

PreparedFilm::Sample PreparedFilm::prepare_media(double a, Complex n1, Complex n2, double cos_theta0, double lambda,
                                                 bool& degenerate) noexcept {
    constexpr std::complex<double> two_i{0.0, 2.0};
    const double q0 = a * cos_theta0;
    const double phase_scale = 2.0 * std::numbers::pi / lambda;
    // q = N cos θ = sqrt((N − n0)(N + n0) + q0²): N² − n0² sin²θ0 written so that it keeps q0's
    // precision near grazing incidence.
    const auto q_of = [&](Complex n) {
        Complex q = std::sqrt((n - a) * (n + a) + q0 * q0);
        if (q.imag() < 0.0 || (q.imag() == 0.0 && q.real() < 0.0)) q = -q;
        return q;
    };
    // Lossless film and substrate below their critical angles: every q is real (the same
    // square root, taken in real arithmetic, a third of the cost of the complex one).
    const double p1_sq = (n1.real() - a) * (n1.real() + a) + q0 * q0;
    const double p2_sq = (n2.real() - a) * (n2.real() + a) + q0 * q0;
    const bool real = n1.imag() == 0.0 && n2.imag() == 0.0 && p1_sq >= 0.0 && p2_sq >= 0.0;
    const Complex q1 = real ? Complex(std::sqrt(p1_sq)) : q_of(n1);
    const Complex q2 = real ? Complex(std::sqrt(p2_sq)) : q_of(n2);
    // Near the film's own critical angle (q1 → 0) both faces reflect totally and the Airy sum
    // becomes a ratio of vanishing quantities that rounding ruins: the transfer matrix (with its
    // sinc) is evaluated there instead.
    degenerate = real ? q1.real() < 1e-3 * n1.real() : std::abs(q1) < 1e-3 * std::abs(n1);
    if (real || (n1.imag() == 0.0 && n2.imag() == 0.0 && q1.imag() == 0.0 && q2.imag() == 0.0)) {
        // Lossless film and substrate, no total reflection: every q is real and the Fresnel
        // amplitudes are r_s = (q_i − q_t)/(q_i + q_t) and, as the ratio of tangential fields,
        // r_p = (N_i² q_t − N_t² q_i)/(N_i² q_t + N_t² q_i) (Born & Wolf §1.5.2; the sign
        // convention cancels in |r|²).
        const double b = n1.real(), c = n2.real(), p1 = q1.real(), p2 = q2.real();
        Sample out{(q0 - p1) / (q0 + p1), (p1 - p2) / (p1 + p2),
                   (a * a * p1 - b * b * q0) / (a * a * p1 + b * b * q0),
                   (b * b * p2 - c * c * p1) / (b * b * p2 + c * c * p1), two_i * (phase_scale * p1),
                   true, {}, {}, {}};
        // Each face's amplitude is (U − V)/(U + V) with U, V >= 0 (s: U = N cos θ of the
        // incident side, V of the other; p: the tangential-field forms above). Then
        // 1 − r² = 4UV/(U + V)² and 1 + r01 r12 = 2(U U' + V V') / ((U + V)(U' + V')): sums of
        // products of non-negative numbers, exact to rounding even where r → ±1.
        const double faces[2][4] = {{q0, p1, p1, p2}, {a * a * p1, b * b * q0, b * b * p2, c * c * p1}};
        for (int k = 0; k < 2; ++k) {
            const double u = faces[k][0], v = faces[k][1], u2 = faces[k][2], v2 = faces[k][3];
            const double s01 = u + v, s12 = u2 + v2;
            const double r01 = (u - v) / s01, r12 = (u2 - v2) / s12;
            const double one_plus_x = 2.0 * (u * u2 + v * v2) / (s01 * s12);
            out.x[k] = r01 * r12;
            out.transmitted[k] = (4.0 * u * v / (s01 * s01)) * (4.0 * u2 * v2 / (s12 * s12));
            out.one_plus_x_sq[k] = one_plus_x * one_plus_x;
        }
        return out;
    }
    // The same amplitudes in complex form (absorbing media, evanescent waves).
    const Complex a2(a * a, 0.0), b2 = n1 * n1, c2 = n2 * n2;
    return {(q0 - q1) / (q0 + q1), (q1 - q2) / (q1 + q2), (a2 * q1 - b2 * q0) / (a2 * q1 + b2 * q0),
            (b2 * q2 - c2 * q1) / (b2 * q2 + c2 * q1), two_i * phase_scale * q1, false, {}, {}, {}};
}

double PreparedFilm::airy_reflectance(const Sample& s, double thickness_nm) noexcept {
    if (s.real) {
        // 1 + x² + 2x cos φ = (1 + x)² − 4x sin²(φ/2): no cancellation where x → −1.
        const double h = std::sin(0.5 * s.phase_per_nm.imag() * thickness_nm);
        const double h2 = 4.0 * h * h;
        const auto transmitted = [&s, h2](int k) {
            const double den = s.one_plus_x_sq[k] - s.x[k] * h2;
            // den >= (1 − |x|)² > 0 for real amplitudes; it is 0 only where a face is a perfect
            // mirror (grazing incidence exactly), whose transmittance is 0.
            return den > 0.0 ? s.transmitted[k] / den : 0.0;
        };
        return std::clamp(1.0 - 0.5 * (transmitted(0) + transmitted(1)), 0.0, 1.0);
    }
    const std::complex<double> z = std::exp(s.phase_per_nm * thickness_nm);
    const auto airy = [&](std::complex<double> r01, std::complex<double> r12) {
        const std::complex<double> r12z = r12 * z;
        return std::norm(r01 + r12z) / std::norm(1.0 + r01 * r12z);
    };
    // Passive media reflect at most what arrives; rounding where a face reflects totally (|r01|
    // = 1) may give 1 + 1e-12.
    return std::clamp(0.5 * (airy(s.r01_s, s.r12_s) + airy(s.r01_p, s.r12_p)), 0.0, 1.0);
}

namespace {

void check_film_angle(const SingleFilm& film, double angle_rad) {
    check_incidence_angle(angle_rad);
    if (!film.ambient.is_lossless()) {
        throw Error("film: the ambient medium '" + film.ambient.name() +
                    "' absorbs (k > 0); the angle of incidence needs a lossless ambient");
    }
}

/// The exact film at a wavelength where the Airy sum is 0/0: by the transfer matrix.
double stack_reflectance(const SingleFilm& film, double thickness_nm, double lambda_nm,
                         double angle_rad) {
    // Thickness is a precondition (>= 0) of the noexcept callers; never throw from here.
    const double t = std::isfinite(thickness_nm) ? std::max(thickness_nm, 0.0) : 0.0;
    const FilmStack stack(film.ambient, {Layer{film.film, t}}, film.substrate);
    return stack.evaluate(lambda_nm, angle_rad, Polarization::unpolarized).R;
}

}  // namespace

PreparedFilm::PreparedFilm(const SingleFilm& film, double angle_rad)
    : m_samples(dense_sample_count), m_film(film), m_angle_rad(angle_rad) {
    check_film_angle(film, angle_rad);
    m_reach = alias_reach(film, angle_rad);
    const double cos_theta0 = std::cos(angle_rad);
    for (int i = 0; i < dense_sample_count; ++i) {
        bool degenerate = false;
        m_samples[i] = prepare(film, cos_theta0, i, degenerate);
        if (degenerate) m_degenerate.push_back(i);
    }
}

double PreparedFilm::reflectance(int i, double thickness_nm) const noexcept {
    if (!m_degenerate.empty() &&
        std::find(m_degenerate.begin(), m_degenerate.end(), i) != m_degenerate.end()) {
        return stack_reflectance(m_film, thickness_nm, DenseSpectrum::wavelength_nm(i), m_angle_rad);
    }
    return airy_reflectance(m_samples[i], thickness_nm);
}

DenseSpectrum PreparedFilm::reflectance_spectrum(double thickness_nm) const {
    DenseSpectrum r;
    for (int i = 0; i < dense_sample_count; ++i) r[i] = reflectance(i, thickness_nm);
    return r;
}

FilmColor PreparedFilm::color(double thickness_nm, const Colorimeter& colorimeter) const noexcept {
    if (const std::optional<Xyz> fine = alias_free_xyz(m_film, thickness_nm, m_angle_rad, m_reach, colorimeter)) {
        return {*fine, colorimeter.linear_rgb(*fine)};
    }
    int i = 0;
    const Xyz xyz = colorimeter.xyz_of([&](double) { return reflectance(i++, thickness_nm); });
    return {xyz, colorimeter.linear_rgb(xyz)};
}

FilmColor PreparedFilm::refined_color(double thickness_nm, const Colorimeter& colorimeter) const noexcept {
    if (const std::optional<Xyz> fine = refined_film_xyz(m_film, thickness_nm, m_angle_rad, m_reach, colorimeter)) {
        return {*fine, colorimeter.linear_rgb(*fine)};
    }
    return color(thickness_nm, colorimeter);
}

bool PreparedFilm::aliases(double thickness_nm) const noexcept { return aliases_on_the_grid(m_reach, thickness_nm); }

double thesis_single_film_reflectance(const SingleFilm& film, double thickness_nm, double lambda_nm,
                                      double angle_rad, double k,
                                      std::optional<bool> phase_change) noexcept {
    const double n0 = film.ambient.index(lambda_nm).real();
    const double n1 = film.film.index(lambda_nm).real();
    const double n2 = film.substrate.index(lambda_nm).real();
    const bool phase = phase_change.value_or(thesis_phase_change(n0, n1, n2));
    const double theta_film = thesis_film_angle_rad(angle_rad, n1, n0);
    // Eq. 24: the film acts as one of index 1 and thickness t′ = t n cos θ.
    const double effective = thesis_effective_thickness_nm(thickness_nm, n1, theta_film);
    return thesis_film_reflectance(lambda_nm, effective, 1.0, phase, k);
}

DenseSpectrum thesis_single_film_spectrum(const SingleFilm& film, double thickness_nm,
                                          double angle_rad, double k,
                                          std::optional<bool> phase_change) {
    return DenseSpectrum::from_function([&](double lambda) {
        return thesis_single_film_reflectance(film, thickness_nm, lambda, angle_rad, k, phase_change);
    });
}

double thesis_matched_k(const SingleFilm& film, double lambda_nm) noexcept {
    const double n0 = film.ambient.index(lambda_nm).real();
    const double n1 = film.film.index(lambda_nm).real();
    const double n2 = film.substrate.index(lambda_nm).real();
    // Normal-incidence Fresnel amplitudes (n_i − n_t)/(n_i + n_t).
    return std::abs((n0 - n1) / (n0 + n1)) + std::abs((n1 - n2) / (n1 + n2));
}

void check_thesis_material(const Material& material, std::string_view role) {
    if (!material.is_lossless()) {
        throw Error("the thesis' closed forms cannot model the absorbing " + std::string(role) +
                    " '" + material.name() +
                    "' (k > 0): they assume a non-absorbing film and substrate (beams of real "
                    "amplitude, phase changes of 0 or π) and would drop the absorption");
    }
}

void check_thesis_single_film(const SingleFilm& film) {
    check_thesis_material(film.film, "film");
    check_thesis_material(film.substrate, "substrate");
}

// --- tables ---------------------------------------------------------------------------------

FilmColorTable::Range FilmColorTable::check_range(double min_nm, double max_nm, double step_nm) {
    if (!(std::isfinite(min_nm) && min_nm >= 0.0)) {
        throw Error("colour table: minimum thickness " + format_shortest(min_nm) + " nm must be >= 0");
    }
    if (!(std::isfinite(max_nm) && max_nm > min_nm)) {
        throw Error("colour table: maximum thickness " + format_shortest(max_nm) +
                    " nm must be greater than the minimum " + format_shortest(min_nm) + " nm");
    }
    if (!(std::isfinite(step_nm) && step_nm > 0.0)) {
        throw Error("colour table: thickness step " + format_shortest(step_nm) + " nm must be > 0");
    }
    const double intervals = std::max(1.0, std::ceil((max_nm - min_nm) / step_nm - 1e-9));
    if (intervals + 1.0 > max_table_entries) {
        throw Error("colour table: " + format_shortest(intervals + 1.0) +
                    " entries is more than the limit of 1e7; use a larger step");
    }
    const auto n = static_cast<std::size_t>(intervals);
    return {min_nm, max_nm, (max_nm - min_nm) / static_cast<double>(n), n + 1};
}

FilmColorTable::FilmColorTable(const Range& r)
    : m_min(r.min), m_max(r.max), m_step(r.step), m_colors(r.count) {}

FilmColor FilmColorTable::at(double thickness_nm) const noexcept {
    double u = (thickness_nm - m_min) / m_step;
    if (!(u > 0.0)) return m_colors.front();  // also NaN
    const double last = static_cast<double>(m_colors.size() - 1);
    if (u >= last) return m_colors.back();
    const auto i = static_cast<std::size_t>(u);
    u -= static_cast<double>(i);
    const FilmColor& a = m_colors[i];
    const FilmColor& b = m_colors[i + 1];
    const auto mix = [u](double x, double y) { return x + u * (y - x); };
    return {{mix(a.xyz.X, b.xyz.X), mix(a.xyz.Y, b.xyz.Y), mix(a.xyz.Z, b.xyz.Z)},
            {mix(a.rgb_linear.r, b.rgb_linear.r), mix(a.rgb_linear.g, b.rgb_linear.g),
             mix(a.rgb_linear.b, b.rgb_linear.b)}};
}

FilmColorTable2D::Grid FilmColorTable2D::check(double max_thickness_nm, double thickness_step_nm,
                                               double cos_min, int cos_steps) {
    if (!(std::isfinite(max_thickness_nm) && max_thickness_nm > 0.0)) {
        throw Error("colour table: maximum thickness " + format_shortest(max_thickness_nm) +
                    " nm must be > 0");
    }
    if (!(std::isfinite(thickness_step_nm) && thickness_step_nm > 0.0)) {
        throw Error("colour table: thickness step " + format_shortest(thickness_step_nm) +
                    " nm must be > 0");
    }
    const double intervals = std::max(1.0, std::ceil(max_thickness_nm / thickness_step_nm - 1e-9));
    if (intervals + 1.0 > max_table_entries) {
        throw Error("colour table: more than 1e7 entries; use larger steps");
    }
    const auto thickness_count = static_cast<std::size_t>(intervals) + 1;
    if (!(cos_min > 0.0 && cos_min < 1.0)) {
        throw Error("colour table: smallest cos θ " + format_shortest(cos_min) +
                    " must be in (0, 1) (angles below 90°)");
    }
    if (cos_steps < 1 || cos_steps > 10000) {
        throw Error("colour table: cos θ steps " + std::to_string(cos_steps) + " must be in 1..10000");
    }
    if (static_cast<double>(thickness_count) * (cos_steps + 1) > max_table_entries) {
        throw Error("colour table: more than 1e7 entries; use larger steps");
    }
    return {max_thickness_nm, max_thickness_nm / intervals, cos_min, thickness_count,
            static_cast<std::size_t>(cos_steps) + 1};
}

FilmColorTable2D::FilmColorTable2D(const Grid& g)
    : m_step(g.step),
      m_cos_min(g.cos_min),
      m_cos_step((1.0 - g.cos_min) / static_cast<double>(g.cos_count - 1)),
      m_thickness_count(g.thickness_count),
      m_cos_count(g.cos_count),
      m_colors(g.thickness_count * g.cos_count) {}

FilmColor FilmColorTable2D::at(double thickness_nm, double cos_theta) const noexcept {
    const auto locate = [](double u, std::size_t count, std::size_t& i, double& f) {
        const double last = static_cast<double>(count - 1);
        if (!(u > 0.0)) u = 0.0;
        if (u >= last) u = last;
        i = std::min(static_cast<std::size_t>(u), count - 2);
        f = u - static_cast<double>(i);
    };
    std::size_t i = 0, j = 0;
    double fi = 0.0, fj = 0.0;
    locate(thickness_nm / m_step, m_thickness_count, i, fi);
    locate((cos_theta - m_cos_min) / m_cos_step, m_cos_count, j, fj);
    const FilmColor& c00 = m_colors[j * m_thickness_count + i];
    const FilmColor& c10 = m_colors[j * m_thickness_count + i + 1];
    const FilmColor& c01 = m_colors[(j + 1) * m_thickness_count + i];
    const FilmColor& c11 = m_colors[(j + 1) * m_thickness_count + i + 1];
    const auto mix = [&](double a, double b, double c, double d) {
        return (1 - fj) * ((1 - fi) * a + fi * b) + fj * ((1 - fi) * c + fi * d);
    };
    return {{mix(c00.xyz.X, c10.xyz.X, c01.xyz.X, c11.xyz.X),
             mix(c00.xyz.Y, c10.xyz.Y, c01.xyz.Y, c11.xyz.Y),
             mix(c00.xyz.Z, c10.xyz.Z, c01.xyz.Z, c11.xyz.Z)},
            {mix(c00.rgb_linear.r, c10.rgb_linear.r, c01.rgb_linear.r, c11.rgb_linear.r),
             mix(c00.rgb_linear.g, c10.rgb_linear.g, c01.rgb_linear.g, c11.rgb_linear.g),
             mix(c00.rgb_linear.b, c10.rgb_linear.b, c01.rgb_linear.b, c11.rgb_linear.b)}};
}

FilmColor exact_film_color(const SingleFilm& film, double thickness_nm, double angle_rad,
                           const Colorimeter& colorimeter) {
    // One pass: prepare each wavelength and sum its Airy reflectance at once, with no table and
    // no copy of the materials; the same numbers as PreparedFilm.
    check_film_angle(film, angle_rad);
    if (const std::optional<Xyz> fine = alias_free_xyz(film, thickness_nm, angle_rad, colorimeter)) {
        return {*fine, colorimeter.linear_rgb(*fine)};
    }
    const double cos_theta0 = std::cos(angle_rad);
    const Xyz xyz = colorimeter.xyz_of([&](double lambda) {
        const int i = static_cast<int>(lambda) - lambda_min_nm;
        bool degenerate = false;
        const PreparedFilm::Sample s = PreparedFilm::prepare(film, cos_theta0, i, degenerate);
        return degenerate ? stack_reflectance(film, thickness_nm, lambda, angle_rad)
                          : PreparedFilm::airy_reflectance(s, thickness_nm);
    });
    return {xyz, colorimeter.linear_rgb(xyz)};
}

FilmColorTable exact_film_color_table(const SingleFilm& film, double angle_rad, double max_thickness_nm,
                                      double step_nm, const Colorimeter& colorimeter) {
    const PreparedFilm prepared(film, angle_rad);
    return FilmColorTable(0.0, max_thickness_nm, step_nm,
                          [&](double t) { return prepared.color(t, colorimeter); });
}

FilmColorTable thesis_film_color_table(bool phase_change, double max_effective_thickness_nm,
                                       double step_nm, const Colorimeter& colorimeter) {
    return FilmColorTable(0.0, max_effective_thickness_nm, step_nm, [&](double t_effective) {
        return color_of(colorimeter, colorimeter.xyz_of([&](double lambda) {
            return thesis_film_reflectance(lambda, t_effective, 1.0, phase_change, 1.0);
        }));
    });
}

FilmColorTable2D exact_film_color_table_2d(const SingleFilm& film, double max_thickness_nm,
                                           double thickness_step_nm, double max_angle_rad,
                                           int cos_steps, const Colorimeter& colorimeter) {
    check_incidence_angle(max_angle_rad);
    // Rows share an angle: prepare each once (the table fills row by row).
    std::optional<PreparedFilm> row;
    double row_cos = -1.0;
    return FilmColorTable2D(max_thickness_nm, thickness_step_nm, std::cos(max_angle_rad), cos_steps,
                            [&](double t, double cos_theta) {
                                if (!row || cos_theta != row_cos) {
                                    row.emplace(film, std::acos(std::min(cos_theta, 1.0)));
                                    row_cos = cos_theta;
                                }
                                return row->color(t, colorimeter);
                            });
}

LookupError measure_exact_table_error(const FilmColorTable2D& table, const SingleFilm& film,
                                      const Colorimeter& colorimeter) {
    LookupError e;
    double sum = 0.0;
    for (std::size_t j = 0; j + 1 < table.cos_count(); ++j) {
        const double c = table.cos_theta(j) + 0.5 * table.cos_step();
        const PreparedFilm prepared(film, std::acos(c));
        for (std::size_t i = 0; i + 1 < table.thickness_count(); ++i) {
            const double t = table.thickness_nm(i) + 0.5 * table.thickness_step_nm();
            const FilmColor direct = prepared.color(t, colorimeter);
            const double d = delta_e_2000_of(colorimeter, table.at(t, c).xyz, direct.xyz);
            sum += d;
            ++e.samples;
            if (d > e.max_delta_e) {
                e.max_delta_e = d;
                e.worst_thickness_nm = t;
                e.worst_cos_theta = c;
            }
        }
    }
    e.mean_delta_e = e.samples ? sum / static_cast<double>(e.samples) : 0.0;
    return e;
}

double choose_exact_table_step(const SingleFilm& film, double angle_rad, double max_thickness_nm,
                               double max_delta_e2000, const Colorimeter& colorimeter,
                               double start_step_nm) {
    if (!(max_delta_e2000 > 0.0)) {
        throw Error("table step: the ΔE2000 bound " + format_shortest(max_delta_e2000) + " must be > 0");
    }
    const PreparedFilm prepared(film, angle_rad);
    for (double step = start_step_nm; step >= start_step_nm / 1024.0; step /= 2.0) {
        const FilmColorTable table =
            exact_film_color_table(film, angle_rad, max_thickness_nm, step, colorimeter);
        const LookupError e = measure_lookup_error(
            table, [&](double t) { return prepared.color(t, colorimeter); }, colorimeter);
        if (e.max_delta_e <= max_delta_e2000) return table.step_nm();
    }
    throw Error("table step: no step down to " + format_shortest(start_step_nm / 1024.0) +
                " nm keeps lookups within ΔE2000 " + format_shortest(max_delta_e2000));
}

}  // namespace irid
