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

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace irid {

/// What an image of a display's signal is written as.
struct DisplayImagePlan {
    std::string view = "aces2";
    Aces2DisplaySpec display;
    /// The display encoding: the one named, else default_display_encoding(display); nullptr for
    /// CIE XYZ (1.0 = 100 cd/m²), which an EXR alone holds (`--to xyz`, or an XYZ display's own).
    const RgbSpace* encoding = nullptr;
    /// Encoded with its curve (an integer file), else linear (EXR).
    bool encoded = false;
    /// Bits per sample of an integer file (the caller may change them before display_image):
    /// 16 for PQ and HLG (whose 8-bit steps are visible), else 8 (JPEG's only).
    int bits = 8;

    /// The encoding's name, "xyz" for CIE XYZ.
    [[nodiscard]] std::string encoding_name() const { return encoding != nullptr ? encoding->name() : "xyz"; }
};

/// The plan for `view` and `display` written to a file of `format`, in the encoding `to` (an RGB
/// space's name, either form: the file decides encoded or linear; or "xyz"). Throws
/// irid::UnknownNameError for an unknown view, display or space, and irid::Error for `to` that
/// is neither an RGB space nor xyz, for CIE XYZ in an integer file (PNG, TIFF and JPEG have no
/// tagged XYZ encoding: the message names EXR), for PQ or HLG in a JPEG (8 bits, and no tag
/// for the curve), and for a display without an RGB encoding of its own when `to` is not given
/// and the file is not an EXR.
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
    /// Pixels of an integer file that it clips, by the double chain's display light in the
    /// encoding's linear RGB, with P the encoding's peak (the linear value of signal 1: 1 for the
    /// 100 cd/m² curves, 100 for PQ, 10 for HLG) and bounds within 1e-9 P taken as met:
    /// - too bright: luminance above the encoding's white at its peak (Y > P), which no colour
    ///   of the encoding reaches;
    /// - out of gamut: a luminance it holds, but a channel below 0 or above P (for HLG: scene
    ///   light, hlg_scene_light_unclamped, above 1), a colour outside its gamut.
    /// None when the encoding holds every colour the display shows, nor for an EXR.
    std::size_t too_bright = 0;
    std::size_t out_of_gamut = 0;
    /// Input pixels with a +Inf, a -Inf, a NaN channel (a pixel may count in more than one), and
    /// with any of them. They are taken as aces2_finite_input does (irid/gamut/aces2_display.h):
    /// +Inf as 65504, -Inf and NaN as 0.
    std::size_t positive_infinite = 0;
    std::size_t negative_infinite = 0;
    std::size_t not_a_number = 0;
    std::size_t non_finite = 0;
    /// Everything to tell the user, one sentence each: the source's notes, then what the counts
    /// above say and what keeps the clipped pixels (the display's own encoding, or an EXR).
    std::vector<std::string> notes;
};

/// Whether the encoding holds every colour the display shows: the corners of its limiting cube,
/// through the chain's last steps into the encoding's linear RGB, lie within [0, P]³ with
/// luminance at most P (P the linear value of signal 1, as DisplayImageReport counts), to 1e-9 P
/// and `margin` of the display's peak more. The cube maps to a parallelepiped and the
/// encoding's range is a cube, so the corners decide; never for HLG, whose range is not a cube
/// in display light.
[[nodiscard]] bool encoding_holds_display(const RgbSpace& encoding, const Aces2Output& output, double margin = 0.0);

/// Converts the image's colours in place and tags it (tag_image, tag_image_xyz) for `format`.
/// An integer file gets, for every sample, the code the double chain's value rounds to at
/// plan.bits, stored as code / (2^bits − 1) so that the writer's rounding keeps it: for 8 bits the
/// float kernel computes the linear light and each colour whose kernel error could move a code
/// (or change what the report counts) is computed in double; for 16 bits, and for HLG, the double
/// chain computes all (docs/DISPLAY.md). Throws irid::Error naming `what` for an image without
/// colour channels, a space that contradicts them (ImageSourceConflict), a damaged or unusable
/// profile.
DisplayImageReport display_image(io::Image& image, const DisplayImagePlan& plan, const DisplayImageOptions& options,
                                 io::ImageFormat format, const std::string& what);

}  // namespace irid
