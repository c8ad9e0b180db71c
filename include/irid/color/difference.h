#pragma once

#include <irid/color/matrix.h>
#include <irid/color/types.h>

#include <string_view>

namespace irid {

/// CIE 1976 ΔE*ab: Euclidean distance in CIELAB.
[[nodiscard]] double delta_e_76(const Lab& a, const Lab& b) noexcept;

/// CIEDE2000 (CIE 142:2001; implemented per Sharma, Wu & Dalal 2005, eq. 1-21), with the
/// parametric factors kL, kC, kH (1 for reference conditions).
[[nodiscard]] double delta_e_2000(const Lab& a, const Lab& b, double k_l = 1.0, double k_c = 1.0,
                                  double k_h = 1.0) noexcept;

/// ΔE*uv: Euclidean distance in CIELUV (Smits 1990, eq. 12).
[[nodiscard]] double delta_e_uv(const Luv& a, const Luv& b) noexcept;
/// ΔH*uv = [(ΔE*uv)² − (ΔL*)² − (ΔC*uv)²]^½ (Smits 1990, eq. 13; CIE 015:2018 §8.3), the
/// hue difference, computed as the equal 2 (C1 C2)^½ |sin(Δh/2)|, which is free of
/// cancellation.
[[nodiscard]] double delta_h_uv(const Luv& a, const Luv& b) noexcept;
/// ΔS: difference of CIELUV saturation s_uv = C*uv / L* (Smits 1990, eq. 14; CIE 015:2018
/// §8.2.2), b minus a. Colours with L* = 0 have saturation 0.
[[nodiscard]] double delta_s_uv(const Luv& a, const Luv& b) noexcept;
/// ΔC*uv, chroma difference b minus a.
[[nodiscard]] double delta_c_uv(const Luv& a, const Luv& b) noexcept;

/// ΔEOK: Euclidean distance in Oklab (CSS Color Module Level 4, §13.2).
[[nodiscard]] double delta_e_ok(const Oklab& a, const Oklab& b) noexcept;

/// The colour differences by name, each on triples of its own space: ciede2000 and cie76 on
/// CIELAB, cieuv (ΔE*uv) on CIELUV, oklab (ΔEOK) on Oklab.
enum class DeltaEMetric { ciede2000, cie76, cieuv, oklab };
/// Throws UnknownNameError listing the names.
[[nodiscard]] DeltaEMetric parse_delta_e_metric(std::string_view name);
[[nodiscard]] std::string_view delta_e_metric_name(DeltaEMetric metric) noexcept;
/// The metric's difference between two triples of its space.
[[nodiscard]] double delta_e(DeltaEMetric metric, const Vec3& a, const Vec3& b) noexcept;

}  // namespace irid
