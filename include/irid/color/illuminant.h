#pragma once

#include <irid/color/spectrum.h>
#include <irid/color/types.h>

#include <array>
#include <string>
#include <string_view>
#include <vector>

namespace irid {

/// Second radiation constant c2 = hc/k [m·K], the value CIE 015:2018 §3.1 uses for Planckian
/// radiators (ITS-90).
inline constexpr double planck_c2_m_k = 1.4388e-2;
/// First radiation constant for spectral radiance, c1L = 2hc² [W·m²·sr⁻¹] (CODATA 2018, exact
/// from the SI definitions of h and c).
inline constexpr double planck_c1l_w_m2_per_sr = 1.191042972e-16;

/// CIE standard illuminant D65: the CIE table at 5 nm (CIE S 014-2), linear between the 5 nm
/// values as CIE 015:2018 §6.1 prescribes.
[[nodiscard]] DenseSpectrum illuminant_d65();
/// CIE illuminant D50: the daylight basis at the CCT 5000 × 1.4388/1.4380 K (CIE 015:2018 §6.1).
[[nodiscard]] DenseSpectrum illuminant_d50();
/// CIE standard illuminant A by its defining formula (CIE S 014-2 / ISO 11664-2):
/// S_A(λ) = 100 (560/λ)⁵ [exp(1.435e7 / (2848 × 560)) - 1] / [exp(1.435e7 / (2848 λ)) - 1],
/// λ in nm (a Planckian radiator at 2856 K on the ITS-90 scale).
[[nodiscard]] DenseSpectrum illuminant_a();
/// The equal-energy illuminant E: 100 at every wavelength.
[[nodiscard]] DenseSpectrum illuminant_e();

/// Chromaticity of CIE daylight of a correlated colour temperature, CIE 015:2018 §4 (daylight: x_D as a cubic in 1/T, y_D as a quadratic in x_D).
/// Throws irid::Error unless 4000 K ≤ cct_k ≤ 25000 K.
[[nodiscard]] Xy daylight_chromaticity(double cct_k);
/// CIE daylight of a correlated colour temperature from the S0, S1, S2 basis with M1 and M2
/// rounded to three decimals (CIE 015:2018 §4), linear between the 5 nm values.
/// Throws irid::Error unless 4000 K ≤ cct_k ≤ 25000 K.
[[nodiscard]] DenseSpectrum daylight_illuminant(double cct_k);
/// The CIE daylight basis S0, S1, S2 (CIE 015:2018 §4) on the 1 nm grid, linear between
/// the 5 nm values.
[[nodiscard]] std::array<DenseSpectrum, 3> daylight_basis();
/// The weights M1, M2 of the daylight basis for a chromaticity (CIE 015:2018 §4, not rounded).
/// Meant for chromaticities near the daylight locus (skies). Throws irid::Error for a
/// non-finite chromaticity or one where the formula's denominator 0.0241 + 0.2562 x − 0.7341 y
/// is not below −0.01 (far from daylight; about −0.14 on the locus).
struct DaylightWeights {
    double m1 = 0, m2 = 0;
};
[[nodiscard]] DaylightWeights daylight_weights(Xy chromaticity);
/// The CIE daylight spectrum S0 + M1 S1 + M2 S2 of a chromaticity (daylight_weights), S0's
/// scale. Near the daylight locus its chromaticity is the one asked for within about 1e-3.
[[nodiscard]] DenseSpectrum daylight_from_chromaticity(Xy chromaticity);

/// Spectral radiance of a Planckian radiator [W·sr⁻¹·m⁻²·nm⁻¹] at lambda_nm.
[[nodiscard]] double planck_radiance(double lambda_nm, double temperature_k) noexcept;
/// A Planckian radiator, normalised to 100 at 560 nm. Throws irid::Error unless
/// 100 K ≤ temperature_k ≤ 1e6 K.
[[nodiscard]] DenseSpectrum blackbody(double temperature_k);

/// An illuminant by name: D50, D55, D65, D75, A, E, D<CCT> (for example D9300, CCT in kelvin
/// 4000-25000), blackbody:<T> (T in kelvin). Case-insensitive. Throws irid::Error listing the
/// accepted forms otherwise. D55 and D75 use the CCTs 5500 and 7500 × 1.4388/1.4380 K.
[[nodiscard]] DenseSpectrum illuminant_by_name(std::string_view name);

/// Names accepted by white_point_xy, for messages.
[[nodiscard]] std::vector<std::string> white_point_names();

/// The name illuminant_by_name reads `name` as, written one way: "D65", "D50", "D55", "D75", "A",
/// "E", "D<CCT>" (the number as it reads back, "D9300"), "blackbody:<T>". Throws as
/// illuminant_by_name does for a name it does not know.
[[nodiscard]] std::string canonical_illuminant_name(std::string_view name);

/// The chromaticity of a named white (CIE 1931 2°). D65 is (0.31270, 0.32900), the value of
/// ITU-R BT.709 and IEC 61966-2-1; D50 (0.34567, 0.35850), D55 (0.33242, 0.34743), D75
/// (0.29902, 0.31485), A (0.44757, 0.40745), C (0.31006, 0.31616) from CIE 015:2004 Table T.3;
/// E (1/3, 1/3). (The NTSC 1953 space keeps the FCC's rounded C, (0.310, 0.316).) Also accepts
/// "x,y" (spaces allowed) for any white. Throws irid::Error otherwise.
[[nodiscard]] Xy white_point_xy(std::string_view name);

}  // namespace irid
