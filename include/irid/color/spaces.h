#pragma once

#include <irid/color/matrix.h>
#include <irid/color/types.h>

namespace irid {

// Conversions between XYZ and the derived spaces. `white` is the reference white's XYZ
// (Y = 1 in relative colorimetry). All are noexcept and total: black, zero chromaticity
// denominators and negative values give defined, finite results.

/// CIE lightness breakpoint ε = (6/29)³ and slope κ = (29/3)³, CIE 015:2018 §8.2: below
/// ε, L* = κ Y/Yn (the linear segment that Smits 1990, eq. 10 omits).
inline constexpr double cie_epsilon = 216.0 / 24389.0;
inline constexpr double cie_kappa = 24389.0 / 27.0;

[[nodiscard]] Xy xyz_to_xy(const Xyz& c, const Xy& black_chromaticity = {1.0 / 3.0, 1.0 / 3.0}) noexcept;
/// XYZ of chromaticity xy at luminance Y (Y / y scale). y = 0 gives black.
[[nodiscard]] Xyz xy_to_xyz(const Xy& c, double Y = 1.0) noexcept;
/// xyY; for black (X + Y + Z = 0) the chromaticity is `black_chromaticity` (usually the white's).
[[nodiscard]] Xyy xyz_to_xyy(const Xyz& c, const Xy& black_chromaticity = {1.0 / 3.0, 1.0 / 3.0}) noexcept;
[[nodiscard]] Xyz xyy_to_xyz(const Xyy& c) noexcept;

/// u' = 4X / (X + 15Y + 3Z), v' = 9Y / (X + 15Y + 3Z) (CIE 015:2018 §8.2.2); for a zero
/// denominator, `black_uv`.
[[nodiscard]] UvPrime xyz_to_uv_prime(const Xyz& c, const UvPrime& black_uv = {4.0 / 19.0, 9.0 / 19.0}) noexcept;
[[nodiscard]] UvPrime xy_to_uv_prime(const Xy& c) noexcept;
[[nodiscard]] Xy uv_prime_to_xy(const UvPrime& c) noexcept;

/// CIE lightness L* of a relative luminance Y/Yn, including the linear segment below ε.
[[nodiscard]] double cie_lightness(double relative_luminance) noexcept;
/// Inverse of cie_lightness.
[[nodiscard]] double cie_lightness_to_relative_luminance(double L) noexcept;

/// CIELUV, CIE 015:2018 §8.2.2 (Smits 1990, eq. 10-11, with the full CIE lightness).
[[nodiscard]] Luv xyz_to_luv(const Xyz& c, const Xyz& white) noexcept;
[[nodiscard]] Xyz luv_to_xyz(const Luv& c, const Xyz& white) noexcept;
/// CIELAB, CIE 015:2018 §8.2.1.
[[nodiscard]] Lab xyz_to_lab(const Xyz& c, const Xyz& white) noexcept;
[[nodiscard]] Xyz lab_to_xyz(const Lab& c, const Xyz& white) noexcept;

[[nodiscard]] LchUv luv_to_lch(const Luv& c) noexcept;
[[nodiscard]] Luv lch_to_luv(const LchUv& c) noexcept;
[[nodiscard]] LchAb lab_to_lch(const Lab& c) noexcept;
[[nodiscard]] Lab lch_to_lab(const LchAb& c) noexcept;

/// CIELUV saturation s_uv = 13 [(u' − u'n)² + (v' − v'n)²]^½ = C*uv / L* (CIE 015:2018 §8.2.2).
[[nodiscard]] double saturation_uv(const Xyz& c, const Xyz& white) noexcept;

/// Oklab (Ottosson 2020, "A perceptual color space for image processing") with its matrices as
/// CSS Color Module Level 4 defines them (§9.2 and its sample code conversions.js, "recalculated
/// for consistent reference white", csswg-drafts issue 6642), as colorjs.io and the browsers
/// use them: Ottosson's, refitted so that the D65 white (x, y) = (0.3127, 0.3290) maps to LMS
/// (1, 1, 1) and to Oklab (1, 0, 0) to within 1e-15. Ottosson's published matrices (below, for
/// reference) differ by under 3.1e-4 and give that white a chroma of 1.2e-4, so their neutral
/// axis would leave every D65 RGB cube just below its white; irid uses the refitted ones
/// everywhere, and they reproduce Ottosson's published table of XYZ → Oklab to its 3 decimals.
/// M1: XYZ with D65 white at Y = 1 → LMS.
inline constexpr Mat3 oklab_m1{{{{0.8190224379967030, 0.3619062600528904, -0.1288737815209879},
                                 {0.0329836539323885, 0.9292868615863434, 0.0361446663506424},
                                 {0.0481771893596242, 0.2642395317527308, 0.6335478284694309}}}};
/// M2: cube-rooted LMS → Lab.
inline constexpr Mat3 oklab_m2{{{{0.2104542683093140, 0.7936177747023054, -0.0040720430116193},
                                 {1.9779985324311684, -2.4285922420485799, 0.4505937096174110},
                                 {0.0259040424655478, 0.7827717124575296, -0.8086757549230774}}}};

/// Inverses of M1 and M2, computed from them (exact round trips).
inline constexpr Mat3 oklab_m1_inverse = inverse_unchecked(oklab_m1);
inline constexpr Mat3 oklab_m2_inverse = inverse_unchecked(oklab_m2);

/// Ottosson's published M1 and M2 (2020, 10 digits), which the refitted ones replace.
inline constexpr Mat3 ottosson_published_oklab_m1{{{{0.8189330101, 0.3618667424, -0.1288597137},
                                                     {0.0329845436, 0.9293118715, 0.0361456387},
                                                     {0.0482003018, 0.2643662691, 0.6338517070}}}};
inline constexpr Mat3 ottosson_published_oklab_m2{{{{0.2104542553, 0.7936177850, -0.0040720468},
                                                     {1.9779984951, -2.4285922050, 0.4505937099},
                                                     {0.0259040371, 0.7827717662, -0.8086757660}}}};

/// Oklab from XYZ relative to D65 (Y = 1 white); the cube root is odd-symmetric (cbrt) so
/// negative LMS values from out-of-gamut colours stay invertible.
[[nodiscard]] Oklab xyz_to_oklab(const Xyz& c) noexcept;
[[nodiscard]] Xyz oklab_to_xyz(const Oklab& c) noexcept;
[[nodiscard]] Oklch oklab_to_oklch(const Oklab& c) noexcept;
[[nodiscard]] Oklab oklch_to_oklab(const Oklch& c) noexcept;

/// Hue angle in degrees in [0, 360) of the vector (a, b); 0 for a = b = 0.
[[nodiscard]] double hue_degrees(double a, double b) noexcept;

}  // namespace irid
