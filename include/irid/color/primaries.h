#pragma once

#include <irid/color/matrix.h>
#include <irid/color/observer.h>
#include <irid/color/spectrum.h>

namespace irid {

/// Colour-matching functions of three monochromatic primaries (Smits 1990, Figure 2: 645, 526
/// and 444 nm), derived from the CIE functions by the linear transform they imply: a stimulus of
/// tristimulus values XYZ is matched by amounts rgb = N P⁻¹ XYZ of the primaries, where the
/// columns of P are the primaries' XYZ (the CIE functions at their wavelengths) and the diagonal
/// N scales each primary so that the equal-energy stimulus is matched by equal amounts, with
/// each function's 1 nm sum equal to that of ȳ (the normalisation of the CIE 1931 RGB system).
struct PrimaryMatchingFunctions {
    double red_nm = 0.0, green_nm = 0.0, blue_nm = 0.0;
    DenseSpectrum r, g, b;
    /// XYZ → amounts of the primaries: r̄ḡb̄(λ) = xyz_to_rgb · x̄ȳz̄(λ).
    Mat3 xyz_to_rgb;
};

/// Throws irid::Error unless every wavelength lies in 360-830 nm and the primaries' XYZ are
/// linearly independent.
[[nodiscard]] PrimaryMatchingFunctions monochromatic_primary_matching_functions(
    double red_nm = 645.0, double green_nm = 526.0, double blue_nm = 444.0,
    Observer observer = Observer::cie1931_2deg);

}  // namespace irid
