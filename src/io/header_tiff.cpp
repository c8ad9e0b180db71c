// A classic TIFF's first directory read before libtiff sees the file (header_reader.h).
//
// libtiff trusts a directory's strip (or tile) offsets and byte counts, and OpenImageIO fills
// what a strip lacks with black. The directory says how many bytes the image data take and how
// many the pixels need; a compression expands its data by at most a known factor, so a file of a
// few hundred bytes cannot declare gigabytes of pixels.
#include "header_reader.h"

#include <irid/error.h>

#include <algorithm>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace irid::io::header {
namespace {

/// The most a TIFF compression expands its data, or nothing when irid knows no bound.
std::optional<double> max_expansion(std::uint32_t compression) {
    switch (compression) {
        case 1:  // none
            return 1.0;
        case 8:
        case 32946:  // deflate: at most 1032-fold (zlib's FAQ, "What's the maximum compression ratio?")
            return 1032.0;
        case 5:  // LZW (TIFF 6.0 §13): a code of at least 9 bits stands for at most 4096 bytes
            return 4096.0 * 8.0 / 9.0;
        case 32773:  // PackBits (TIFF 6.0 §9): two bytes repeat one byte at most 128 times
            return 64.0;
        default:
            return std::nullopt;
    }
}

const char* compression_name(std::uint32_t compression) {
    switch (compression) {
        case 1: return "uncompressed data";
        case 5: return "LZW";
        case 8:
        case 32946: return "deflate";
        case 32773: return "PackBits";
        default: return "its compression";
    }
}

class Directory {
public:
    Directory(Reader& file, bool little) : m_file(file), m_little(little) {}

    std::uint32_t u16(const unsigned char* q) const {
        return m_little ? static_cast<std::uint32_t>(q[0] | q[1] << 8) : static_cast<std::uint32_t>(q[0] << 8 | q[1]);
    }
    std::uint32_t u32(const unsigned char* q) const { return m_little ? little_endian32(q) : big_endian32(q); }

    /// Bytes of one value of a TIFF field type (TIFF 6.0 §2, "Types"), 0 for an unknown one.
    static std::uint64_t type_size(std::uint32_t type) {
        static constexpr std::uint64_t sizes[] = {0, 1, 1, 2, 4, 8, 1, 1, 2, 4, 8, 4, 8};
        return type < 13 ? sizes[type] : 0;
    }

    /// An entry's integer values (BYTE, SHORT or LONG), or nothing when they lie past the file.
    std::optional<std::vector<std::uint64_t>> integers(const unsigned char* e) const {
        const std::uint32_t type = u16(e + 2);
        const std::uint64_t count = u32(e + 4), size = type_size(type);
        if (type != 1 && type != 3 && type != 4) return std::vector<std::uint64_t>{};
        std::vector<unsigned char> bytes;
        if (count * size <= 4) {
            bytes.assign(e + 8, e + 8 + count * size);
        } else {
            bytes = read_bytes(m_file, u32(e + 8), count * size);
            if (bytes.size() != count * size) return std::nullopt;
        }
        std::vector<std::uint64_t> out(count);
        for (std::uint64_t i = 0; i < count; ++i) {
            const unsigned char* q = bytes.data() + i * size;
            out[i] = size == 1 ? q[0] : size == 2 ? u16(q) : u32(q);
        }
        return out;
    }

private:
    Reader& m_file;
    bool m_little;
};

}  // namespace

void check_tiff(const std::string& shown, Reader& file, const ImageLimits& limits, HeaderFacts& facts) {
    unsigned char head[8];
    if (!file.read(0, head, sizeof head)) return;
    const Directory dir(file, head[0] == 'I');
    const std::uint64_t ifd = dir.u32(head + 4);
    unsigned char count_bytes[2];
    if (!file.read(ifd, count_bytes, 2)) return;  // libtiff names it
    const std::uint32_t entries = dir.u16(count_bytes);

    std::uint64_t width = 0, height = 0, samples = 1, bits = 1, compression = 1;
    std::vector<std::uint64_t> offsets, counts;
    const char* unit = "strip";
    for (std::uint32_t i = 0; i < entries; ++i) {
        unsigned char e[12];
        if (!file.read(ifd + 2 + 12 * std::uint64_t{i}, e, sizeof e)) return;
        const std::uint32_t tag = dir.u16(e);
        if (tag == 34675) {  // the ICC profile (TIFF/EP, ICC.1 Annex B.3)
            const std::uint64_t size = Directory::type_size(dir.u16(e + 2)) * dir.u32(e + 4);
            const std::uint64_t at = size <= 4 ? ifd + 2 + 12 * std::uint64_t{i} + 8 : dir.u32(e + 8);
            if (size == 0 || at > file.size() || size > file.size() - at) {
                facts.icc_damage = "its ICC profile tag (34675) declares " + std::to_string(size) +
                                   " bytes at byte " + std::to_string(at) + ", and the file holds " +
                                   std::to_string(file.size());
            } else {
                check_icc(shown, read_bytes(file, at, size));
            }
            continue;
        }
        if (tag != 256 && tag != 257 && tag != 258 && tag != 259 && tag != 277 && tag != 273 &&
            tag != 279 && tag != 324 && tag != 325) {
            continue;
        }
        const std::optional<std::vector<std::uint64_t>> values = dir.integers(e);
        if (!values) {
            corrupt(shown, "its TIFF tag " + std::to_string(tag) + " declares " + std::to_string(dir.u32(e + 4)) +
                               " values at byte " + std::to_string(dir.u32(e + 8)) + ", past the file's " +
                               std::to_string(file.size()) + " bytes");
        }
        if (values->empty()) continue;  // libtiff names a wrong type
        const std::uint64_t first = values->front();
        switch (tag) {
            case 256: width = first; break;
            case 257: height = first; break;
            case 258: bits = first; break;
            case 259: compression = first; break;
            case 277: samples = first; break;
            case 273: offsets = *values; break;
            case 279: counts = *values; break;
            case 324: offsets = *values; unit = "tile"; break;
            case 325: counts = *values; unit = "tile"; break;
            default: break;
        }
    }
    if (width == 0 || height == 0) return;
    check_declared_pixels(shown, width, height, limits);

    std::uint64_t coded = 0;
    for (std::size_t i = 0; i < std::min(offsets.size(), counts.size()); ++i) {
        if (offsets[i] > file.size() || counts[i] > file.size() - offsets[i]) {
            corrupt(shown, std::string("its ") + unit + " " + std::to_string(i) + " declares " +
                               std::to_string(counts[i]) + " bytes at byte " + std::to_string(offsets[i]) +
                               ", and the file holds " + std::to_string(file.size()));
        }
        coded += counts[i];
    }
    const std::optional<double> expansion = max_expansion(static_cast<std::uint32_t>(compression));
    if (!expansion || counts.empty()) return;
    const double needed = static_cast<double>(width) * static_cast<double>(height) *
                          static_cast<double>(samples) * static_cast<double>(bits) / 8.0;
    if (needed > *expansion * static_cast<double>(coded) + 1024.0) {
        corrupt(shown, declared_size_text(width, height) + " of " + std::to_string(samples) + " samples at " +
                           std::to_string(bits) + " bits need " +
                           std::to_string(static_cast<std::uint64_t>(needed)) + " bytes, and its " +
                           std::to_string(coded) + " bytes of " + compression_name(static_cast<std::uint32_t>(compression)) +
                           " cannot hold them" +
                           (compression == 1 ? std::string()
                                             : " (they expand at most " + std::to_string(static_cast<int>(*expansion)) + "-fold)"));
    }
}

}  // namespace irid::io::header
