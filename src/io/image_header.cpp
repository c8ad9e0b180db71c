// What an image file's header declares, checked against the file itself before a decoder sees
// it (image_header.h). libpng and OpenEXR allocate what a header declares before they read it:
// a chunk's length, an attribute's size, the line-offset table of the data window. A file of a
// few hundred bytes can so ask for gigabytes. These checks need only the file's bytes.
#include "image_header.h"
#include "header_reader.h"

#include <irid/error.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>
#include <utility>
#include <vector>

#include <fcntl.h>
#include <zlib.h>
#include <sys/stat.h>
#include <unistd.h>

namespace irid::io {
namespace header {

std::vector<unsigned char> read_bytes(Reader& file, std::uint64_t offset, std::uint64_t n) {
    std::vector<unsigned char> out;
    if (offset > file.size() || n > file.size() - offset) return out;
    out.resize(n);
    for (std::uint64_t done = 0; done < n;) {
        const std::size_t piece = static_cast<std::size_t>(std::min<std::uint64_t>(n - done, 1 << 15));
        if (!file.read(offset + done, out.data() + done, piece)) return {};
        done += piece;
    }
    return out;
}

std::string printable(const unsigned char* p, std::size_t n) {
    std::string s;
    for (std::size_t i = 0; i < n; ++i) s += (p[i] >= 0x20 && p[i] < 0x7F) ? static_cast<char>(p[i]) : '?';
    return s;
}

void corrupt(const std::string& shown, const std::string& what) {
    throw Error(shown + ": truncated or corrupt: " + what);
}

/// An embedded ICC profile's tag table (ICC.1:2022 §7.3): every tag inside the profile.
/// OpenImageIO 2.4 reads the tags of a TIFF's or JPEG's profile without checking them against
/// its size (decode_icc_profile), and a tag offset that wraps past 2^32 crashes it; libpng
/// drops such a PNG profile itself.
void check_icc(const std::string& shown, const std::vector<unsigned char>& p) {
    const std::string where = shown + ": ICC profile: damaged: ";
    if (p.size() < 132) {
        throw Error(where + "only " + std::to_string(p.size()) + " bytes; a profile holds a 128-byte "
                    "header and a tag table");
    }
    const std::uint64_t declared = big_endian32(p.data());
    if (declared > p.size()) {
        throw Error(shown + ": ICC profile: truncated: its header declares " + std::to_string(declared) +
                    " bytes and " + std::to_string(p.size()) + " are there");
    }
    const std::uint64_t size = declared;
    const std::uint64_t count = big_endian32(p.data() + 128);
    if (132 + 12 * count > size) {
        throw Error(where + "its tag table of " + std::to_string(count) + " tags runs past its " +
                    std::to_string(size) + " bytes");
    }
    const auto past = [&](std::uint64_t i, const unsigned char* t, const std::string& what) {
        throw Error(where + "tag " + std::to_string(i) + " ('" + printable(t, 4) + "') " + what +
                    " runs past the profile's " + std::to_string(size) + " bytes");
    };
    for (std::uint64_t i = 0; i < count; ++i) {
        const unsigned char* t = p.data() + 132 + 12 * i;
        const std::uint64_t offset = big_endian32(t + 4), length = big_endian32(t + 8);
        if (offset + std::max<std::uint64_t>(length, 4) > size) {
            past(i, t, "at byte " + std::to_string(offset) + ", " + std::to_string(length) + " bytes long,");
        }
        // The text types OpenImageIO decodes (ICC.1:2022 §10.24 textType, §10.15
        // multiLocalizedUnicodeType, and ICC.1:2001's textDescriptionType): their headers must
        // fit in the tag, and each string in the profile.
        const unsigned char* body = p.data() + offset;
        const std::string type = printable(body, 4);
        if ((type == "text" && length < 8) || (type == "desc" && length < 12) ||
            (type == "mluc" && length < 16)) {
            throw Error(where + "tag " + std::to_string(i) + " ('" + printable(t, 4) + "') of type '" +
                        type + "' is " + std::to_string(length) + " bytes, shorter than its header");
        }
        if (type == "mluc") {
            const std::uint64_t records = big_endian32(body + 8), record_size = big_endian32(body + 12);
            if (offset + 16 + records * 12 > size) past(i, t, "holds " + std::to_string(records) + " records that");
            for (std::uint64_t r = 0; record_size == 12 && r < records; ++r) {
                const unsigned char* rec = body + 16 + 12 * r;
                const std::uint64_t n = big_endian32(rec + 4), at = big_endian32(rec + 8);
                if (offset + at + n > size) past(i, t, "has a string of " + std::to_string(n) + " bytes that");
            }
        }
    }
}

}  // namespace header

namespace {
using namespace header;

/// deflate (RFC 1951) expands its input at most about 1032-fold: a 258-byte match costs at
/// least 2 bits (zlib's FAQ, "What's the maximum compression ratio?": 1032:1).
constexpr double deflate_max_expansion = 1032.0;

/// PNG's iCCP chunk (ISO/IEC 15948 §11.3.3.3): a name, a NUL, the compression method (0) and the
/// zlib-compressed profile, which is inflated (up to 64 MiB) and checked as TIFF's and JPEG's
/// are: libpng checks the header of a profile, not its tag table, which OpenImageIO 2.4 then
/// reads unchecked.
void check_png_icc(const std::string& shown, Reader& file, std::uint64_t offset, std::uint64_t length) {
    if (length > (std::uint64_t{64} << 20)) return;
    const std::vector<unsigned char> chunk = read_bytes(file, offset, length);
    // The name: 1 to 79 bytes and a NUL; then the compression method, then the data.
    const auto name_end = chunk.begin() + static_cast<std::ptrdiff_t>(std::min<std::size_t>(chunk.size(), 80));
    const auto nul = std::find(chunk.begin(), name_end, 0);
    if (nul == name_end) return;  // libpng refuses such a chunk
    const std::size_t data = static_cast<std::size_t>(nul - chunk.begin()) + 2;
    if (data >= chunk.size()) return;
    z_stream z{};
    if (inflateInit(&z) != Z_OK) return;
    z.next_in = const_cast<Bytef*>(chunk.data() + data);
    z.avail_in = static_cast<uInt>(chunk.size() - data);
    std::vector<unsigned char> profile;
    int status = Z_OK;
    while (status == Z_OK && profile.size() < (std::size_t{64} << 20)) {
        const std::size_t done = profile.size();
        profile.resize(done + (1 << 16));
        z.next_out = profile.data() + done;
        z.avail_out = 1 << 16;
        status = inflate(&z, Z_NO_FLUSH);
        profile.resize(done + (1 << 16) - z.avail_out);
    }
    inflateEnd(&z);
    // What was inflated, even when the stream ends badly: libpng does not check the checksum
    // of a compressed chunk, and passes on what it inflated.
    if (status != Z_STREAM_END && profile.size() < 132) return;
    check_icc(shown, profile);
}

/// PNG (ISO/IEC 15948): every chunk must fit in the file, and the image data (IDAT) must be able
/// to hold the pixels the header (IHDR) declares.
void check_png(const std::string& shown, Reader& file, const ImageLimits& limits, HeaderFacts& facts) {
    std::uint64_t pos = 8, idat_bytes = 0;
    std::uint64_t width = 0, height = 0;
    unsigned depth = 0, colour_type = 0;
    bool have_header = false;
    unsigned char head[8];
    while (file.read(pos, head, sizeof head)) {
        const std::uint64_t length = big_endian32(head);
        const std::string type = printable(head + 4, 4);
        const std::uint64_t left = file.size() - pos - 8;  // data and CRC
        if (length + 4 > left) {
            corrupt(shown, "its " + type + " chunk at byte " + std::to_string(pos) + " declares " +
                               std::to_string(length) + " bytes, and " +
                               std::to_string(left >= 4 ? left - 4 : 0) + " remain");
        }
        if (type == "IHDR" && length >= 13) {
            unsigned char ihdr[13];
            if (!file.read(pos + 8, ihdr, sizeof ihdr)) break;
            width = big_endian32(ihdr);
            height = big_endian32(ihdr + 4);
            depth = ihdr[8];
            colour_type = ihdr[9];
            have_header = true;
        } else if (type == "IDAT") {
            idat_bytes += length;
        } else if (type == "iCCP") {
            facts.png_icc_chunk = true;
            check_png_icc(shown, file, pos + 8, length);
        } else if (type == "IEND") {
            break;
        }
        pos += 12 + length;
    }
    if (!have_header || width == 0 || height == 0) return;  // the decoder names what is wrong
    check_declared_pixels(shown, width, height, limits);
    // Samples per pixel by colour type: grey, -, RGB, palette, grey + alpha, -, RGBA.
    static constexpr unsigned samples_of[] = {1, 0, 3, 1, 2, 0, 4};
    const unsigned samples = colour_type < 7 ? samples_of[colour_type] : 0;
    if (samples == 0 || depth == 0 || depth > 16) return;
    // Each row: a filter byte and its samples, packed (the non-interlaced size, the smallest).
    const double raw = static_cast<double>(height) *
                       (1.0 + std::ceil(static_cast<double>(width) * samples * depth / 8.0));
    if (raw > deflate_max_expansion * static_cast<double>(idat_bytes) + 1024.0) {
        corrupt(shown, std::to_string(width) + " x " + std::to_string(height) + " pixels need " +
                           std::to_string(static_cast<std::uint64_t>(raw)) +
                           " bytes of image data, and its " + std::to_string(idat_bytes) +
                           " bytes of compressed data cannot hold them (deflate expands at most "
                           "1032-fold)");
    }
}

/// OpenEXR (the file layout of openexr.com, "OpenEXR File Layout"): every attribute of the
/// header(s) must fit in the file, and the first part's data window within the limits.
void check_exr(const std::string& shown, Reader& file, const ImageLimits& limits) {
    unsigned char version[4];
    if (!file.read(4, version, sizeof version)) return;
    const bool multipart = (version[1] & 0x10) != 0;  // flag bit 12
    std::uint64_t pos = 8;
    int part = 0;
    bool header_empty = true;
    // "name\0type\0" then a 4-byte size and the value; names are at most 255 bytes.
    const auto read_string = [&](std::uint64_t from, std::string& out) -> std::uint64_t {
        out.clear();
        unsigned char c = 0;
        for (std::uint64_t i = from; i < from + 256; ++i) {
            if (!file.read(i, &c, 1)) return 0;
            if (c == 0) return i + 1;
            out += static_cast<char>(c);
        }
        return 0;
    };
    while (pos < file.size()) {
        unsigned char first = 0;
        if (!file.read(pos, &first, 1)) return;
        if (first == 0) {  // the end of a header
            ++pos;
            if (!multipart || header_empty) return;
            header_empty = true;
            ++part;
            continue;
        }
        header_empty = false;
        std::string name, type;
        const std::uint64_t after_name = read_string(pos, name);
        if (after_name == 0) return;
        const std::uint64_t after_type = read_string(after_name, type);
        if (after_type == 0) return;
        unsigned char size_bytes[4];
        if (!file.read(after_type, size_bytes, 4)) return;
        const std::uint64_t size = little_endian32(size_bytes);
        const std::uint64_t left = file.size() - (after_type + 4);
        if (size > left) {
            corrupt(shown, "its header attribute '" + printable(reinterpret_cast<const unsigned char*>(name.data()), std::min<std::size_t>(name.size(), 40)) +
                               "' declares " + std::to_string(size) + " bytes, and " +
                               std::to_string(left) + " remain");
        }
        if (part == 0 && name == "dataWindow" && type == "box2i" && size == 16) {
            unsigned char box[16];
            if (file.read(after_type + 4, box, sizeof box)) {
                const auto signed32 = [&](int i) {
                    return static_cast<std::int64_t>(static_cast<std::int32_t>(little_endian32(box + i)));
                };
                const std::int64_t w = signed32(8) - signed32(0) + 1;
                const std::int64_t h = signed32(12) - signed32(4) + 1;
                if (w >= 1 && h >= 1) {
                    check_declared_pixels(shown, static_cast<std::uint64_t>(w),
                                          static_cast<std::uint64_t>(h), limits);
                }
            }
        }
        pos = after_type + 4 + size;
    }
}

}  // namespace

std::string declared_size_text(std::uint64_t width, std::uint64_t height) {
    const double mpixel = static_cast<double>(width) * static_cast<double>(height) / 1e6;
    char buffer[96];
    std::snprintf(buffer, sizeof buffer, "%llu x %llu pixels (%.1f Mpixel)",
                  static_cast<unsigned long long>(width), static_cast<unsigned long long>(height),
                  mpixel);
    return buffer;
}

void check_declared_pixels(const std::string& shown, std::uint64_t width, std::uint64_t height,
                           const ImageLimits& limits) {
    const auto max = static_cast<std::uint64_t>(limits.max_pixels);
    if (width > max || height > max || width * height > max) {
        throw Error(shown + ": the image declares " + declared_size_text(width, height) +
                    "; irid reads at most " + std::to_string(limits.max_pixels) + " pixels (" +
                    std::to_string(limits.max_pixels >> 20) + " Mpixel)");
    }
}

HeaderFacts check_image_header(const std::filesystem::path& path, const ImageLimits& limits) {
    const std::string shown = path.string();
    HeaderFacts facts;
    int fd = -1;
    do {
        fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NOCTTY | O_NONBLOCK);
    } while (fd < 0 && errno == EINTR);
    if (fd < 0) return facts;  // the decoder reports it, with the path
    struct Closer {
        int fd;
        ~Closer() { ::close(fd); }
    } closer{fd};
    struct stat st {};
    if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) return facts;
    Reader file(fd, static_cast<std::uint64_t>(st.st_size));
    unsigned char magic[8];
    if (!file.read(0, magic, sizeof magic)) return facts;
    if (std::memcmp(magic, "\x89PNG\r\n\x1a\n", 8) == 0) check_png(shown, file, limits, facts);
    if (std::memcmp(magic, "\x76\x2f\x31\x01", 4) == 0) check_exr(shown, file, limits);
    if (std::memcmp(magic, "II*\0", 4) == 0 || std::memcmp(magic, "MM\0*", 4) == 0 ||
        std::memcmp(magic, "II+\0", 4) == 0 || std::memcmp(magic, "MM\0+", 4) == 0) {
        check_tiff(shown, file, limits, facts);
    }
    if (std::memcmp(magic, "\xff\xd8\xff", 3) == 0) check_jpeg(shown, file, limits, facts);
    return facts;
}

}  // namespace irid::io
