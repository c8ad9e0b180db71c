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
        check_tiff_directories(shown, path);
    }
    if (std::memcmp(magic, "\xff\xd8\xff", 3) == 0) check_jpeg(shown, file, limits, facts);
    return facts;
}

}  // namespace irid::io
