// Fuzz harness: images through irid_io (irid::io::read_image, include/irid/io/image.h, which
// loads the OpenImageIO module libirid_oiio.so), then what `irid clip IN OUT` does with what
// OpenImageIO returns (apps/irid/commands/clip.cpp: decide_image_source, then the steps of
// clip_image re-created here from the same library calls): the colour channels (R, G, B by
// name, else X, Y, Z), alpha (EXR colour is taken as premultiplied), the decoding of an encoded
// source, clip_batch, the re-encoding and premultiplication of the output and write_image to a
// scratch file, which is read back.
//
// Input: the file's bytes. Its name's extension follows its magic number (PNG, TIFF, EXR, JPEG,
// HDR, BMP, GIF, PNM; else none, and OpenImageIO probes the content). The clip's parameters
// (method, source and destination spaces, encoded or linear source, output format and bits,
// peak) come from a hash of the bytes. Images are read with irid's limits lowered to 2^20 pixels
// and 2^22 samples (io::ImageLimits), so that a harness run never needs more than a few hundred
// MB; irid's own limits are 64 Mpixel and 2^28 samples (docs/RELIABILITY.md).
//
// Its space is read as irid clip reads it (irid/exchange/icc.h: the ICC profile through Little
// CMS, the EXR chromaticities).
//
// Checked: an image read has width, height, channels >= 1, one name per channel and
// width x height x channels samples; the clipped colours are finite and inside [0, max]^3; an
// image written reads back with the same size and channel count.
#include "fuzz_support.h"

#include <irid/color/rgb.h>
#include <irid/error.h>
#include <irid/exchange/icc.h>
#include <irid/exchange/image_source.h>
#include <irid/gamut/batch.h>
#include <irid/gamut/clip.h>
#include <irid/io/image.h>

#include <OpenImageIO/imageio.h>

#include <array>
#include <cmath>
#include <cstring>
#include <optional>
#include <string>
#include <vector>

namespace {

namespace io = irid::io;

constexpr long long max_pixels = 1LL << 20;
constexpr int max_channels = 64;

std::string extension_for(const std::uint8_t* d, std::size_t n) {
    const auto starts = [&](const char* magic, std::size_t len) {
        return n >= len && std::memcmp(d, magic, len) == 0;
    };
    if (starts("\x89PNG", 4)) return ".png";
    if (starts("II*\0", 4) || starts("MM\0*", 4)) return ".tif";
    if (starts("\x76\x2f\x31\x01", 4)) return ".exr";
    if (starts("\xff\xd8\xff", 3)) return ".jpg";
    if (starts("#?", 2)) return ".hdr";
    if (starts("BM", 2)) return ".bmp";
    if (starts("GIF8", 4)) return ".gif";
    if (n >= 2 && d[0] == 'P' && d[1] >= '1' && d[1] <= '7') return ".pnm";
    return "";
}

std::uint64_t fnv1a(const std::uint8_t* d, std::size_t n) {
    std::uint64_t h = 14695981039346656037ull;
    for (std::size_t i = 0; i < n; ++i) h = (h ^ d[i]) * 1099511628211ull;
    return h;
}

/// What the harness reads: irid's own limits, tighter (a few hundred MB at most per input).
constexpr io::ImageLimits harness_limits{.max_pixels = max_pixels,
                                         .max_samples = 1LL << 22,
                                         .max_channels = max_channels};

void check_read(const io::Image& image) {
    IRID_FUZZ_REQUIRE(image.width >= 1 && image.height >= 1 && image.channels >= 1,
                      "image size " + std::to_string(image.width) + " x " +
                          std::to_string(image.height) + " x " + std::to_string(image.channels));
    IRID_FUZZ_REQUIRE(image.channel_names.size() == static_cast<std::size_t>(image.channels),
                      "one channel name per channel");
    IRID_FUZZ_REQUIRE(
        image.pixels.size() == image.pixel_count() * static_cast<std::size_t>(image.channels),
        "width x height x channels samples");
}

/// `irid clip --method M --from FROM --to TO [--max PEAK] IN OUT` on an image already read.
void clip_like_the_cli(io::Image image, bool exr_in, std::uint64_t h) {
    const auto spaces = irid::builtin_rgb_spaces();
    const auto methods = irid::clip_methods();
    const irid::ClipMethod method = methods[h % methods.size()];
    const irid::RgbSpace& dest = *spaces[(h >> 4) % spaces.size()];
    const irid::RgbSpace& source = (h >> 8) & 1 ? *spaces[(h >> 9) % spaces.size()] : dest;
    const bool encoded_source = (h >> 13) & 1;
    const char* const outputs[] = {"out.exr", "out.png", "out.tif"};
    const std::string out_name = outputs[(h >> 14) % 3];
    const bool exr_out = out_name == "out.exr";
    const int bits = (h >> 16) & 1 ? 16 : 8;
    const double max = exr_out && ((h >> 17) & 1) ? 4.0 : 1.0;  // PNG and TIFF need <= 1
    const bool same_space = &source == &dest;

    // colour_channels(): R, G and B by name, else X, Y and Z (CIE XYZ), else the CLI refuses.
    std::array<int, 3> rgb{image.channel_index("R"), image.channel_index("G"),
                           image.channel_index("B")};
    bool xyz = false;
    if (rgb[0] < 0 || rgb[1] < 0 || rgb[2] < 0) {
        rgb = {image.channel_index("X"), image.channel_index("Y"), image.channel_index("Z")};
        if (rgb[0] < 0 || rgb[1] < 0 || rgb[2] < 0) return;
        xyz = true;
    }
    // As irid clip does for images: what a display gets (aces-rgc's clip=true).
    const irid::GamutClipper clipper(method, irid::Gamut(dest, max), irid::display_clip_settings(method));
    const std::size_t pixels = image.pixel_count();
    const auto stride = static_cast<std::size_t>(image.channels);
    const int alpha = image.channel_index("A");
    const bool premultiplied_in = alpha >= 0 && exr_in;
    const bool premultiplied_out = alpha >= 0 && exr_out;
    std::vector<float> colours(pixels * 3);
    for (std::size_t i = 0; i < pixels; ++i) {
        const float* s = &image.pixels[i * stride];
        const float a = premultiplied_in ? s[alpha] : 1.0f;
        const float k = a > 0.0f ? 1.0f / a : 1.0f;
        irid::Rgb c{irid::finite_or_default(s[rgb[0]] * k), irid::finite_or_default(s[rgb[1]] * k),
                    irid::finite_or_default(s[rgb[2]] * k)};
        if (xyz) {
            c = dest.from_xyz({c.r, c.g, c.b});
        } else {
            if (encoded_source) c = source.decode(c);
            if (!same_space) c = dest.from_xyz(source.to_xyz(c));
        }
        colours[i * 3] = static_cast<float>(c.r);
        colours[i * 3 + 1] = static_cast<float>(c.g);
        colours[i * 3 + 2] = static_cast<float>(c.b);
    }
    irid::clip_batch(clipper, colours, irid::BatchOptions{.threads = 1, .simd = true});
    const auto max_f = static_cast<float>(max);
    for (const float v : colours) {
        IRID_FUZZ_REQUIRE(std::isfinite(v) && v >= 0.0f && v <= max_f,
                          "clipped colour outside [0, max]: " + std::to_string(v) + " (" +
                              std::string(irid::clip_method_name(method)) + ")");
    }
    for (std::size_t i = 0; i < pixels; ++i) {
        irid::Rgb c{colours[i * 3], colours[i * 3 + 1], colours[i * 3 + 2]};
        if (!exr_out) c = dest.encode(c);
        float* d = &image.pixels[i * stride];
        if (premultiplied_out && (d[alpha] > 0.0f || !premultiplied_in)) {
            const double a = d[alpha];
            c = {c.r * a, c.g * a, c.b * a};
        }
        d[rgb[0]] = static_cast<float>(c.r);
        d[rgb[1]] = static_cast<float>(c.g);
        d[rgb[2]] = static_cast<float>(c.b);
    }
    image.color_space = exr_out ? dest.name() + "-linear" : dest.name();
    image.description =
        "irid fuzz_image: clip --method " + std::string(irid::clip_method_name(method));
    const auto out = irid::fuzz::ScratchDir::path() / out_name;
    try {
        io::write_image(out, image, io::ImageEncoding{.bits = bits, .compression = {}});
    } catch (const irid::Error&) {
        return;  // OpenImageIO refused (e.g. more channels than PNG holds): the CLI exits 1
    }
    const io::Image back = io::read_image(out);
    IRID_FUZZ_REQUIRE(
        back.width == image.width && back.height == image.height && back.channels == image.channels,
        out_name + " was written as " + std::to_string(image.width) + " x " +
            std::to_string(image.height) + " x " + std::to_string(image.channels) +
            " and reads back as " + std::to_string(back.width) + " x " +
            std::to_string(back.height) + " x " + std::to_string(back.channels));
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    OIIO::attribute("threads", 1);
    // Load the module now, before fuzzing starts (its coverage counters are then registered
    // with libFuzzer from the first input on).
    try {
        (void)io::read_image(irid::fuzz::ScratchDir::path() / "absent.png");
    } catch (const irid::Error& e) {
        if (std::strstr(e.what(), "module") != nullptr) {
            std::fprintf(stderr, "fuzz_image: %s\n", e.what());
            std::abort();
        }
    }
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string ext = extension_for(data, size);
    const bool exr_in = ext == ".exr";
    const auto path = irid::fuzz::write_scratch("in" + ext, data, size);
    io::Image image;
    try {
        image = io::read_image(path, harness_limits);
    } catch (const irid::Error&) {
        return 0;
    }
    check_read(image);
    // Where its colours come from, as irid clip decides it without --from (the channels, the
    // file's ICC profile or EXR chromaticities): refused with irid::Error, or a space.
    try {
        const bool xyz = image.channel_index("R") < 0 && image.channel_index("X") >= 0;
        const irid::ImageSource source = irid::decide_image_source(image, xyz, std::nullopt, "fuzz", "--from");
        if (source.file) {
            IRID_FUZZ_REQUIRE(source.file->rgb.has_value() != (source.file->profile != nullptr),
                              "an image space is exact or goes through Little CMS");
        }
    } catch (const irid::Error&) {
    }
    clip_like_the_cli(std::move(image), exr_in, fnv1a(data, size));
    return 0;
}
