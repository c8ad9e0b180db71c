#pragma once

#include <irid/color/matrix.h>
#include <irid/color/types.h>

#include <string_view>

namespace irid {

/// Chromatic adaptation transforms: von Kries scaling in a cone-like space.
enum class ChromaticAdaptation {
    /// Lam 1985 (Bradford), linear form as in ICC.1:2010 Annex E and CIE 159:2004 notes.
    bradford,
    /// CAT02, CIE 159:2004 (CIECAM02), complete adaptation (D = 1).
    cat02,
    /// von Kries with the Hunt-Pointer-Estévez cone fundamentals normalised to D65
    /// (Fairchild, Color Appearance Models, 3rd ed., ch. 9).
    von_kries,
    /// No adaptation: XYZ passes through unchanged.
    none,
};

/// The cone-space matrix of a transform (identity for `none`).
[[nodiscard]] Mat3 cone_response_matrix(ChromaticAdaptation method) noexcept;

/// The XYZ → XYZ matrix that maps colours seen under source_white to corresponding colours
/// under destination_white: M⁻¹ diag(M w_d / M w_s) M. Throws irid::Error if a white has a
/// zero cone response.
[[nodiscard]] Mat3 adaptation_matrix(const Xyz& source_white, const Xyz& destination_white,
                                     ChromaticAdaptation method = ChromaticAdaptation::bradford);

/// "bradford", "cat02", "von-kries", "none". Throws irid::Error listing the names otherwise.
[[nodiscard]] ChromaticAdaptation parse_chromatic_adaptation(std::string_view name);

}  // namespace irid
