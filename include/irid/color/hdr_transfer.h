#pragma once

// The HDR transfer functions of ITU-R BT.2100-2: PQ (SMPTE ST 2084), in absolute luminance, and
// HLG (ARIB STD-B67), relative to the display's peak with its luminance-dependent system gamma.
// Every function maps any input to a finite output: NaN is taken as 0, and values beyond the
// domain are clamped to it (stated per function).

#include <array>

namespace irid {

/// PQ's peak [cd/m²]: signal 1.0 (BT.2100-2 Table 4).
inline constexpr double pq_peak_nits = 10000.0;

/// PQ's inverse EOTF: display luminance [cd/m²], clamped to [0, 10000], to the non-linear
/// signal E' in [0, 1]. 0 cd/m² gives c1^m2 ≈ 7.3e-7, not 0, as the standard's formula does.
[[nodiscard]] double pq_encode(double nits) noexcept;
/// PQ's EOTF: the signal, clamped to [0, 1], to display luminance [cd/m²].
[[nodiscard]] double pq_decode(double signal) noexcept;

/// HLG's OETF: normalised scene light E, clamped to [0, 1], to the signal E' in [0, 1].
[[nodiscard]] double hlg_oetf(double scene) noexcept;
/// The inverse of hlg_oetf: the signal, clamped to [0, 1], to scene light in [0, 1].
[[nodiscard]] double hlg_inverse_oetf(double signal) noexcept;

/// HLG's system gamma for a display of nominal peak luminance L_W [cd/m²]:
/// 1.2 + 0.42 log10(L_W / 1000) (BT.2100-2 Table 5, note 5b; L_W clamped to [100, 10000]).
[[nodiscard]] double hlg_system_gamma(double peak_nits) noexcept;

/// HLG's OOTF: scene light RGB (each in [0, 1], Rec.2020 primaries) to display light [cd/m²],
/// F_D = L_W Y_S^(γ − 1) E with Y_S the scene luminance (0.2627 R + 0.6780 G + 0.0593 B) and a
/// black level of 0. Channels are clamped to [0, 1] first.
[[nodiscard]] std::array<double, 3> hlg_ootf(const std::array<double, 3>& scene, double peak_nits) noexcept;
/// The inverse OOTF: display light [cd/m²], clamped to [0, 2 L_W] (beyond every value the OOTF
/// gives), to scene light, clamped to [0, 1].
[[nodiscard]] std::array<double, 3> hlg_inverse_ootf(const std::array<double, 3>& display, double peak_nits) noexcept;

/// The inverse OOTF without its clamps: display light [cd/m²] to the scene light E that would
/// show it, which lies outside [0, 1] (a channel of E below 0 or above 1) exactly when the
/// signal cannot hold the colour; zero when the luminance Y_D is not above 0, NaN taken as 0.
[[nodiscard]] std::array<double, 3> hlg_scene_light_unclamped(const std::array<double, 3>& display,
                                                              double peak_nits) noexcept;

/// HLG's EOTF (OOTF of the inverse OETF, black level 0) and its inverse, signal RGB ↔ display
/// light [cd/m²] on a display of peak L_W.
[[nodiscard]] std::array<double, 3> hlg_decode(const std::array<double, 3>& signal, double peak_nits) noexcept;
[[nodiscard]] std::array<double, 3> hlg_encode(const std::array<double, 3>& display, double peak_nits) noexcept;

}  // namespace irid
