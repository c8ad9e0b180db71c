#pragma once

// Images through OpenImageIO: read anything OpenImageIO reads (EXR, TIFF, PNG, HDR, JPEG, ...)
// into float pixels, write EXR (linear, 32-bit float), PNG/TIFF (encoded, 8 or 16 bit) or JPEG
// (encoded, 8 bit).
// Output files appear only when complete, and never replace what is not a regular file
// (irid/io/output_file.h). Inputs are checked against stated limits before any pixel is
// allocated (ImageLimits).
//
// Values are passed through as they are stored: irid_io converts numbers, never colours.
// An 8- or 16-bit file (PNG, TIFF, JPEG) holds encoded values (sRGB, a gamma, ...); read_image
// returns them scaled to [0, 1] and still encoded, and the caller decodes them with the transfer
// function of the space they are in. write_image likewise expects encoded values in [0, 1] for
// PNG, TIFF and JPEG, and linear values for EXR.

#include <array>
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace irid::io {

/// An image in memory: float samples, interleaved (pixel by pixel, channel by channel), rows
/// from the top. Only the first subimage and its data window are read.
struct Image {
    int width = 0;
    int height = 0;
    int channels = 0;
    /// One name per channel ("R", "G", "B", "A", "Z", ...).
    std::vector<std::string> channel_names;
    /// width × height × channels samples; sample c of pixel (x, y) is at
    /// (y × width + x) × channels + c.
    std::vector<float> pixels;
    /// The colour space of the values, for example "srgb" or "srgb-linear"; empty when unknown.
    /// Written as "oiio:ColorSpace" (which PNG keeps) and "irid:ColorSpace" (which EXR keeps;
    /// OpenImageIO drops "oiio:" attributes from EXR). TIFF keeps neither through OpenImageIO
    /// 2.4: name the space in the description too. Read from "irid:ColorSpace", else
    /// "oiio:ColorSpace" (OpenImageIO reports "Linear" for any other EXR, "sRGB" for a PNG with
    /// an sRGB chunk).
    std::string color_space;
    /// A free-text description ("ImageDescription"), empty when none.
    std::string description;
    /// The ICC profile embedded in the file (OpenImageIO's "ICCProfile": PNG iCCP, TIFF tag
    /// 34675, JPEG APP2), its bytes as stored; empty when none. write_image embeds it in PNG and
    /// TIFF files (EXR has no place for one). irid_io does not look inside: irid/exchange/icc.h
    /// reads and builds profiles.
    std::vector<unsigned char> icc_profile;
    /// The file has an ICC profile that is damaged in its container or that its decoder rejected
    /// (libpng drops an iCCP chunk whose profile it finds invalid, with only a warning; JPEG APP2
    /// segments not numbered 1..N; a TIFF profile tag past the file). icc_profile is then empty,
    /// and icc_profile_damage says what is wrong. Set by read_image.
    bool icc_profile_rejected = false;
    std::string icc_profile_damage;
    /// OpenEXR's "chromaticities" (red x, y, green x, y, blue x, y, white x, y), 8 values, or
    /// empty when the file has none. write_image writes it to EXR files only.
    std::vector<float> chromaticities;
    /// OpenEXR's "adoptedNeutral" (x, y), 2 values, or empty. EXR files only.
    std::vector<float> adopted_neutral;
    /// What a PNG says of its colour besides an ICC profile (ISO/IEC 15948 §11.3.3, PNG Third
    /// Edition §11.3.2.6): an sRGB chunk; gAMA's gamma (samples = light^gamma, 0 when absent);
    /// cHRM's red, green, blue and white x, y (8 values, or empty); cICP's colour primaries,
    /// transfer, matrix and full-range codes (ITU-T H.273; 4 values, or empty). Set by
    /// read_image; irid/exchange decides what they mean (image_space).
    bool png_srgb = false;
    double png_gamma = 0.0;
    std::vector<float> png_chromaticities;
    std::vector<unsigned char> png_cicp;
    /// Where the pixels sit in their frame, as OpenEXR's windows say it: the top-left pixel is
    /// at (origin_x, origin_y) (the data window's corner; the window is width × height), and the
    /// frame is display_window (x min, y min, x max, y max, inclusive, as exrheader prints it),
    /// or the data window itself when empty. read_image sets them from an EXR (any other file:
    /// 0, 0 and no display window); write_image writes them to EXR only (windows_dropped says
    /// when another format loses them).
    int origin_x = 0;
    int origin_y = 0;
    std::optional<std::array<int, 4>> display_window;
    /// How the file read stored its samples: bits per sample (8, 16, 32, ...) and whether they
    /// are integers, i.e. encoded values (true for 8/16-bit PNG and TIFF, false for EXR and HDR).
    /// Set by read_image; ignored by write_image.
    int stored_bits = 32;
    bool stored_integer = false;
    /// The file holds CMYK (a JPEG or TIFF), which OpenImageIO converted to RGB without a profile
    /// (R = (1 - C)(1 - K) and so on): its RGB is no colour space. Set by read_image.
    bool stored_cmyk = false;
    /// The colour model of the stored samples when OpenImageIO converted them to RGB without a
    /// profile: "CMYK", "YCCK" (a JPEG's Adobe transform 2), "CIELab", "ICCLab" or "ITULab" (TIFF
    /// photometric 8, 9, 10, converted through libtiff's own display model); empty when the
    /// samples are the file's own RGB or grey. Set by read_image.
    std::string stored_model;

    /// An image of this size with every sample 0. Channel names default to R, G, B, A for up to
    /// four channels and to "channel<i>" beyond. Throws irid::Error when a dimension is < 1.
    [[nodiscard]] static Image blank(int width, int height, int channels);

    [[nodiscard]] std::size_t pixel_count() const noexcept {
        return static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
    }
    /// The index of the channel with this exact name, or -1.
    [[nodiscard]] int channel_index(std::string_view name) const noexcept;
    [[nodiscard]] float& at(int x, int y, int c) noexcept { return pixels[index(x, y, c)]; }
    [[nodiscard]] float at(int x, int y, int c) const noexcept { return pixels[index(x, y, c)]; }

private:
    [[nodiscard]] std::size_t index(int x, int y, int c) const noexcept {
        return (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
                static_cast<std::size_t>(x)) *
                   static_cast<std::size_t>(channels) +
               static_cast<std::size_t>(c);
    }
};

/// What read_image accepts, checked on the file's header before anything is allocated.
struct ImageLimits {
    /// Pixels (width × height of the data window): 64 Mpixel, the renderer's limit (8192², or
    /// an 11K × 6K frame).
    long long max_pixels = 64LL * 1024 * 1024;
    /// Samples (pixels × channels): 2^28, 1 GiB of float samples.
    long long max_samples = 1LL << 28;
    /// Channels of one image.
    int max_channels = 64;
};

/// Reads the first subimage of any file OpenImageIO reads, converted to float (integers scaled
/// to [0, 1], still encoded: see above). Only regular files are read (a FIFO or a device would
/// block or cannot be searched). Throws irid::Error naming the file when it does not exist, is
/// not a regular file, cannot be read (unknown format, truncated, a deep or volume image), or
/// declares more pixels, samples or channels than `limits` allow (the message gives both).
[[nodiscard]] Image read_image(const std::filesystem::path& path, const ImageLimits& limits = {});

/// How write_image stores samples in PNG and TIFF.
struct ImageEncoding {
    /// 8 or 16 bits per sample in PNG and TIFF (EXR is always 32-bit float).
    int bits = 8;
    /// OpenImageIO's "compression" for the format ("zip", "piz", "none", ...); empty for the
    /// format's default.
    std::string compression;
};

/// The formats write_image produces, chosen by the file name's extension (case-insensitive).
enum class ImageFormat {
    /// .exr: OpenEXR, 32-bit float, values as given (linear).
    exr,
    /// .png: 8 or 16 bit, values in [0, 1] (encoded).
    png,
    /// .tif, .tiff: 8 or 16 bit, values in [0, 1] (encoded).
    tiff,
    /// .jpg, .jpeg: 8 bit, 1 or 3 channels (no alpha), values in [0, 1] (encoded); baseline JPEG
    /// at quality 95 unless ImageEncoding::compression says "jpeg:Q" (Q 1-100).
    jpeg,
};

/// The format for a file name; throws irid::Error naming the file and listing the supported
/// extensions (.exr, .png, .tif, .tiff, .jpg, .jpeg) otherwise.
[[nodiscard]] ImageFormat image_format_for(const std::filesystem::path& path);
/// True for the integer formats (PNG, TIFF, JPEG), whose values are encoded and in [0, 1].
[[nodiscard]] constexpr bool is_integer_format(ImageFormat f) noexcept {
    return f != ImageFormat::exr;
}

/// The largest magnitude of a window coordinate write_image writes: OpenEXR refuses windows
/// whose corners pass ±(2^31 − 1) / 2 (its header's sanity check).
inline constexpr int max_window_coordinate = (1 << 30) - 1;

/// The data window as an inclusive box (origin_x, origin_y, origin_x + width − 1, ...).
[[nodiscard]] std::array<long long, 4> data_window(const Image& image) noexcept;

/// Sets image's windows from inclusive boxes (x min, y min, x max, y max), each optional:
/// the data window must be width × height and the display window a box (min <= max), every
/// corner within ±max_window_coordinate. Throws irid::Error naming which and why.
void set_windows(Image& image, const std::optional<std::array<long long, 4>>& data_window,
                 const std::optional<std::array<long long, 4>>& display_window);

/// A note when `image` has windows (an origin other than 0, 0, or a display window other than
/// its data window) and `format` keeps none (PNG, TIFF, JPEG): "the data window 100 50 107 53
/// and display window 0 0 1919 1079 are not kept in PNG; write an EXR to keep where the pixels
/// sit". Empty otherwise.
[[nodiscard]] std::string windows_dropped(const Image& image, ImageFormat format);

class OutputFile;

/// Writes `image` to `path` in the format of its extension (see ImageFormat), with its
/// channel names, the colour space (see Image::color_space) and "ImageDescription" =
/// image.description (each when not empty). Samples are written as they are, alpha included
/// (colour is never divided or multiplied by alpha: PNG's alpha is marked unassociated). PNG and
/// TIFF samples are quantised with rounding: round(v × (2^bits − 1)) after clamping v to [0, 1];
/// NaN becomes 0. EXR stores the floats exactly. The file is written as an OutputFile: it appears
/// only when complete (a device or FIFO is written straight into); on failure the destination is
/// as it was, no temporary file is left, and irid::Error names the file and what was wrong
/// (unsupported extension, bad bit depth, folder missing or not writable, a full disk with the
/// system's reason, OpenImageIO's message).
void write_image(const std::filesystem::path& path, const Image& image,
                 const ImageEncoding& encoding = {});
/// The same into an output opened by the caller (the format from file.target()'s extension),
/// for commands that write several files and commit them together. The caller commits.
void write_image(OutputFile& file, const Image& image, const ImageEncoding& encoding = {});

}  // namespace irid::io
