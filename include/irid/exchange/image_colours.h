#pragma once

// An image's colour channels, and changing them in place: what `irid clip IN OUT` and
// `irid display IN OUT` share between reading and writing.
//
// - Colour channels: R, G and B by name; else X, Y and Z (a CIE XYZ image).
// - Alpha: an EXR's colour is premultiplied by alpha (associated alpha, the OpenEXR
//   convention), a PNG's or TIFF's is not. The colour is changed unpremultiplied and
//   premultiplied again only for an EXR output; a fully transparent pixel keeps its values on
//   the way in (light added without covering), and a transparent EXR pixel is not multiplied by
//   its alpha of 0 on the way out.
// - Every other channel is left as it was.

#include <irid/io/image.h>

#include <array>
#include <functional>
#include <span>
#include <string>

namespace irid {

/// Where an image's colour channels are and what they hold.
struct ImageColourChannels {
    std::array<int, 3> index{};
    /// X, Y and Z channels: the image is CIE XYZ.
    bool xyz = false;
};

/// R, G and B by name, else X, Y and Z; throws irid::Error naming `what` (the file) and the
/// channels it has otherwise. `purpose` ends the message ("clip needs ...").
[[nodiscard]] ImageColourChannels image_colour_channels(const io::Image& image, const std::string& what,
                                                        const std::string& purpose = "clip");

struct ImageColourOptions {
    /// The input's colour is premultiplied by its "A" channel (an EXR with alpha).
    bool premultiplied_in = false;
    /// The output's colour is to be premultiplied (an EXR output with alpha).
    bool premultiplied_out = false;
    /// Threads (0: all).
    int threads = 0;
};

/// Gathers the colour channels (unpremultiplied) into interleaved triples, calls `change` on
/// them once (it may throw: nothing of the image has changed then), and scatters the result back
/// (premultiplied for an EXR output), renaming X, Y, Z channels to R, G, B.
void change_image_colours(io::Image& image, const ImageColourChannels& channels, const ImageColourOptions& options,
                          const std::function<void(std::span<float>)>& change);

}  // namespace irid
