#pragma once

namespace irid {

// Colour value types. Member names follow the colour-science symbols (X, Y, Z; L*, a*, b*...).
// They are plain aggregates: no invariants, any finite value is representable, including the
// out-of-gamut and negative values the gamut-clipping code must see.

/// CIE 1931 (or 1964) tristimulus values. irid's relative colorimetry puts the reference
/// white at Y = 1.
struct Xyz {
    double X = 0.0, Y = 0.0, Z = 0.0;
};
/// Chromaticity coordinates x, y.
struct Xy {
    double x = 0.0, y = 0.0;
};
/// D65's chromaticity to four digits, as sRGB (IEC 61966-2-1), Rec.709 (ITU-R BT.709-6),
/// Display P3, Rec.2020 and Oklab give it; the white of every D65 space irid builds in.
inline constexpr Xy d65_xy{0.3127, 0.3290};
/// Chromaticity plus luminance.
struct Xyy {
    double x = 0.0, y = 0.0, Y = 0.0;
};
/// CIE 1976 UCS chromaticity u', v'.
struct UvPrime {
    double u = 0.0, v = 0.0;
};
/// CIE 1976 L*u*v* (CIELUV). L in 0..100 for relative colours.
struct Luv {
    double L = 0.0, u = 0.0, v = 0.0;
};
/// CIE 1976 L*a*b* (CIELAB).
struct Lab {
    double L = 0.0, a = 0.0, b = 0.0;
};
/// CIELCh(uv): lightness, chroma C*uv, hue angle h_uv in degrees [0, 360).
struct LchUv {
    double L = 0.0, C = 0.0, h = 0.0;
};
/// CIELCh(ab): lightness, chroma C*ab, hue angle h_ab in degrees [0, 360).
struct LchAb {
    double L = 0.0, C = 0.0, h = 0.0;
};
/// Oklab (Ottosson 2020). L in 0..1 for relative colours.
struct Oklab {
    double L = 0.0, a = 0.0, b = 0.0;
};
/// Oklch: Oklab lightness, chroma and hue in degrees [0, 360).
struct Oklch {
    double L = 0.0, C = 0.0, h = 0.0;
};
/// An RGB triple: linear or encoded, as the function taking it says.
struct Rgb {
    double r = 0.0, g = 0.0, b = 0.0;
};

}  // namespace irid
