#pragma once

#include <irid/color/spectrum.h>
#include <irid/color/types.h>

#include <span>
#include <string_view>

namespace irid {

/// The CIE standard colorimetric observers.
enum class Observer {
    /// CIE 1931 standard colorimetric observer (2 degree field).
    cie1931_2deg,
    /// CIE 1964 supplementary standard colorimetric observer (10 degree field).
    cie1964_10deg,
};

/// The colour-matching functions x̄, ȳ, z̄ of an observer, 360-830 nm at 1 nm.
struct ColorMatchingFunctions {
    DenseSpectrum x, y, z;
};

/// The CIE tables, CIE 015:2018 (data/cie1931_2deg_xyz_cmf.csv, data/cie1964_10deg_xyz_cmf.csv).
[[nodiscard]] const ColorMatchingFunctions& color_matching_functions(Observer observer) noexcept;

/// "cie1931" or "cie1964" (also "2" / "10"). Throws irid::Error listing the names otherwise.
[[nodiscard]] Observer parse_observer(std::string_view name);
[[nodiscard]] std::string_view observer_name(Observer observer) noexcept;

/// Tristimulus values of a monochromatic stimulus of unit radiance at any wavelength in
/// 360-830 nm: the colour-matching functions, linear between the 1 nm table entries (zero
/// outside). Its chromaticity is the spectral locus.
[[nodiscard]] Xyz monochromatic_xyz(double lambda_nm, Observer observer = Observer::cie1931_2deg) noexcept;

/// Chromaticity of the spectral locus at lambda_nm.
[[nodiscard]] Xy spectral_locus_xy(double lambda_nm, Observer observer = Observer::cie1931_2deg);

/// Whether a chromaticity is that of some light: strictly inside the CIE 1931 spectral locus
/// (380–700 nm at 1 nm; beyond 700 nm the locus hardly moves and its tabulated tail wavers)
/// closed by the purple line.
[[nodiscard]] bool is_real_chromaticity(const Xy& xy) noexcept;
/// Throws irid::Error naming `what` unless is_real_chromaticity: a reference white outside the
/// diagram has no light and its XYZ makes CIELAB, CIELUV and the adaptations meaningless (a
/// white with y near 0 has an infinite X and Z).
void check_white_chromaticity(const Xy& xy, std::string_view what = "white");

/// Luminous efficacy for absolute photometry [lm/W]: 683, the SI K_cd (definition of the candela,
/// 683 lm/W at 540e12 Hz), which the issue and most software use. CIE 015:2018's K_m for the
/// tabulated V(λ) is 683.002 lm/W (683 × V(555)/V(555.016)), 3e-6 larger.
inline constexpr double max_luminous_efficacy_lm_per_w = 683.0;

/// Tristimulus values of a reflectance (or transmittance) factor seen under an illuminant,
/// CIE 015:2018 §7.1-7.2: k Σ S(λ) R(λ) x̄(λ) Δλ at Δλ = 1 nm over 360-830 nm, with
/// k = 1 / Σ S(λ) ȳ(λ) Δλ so the perfect reflecting diffuser has Y = 1.
[[nodiscard]] Xyz reflectance_to_xyz(const DenseSpectrum& reflectance, const DenseSpectrum& illuminant,
                                     Observer observer = Observer::cie1931_2deg) noexcept;

/// reflectance_to_xyz of a reflectance sampled at strictly increasing wavelengths (any
/// spacing), resampled to 1 nm by linear interpolation with the ends held (CIE 015:2018 §7.2.2).
/// Throws irid::Error for fewer than two samples, sizes that differ, a wavelength that is not
/// finite and positive or not above the one before, wavelengths that miss 360-830 nm, or a
/// result too large to be finite.
[[nodiscard]] Xyz sampled_reflectance_to_xyz(std::span<const double> wavelengths_nm,
                                             std::span<const double> values,
                                             const DenseSpectrum& illuminant,
                                             Observer observer = Observer::cie1931_2deg);
/// The wavelength checks of sampled_reflectance_to_xyz alone.
void check_sample_wavelengths(std::span<const double> wavelengths_nm);

/// The illuminant's white: reflectance_to_xyz of the perfect reflecting diffuser (Y = 1).
[[nodiscard]] Xyz illuminant_white(const DenseSpectrum& illuminant,
                                   Observer observer = Observer::cie1931_2deg);

/// Relative tristimulus values of an emission spectrum: scaled so that Y = 1 (the spectrum's
/// own luminance is the unit). Throws irid::Error when the spectrum's Y is not positive.
[[nodiscard]] Xyz emission_to_xyz_relative(const DenseSpectrum& spectral_power,
                                           Observer observer = Observer::cie1931_2deg);

/// Absolute tristimulus values of an emission spectrum: K_m Σ S(λ) x̄(λ) Δλ with
/// K_m = 683 lm/W. Spectral radiance in W·sr⁻¹·m⁻²·nm⁻¹ gives Y as luminance in cd/m².
[[nodiscard]] Xyz emission_to_xyz_absolute(const DenseSpectrum& spectral_power,
                                           Observer observer = Observer::cie1931_2deg) noexcept;

/// Monte Carlo estimate of ∫ s(λ) x̄(λ) dλ (and ȳ, z̄) from one hero-wavelength sample; its
/// expectation over the hero wavelength is the integral over [360, 830] nm.
template <int N>
[[nodiscard]] Xyz estimate_xyz_integral(const SampledSpectrum<N>& s, const SampledWavelengths<N>& w,
                                        Observer observer = Observer::cie1931_2deg) noexcept {
    Xyz sum;
    for (int i = 0; i < N; ++i) {
        const Xyz cmf = monochromatic_xyz(w[i], observer);
        const double weight = s[i] / (w.pdf(i) * N);
        sum.X += cmf.X * weight;
        sum.Y += cmf.Y * weight;
        sum.Z += cmf.Z * weight;
    }
    return sum;
}

}  // namespace irid
