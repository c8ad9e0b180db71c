#pragma once

// The space a PNG's colour chunks name, when it has them (image_space, icc.cpp): cICP (PNG Third
// Edition §11.3.2.6, ITU-T H.273 codes), then after an ICC profile the sRGB chunk, then gAMA
// with cHRM (ISO/IEC 15948 §11.3.3).

#include <irid/exchange/icc.h>
#include <irid/io/image.h>

#include <string>

namespace irid::detail {

/// The space of image.png_cicp's codes: the SDR combinations of BT.709 (1) or Display P3 (12)
/// primaries with the sRGB (13) or linear (8) transfer, and BT.2020 (9) primaries with the
/// linear transfer; RGB (matrix 0), full range. Throws irid::Error naming `what` and the codes
/// for any other.
[[nodiscard]] ImageSpace png_cicp_space(const io::Image& image, const std::string& what);

/// The space of an sRGB chunk (sRGB), or of gAMA and cHRM: cHRM's primaries and white (sRGB's
/// when absent) with gAMA's power law (sRGB's curve when absent), the absent half named in the
/// origin. Throws irid::Error naming `what` for chromaticities that make no space or a gamma
/// below 0.1.
[[nodiscard]] ImageSpace png_chunks_space(const io::Image& image, const std::string& what);

}  // namespace irid::detail
