#include <irid/error.h>
#include <irid/io/atomic_file.h>
#include <irid/io/image.h>

#include "image_backend.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <system_error>

namespace irid::io {
namespace fs = std::filesystem;

namespace {

/// The colour space under a name OpenEXR files keep (OpenImageIO drops "oiio:" attributes
/// from EXR files and reports "Linear" instead).
constexpr const char* color_space_attribute = "irid:ColorSpace";

std::string default_channel_name(int c, int channels) {
    static const char* const rgba[] = {"R", "G", "B", "A"};
    if (channels <= 4) return rgba[c];
    if (c < 4) return rgba[c];
    return "channel" + std::to_string(c);
}


/// OpenImageIO's message, or a fallback when it has none.
std::string message_or(std::string message, const char* fallback) {
    while (!message.empty() && (message.back() == '\n' || message.back() == ' ')) {
        message.pop_back();
    }
    return message.empty() ? std::string(fallback) : message;
}

/// Encoded [0, 1] samples → integers with rounding (NaN → 0, clamped).
template <class T>
std::vector<T> quantise(const std::vector<float>& samples) {
    constexpr double top = static_cast<double>(std::numeric_limits<T>::max());
    std::vector<T> out(samples.size());
    for (std::size_t i = 0; i < samples.size(); ++i) {
        const double v = static_cast<double>(samples[i]);
        const double clamped = std::isnan(v) ? 0.0 : std::clamp(v, 0.0, 1.0);
        out[i] = static_cast<T>(std::lround(clamped * top));
    }
    return out;
}

void check_image(const fs::path& path, const Image& image) {
    const std::string shown = path.string();
    if (image.width < 1 || image.height < 1 || image.channels < 1) {
        throw Error(shown + ": cannot write an image of " + std::to_string(image.width) + " x " +
                    std::to_string(image.height) + " pixels with " +
                    std::to_string(image.channels) + " channels (each must be at least 1)");
    }
    const std::size_t expected = image.pixel_count() * static_cast<std::size_t>(image.channels);
    if (image.pixels.size() != expected) {
        throw Error(shown + ": the image holds " + std::to_string(image.pixels.size()) +
                    " samples instead of width x height x channels = " + std::to_string(expected));
    }
    if (!image.channel_names.empty() &&
        image.channel_names.size() != static_cast<std::size_t>(image.channels)) {
        throw Error(shown + ": " + std::to_string(image.channel_names.size()) +
                    " channel names for " + std::to_string(image.channels) + " channels");
    }
}

}  // namespace

Image oiio_read(const fs::path& path) {
    const std::string shown = path.string();
    std::error_code ec;
    if (!fs::exists(path, ec)) throw Error(shown + ": no such file");
    if (fs::is_directory(path, ec)) throw Error(shown + ": is a directory, not an image");

    // Samples exactly as stored: no premultiplication of colour by an unassociated alpha (PNG,
    // some TIFFs), so that colour and alpha pass through unchanged.
    OIIO::ImageSpec config;
    config.attribute("oiio:UnassociatedAlpha", 1);
    auto in = OIIO::ImageInput::open(shown, &config);
    if (!in) {
        throw Error(shown + ": cannot read the image: " +
                    message_or(OIIO::geterror(), "not a format OpenImageIO reads"));
    }
    const OIIO::ImageSpec& spec = in->spec();
    if (spec.deep) throw Error(shown + ": deep images are not supported");
    if (spec.depth > 1) throw Error(shown + ": volume images are not supported");
    if (spec.width < 1 || spec.height < 1 || spec.nchannels < 1) {
        throw Error(shown + ": the image is empty");
    }

    Image image;
    image.width = spec.width;
    image.height = spec.height;
    image.channels = spec.nchannels;
    for (int c = 0; c < spec.nchannels; ++c) {
        const std::string name = static_cast<std::size_t>(c) < spec.channelnames.size()
                                     ? spec.channelnames[static_cast<std::size_t>(c)]
                                     : "";
        image.channel_names.push_back(name.empty() ? default_channel_name(c, spec.nchannels)
                                                   : name);
    }
    // irid's own attribute first: OpenImageIO reports "Linear" for every EXR.
    image.color_space = spec.get_string_attribute(color_space_attribute);
    if (image.color_space.empty()) image.color_space = spec.get_string_attribute("oiio:ColorSpace");
    image.description = spec.get_string_attribute("ImageDescription");
    image.stored_integer = !spec.format.is_floating_point();
    image.stored_bits =
        spec.get_int_attribute("oiio:BitsPerSample", static_cast<int>(spec.format.size() * 8));

    image.pixels.resize(image.pixel_count() * static_cast<std::size_t>(image.channels));
    if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeFloat, image.pixels.data())) {
        throw Error(shown + ": cannot read the pixels: " +
                    message_or(in->geterror(), "the file is damaged or truncated"));
    }
    in->close();
    return image;
}

void oiio_write(const fs::path& path, const Image& image, const ImageEncoding& encoding) {
    const std::string shown = path.string();
    const ImageFormat format = image_format_for(path);
    if (is_integer_format(format) && encoding.bits != 8 && encoding.bits != 16) {
        throw Error(shown + ": " + std::to_string(encoding.bits) +
                    " bits per sample; PNG and TIFF are written with 8 or 16");
    }
    check_image(path, image);

    AtomicFile file(path);
    const char* format_name = format == ImageFormat::exr   ? "openexr"
                              : format == ImageFormat::png ? "png"
                                                           : "tiff";
    auto out = OIIO::ImageOutput::create(format_name);
    if (!out) {
        throw Error(shown + ": OpenImageIO cannot write " + format_name + ": " +
                    message_or(OIIO::geterror(), "no such plugin"));
    }
    const OIIO::TypeDesc type = format == ImageFormat::exr ? OIIO::TypeDesc(OIIO::TypeDesc::FLOAT)
                                : encoding.bits == 8       ? OIIO::TypeDesc(OIIO::TypeDesc::UINT8)
                                                           : OIIO::TypeDesc(OIIO::TypeDesc::UINT16);
    OIIO::ImageSpec spec(image.width, image.height, image.channels, type);
    spec.alpha_channel = -1;
    for (int c = 0; c < image.channels; ++c) {
        const std::string name = image.channel_names.empty()
                                     ? default_channel_name(c, image.channels)
                                     : image.channel_names[static_cast<std::size_t>(c)];
        spec.channelnames[static_cast<std::size_t>(c)] = name;
        if ((name == "A" || name == "a" || name == "Alpha") && spec.alpha_channel < 0) {
            spec.alpha_channel = c;
        }
    }
    // Colour and alpha are written as given (no division of colour by alpha for PNG).
    spec.attribute("oiio:UnassociatedAlpha", 1);
    if (!image.color_space.empty()) {
        spec.attribute("oiio:ColorSpace", image.color_space);      // PNG keeps it (a text chunk)
        spec.attribute(color_space_attribute, image.color_space);  // EXR keeps it
    }
    if (!image.description.empty()) spec.attribute("ImageDescription", image.description);
    if (!encoding.compression.empty()) spec.attribute("compression", encoding.compression);

    const std::string temporary = file.temporary_path().string();
    if (!out->open(temporary, spec)) {
        throw Error(shown + ": cannot write: " +
                    message_or(out->geterror(), "cannot create the file in its folder"));
    }
    bool ok = false;
    if (format == ImageFormat::exr) {
        ok = out->write_image(OIIO::TypeDesc::FLOAT, image.pixels.data());
    } else if (encoding.bits == 8) {
        const std::vector<std::uint8_t> samples = quantise<std::uint8_t>(image.pixels);
        ok = out->write_image(OIIO::TypeDesc::UINT8, samples.data());
    } else {
        const std::vector<std::uint16_t> samples = quantise<std::uint16_t>(image.pixels);
        ok = out->write_image(OIIO::TypeDesc::UINT16, samples.data());
    }
    const bool closed = out->close();
    if (!ok || !closed) {
        throw Error(shown +
                    ": writing failed: " + message_or(out->geterror(), "the disk may be full"));
    }
    out.reset();
    file.commit();
}

namespace {

bool backend_read(const char* path, Image* out, std::string* error) noexcept {
    try {
        *out = oiio_read(path);
        return true;
    } catch (const std::exception& e) {
        *error = e.what();
    } catch (...) {
        *error = std::string(path) + ": reading failed";
    }
    return false;
}

bool backend_write(const char* path, const Image* image, const ImageEncoding* encoding,
                   std::string* error) noexcept {
    try {
        oiio_write(path, *image, *encoding);
        return true;
    } catch (const std::exception& e) {
        *error = e.what();
    } catch (...) {
        *error = std::string(path) + ": writing failed";
    }
    return false;
}

constexpr ImageBackend backend{image_backend_abi_version, &backend_read, &backend_write};

}  // namespace

}  // namespace irid::io

extern "C" const irid::io::ImageBackend* irid_image_backend() { return &irid::io::backend; }
