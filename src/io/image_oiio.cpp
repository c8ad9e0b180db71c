#include <irid/error.h>
#include <irid/io/image.h>
#include <irid/io/output_file.h>

#include "image_backend.h"
#include "image_header.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <sys/stat.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

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

/// The lines of a decoder's complaint that do not mean lost or made-up pixels. libjpeg's
/// warnings reach OpenImageIO 2.4's error state too, and some concern the headers only (jerror.h:
/// JWRN_EXTRANEOUS_DATA, bytes skipped before a marker; JWRN_JFIF_MAJOR; JWRN_NOT_SEQUENTIAL,
/// odd but decodable SOS parameters; JWRN_ADOBE_XFORM; JWRN_JFIF_BADTHUMBNAILSIZE). At close,
/// after every row was read, "Premature end of JPEG file" means only that the EOI marker is
/// missing (libjpeg's finish_decompress looks for it).
std::string drop_harmless(const std::string& complaint, bool at_close) {
    static constexpr const char* harmless[] = {
        "extraneous bytes before marker", "unknown JFIF revision number",
        "Invalid SOS parameters for sequential JPEG", "Unknown Adobe color transform code",
        "thumbnail image size does not match data length"};
    std::string kept;
    std::size_t start = 0;
    while (start < complaint.size()) {
        std::size_t end = complaint.find('\n', start);
        if (end == std::string::npos) end = complaint.size();
        const std::string line = complaint.substr(start, end - start);
        bool drop = line.find_first_not_of(" ") == std::string::npos ||
                    (at_close && line.find("Premature end of JPEG file") != std::string::npos);
        for (const char* h : harmless) drop = drop || line.find(h) != std::string::npos;
        if (!drop) kept += (kept.empty() ? "" : "\n") + line;
        start = end + 1;
    }
    return kept;
}

/// The first line of a message, with how many more there were (libtiff repeats its complaint for
/// every strip that follows a short one).
std::string first_line(const std::string& message) {
    const std::size_t end = message.find('\n');
    if (end == std::string::npos) return message;
    const auto more = static_cast<std::size_t>(std::count(message.begin() + static_cast<std::ptrdiff_t>(end), message.end(), '\n'));
    return message.substr(0, end) + " (and " + std::to_string(more) + " more like it)";
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

/// Windows OpenEXR can hold: every corner within ±max_window_coordinate, a display window with
/// min <= max.
void check_windows(const fs::path& path, const Image& image) {
    const auto data = data_window(image);
    const auto inside = [](long long v) { return v >= -max_window_coordinate && v <= max_window_coordinate; };
    if (!std::all_of(data.begin(), data.end(), inside)) {
        throw Error(path.string() + ": the data window starts at " + std::to_string(image.origin_x) + ", " +
                    std::to_string(image.origin_y) + "; OpenEXR holds corners within ±" +
                    std::to_string(max_window_coordinate));
    }
    if (const auto& d = image.display_window) {
        if (!std::all_of(d->begin(), d->end(), inside) || (*d)[0] > (*d)[2] || (*d)[1] > (*d)[3]) {
            throw Error(path.string() + ": the display window " + std::to_string((*d)[0]) + " " +
                        std::to_string((*d)[1]) + " " + std::to_string((*d)[2]) + " " + std::to_string((*d)[3]) +
                        " is no box OpenEXR holds (x min <= x max, y min <= y max, corners within ±" +
                        std::to_string(max_window_coordinate) + ")");
        }
    }
}

/// The file's declared size against the limits, before anything is allocated.
void check_limits(const std::string& shown, const OIIO::ImageSpec& spec, const ImageLimits& limits) {
    const long long w = spec.width, h = spec.height, c = spec.nchannels;
    if (w < 1 || h < 1 || c < 1) throw Error(shown + ": the image is empty");
    if (c > limits.max_channels) {
        throw Error(shown + ": the image declares " + std::to_string(c) + " channels; irid reads at most " +
                    std::to_string(limits.max_channels));
    }
    check_declared_pixels(shown, static_cast<std::uint64_t>(w), static_cast<std::uint64_t>(h),
                          limits);
    if (w * h > limits.max_samples / c) {
        throw Error(shown + ": the image declares " +
                    declared_size_text(static_cast<std::uint64_t>(w), static_cast<std::uint64_t>(h)) +
                    " of " +
                    std::to_string(c) + " channels; irid reads at most " +
                    std::to_string(limits.max_samples) + " samples");
    }
}

}  // namespace

Image oiio_read(const fs::path& path, const ImageLimits& limits) {
    const std::string shown = path.string();
    struct stat st {};
    if (::stat(path.c_str(), &st) != 0) {
        throw Error(shown + (errno == ENOENT ? std::string(": no such file")
                                             : ": cannot read: " + std::string(std::strerror(errno))));
    }
    if (S_ISDIR(st.st_mode)) throw Error(shown + ": is a directory, not an image");
    if (!S_ISREG(st.st_mode)) {
        throw Error(shown + ": is not a regular file (" +
                    (S_ISFIFO(st.st_mode)  ? "a FIFO"
                     : S_ISCHR(st.st_mode) ? "a character device"
                     : S_ISBLK(st.st_mode) ? "a block device"
                                           : "a socket") +
                    "); images are read from regular files");
    }

    // Samples exactly as stored: no premultiplication of colour by an unassociated alpha (PNG,
    // some TIFFs), so that colour and alpha pass through unchanged.
    OIIO::ImageSpec config;
    config.attribute("oiio:UnassociatedAlpha", 1);
    (void)OIIO::geterror();  // nothing left over from an earlier file is blamed on this one
    auto in = OIIO::ImageInput::open(shown, &config);
    if (!in) {
        throw Error(shown + ": cannot read the image: " +
                    message_or(OIIO::geterror(), "not a format OpenImageIO reads"));
    }
    const OIIO::ImageSpec& spec = in->spec();
    if (spec.deep) throw Error(shown + ": deep images are not supported");
    if (spec.depth > 1) throw Error(shown + ": volume images are not supported");
    check_limits(shown, spec, limits);

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
    if (const OIIO::ParamValue* icc = spec.find_attribute("ICCProfile");
        icc != nullptr && icc->type().basetype == OIIO::TypeDesc::UINT8 && icc->nvalues() > 0) {
        const auto* bytes = static_cast<const unsigned char*>(icc->data());
        image.icc_profile.assign(bytes, bytes + icc->type().numelements() * icc->nvalues());
    }
    // As many floats as the attribute holds (up to 64): a wrong count is for the reader of the
    // space to refuse, not to drop here.
    const auto floats = [&spec](const char* name) {
        std::vector<float> out;
        const OIIO::ParamValue* p = spec.find_attribute(name);
        if (p == nullptr || p->type().basetype != OIIO::TypeDesc::FLOAT) return out;
        const std::size_t count = p->type().basevalues() * static_cast<std::size_t>(p->nvalues());
        const auto* v = static_cast<const float*>(p->data());
        out.assign(v, v + std::min<std::size_t>(count, 64));
        return out;
    };
    image.chromaticities = floats("chromaticities");
    image.adopted_neutral = floats("adoptedNeutral");
    // Windows are OpenEXR's (OpenEXR keeps their corners within ±2^30); other formats' origins
    // (a TIFF's XPosition times its resolution) are no such thing and are left at 0, 0.
    if (std::string_view(in->format_name()) == "openexr") {
        image.origin_x = spec.x;
        image.origin_y = spec.y;
        const long long x1 = static_cast<long long>(spec.full_x) + spec.full_width - 1;
        const long long y1 = static_cast<long long>(spec.full_y) + spec.full_height - 1;
        const bool own = spec.full_x == spec.x && spec.full_y == spec.y && spec.full_width == spec.width &&
                         spec.full_height == spec.height;
        if (!own && x1 <= max_window_coordinate && y1 <= max_window_coordinate) {
            image.display_window = std::array<int, 4>{spec.full_x, spec.full_y, static_cast<int>(x1), static_cast<int>(y1)};
        }
    }
    image.stored_integer = !spec.format.is_floating_point();
    // OpenImageIO names a JPEG's CMYK "CMYK" and its YCCK (Adobe transform 2) "YCbCrK"; a TIFF's
    // photometric interpretation 5 is CMYK, 8-10 the L*a*b* encodings (TIFF 6.0 §23, TIFF-F).
    const std::string jpeg_model = spec.get_string_attribute("jpeg:ColorSpace");
    const int photometric = spec.get_int_attribute("tiff:PhotometricInterpretation", -1);
    if (jpeg_model == "CMYK" || spec.get_string_attribute("tiff:ColorSpace") == "CMYK") {
        image.stored_model = "CMYK";
    } else if (jpeg_model == "YCbCrK") {
        image.stored_model = "YCCK";
    } else if (photometric == 8 || photometric == 9 || photometric == 10) {
        static constexpr const char* lab[] = {"CIELab", "ICCLab", "ITULab"};
        image.stored_model = lab[photometric - 8];
    }
    image.stored_cmyk = image.stored_model == "CMYK" || image.stored_model == "YCCK";
    image.stored_bits =
        spec.get_int_attribute("oiio:BitsPerSample", static_cast<int>(spec.format.size() * 8));

    // In strips of about 16 MiB (whole rows of tiles for a tiled file), the buffer growing as
    // the data arrive: a header may declare far more pixels than the file holds, and a file cut
    // short then costs what it holds, not what it claims.
    const auto row_samples = static_cast<std::size_t>(spec.width) * static_cast<std::size_t>(spec.nchannels);
    const int unit = spec.tile_width > 0 ? std::max(1, spec.tile_height) : 1;
    const int strip = std::max(unit, static_cast<int>((std::size_t{4} << 20) / row_samples) / unit * unit);
    const int z_end = spec.z + std::max(1, spec.depth);
    for (int row = 0; row < spec.height; row += strip) {
        const int rows = std::min(strip, spec.height - row);
        const std::size_t done = image.pixels.size();
        image.pixels.resize(done + static_cast<std::size_t>(rows) * row_samples);
        float* out = image.pixels.data() + done;
        const bool ok =
            spec.tile_width > 0
                ? in->read_tiles(0, 0, spec.x, spec.x + spec.width, spec.y + row,
                                 spec.y + row + rows, spec.z, z_end, 0, spec.nchannels,
                                 OIIO::TypeFloat, out)
                : in->read_scanlines(0, 0, spec.y + row, spec.y + row + rows, spec.z, 0,
                                     spec.nchannels, OIIO::TypeFloat, out);
        // OpenImageIO 2.4 reports a decoder's complaint (libjpeg's "Premature end of JPEG file",
        // libtiff's short strip) through geterror() while the read itself returns true and
        // has_error() false, and fills what is missing with grey or black.
        std::string complaint = drop_harmless(in->geterror(), false);
        if (!ok || !complaint.empty()) {
            throw Error(shown + ": cannot read the pixels (damaged or truncated): " +
                        first_line(message_or(std::move(complaint), "OpenImageIO gave no reason")));
        }
    }
    const bool closed = in->close();
    if (std::string complaint = drop_harmless(in->geterror(), true); !closed || !complaint.empty()) {
        throw Error(shown + ": cannot read the pixels (damaged or truncated): " +
                    first_line(message_or(std::move(complaint), "closing the file failed")));
    }
    if (std::string complaint = OIIO::geterror(); !complaint.empty()) {
        throw Error(shown + ": cannot read the image: " + first_line(message_or(std::move(complaint), "")));
    }
    return image;
}

namespace {

/// OpenImageIO writes through this proxy into irid's OutputFile, so that every byte goes through
/// one writer that checks every write (OpenImageIO 2.4's PNG writer ignores failed writes and
/// reports success on a full disk). A seekable output (a temporary file) is written in place; a
/// stream (a device, a FIFO, standard output) cannot go back to fill in an index, so the file is
/// assembled in memory and written out when OpenImageIO is done.
class OutputProxy final : public OIIO::Filesystem::IOProxy {
public:
    explicit OutputProxy(OutputFile& file)
        : IOProxy(file.target().string(), IOProxy::Write), m_file(file) {}

    const char* proxytype() const override { return "irid-output"; }
    void close() override { m_mode = Closed; }
    bool seek(int64_t offset) override {
        if (offset < 0) return false;
        m_pos = offset;
        return true;
    }
    size_t write(const void* buf, size_t size) override {
        const size_t n = pwrite(buf, size, m_pos);
        m_pos += static_cast<int64_t>(n);
        return n;
    }
    size_t pwrite(const void* buf, size_t size, int64_t offset) override {
        if (!m_failure.empty() || offset < 0) return 0;
        const auto at = static_cast<std::size_t>(offset);
        try {
            if (m_file.seekable()) {
                m_file.write_at(buf, size, at);
            } else {
                if (m_memory.size() < at + size) m_memory.resize(at + size);
                std::memcpy(m_memory.data() + at, buf, size);
            }
        } catch (const std::exception& e) {
            m_failure = e.what();
            return 0;
        }
        m_size = std::max(m_size, at + size);
        return size;
    }
    size_t read(void* buf, size_t size) override {
        const size_t n = pread(buf, size, m_pos);
        m_pos += static_cast<int64_t>(n);
        return n;
    }
    size_t pread(void* buf, size_t size, int64_t offset) override {
        if (offset < 0) return 0;
        const auto at = static_cast<std::size_t>(offset);
        if (m_file.seekable()) return m_file.read_at(buf, size, at);
        if (at >= m_memory.size()) return 0;
        const std::size_t n = std::min(size, m_memory.size() - at);
        std::memcpy(buf, m_memory.data() + at, n);
        return n;
    }
    size_t size() const override { return m_size; }

    /// For a stream: writes what was assembled. Throws irid::Error on failure.
    void finish() {
        if (!m_failure.empty()) throw Error(m_failure);
        if (!m_file.seekable()) m_file.write(m_memory.data(), m_memory.size());
    }
    [[nodiscard]] const std::string& failure() const noexcept { return m_failure; }

private:
    OutputFile& m_file;
    std::vector<char> m_memory;
    std::size_t m_size = 0;
    std::string m_failure;
};

}  // namespace

void oiio_write(OutputFile& file, const Image& image, const ImageEncoding& encoding) {
    const fs::path& path = file.target();
    const std::string shown = path.string();
    const ImageFormat format = image_format_for(path);
    if (is_integer_format(format) && encoding.bits != 8 && encoding.bits != 16) {
        throw Error(shown + ": " + std::to_string(encoding.bits) +
                    " bits per sample; PNG and TIFF are written with 8 or 16");
    }
    if (format == ImageFormat::jpeg && encoding.bits != 8) {
        throw Error(shown + ": " + std::to_string(encoding.bits) +
                    " bits per sample; JPEG holds 8 (write PNG or TIFF for 16)");
    }
    check_image(path, image);
    if (format == ImageFormat::jpeg && image.channels != 1 && image.channels != 3) {
        throw Error(shown + ": " + std::to_string(image.channels) +
                    " channels; JPEG holds 1 (grey) or 3 (RGB), no alpha (write PNG or TIFF for "
                    "alpha)");
    }
    std::string quality = "jpeg:95";
    if (format == ImageFormat::jpeg && !encoding.compression.empty()) {
        const std::string& c = encoding.compression;
        const std::string digits = c.rfind("jpeg:", 0) == 0 ? c.substr(5) : "";
        const bool number = !digits.empty() && digits.size() <= 3 &&
                            digits.find_first_not_of("0123456789") == std::string::npos;
        if (!number || std::stoi(digits) < 1 || std::stoi(digits) > 100) {
            throw Error(shown + ": compression '" + c + "'; JPEG takes jpeg:Q with a quality Q of 1 to 100");
        }
        quality = c;
    }

    const char* format_name = format == ImageFormat::exr    ? "openexr"
                              : format == ImageFormat::png  ? "png"
                              : format == ImageFormat::jpeg ? "jpeg"
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
        // PNG keeps it (a text chunk). Not given to TIFF: OpenImageIO 2.4 turns it into an Exif
        // directory, which its TIFF writer links wrongly when writing through an IOProxy (the
        // file's first directory pointer ends up at the Exif one, losing the image).
        if (format != ImageFormat::tiff) spec.attribute("oiio:ColorSpace", image.color_space);
        spec.attribute(color_space_attribute, image.color_space);  // EXR keeps it
    }
    if (!image.description.empty()) spec.attribute("ImageDescription", image.description);
    if (format == ImageFormat::exr) {
        check_windows(path, image);
        spec.x = image.origin_x;
        spec.y = image.origin_y;
        spec.full_x = spec.x;
        spec.full_y = spec.y;
        spec.full_width = spec.width;
        spec.full_height = spec.height;
        if (const auto& d = image.display_window) {
            spec.full_x = (*d)[0];
            spec.full_y = (*d)[1];
            spec.full_width = (*d)[2] - (*d)[0] + 1;
            spec.full_height = (*d)[3] - (*d)[1] + 1;
        }
        if (image.chromaticities.size() == 8) {
            spec.attribute("chromaticities", OIIO::TypeDesc(OIIO::TypeDesc::FLOAT, 8),
                           image.chromaticities.data());
        }
        if (image.adopted_neutral.size() == 2) {
            spec.attribute("adoptedNeutral",
                           OIIO::TypeDesc(OIIO::TypeDesc::FLOAT, OIIO::TypeDesc::VEC2),
                           image.adopted_neutral.data());
        }
    } else if (!image.icc_profile.empty()) {
        spec.attribute("ICCProfile",
                       OIIO::TypeDesc(OIIO::TypeDesc::UINT8, static_cast<int>(image.icc_profile.size())),
                       image.icc_profile.data());
    }
    if (format == ImageFormat::jpeg) {
        spec.attribute("compression", quality);
    } else if (!encoding.compression.empty()) {
        spec.attribute("compression", encoding.compression);
    }

    OutputProxy proxy(file);
    OIIO::Filesystem::IOProxy* proxy_pointer = &proxy;
    spec.attribute("oiio:ioproxy", OIIO::TypeDesc::PTR, &proxy_pointer);
    const auto failed = [&](const char* what, const char* fallback) {
        // irid's own record of a failed write names the file and the system's reason.
        if (!proxy.failure().empty()) return Error(proxy.failure());
        return Error(shown + ": " + what + ": " + message_or(out->geterror(), fallback));
    };
    if (!out->open(shown, spec)) throw failed("cannot write", "OpenImageIO refused the image");
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
    if (!ok || !closed) throw failed("writing failed", "OpenImageIO reported no reason");
    out.reset();
    proxy.finish();
}

namespace {

bool backend_read(const char* path, const ImageLimits* limits, Image* out,
                  std::string* error) noexcept {
    try {
        *out = oiio_read(path, *limits);
        return true;
    } catch (const std::exception& e) {
        *error = e.what();
    } catch (...) {
        *error = std::string(path) + ": reading failed";
    }
    return false;
}

bool backend_write(OutputFile* file, const Image* image, const ImageEncoding* encoding,
                   std::string* error) noexcept {
    try {
        oiio_write(*file, *image, *encoding);
        return true;
    } catch (const std::exception& e) {
        *error = e.what();
    } catch (...) {
        *error = file->target().string() + ": writing failed";
    }
    return false;
}

constexpr ImageBackend backend{image_backend_abi_version, &backend_read, &backend_write};

}  // namespace

}  // namespace irid::io

extern "C" const irid::io::ImageBackend* irid_image_backend() { return &irid::io::backend; }
