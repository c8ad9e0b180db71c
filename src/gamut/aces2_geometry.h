#pragma once

// The geometry of the ACES 2.0 gamut compression in the (M, J) plane of one hue, shared by the
// per-colour rendering (aces2.cpp) and the table builder (aces2_tables.cpp, which fits the upper
// hull's γ through it): the focus gain, the compression line through a colour, and the
// estimate of where that line meets the gamut's hull. OpenColorIO 2.4.2+'s formulas
// (src/OpenColorIO/ops/fixedfunction/ACES2/Transform.cpp), in the precision T of the caller:
// double per colour, float where the table builder follows OpenColorIO's float arithmetic.

#include "aces2_constants.h"

#include <algorithm>
#include <cmath>

namespace irid::aces2 {

template <class T>
inline T lerp(T a, T b, T t) noexcept {
    return a + t * (b - a);
}

/// The J above which the focus gain rises: a blend from the cusp's J toward the peak's.
template <class T>
inline T focus_threshold(T cusp_j, T limit_j_max) noexcept {
    return lerp(cusp_j, limit_j_max, T(focus_gain_blend));
}

/// The focus point's J: from the cusp toward mid grey, by 1.3 − J_cusp / J_max (at most 1).
template <class T>
inline T focus_j_of(T cusp_j, T mid_j, T limit_j_max) noexcept {
    return lerp(cusp_j, mid_j, std::min(T(1), T(cusp_mid_blend) - cusp_j / limit_j_max));
}

/// The slope gain of the compression toward the focus: limit_j_max · focus_dist, times
/// 1 + log10(r)² above the threshold (aces2_constants.h). Finite for every finite j.
template <class T>
inline T focus_gain(T j, T threshold, T limit_j_max, T focus_dist) noexcept {
    T gain = limit_j_max * focus_dist;
    if (j > threshold) {
        const T l = std::log10((limit_j_max - threshold) /
                               std::max(T(focus_gain_min_distance), limit_j_max - j));
        gain = gain * (l * l + T(1));
    }
    return gain;
}

/// Where the compression line through (J, M) meets the J axis: the root of a quadratic, taken
/// in the form without cancellation.
template <class T>
inline T solve_j_intersect(T j, T m, T focus_j, T max_j, T slope_gain) noexcept {
    const T m_scaled = m / slope_gain;
    const T a = m_scaled / focus_j;
    if (j < focus_j) {
        const T b = T(1) - m_scaled;
        const T c = -j;
        return T(-2) * c / (b + std::sqrt(b * b - T(4) * a * c));
    }
    const T b = -(T(1) + m_scaled + max_j * a);
    const T c = max_j * m_scaled + j;
    return T(-2) * c / (b - std::sqrt(b * b - T(4) * a * c));
}

/// The slope dJ/dM of the compression line that meets the J axis at j_intersect.
template <class T>
inline T compression_slope(T j_intersect, T focus_j, T limit_j_max, T slope_gain) noexcept {
    const T scaler = j_intersect < focus_j ? j_intersect : limit_j_max - j_intersect;
    return scaler * (j_intersect - focus_j) / (focus_j * slope_gain);
}

/// The M where the line J = slope M + J_axis meets the boundary J = J_max (M / M_max)^(1/γ),
/// estimated through a reference intersection (no iteration). A line that meets the axis at or
/// beyond the boundary's apex (J_axis <= 0, which rounding gives a colour at the peak's J) meets
/// the boundary at M = 0, the limit from inside; OpenColorIO's float code takes the power of the
/// negative number there and returns NaN (docs/DISPLAY.md).
template <class T>
inline T line_boundary_m(T j_axis, T slope, T inv_gamma, T j_max, T m_max, T j_reference) noexcept {
    const T shifted = j_reference * std::pow(std::max(j_axis, T(0)) / j_reference, inv_gamma);
    return shifted * m_max / (j_max - slope * m_max);
}

/// A smooth minimum over a cubic polynomial, its width relative to `scale`.
template <class T>
inline T smooth_min(T a, T b, T scale) noexcept {
    const T s = T(smooth_cusps) * scale;
    const T h = std::max(s - std::abs(a - b), T(0)) / s;
    return std::min(a, b) - h * h * h * s * (T(1) / T(6));
}

/// The gamut boundary's M along the compression line: the lower hull (γ_bottom from the origin
/// to the cusp) and the upper hull (γ_top, flipped about J_max) meeting in a smooth minimum.
template <class T>
inline T gamut_boundary_m(T cusp_j, T cusp_m, T j_max, T gamma_top_inv, T gamma_bottom_inv,
                          T j_intersect_source, T slope, T j_intersect_cusp) noexcept {
    const T lower = line_boundary_m(j_intersect_source, slope, gamma_bottom_inv, cusp_j, cusp_m,
                                    j_intersect_cusp);
    const T upper = line_boundary_m(j_max - j_intersect_source, -slope, gamma_top_inv,
                                    j_max - cusp_j, cusp_m, j_max - j_intersect_cusp);
    return smooth_min(lower, upper, cusp_m);
}

}  // namespace irid::aces2
