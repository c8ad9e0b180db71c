#pragma once

// The constants of the ACES 2.0 output transform that more than one implementation reads: the
// double reference (aces2_model.cpp, aces2.cpp) and the Highway kernel (aces2_simd.cpp). The
// Academy's values (aces-core, Lib.Academy.OutputTransform.ctl and Lib.Academy.Tonescale.ctl);
// OpenColorIO's ops/fixedfunction/ACES2 uses the same.

#include <array>

namespace irid::aces2 {

/// 1.0 of scene and display values in cd/m², and the scale of J (the white's J is 100).
inline constexpr double reference_luminance = 100.0;
inline constexpr double j_scale = 100.0;

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
/// toward the peak's J) and the gain's exponent 1/0.55, and the share of the gamut boundary's M
/// below which chroma is left alone.
inline constexpr double smooth_cusps = 0.12;
inline constexpr double cusp_mid_blend = 1.3;
inline constexpr double focus_gain_blend = 0.3;
inline constexpr double focus_adjust_gain_inv = 1.0 / 0.55;
inline constexpr double compression_threshold = 0.75;

}  // namespace irid::aces2
