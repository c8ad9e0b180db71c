#pragma once

// Clipping an image's colours (what `irid clip IN OUT` does between reading and writing),
// through change_image_colours (irid/exchange/image_colours.h: the channels by name, alpha), with
// the pipeline's float path (irid/gamut/pipeline.h): conversion, the batch kernels, and the
// destination's transfer function when the output is an integer file.

#include <irid/exchange/icc.h>
#include <irid/exchange/image_colours.h>
#include <irid/gamut/pipeline.h>
#include <irid/io/image.h>

#include <string>

namespace irid {

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
