#pragma once

// Showing an image through a display transform (what `irid display IN OUT` does between reading
// and writing): scene colours of the file's space, or the one named, through the view to the
// display's signal in a display encoding (irid/color/rgb.h), encoded for an integer file (PNG,
// TIFF, JPEG) and linear for EXR, with the channels and alpha of change_image_colours.

#include <irid/color/rgb.h>
#include <irid/exchange/image_colours.h>
#include <irid/exchange/image_source.h>
#include <irid/gamut/aces2_display.h>
#include <irid/io/image.h>

#include <optional>
#include <string>

namespace irid {

/// What an image of a display's signal is written as.
struct DisplayImagePlan {
    std::string view = "aces2";
    Aces2DisplaySpec display;
    /// The display encoding: the one named, else default_display_encoding(display).
    const RgbSpace* encoding = nullptr;
    /// Encoded with its curve (an integer file), else linear (EXR).
    bool encoded = false;
    /// Bits per sample of an integer file (the caller may change them before display_image):
    /// 16 for PQ (whose 8-bit steps are visible), else 8; JPEG holds 8.
    int bits = 8;
};

/// The plan for `view` and `display` written to a file of `format`, in the encoding `to` (an RGB
/// space's name, either form: the file decides encoded or linear). Throws
/// irid::UnknownNameError for an unknown view, display or space, and irid::Error for `to` that
/// is not an RGB space or a display without an RGB encoding of its own when `to` is not given.
[[nodiscard]] DisplayImagePlan plan_display_image(const std::string& view, const std::string& display,
                                                  const std::optional<std::string>& to, io::ImageFormat format);

struct DisplayImageOptions {
    /// The scene space of the colours; nothing for the file's (its ICC profile or EXR
    /// chromaticities), or ACES2065-1 when the file says nothing.
    std::optional<ColorSpace> from;
    bool premultiplied_in = false;
    bool premultiplied_out = false;
    int threads = 0;
};

/// What display_image found and did, for messages and the output's description.
struct DisplayImageReport {
    /// Where the scene colours came from (decide_image_source), with its notes.
    ImageSource source;
    /// Pixels of an integer file with a channel above 1 (brighter than its encoding holds),
    /// which the file clips.
    std::size_t clipped = 0;
};

/// Converts the image's colours in place and tags it (tag_image) for `format`. An integer file
/// gets values whose codes at plan.bits are the double chain's: for 8 bits the float kernel
/// computes them and each colour whose kernel error could move a channel to another code is
/// computed in double; for 16 bits the double chain computes all (docs/DISPLAY.md). Throws
/// irid::Error naming `what` for an image without colour channels, a space that contradicts
/// them (ImageSourceConflict), a damaged or unusable profile.
DisplayImageReport display_image(io::Image& image, const DisplayImagePlan& plan, const DisplayImageOptions& options,
                                 io::ImageFormat format, const std::string& what);

}  // namespace irid
