#pragma once

// The SIMD kernel of Converter::convert for linear RGB or XYZ → Oklab (convert_simd.cpp).

#include <cstddef>

namespace irid::detail {

/// Oklab of n colours (interleaved triples): LMS = to_lms · c, their real cube roots, then
/// Ottosson's M2, in double whatever T is (float is promoted on load and rounded on store).
/// Matrices row-major. A block of lanes with an LMS component that is not finite, or whose
/// magnitude is outside [1e-30, 1e30] (and not 0), is computed by the scalar path (std::cbrt),
/// as are the last colours that do not fill a vector. Each cube root is within a few ulp of
/// std::cbrt (tests/color/convert_test.cpp).
void linear_to_oklab_simd(const double* in, double* out, std::size_t n, const double* to_lms,
                          const double* m2) noexcept;
void linear_to_oklab_simd(const float* in, float* out, std::size_t n, const double* to_lms,
                          const double* m2) noexcept;

}  // namespace irid::detail
