#pragma once

// The colour of a film: spectral reflectance × illuminant → XYZ → RGB, for both families (the
// thesis' closed forms and the exact optics), colour tables like the thesis' §3.3 (thickness →
// colour, and thickness × cos θ → colour for the exact model). Colours are relative, as the
// Colorimeter (irid/color/colorimeter.h) makes them.

#include <irid/color/colorimeter.h>
#include <irid/color/illuminant.h>
#include <irid/color/observer.h>
#include <irid/color/rgb.h>
#include <irid/color/spectrum.h>
#include <irid/color/types.h>
#include <irid/optics/material.h>
#include <irid/optics/multilayer.h>

#include <complex>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace irid {

/// A colour with its linear RGB (unclipped).
struct FilmColor {
    Xyz xyz;
    Rgb rgb_linear;
};

/// Ambient | film | substrate: the single film of the thesis' models and of the colour tables.
struct SingleFilm {
    Material ambient;
    Material film;
    Material substrate;
};

/// What the aliasing of the 1 nm sum depends on besides the thickness, per nanometre of it, at
/// one angle (fine_sum.h finds it): the optical path of a round trip (2 n1 cos θ1 at 555 nm) and
/// the reach of the round trips whose amplitude is above 1e-3 of the first (|q|^m, q = r01 r12 at
/// 555 nm, the larger of s and p).
struct AliasReach {
    double opd_per_nm = 0.0;
    double reach_per_nm = 0.0;
};

/// One film at one angle of incidence, prepared on the 1 nm grid for evaluation at any thickness:
/// the Fresnel amplitudes of both faces and the phase per nanometre are computed once per
/// wavelength (they do not depend on the thickness), so a reflectance is the Airy sum alone
/// (Born & Wolf §7.6.1), r = (r01 + r12 z) / (1 + r01 r12 z), z = e^{2iβ}, β = 2π d N1 cos θ1 / λ.
/// Exact: equal to FilmStack::evaluate with the one layer (tested to 1e-12). Unpolarised.
class PreparedFilm {
public:
    /// Throws irid::Error for an angle outside [0, π/2) or an absorbing ambient.
    PreparedFilm(const SingleFilm& film, double angle_rad);

    /// Reflectance at the i-th wavelength of the 1 nm grid (360 + i nm). Precondition for this
    /// and the two below: thickness_nm finite and >= 0.
    [[nodiscard]] double reflectance(int i, double thickness_nm) const noexcept;
    [[nodiscard]] DenseSpectrum reflectance_spectrum(double thickness_nm) const;
    [[nodiscard]] FilmColor color(double thickness_nm, const Colorimeter& colorimeter) const noexcept;
    /// color() without aliasing at any thickness (refined_film_xyz): for one colour, not tables.
    [[nodiscard]] FilmColor refined_color(double thickness_nm, const Colorimeter& colorimeter) const noexcept;
    /// color() at this thickness is a 1 nm sum that aliases (aliases_on_the_grid).
    [[nodiscard]] bool aliases(double thickness_nm) const noexcept;

    /// What the film's reflectance at one wavelength needs besides the thickness.
    struct Sample {
        std::complex<double> r01_s, r12_s, r01_p, r12_p;
        /// 2i × 2π N1 cos θ1 / λ: z = exp(phase_per_nm × d).
        std::complex<double> phase_per_nm;
        /// Every amplitude real and the phase purely imaginary (lossless, no total reflection):
        /// then, per polarisation, with x = r01 r12, R = 1 − (1 − r01²)(1 − r12²) / ((1 + x)² −
        /// 4 x sin²(φ/2)), which is (r01² + r12² + 2x cos φ) / (1 + x² + 2x cos φ) written so
        /// that no digit is lost where both faces reflect almost totally (grazing incidence,
        /// extreme indices): each factor is formed from the media's N cos θ directly.
        bool real;
        /// For a real sample, s then p: x, (1 − r01²)(1 − r12²) and (1 + x)².
        double x[2], transmitted[2], one_plus_x_sq[2];
    };
    /// The amplitudes and phase at the i-th wavelength for an angle of incidence of cosine
    /// cos_theta in the ambient; `degenerate` when the film is within |N1 cos θ1| < 1e-3 |N1| of
    /// its own critical angle there, where the Airy sum loses its digits (use the transfer matrix).
    static Sample prepare(const SingleFilm& film, double cos_theta, int i, bool& degenerate) noexcept;
    /// The same at any wavelength [nm] (the finer sums of fine_sum.h).
    static Sample prepare_at(const SingleFilm& film, double cos_theta, double lambda_nm, bool& degenerate) noexcept;
    /// The same from the media's indices at that wavelength (ambient lossless: its real index).
    static Sample prepare_media(double n0, std::complex<double> n1, std::complex<double> n2, double cos_theta,
                                double lambda_nm, bool& degenerate) noexcept;
    /// The unpolarised Airy reflectance of a prepared sample at a thickness (not for degenerate
    /// samples).
    static double airy_reflectance(const Sample& s, double thickness_nm) noexcept;

private:
    std::vector<Sample> m_samples;
    /// Wavelength indices where the film sits exactly at its own critical angle; evaluated by
    /// the transfer matrix instead.
    std::vector<int> m_degenerate;
    SingleFilm m_film;
    double m_angle_rad;
    /// What color() asks alias_free_xyz with, found once for the angle.
    AliasReach m_reach{};
};

/// The exact reflectance spectrum of a stack at 1 nm (transfer-matrix method, all internal
/// reflections, Fresnel amplitudes, dispersion). angle_rad in [0, π/2) in the ambient.
[[nodiscard]] DenseSpectrum exact_reflectance_spectrum(const FilmStack& stack, double angle_rad,
                                                       Polarization polarization = Polarization::unpolarized);

/// The thesis' single-film reflectance (Smits 1990, eq. 21/22 with the effective thickness of
/// eq. 23/24) for a film of real materials: at each wavelength the film's index is n(λ) = Re N(λ)
/// and the angle inside it follows Snell's law from the ambient's Re N(λ). The phase case is
/// `phase_change` when given, otherwise eq. 19's rule applied to the real indices at each
/// wavelength (thesis_phase_change). K scales the amplitude (default 1, as the thesis writes).
[[nodiscard]] double thesis_single_film_reflectance(const SingleFilm& film, double thickness_nm,
                                                    double lambda_nm, double angle_rad, double k,
                                                    std::optional<bool> phase_change) noexcept;
[[nodiscard]] DenseSpectrum thesis_single_film_spectrum(const SingleFilm& film, double thickness_nm,
                                                        double angle_rad, double k = 1.0,
                                                        std::optional<bool> phase_change = std::nullopt);

/// K for which the thesis' single film has the exact film's maxima at normal incidence: the two
/// beams reflected at the film's faces interfere to at most (|r01| + |r12|)², and eq. 21/22 peak
/// at K², so K = |r01| + |r12| (Fresnel amplitudes at normal incidence, real indices at
/// lambda_nm). The thesis leaves K free; this is the choice the error study uses.
[[nodiscard]] double thesis_matched_k(const SingleFilm& film, double lambda_nm = 555.0) noexcept;

/// Throws irid::Error unless the thesis' closed forms can model a material in the given role
/// ("film", "substrate"): it must be lossless (k = 0 at every wavelength, Material::is_lossless,
/// the check the renderer applies to its films). Eq. 19–22 and 25 add beams of equal, real
/// amplitude whose reflections shift the phase by 0 or π; an absorbing medium attenuates the
/// beams and shifts the phase by other amounts, and thesis_single_film_reflectance would
/// silently use Re N alone. The exact model (FilmStack, PreparedFilm) handles absorption.
void check_thesis_material(const Material& material, std::string_view role);
/// check_thesis_material for the film and the substrate (the ambient is lossless already for
/// every model, as the angle of incidence needs).
void check_thesis_single_film(const SingleFilm& film);

/// Thickness → colour sampled every step from min to max (the thesis' §3.3 table), looked up
/// with linear interpolation (XYZ and linear RGB are linear in the reflectance, so interpolating
/// colours is interpolating spectra). Thicknesses outside the range clamp to its ends.
class FilmColorTable {
public:
    /// Computes color_of(t) at t = min, min + step, ..., max (step shrunk so it divides the
    /// range). Throws irid::Error unless 0 <= min < max, step > 0 and the table has at most
    /// 10⁷ entries.
    template <class F>
    FilmColorTable(double min_nm, double max_nm, double step_nm, F&& color_of)
        : FilmColorTable(check_range(min_nm, max_nm, step_nm)) {
        for (std::size_t i = 0; i < m_colors.size(); ++i) m_colors[i] = color_of(thickness_nm(i));
    }

    [[nodiscard]] FilmColor at(double thickness_nm) const noexcept;
    [[nodiscard]] double thickness_nm(std::size_t i) const noexcept { return m_min + m_step * static_cast<double>(i); }
    [[nodiscard]] std::size_t size() const noexcept { return m_colors.size(); }
    [[nodiscard]] double step_nm() const noexcept { return m_step; }
    [[nodiscard]] double min_nm() const noexcept { return m_min; }
    [[nodiscard]] double max_nm() const noexcept { return m_max; }
    [[nodiscard]] std::span<const FilmColor> colors() const noexcept { return m_colors; }

private:
    struct Range {
        double min, max, step;
        std::size_t count;
    };
    static Range check_range(double min_nm, double max_nm, double step_nm);
    explicit FilmColorTable(const Range& r);

    double m_min, m_max, m_step;
    std::vector<FilmColor> m_colors;
};

/// Thickness × cos θ → colour for the exact model, bilinear lookup: the exact film's colour
/// depends on the angle through cos θ in every layer, which no single effective thickness
/// captures, so the table keeps both axes. cos θ runs from cos_min to 1 in equal steps.
class FilmColorTable2D {
public:
    template <class F>
    FilmColorTable2D(double max_thickness_nm, double thickness_step_nm, double cos_min,
                     int cos_steps, F&& color_of)
        : FilmColorTable2D(check(max_thickness_nm, thickness_step_nm, cos_min, cos_steps)) {
        for (std::size_t j = 0; j < m_cos_count; ++j) {
            for (std::size_t i = 0; i < m_thickness_count; ++i) {
                m_colors[j * m_thickness_count + i] = color_of(thickness_nm(i), cos_theta(j));
            }
        }
    }

    [[nodiscard]] FilmColor at(double thickness_nm, double cos_theta) const noexcept;
    [[nodiscard]] double thickness_nm(std::size_t i) const noexcept { return m_step * static_cast<double>(i); }
    [[nodiscard]] double cos_theta(std::size_t j) const noexcept {
        return m_cos_min + m_cos_step * static_cast<double>(j);
    }
    [[nodiscard]] std::size_t thickness_count() const noexcept { return m_thickness_count; }
    [[nodiscard]] std::size_t cos_count() const noexcept { return m_cos_count; }
    [[nodiscard]] double thickness_step_nm() const noexcept { return m_step; }
    [[nodiscard]] double cos_step() const noexcept { return m_cos_step; }

private:
    struct Grid {
        double max, step, cos_min;
        std::size_t thickness_count, cos_count;
    };
    static Grid check(double max_thickness_nm, double thickness_step_nm, double cos_min, int cos_steps);
    explicit FilmColorTable2D(const Grid& g);

    double m_step, m_cos_min, m_cos_step;
    std::size_t m_thickness_count, m_cos_count;
    std::vector<FilmColor> m_colors;
};

/// The colour of a single film by the exact model (unpolarised, Airy/transfer matrix).
[[nodiscard]] FilmColor exact_film_color(const SingleFilm& film, double thickness_nm,
                                         double angle_rad, const Colorimeter& colorimeter);

/// A table for the exact model at one angle, thickness 0..max.
[[nodiscard]] FilmColorTable exact_film_color_table(const SingleFilm& film, double angle_rad,
                                                    double max_thickness_nm, double step_nm,
                                                    const Colorimeter& colorimeter);
/// The thesis' table (§3.3): one per phase case, for n = 1 at normal incidence, indexed by the
/// effective thickness t′ = t n cos θ (eq. 24), K = 1 (colours scale by K²).
[[nodiscard]] FilmColorTable thesis_film_color_table(bool phase_change, double max_effective_thickness_nm,
                                                     double step_nm, const Colorimeter& colorimeter);
/// The 2-D table for the exact model over thickness 0..max and cos θ in [cos(max angle), 1].
[[nodiscard]] FilmColorTable2D exact_film_color_table_2d(const SingleFilm& film, double max_thickness_nm,
                                                         double thickness_step_nm, double max_angle_rad,
                                                         int cos_steps, const Colorimeter& colorimeter);

/// How far a table's lookups are from the colours they stand for, in CIEDE2000 (CIELAB relative
/// to the colorimeter's white).
struct LookupError {
    double max_delta_e = 0.0;
    double mean_delta_e = 0.0;
    /// Where the maximum is [nm] (and, for 2-D tables, the cos θ).
    double worst_thickness_nm = 0.0;
    double worst_cos_theta = 1.0;
    std::size_t samples = 0;
};

/// Compares lookups with direct colours at the midpoints between nodes (where linear
/// interpolation errs most) and at a third of each interval.
template <class F>
[[nodiscard]] LookupError measure_lookup_error(const FilmColorTable& table, F&& direct,
                                               const Colorimeter& colorimeter);
[[nodiscard]] LookupError measure_exact_table_error(const FilmColorTable2D& table, const SingleFilm& film,
                                                    const Colorimeter& colorimeter);

/// The coarsest step (from start_step_nm, halved until it holds) for which an exact single-film
/// table at this angle keeps every measured lookup within max_delta_e2000. Throws irid::Error if
/// no step down to start_step_nm / 1024 does.
[[nodiscard]] double choose_exact_table_step(const SingleFilm& film, double angle_rad,
                                             double max_thickness_nm, double max_delta_e2000,
                                             const Colorimeter& colorimeter,
                                             double start_step_nm = 16.0);

// --- implementation of the template -------------------------------------------------------

template <class F>
LookupError measure_lookup_error(const FilmColorTable& table, F&& direct, const Colorimeter& colorimeter) {
    LookupError e;
    double sum = 0.0;
    for (std::size_t i = 0; i + 1 < table.size(); ++i) {
        for (const double f : {0.5, 1.0 / 3.0}) {
            const double t = table.thickness_nm(i) + f * table.step_nm();
            const double d = delta_e_2000_of(colorimeter, table.at(t).xyz, direct(t).xyz);
            sum += d;
            ++e.samples;
            if (d > e.max_delta_e) {
                e.max_delta_e = d;
                e.worst_thickness_nm = t;
            }
        }
    }
    e.mean_delta_e = e.samples ? sum / static_cast<double>(e.samples) : 0.0;
    return e;
}

}  // namespace irid
