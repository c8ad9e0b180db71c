#pragma once

// Where an image's colours come from: the one decision `irid clip IN OUT` and Python's
// clip_image make before clipping, from the channels' names (X, Y, Z is CIE XYZ), the space the
// caller names, the file's ICC profile or EXR chromaticities (irid/exchange/icc.h), and how the
// file stored its samples; with what the user must be told about it.

#include <irid/color/convert.h>
#include <irid/error.h>
#include <irid/exchange/icc.h>
#include <irid/io/image.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace irid {

struct ImageSource {
    /// The space the clip pipeline starts from: xyz (X, Y, Z channels, or a profile that is not
    /// matrix/TRC), the file's RGB, or the caller's. When it is the file's it points into `file`.
    ColorSpace space;
    /// The file's space, when the file decided (no space given, RGB channels).
    std::shared_ptr<const ImageSpace> file;
    /// The source in words, for an output's description: "acescg-linear", "adobe-rgb (the ICC
    /// profile 'Adobe RGB (1998)' ...)".
    std::string described;
    /// What to tell the user, one sentence each: a space assumed for an untagged file, a file's
    /// own space overridden by the caller's, encoded samples taken as linear light.
    std::vector<std::string> notes;
};

/// The caller's space contradicts the channels (an RGB space for an image of X, Y and Z): the
/// caller's mistake, not the file's.
class ImageSourceConflict : public Error {
public:
    using Error::Error;
};

/// The file says something about its space: an ICC profile (even a rejected one), EXR
/// chromaticities, a PNG's colour chunks (sRGB, gAMA, cHRM, cICP), or samples OpenImageIO
/// converted from another model (CMYK, YCCK, L*a*b*).
[[nodiscard]] bool image_says_its_space(const io::Image& image) noexcept;

/// Decides where the colours of `image` (named `what` in messages) come from.
/// - X, Y and Z channels: CIE XYZ; a `given` space other than xyz throws ImageSourceConflict.
/// - A `given` space: it, with a note when the file said something else (its profile, a
///   damaged profile, chromaticities, CMYK samples).
/// - Otherwise the file's: image_space() (which throws irid::Error for a damaged or unusable
///   profile, and for CMYK samples without a profile, whose RGB OpenImageIO made up); a note
///   when an integer file says nothing and is taken as sRGB.
/// - A note when integer (encoded) samples are taken as linear light.
/// `option` is how the caller names the source space in notes ("--from", "source=").
[[nodiscard]] ImageSource decide_image_source(const io::Image& image, bool xyz_channels,
                                              const std::optional<ColorSpace>& given,
                                              const std::string& what, const std::string& option);

}  // namespace irid
