#pragma once

// What the header checks of each container share (image_header.cpp, header_jpeg.cpp,
// header_tiff.cpp): a buffered reader of the file's bytes, byte order, and the messages.

#include "image_header.h"

#include <array>
#include <cerrno>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include <unistd.h>

namespace irid::io::header {

/// Reads a file front to back through a buffer, and skips ahead without reading.
class Reader {
public:
    Reader(int fd, std::uint64_t size) : m_fd(fd), m_size(size) {}
    [[nodiscard]] std::uint64_t size() const noexcept { return m_size; }
    [[nodiscard]] int fd() const noexcept { return m_fd; }
    /// `n` bytes at `offset` (n <= buffer size), or false when the file ends first.
    bool read(std::uint64_t offset, void* out, std::size_t n) {
        if (offset > m_size || n > m_size - offset) return false;
        if (offset < m_start || offset + n > m_start + m_valid) {
            m_start = offset;
            m_valid = 0;
            while (m_valid < m_buffer.size() && m_start + m_valid < m_size) {
                const ssize_t got = ::pread(m_fd, m_buffer.data() + m_valid,
                                            m_buffer.size() - m_valid,
                                            static_cast<off_t>(m_start + m_valid));
                if (got < 0 && errno == EINTR) continue;
                if (got <= 0) break;
                m_valid += static_cast<std::size_t>(got);
            }
            if (offset + n > m_start + m_valid) return false;
        }
        std::memcpy(out, m_buffer.data() + (offset - m_start), n);
        return true;
    }

    /// `n` bytes at `offset`, read straight from the file, past the buffer: for small reads far
    /// apart (an EXR's chunk headers), where refilling the buffer at each would read it all.
    bool read_unbuffered(std::uint64_t offset, void* out, std::size_t n) const {
        if (offset > m_size || n > m_size - offset) return false;
        std::size_t got = 0;
        while (got < n) {
            const ssize_t r = ::pread(m_fd, static_cast<unsigned char*>(out) + got, n - got,
                                      static_cast<off_t>(offset + got));
            if (r < 0 && errno == EINTR) continue;
            if (r <= 0) return false;
            got += static_cast<std::size_t>(r);
        }
        return true;
    }

private:
    int m_fd;
    std::uint64_t m_size;
    std::uint64_t m_start = 0;
    std::size_t m_valid = 0;
    std::array<unsigned char, 1 << 16> m_buffer{};
};

inline std::uint32_t big_endian32(const unsigned char* p) noexcept {
    return static_cast<std::uint32_t>(p[0]) << 24 | static_cast<std::uint32_t>(p[1]) << 16 |
           static_cast<std::uint32_t>(p[2]) << 8 | static_cast<std::uint32_t>(p[3]);
}

inline std::uint32_t little_endian32(const unsigned char* p) noexcept {
    return static_cast<std::uint32_t>(p[0]) | static_cast<std::uint32_t>(p[1]) << 8 |
           static_cast<std::uint32_t>(p[2]) << 16 | static_cast<std::uint32_t>(p[3]) << 24;
}

/// `n` bytes at `offset`, in pieces the reader's buffer holds; empty when the file ends first.
std::vector<unsigned char> read_bytes(Reader& file, std::uint64_t offset, std::uint64_t n);

/// "????" for bytes that are not printable ASCII.
std::string printable(const unsigned char* p, std::size_t n);

/// Throws irid::Error "<shown>: truncated or corrupt: <what>".
[[noreturn]] void corrupt(const std::string& shown, const std::string& what);

/// Throws irid::Error naming `shown` when an embedded ICC profile's header or tag table runs past
/// its bytes (OpenImageIO 2.4 reads a TIFF's or JPEG's tags unchecked).
void check_icc(const std::string& shown, const std::vector<unsigned char>& profile);

/// PNG (ISO/IEC 15948): every chunk inside the file and matching its CRC, an IEND chunk, the
/// image data able to hold the pixels declared, the iCCP profile, and the colour chunks (gAMA,
/// cHRM, sRGB, cICP: once each, of their own length, before the image data) into `facts`
/// (header_png.cpp).
void check_png(const std::string& shown, Reader& file, const ImageLimits& limits, HeaderFacts& facts);

/// OpenEXR: every attribute of the header(s) inside the file, the first part's data window
/// within `limits`, and a single-part file's chunk table (header_exr.cpp).
void check_exr(const std::string& shown, Reader& file, const ImageLimits& limits);

/// JPEG (ITU-T T.81 Annex B): the declared size against `limits` and against the coded data
/// after the first scan header; the APP2 ICC profile chunks (ICC.1 Annex B.4), whose damage goes
/// to facts.icc_damage (header_jpeg.cpp).
void check_jpeg(const std::string& shown, Reader& file, const ImageLimits& limits, HeaderFacts& facts);

/// A strip or tile of coded data: where it is, its bytes, and the bytes it decodes to.
struct CodedUnit {
    std::uint64_t offset = 0;
    std::uint64_t count = 0;
    std::uint64_t expected = 0;
};

/// Inflates each deflate-coded unit as libtiff does (tif_zip.c): throws irid::Error naming the
/// file and the unit ("strip" or "tile") when its data are damaged or end before the bytes it
/// holds (header_deflate.cpp). Units whose `expected` is 0 are skipped.
void check_deflate_units(const std::string& shown, const Reader& file, const std::vector<CodedUnit>& units,
                         const char* unit);

/// Every directory of a TIFF read by libtiff, as tiffinfo reads them: throws irid::Error naming
/// the file and libtiff's first error (a tag value out of range, a broken chain of directories;
/// its warnings pass). Files libtiff cannot open pass (the decoder names them)
/// (header_libtiff.cpp).
void check_tiff_directories(const std::string& shown, const std::filesystem::path& path);

/// TIFF (TIFF 6.0, and BigTIFF): the first directory's size against `limits`, its strips or tiles
/// against the file and what they can expand to, and its ICC profile tag (header_tiff.cpp).
void check_tiff(const std::string& shown, Reader& file, const ImageLimits& limits, HeaderFacts& facts);

}  // namespace irid::io::header
