#pragma once

// The constants of the ACES 2.0 output transform that more than one implementation reads: the
// double reference (aces2_model.cpp, aces2.cpp), the table builder (aces2_tables.cpp) and the
// Highway kernel (aces2_simd_forward.cpp, aces2_simd_inverse.cpp, aces2_simd-inl.h). The Academy's
// values (aces-core, Lib.Academy.OutputTransform.ctl and Lib.Academy.Tonescale.ctl); OpenColorIO's
// ops/fixedfunction/ACES2 uses the same.

#include <irid/color/matrix.h>
#include <irid/color/rgb.h>
#include <irid/color/types.h>

#include <array>

namespace irid::aces2 {

/// The hue tables' nominal entries: 360, one per degree for the reach (OpenColorIO's).
inline constexpr int table_hues = 360;

/// 1.0 of scene and display values in cd/m², and the scale of J (the white's J is 100).
inline constexpr double reference_luminance = 100.0;
inline constexpr double j_scale = 100.0;

// Viewing conditions of the model (aces-core Lib.Academy.OutputTransform, "init_JMhParams"):
// adapting luminance L_A = 100 cd/m², background Y_b = 20, dim surround (F, c, N_c) =
// (0.9, 0.59, 0.9).
inline constexpr double adapting_luminance = 100.0;
inline constexpr double background_y = 20.0;
inline constexpr double surround_c = 0.59;
inline constexpr double surround_nc = 0.9;

/// The cone primaries of the model (aces-core: the CAM16 primaries refitted), with the white
/// 0.333, 0.333 as the Academy gives it (outside their triangle).
inline constexpr RgbPrimaries cone_primaries{{0.8336, 0.1735}, {2.3854, -1.4659}, {0.087, -0.125}};
inline constexpr Xy cone_white{0.333, 0.333};

/// ACES AP0 (the scene's primaries) and AP1 (the reach gamut's), with the ACES white
/// (SMPTE ST 2065-1, Academy S-2014-004).
inline constexpr RgbPrimaries ap0{{0.7347, 0.2653}, {0.0, 1.0}, {0.0001, -0.0770}};
inline constexpr RgbPrimaries ap1{{0.713, 0.293}, {0.165, 0.830}, {0.128, 0.044}};
inline constexpr Xy aces_white{0.32168, 0.33767};

/// The inverse response takes a response of at most this share of response_scale: OpenColorIO
/// 2.4.2+ (Transform.cpp, _post_adaptation_cone_response_compression_inv) limits it there, which
/// keeps it finite where the response diverges; no forward response comes near it.
inline constexpr double response_inverse_share = 0.99;

/// The compressive response R_a = 400 (F_L R)^0.42 / (27.13 + (F_L R)^0.42) (Hellwig,
/// Stolitzka & Fairchild 2022, eq. 8, with its offset 0.2713 and scale 4 times the reference).
inline constexpr double response_exponent = 0.42;
inline constexpr double response_offset = 0.2713 * reference_luminance;
inline constexpr double response_scale = 4.0 * reference_luminance;

/// The hue-dependent normalisation of M: a Fourier fit over hue h,
/// c0 + c1 cos h + c2 cos 2h + c3 cos 3h + c4 sin h + c5 sin 2h + c6 sin 3h.
inline constexpr std::array<double, 7> m_norm_coefficients{77.12896, 11.34072, 16.46899, 7.88380,
                                                           14.66441, -6.37224, 9.19364};

/// Gamut compression: the smoothing of the hull at the cusp (of the cusp's M), the focus point's
/// blend from the cusp toward mid grey, the J threshold of the focus gain (a blend from the cusp
/// toward the peak's J), and the share of the gamut boundary's M below which chroma is left alone.
/// Above the threshold the focus gain is 1 + log10(r)², r = (J_max − threshold) / max(1e-4,
/// J_max − J): OpenColorIO 2.4.2 and later (pull request 2127), which squares the logarithm where
/// the Academy's 2024 CTL and OpenColorIO 2.4.0–2.4.1 raise it to 1/0.55 (docs/DISPLAY.md).
inline constexpr double smooth_cusps = 0.12;
inline constexpr double cusp_mid_blend = 1.3;
inline constexpr double focus_gain_blend = 0.3;
inline constexpr double focus_gain_min_distance = 1e-4;
inline constexpr double compression_threshold = 0.75;

/// The normalised primary matrix (SMPTE RP 177, RGB to XYZ with the white at Y = 1) without
/// rgb_to_xyz_matrix's checks: the model's cone "primaries" all lie below their white (y < 0.18),
/// so the white is outside their triangle. aces2_model.cpp.
[[nodiscard]] Mat3 primary_matrix(const RgbPrimaries& primaries, const Xy& white);

}  // namespace irid::aces2
