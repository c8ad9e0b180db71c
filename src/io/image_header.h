#pragma once

// Checks of what an image file declares, made before any decoder reads it (image_header.cpp),
// and the pixel-count check and message that read_image applies to every format.

#include <irid/io/image.h>

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace irid::io {

/// What a file's header holds that the decoder may not pass on.
struct HeaderFacts {
    /// A PNG with an iCCP chunk (libpng drops a profile it finds invalid, with only a warning).
    bool png_icc_chunk = false;
    /// A PNG's colour chunks (ISO/IEC 15948 §11.3.3; PNG Third Edition §11.3.2.6 for cICP): an
    /// sRGB chunk; gAMA's gamma (0 when absent); cHRM's red, green, blue and white x, y (empty
    /// when absent); cICP's four codes (empty when absent); the types seen, in order.
    bool png_srgb = false;
    double png_gamma = 0.0;
    std::vector<float> png_chromaticities;
    std::vector<unsigned char> png_cicp;
    std::string png_colour_chunks;
    /// Why the file's embedded ICC profile is damaged in its container (JPEG APP2 segments not
    /// numbered 1..N, a TIFF profile tag past the file); empty when it is whole or absent.
    std::string icc_damage;
    /// The profile as its container holds it, which read_image passes on instead of OpenImageIO's:
    /// a JPEG's APP2 segments joined by their sequence numbers (ICC.1 Annex B.4), whatever order
    /// OpenImageIO joins them in; a TIFF's tag 34675 of any integer type (libtiff drops one not
    /// typed UNDEFINED or BYTE). Empty when the file has none, or when icc_damage is set.
    std::vector<unsigned char> container_icc_profile;
};

/// For PNG, OpenEXR, TIFF and JPEG files: throws irid::Error naming the file when the declared
/// size (PNG IHDR, EXR dataWindow, TIFF's first directory, JPEG's frame header) is beyond
/// `limits`, when a chunk, a header attribute, a TIFF strip or tile declares more bytes than the
/// file holds, when the compressed data cannot hold the pixels declared (PNG, TIFF, Huffman-coded
/// JPEG), or when an embedded ICC profile's tag table runs past the profile (OpenImageIO 2.4
/// reads it unchecked). Damage of a profile's container (JPEG's APP2 numbering, a TIFF tag past
/// the file) is returned in HeaderFacts::icc_damage instead, for the caller to refuse or
/// override. Other formats, and files it cannot open, pass (the decoder reports them).
HeaderFacts check_image_header(const std::filesystem::path& path, const ImageLimits& limits);

/// Throws irid::Error "<file>: the image declares W x H pixels (N Mpixel); irid reads at most
/// ..." when width × height is beyond limits.max_pixels.
void check_declared_pixels(const std::string& shown, std::uint64_t width, std::uint64_t height,
                           const ImageLimits& limits);

/// "3840 x 2160 pixels (8.3 Mpixel)".
[[nodiscard]] std::string declared_size_text(std::uint64_t width, std::uint64_t height);

}  // namespace irid::io
