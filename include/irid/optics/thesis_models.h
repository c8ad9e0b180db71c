#pragma once

// The closed-form interference models of Smits 1990, chapter 3 ("Interference Phenomena and an
// Efficient Solution to the Out of Gamut Colors Problem", University of Oregon), implemented as
// the thesis writes them. They are approximations: two-beam (single film) and equal-amplitude
// N-beam (multiple films) interference, with no Fresnel amplitudes; the exact physics lives
// beside them in irid_optics.
//
// Units: lengths in nanometres (`_nm`). Angles in the noexcept kernels are in radians (`_rad`);
// the spectrum helpers and tables, like the command line, take degrees (`_deg`). An angle is
// measured in the ambient medium unless its name says it is inside the film.
//
// Where the thesis text leaves a choice, these are the decisions taken (each is tested):
// - Phase change (eq. 19): a π shift at each reflection from a medium of higher index (strictly
//   higher: equal indices give no shift). The single-film phase change of eq. 21 applies when
//   exactly one of the two reflections (ambient→film, film→substrate) has the shift: a soap
//   film in air, oil (1.47) on water (1.33) and an air gap between glass plates do; a film whose
//   index lies between the ambient's and the substrate's does not (eq. 22).
// - Eq. 21 is evaluated as K² sin²(2πtn/λ), which is [K cos(2πtn/λ + π/2)]² exactly, so that a
//   film of zero thickness is exactly black instead of cos²(π/2) ≈ 4e-33.
// - View angle (eq. 23–24): θ in t′ = t n cos θ is the angle inside the film, from Snell's law
//   n_ambient sin θ_ambient = n_film sin θ. The ambient index is a parameter (air, 1, by
//   default). Beyond the critical angle (a film of lower index than the ambient) no wave
//   crosses the film; the angle is then taken as grazing, 90°, so t′ = 0.
// - The table trick (§3.3): eq. 21/22 depend on t, n and θ only through t′ = t n cos θ, so one
//   table per phase case, computed for n = 1 at normal incidence and indexed by t′, serves
//   every film. ThesisFilmTable stores colours (XYZ), not spectra, as the thesis' tables do; it
//   is computed for K = 1 and scales by K² at lookup (ρ ∝ K² and XYZ is linear in ρ).
// - Multiple films (eq. 25, after Anderson 1942): l is the number of films (periods) of the
//   stack, `periods` here, the `--periods L` of the command line; l + 1 interfaces reflect
//   l + 1 beams, each delayed by 2·2πt/λ from the one before, whose sum has the intensity
//   (sin((l+1)x) / sin x)², x = 2πt/λ. The t of eq. 25 is the effective thickness t_θ of
//   eq. 26 (or 29), so at normal incidence it is the optical thickness t·n of a period. The
//   model is not normalised: its peak is ½K(l+1)² (84.5 for the Morpho's l = 12 at K = 1);
//   K = 2/(l+1)² (thesis_unit_peak_k) makes the peak 1. The parameter structs default K to 1,
//   the thesis as written; the renderer, the figures and the command line use 2/(l+1)².
// - Eq. 26 and 29 take the ambient to be air (index 1) and θ to be the angle in air; n ≥ 1 is
//   required so that n² − sin²θ ≥ 0 at every angle.
// - Morpho (eq. 29): d₁ is a path in air (it goes with cos θ), d₂ one in chitin of index n (it
//   goes with (n² − sin²θ)^½); "twelve mullions" is l = 12. The blend "over mullion
//   thicknesses from 50 to 150 nm" takes 101 equally spaced samples (every nm, endpoints
//   included) and the arithmetic mean of the reflectance spectra; because XYZ is linear in ρ
//   this is also the mean of the colours. The text does not say which of d₁, d₂ varies. Varying
//   d₂ (the chitin) sweeps the first-order peaks 2(d₁ + d₂n) over 456–768 nm and turns the
//   wing a pale yellow-white (D65: xy ≈ 0.38, 0.42), which contradicts the blue wing of the
//   thesis' Figure 9; varying d₁ (the spacing, which the default 150 nm bounds) keeps the peaks
//   at 256–456 nm and the wing blue-violet. So the default blend varies d₁;
//   MorphoBlend::varies selects d₂.
// - The Morpho table is sampled at equal steps over θ ∈ [0°, 90°] (90° is the last node, so a
//   lookup anywhere in [0°, 90°) interpolates between two nodes).

#include <string_view>
#include <irid/color/observer.h>
#include <irid/color/spectrum.h>
#include <irid/color/types.h>

#include <optional>
#include <vector>

namespace irid {

// --- One film: Smits 1990, eq. 19–24 ----------------------------------------------------------

/// A film of the thesis' single-film model. Defaults: a soap film (water) in air.
struct ThesisFilmParameters {
    /// Refractive index of the film (water, 1.33).
    double n_film = 1.33;
    /// Refractive index of the ambient medium, used only by Snell's law for the view angle.
    double n_ambient = 1.0;
    /// Eq. 21 when true, eq. 22 when false; thesis_phase_change() decides it from the indices.
    bool phase_change = true;
    /// The thesis' amplitude factor K (ρ scales by K²).
    double K = 1.0;
};

/// Throws irid::Error naming the parameter unless n_film > 0, n_ambient > 0 and K ≥ 0, all
/// finite.
void validate_thesis_film(const ThesisFilmParameters& film);

/// Smits 1990, eq. 19–20: whether the two reflected beams of a film differ by a phase change of
/// π. Each reflection from a medium of higher index shifts by π; the beams differ when exactly
/// one of the two reflections (ambient→film, film→substrate) is such a reflection.
[[nodiscard]] bool thesis_phase_change(double n_ambient, double n_film,
                                       double n_substrate) noexcept;

/// Smits 1990, eq. 21 (phase_change) and eq. 22: ρ(λ) = [K cos(2πtn/λ + π/2)]² with a phase
/// change, [K cos(2πtn/λ)]² without, for thickness t [nm] and index n at normal incidence.
/// With t = t′ (eq. 24) and n = 1 it is the reflectance at any angle.
[[nodiscard]] double thesis_film_reflectance(double lambda_nm, double thickness_nm, double n_film,
                                             bool phase_change, double K = 1.0) noexcept;

/// Snell's law, the angle inside the film [rad] for an angle θ_ambient [rad] in the ambient:
/// n_ambient sin θ_ambient = n_film sin θ. Beyond the critical angle: π/2 (grazing).
[[nodiscard]] double thesis_film_angle_rad(double theta_ambient_rad, double n_film,
                                           double n_ambient = 1.0) noexcept;

/// Smits 1990, eq. 23–24: the effective thickness t′ = t n cos θ [nm], θ inside the film. The
/// film of thickness t and index n seen at θ reflects like a film of thickness t′ and index 1
/// at normal incidence.
[[nodiscard]] double thesis_effective_thickness_nm(double thickness_nm, double n_film,
                                                   double theta_film_rad) noexcept;

/// The reflectance spectrum of eq. 21/22 with eq. 23–24 on the 1 nm grid, angle in the ambient.
/// Throws irid::Error unless the parameters are valid, thickness_nm ≥ 0 and 0° ≤ angle_deg < 90°.
[[nodiscard]] DenseSpectrum thesis_film_spectrum(const ThesisFilmParameters& film,
                                                 double thickness_nm, double angle_deg = 0.0);

/// The thesis' colour table for one phase case (Smits 1990, §3.3 with eq. 24): the colour of a
/// film of index 1 at normal incidence, K = 1, at effective thicknesses 0, h, 2h, ..., t′_max,
/// linear in between. Any film of that phase case is looked up by its t′.
///
/// Interpolation error: ρ = sin²(2πt′/λ) or cos²(2πt′/λ) has |∂²ρ/∂t′²| ≤ 8π²/λ², and each of
/// X, Y, Z is a non-negative weighting of ρ summing to the white's value W, so a lookup is within
/// h²/8 · 8π²W/λ_min² = π²h²W/λ_min² (λ_min = 360 nm) of the exact colour: 8.3e-5 for h = 1 nm
/// under D65 (W ≤ 1.089), times K².
class ThesisFilmTable {
public:
    /// Throws irid::Error unless 0 < max_effective_thickness_nm ≤ 1e6 nm and
    /// 0 < step_nm ≤ max_effective_thickness_nm with at most 1e7 entries, or if the illuminant
    /// has no luminance. The step is shrunk so that it divides the range evenly.
    ThesisFilmTable(bool phase_change, double max_effective_thickness_nm, double step_nm,
                    const DenseSpectrum& illuminant, Observer observer = Observer::cie1931_2deg);

    /// XYZ (white Y = 1) of a film of effective thickness t′ [nm] and amplitude factor K.
    /// t′ beyond the table is clamped to its ends.
    [[nodiscard]] Xyz at(double effective_thickness_nm, double K = 1.0) const noexcept;

    [[nodiscard]] bool phase_change() const noexcept { return m_phase_change; }
    [[nodiscard]] double step_nm() const noexcept { return m_step_nm; }
    [[nodiscard]] double max_effective_thickness_nm() const noexcept;

private:
    bool m_phase_change;
    double m_step_nm;
    std::vector<Xyz> m_colors;
};

// --- Multiple films: Smits 1990, eq. 25–26 (Anderson 1942) ------------------------------------

/// A stack of l equal films in the thesis' multilayer model. Defaults: chitin and twelve
/// periods, the thesis' Morpho case.
struct ThesisMultilayerParameters {
    /// Refractive index of the films (chitin, 1.56). Must be ≥ 1 (eq. 26 assumes air around).
    double n = 1.56;
    /// l, the number of films (periods); l + 1 interfaces reflect.
    int periods = 12;
    /// The thesis' amplitude factor K (I scales by K).
    double K = 1.0;
};

/// The numbers of periods accepted: at least one film (with none, eq. 25 is one interface, which
/// K = 2/(l+1)² turns into a perfect mirror), and far beyond any natural multilayer.
inline constexpr int thesis_min_periods = 1;
inline constexpr int thesis_max_periods = 1'000'000;

/// Throws irid::Error "periods N must be in 1..1000000 (...)" unless periods is in
/// [thesis_min_periods, thesis_max_periods]: the one check of every caller (models, command
/// line, Python).
void check_thesis_periods(int periods);

/// Throws irid::Error unless n is finite and >= 1: eq. 26 and 29 take the films to be in air,
/// so a film's index below the ambient's has no meaning there. `what` names the film ("'chitin'
/// has 1.56 at 555 nm" style detail is the caller's `what`).
void check_thesis_air_index(double n, std::string_view what);

/// Throws irid::Error naming the parameter unless 1 ≤ n (finite), periods within
/// check_thesis_periods, K ≥ 0.
void validate_thesis_multilayer(const ThesisMultilayerParameters& stack);

/// Smits 1990, eq. 25 (after Anderson 1942): I = ½K (sin(2π(l+1)t/λ) / sin(2πt/λ))², t the
/// effective thickness [nm] of one period (eq. 26 or 29). Where sin(2πt/λ) = 0, at t = mλ/2,
/// the value is its limit ½K(l+1)²; near there it is evaluated without cancellation.
[[nodiscard]] double thesis_multilayer_reflectance(double lambda_nm, double effective_thickness_nm,
                                                   int periods, double K = 1.0) noexcept;

/// K = 2/(l+1)² for l = periods: eq. 25's maximum ½K(l+1)², where 2t = mλ puts all l + 1
/// beams in phase, is then 1, the most a surface can reflect, and every other value is below it
/// ((sin((l+1)x) / sin x)² ≤ (l+1)²). The renderer's and the figures' K for the Morpho wing, and
/// the command line's default for the multilayer and Morpho models (with K = 1 the twelve
/// mullions peak at 84.5). Precondition: periods >= 0.
[[nodiscard]] double thesis_unit_peak_k(int periods) noexcept;

/// Smits 1990, eq. 26: t_θ = t (n² − sin²θ)^½ [nm], θ [rad] the angle in air.
[[nodiscard]] double thesis_multilayer_effective_thickness_nm(double thickness_nm, double n,
                                                              double theta_rad) noexcept;

/// The spectrum of eq. 25 with eq. 26 on the 1 nm grid, for periods of thickness t [nm] seen at
/// angle_deg in air. Throws irid::Error unless the parameters are valid, thickness_nm ≥ 0 and
/// 0° ≤ angle_deg < 90°.
[[nodiscard]] DenseSpectrum thesis_multilayer_spectrum(const ThesisMultilayerParameters& stack,
                                                       double thickness_nm, double angle_deg = 0.0);

// --- The Morpho wing: Smits 1990, eq. 29 with eq. 25 ------------------------------------------

/// The thesis' Morpho wing: mullions of chitin in air.
struct MorphoParameters {
    /// d₁, the path in air per period [nm] (goes with cos θ).
    double d1_nm = 150.0;
    /// d₂, the mullion (chitin) thickness per period [nm] (goes with (n² − sin²θ)^½).
    double d2_nm = 50.0;
    /// Refractive index of chitin (Morpho cuticle). Must be ≥ 1.
    double n = 1.56;
    /// l, the number of mullions (twelve in the thesis).
    int periods = 12;
    /// The thesis' amplitude factor K of eq. 25.
    double K = 1.0;
};

/// The thickness of eq. 29 that MorphoBlend varies.
enum class MorphoBlendThickness {
    /// d₂, the chitin: the literal reading, which turns the blended wing yellow-white.
    d2,
    /// d₁, the spacing: the default, which keeps the wing blue as in Figure 9.
    d1,
};

/// The thesis' blend over mullion thicknesses: the varied thickness takes `samples` equally
/// spaced values from min_nm to max_nm (both included) and the reflectance spectra are averaged
/// with equal weights; every other parameter is the wing's.
struct MorphoBlend {
    double min_nm = 50.0;
    double max_nm = 150.0;
    /// 101 samples: every 1 nm from 50 to 150 nm.
    int samples = 101;
    MorphoBlendThickness varies = MorphoBlendThickness::d1;
};

/// Throws irid::Error naming the parameter unless d1, d2 ≥ 0, n ≥ 1 (all finite),
/// 0 ≤ periods ≤ 1e6 and K ≥ 0 ("morpho: d1 -3 nm must be finite and >= 0").
void validate_morpho(const MorphoParameters& wing);
/// Throws irid::Error unless 0 ≤ min_nm ≤ max_nm (finite) and 2 ≤ samples ≤ 100000.
void validate_morpho_blend(const MorphoBlend& blend);

/// Smits 1990, eq. 29: t_θ = d₁ cos θ + d₂ (n² − sin²θ)^½ [nm], θ [rad] the angle in air.
[[nodiscard]] double morpho_effective_thickness_nm(const MorphoParameters& wing,
                                                   double theta_rad) noexcept;

/// Smits 1990, eq. 25 with t = t_θ of eq. 29.
[[nodiscard]] double morpho_reflectance(const MorphoParameters& wing, double lambda_nm,
                                        double theta_rad) noexcept;

/// The wing's spectrum on the 1 nm grid at angle_deg in air. Throws irid::Error unless the
/// parameters are valid and 0° ≤ angle_deg < 90°.
[[nodiscard]] DenseSpectrum morpho_spectrum(const MorphoParameters& wing, double angle_deg = 0.0);

/// The blend's mean reflectance at one wavelength and angle θ [rad] in air, for a wing and blend
/// that passed validate_morpho and validate_morpho_blend.
[[nodiscard]] double morpho_blend_reflectance(const MorphoParameters& wing, const MorphoBlend& blend,
                                              double lambda_nm, double theta_rad) noexcept;

/// The blend's continuous form: the mean of eq. 25 over the varied thickness spread uniformly
/// over [min_nm, max_nm] (instead of blend.samples equal steps), in closed form. The Fejér
/// kernel (sin((l+1)x) / sin x)² = (l+1) + 2 Σ_{k=1}^{l} (l+1−k) cos 2kx, with x = 2πt_θ/λ
/// linear in the varied thickness, averages term by term: cos 2kx over [x_a, x_b] has the mean
/// (sin 2kx_b − sin 2kx_a) / (2k (x_b − x_a)). O(l) per wavelength, exact to rounding; the
/// sampled blend converges to it as the samples grow. For a wing and blend that passed
/// validation.
[[nodiscard]] double morpho_blend_reflectance_continuous(const MorphoParameters& wing,
                                                         const MorphoBlend& blend,
                                                         double lambda_nm,
                                                         double theta_rad) noexcept;

/// The blended spectrum (see MorphoBlend): the mean of morpho_spectrum over the samples of the
/// varied thickness, whose value in `wing` is not used. Throws irid::Error as morpho_spectrum and
/// validate_morpho_blend.
[[nodiscard]] DenseSpectrum morpho_blend_spectrum(const MorphoParameters& wing,
                                                  const MorphoBlend& blend, double angle_deg = 0.0);

/// The thesis' Morpho table: the wing's colour (optionally blended) at angles 0, h, ..., 90°,
/// linear in between.
class MorphoTable {
public:
    /// Throws irid::Error unless the wing (and blend) are valid, 0 < step_deg ≤ 90 and the
    /// illuminant has luminance. The step is shrunk so that it divides 90° evenly.
    MorphoTable(const MorphoParameters& wing, const DenseSpectrum& illuminant,
                Observer observer = Observer::cie1931_2deg, double step_deg = 1.0,
                const std::optional<MorphoBlend>& blend = std::nullopt);

    /// XYZ (white Y = 1) at angle_deg in air; angles outside [0°, 90°] are clamped.
    [[nodiscard]] Xyz at(double angle_deg) const noexcept;

    [[nodiscard]] double step_deg() const noexcept { return m_step_deg; }

private:
    double m_step_deg;
    std::vector<Xyz> m_colors;
};

}  // namespace irid
