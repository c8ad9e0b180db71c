#pragma once

// Clipping an image's colours (what `irid clip IN OUT` does between reading and writing): the
// colour channels found by name, alpha handled, every other channel left as it was.
//
// - Colour channels: R, G and B by name; else X, Y and Z (a CIE XYZ image, whose pipeline must
//   then start from xyz).
// - Alpha: an EXR's colour is premultiplied by alpha (associated alpha, the OpenEXR
//   convention), a PNG's or TIFF's is not. The colour is clipped unpremultiplied and
//   premultiplied again only for an EXR output; a fully transparent pixel keeps its values on
//   the way in (light added without covering), and a transparent EXR pixel is not multiplied by
//   its alpha of 0 on the way out.
// - The pipeline's float path (irid/gamut/pipeline.h): conversion, the batch kernels, and the
//   destination's transfer function when the output is an integer file.

#include <irid/exchange/icc.h>
#include <irid/gamut/pipeline.h>
#include <irid/io/image.h>

#include <array>
#include <string>

namespace irid {

/// Where an image's colour channels are and what they hold.
struct ImageColourChannels {
    std::array<int, 3> index{};
    /// X, Y and Z channels: the image is CIE XYZ.
    bool xyz = false;
};

/// R, G and B by name, else X, Y and Z; throws irid::Error naming `what` (the file) and the
/// channels it has otherwise.
[[nodiscard]] ImageColourChannels image_colour_channels(const io::Image& image, const std::string& what);

struct ImageClipOptions {
    /// The input's colour is premultiplied by its "A" channel (an EXR with alpha).
    bool premultiplied_in = false;
    /// The output's colour is to be premultiplied (an EXR output with alpha).
    bool premultiplied_out = false;
    /// Encode with the destination's transfer function (an integer output file).
    bool encode = false;
    /// Threads (0: all).
    int threads = 0;
    /// A profile that is not matrix/TRC (ImageSpace::profile): the colours go to XYZ through it
    /// first, relative to the pipeline's white, and the pipeline must start from xyz.
    const IccProfile* profile = nullptr;
};

/// Clips the image's colour channels in place through `pipeline`, renaming X, Y, Z channels to
/// R, G, B. Throws irid::Error (naming `what` and the pixel) for a colour the pipeline cannot
/// convert (xyY y = 0 with Y ≠ 0), before any pixel is changed, and when `options.profile` is
/// given with a pipeline that does not start from xyz.
void clip_image(io::Image& image, const ImageColourChannels& channels, const ClipPipeline& pipeline,
                const ImageClipOptions& options, const std::string& what);

}  // namespace irid
