#pragma once

// Checks of what an image file declares, made before any decoder reads it (image_header.cpp),
// and the pixel-count check and message that read_image applies to every format.

#include <irid/io/image.h>

#include <cstdint>
#include <filesystem>
#include <string>

namespace irid::io {

/// What a file's header holds that the decoder may not pass on.
struct HeaderFacts {
    /// A PNG with an iCCP chunk (libpng drops a profile it finds invalid, with only a warning).
    bool png_icc_chunk = false;
};

/// For PNG and OpenEXR files: throws irid::Error naming the file when a chunk or a header
/// attribute declares more bytes than the file holds, when a PNG's compressed data cannot hold
/// the pixels its header declares, or when the declared size (PNG IHDR, EXR dataWindow) is
/// beyond `limits`, and, for TIFF and JPEG, when an embedded ICC profile's tag table runs past
/// the profile (OpenImageIO 2.4 reads it unchecked). Other formats, and files it cannot open,
/// pass (the decoder reports them).
HeaderFacts check_image_header(const std::filesystem::path& path, const ImageLimits& limits);

/// Throws irid::Error "<file>: the image declares W x H pixels (N Mpixel); irid reads at most
/// ..." when width × height is beyond limits.max_pixels.
void check_declared_pixels(const std::string& shown, std::uint64_t width, std::uint64_t height,
                           const ImageLimits& limits);

/// "3840 x 2160 pixels (8.3 Mpixel)".
[[nodiscard]] std::string declared_size_text(std::uint64_t width, std::uint64_t height);

}  // namespace irid::io
