// A PNG's chunks read before libpng sees the file (header_reader.h): their sizes and CRCs, the
// image data against the pixels declared, the ICC profile, and the chunks that say what the
// samples mean (ISO/IEC 15948:2004, and PNG Third Edition (W3C, 2025) for cICP).
#include "header_reader.h"

#include <irid/error.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include <zlib.h>

namespace irid::io::header {
namespace {

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

/// The CRC of a chunk (ISO/IEC 15948 §5.3: over its type and data) against the one it stores.
bool crc_matches(Reader& file, std::uint64_t pos, std::uint64_t length) {
    unsigned char piece[1 << 15];
    uLong crc = crc32(0L, Z_NULL, 0);
    for (std::uint64_t done = 0; done < length + 4;) {
        const auto n = static_cast<std::size_t>(std::min<std::uint64_t>(sizeof piece, length + 4 - done));
        if (!file.read(pos + 4 + done, piece, n)) return false;
        crc = crc32(crc, piece, static_cast<uInt>(n));
        done += n;
    }
    unsigned char stored[4];
    return file.read(pos + 8 + length, stored, 4) && big_endian32(stored) == static_cast<std::uint32_t>(crc);
}

/// The colour chunks (§11.3.3): each once, before the image data, of its own length.
void read_colour_chunk(const std::string& shown, Reader& file, const std::string& type, std::uint64_t pos,
                       std::uint64_t length, bool after_data, HeaderFacts& facts) {
    static constexpr struct {
        const char* type;
        std::uint64_t length;
    } sizes[] = {{"gAMA", 4}, {"cHRM", 32}, {"sRGB", 1}, {"cICP", 4}};
    const auto* it = std::find_if(std::begin(sizes), std::end(sizes), [&](const auto& s) { return type == s.type; });
    if (it == std::end(sizes)) return;
    const std::string where = "its " + type + " chunk at byte " + std::to_string(pos);
    if (length != it->length) {
        corrupt(shown, where + " holds " + std::to_string(length) + " bytes; it holds " + std::to_string(it->length));
    }
    if (after_data) corrupt(shown, where + " follows the image data, which it must precede");
    if (facts.png_colour_chunks.find(type) != std::string::npos) corrupt(shown, where + " repeats an earlier one");
    facts.png_colour_chunks += (facts.png_colour_chunks.empty() ? "" : " ") + type;
    unsigned char v[32];
    if (!file.read(pos + 8, v, static_cast<std::size_t>(length))) return;
    if (type == "gAMA") {
        const std::uint32_t g = big_endian32(v);
        if (g == 0) corrupt(shown, where + " gives a gamma of 0");
        facts.png_gamma = g / 100000.0;
    } else if (type == "cHRM") {
        // White, red, green, blue x, y, each times 100000; irid's order is red, green, blue, white.
        static constexpr int order[] = {2, 3, 4, 5, 6, 7, 0, 1};
        for (int k : order) facts.png_chromaticities.push_back(static_cast<float>(big_endian32(v + 4 * k) / 100000.0));
    } else if (type == "sRGB") {
        facts.png_srgb = true;
    } else {
        facts.png_cicp.assign(v, v + 4);
    }
}

/// PNG (ISO/IEC 15948): every chunk must fit in the file, and the image data (IDAT) must be able
/// to hold the pixels the header (IHDR) declares.
}  // namespace

void check_png(const std::string& shown, Reader& file, const ImageLimits& limits, HeaderFacts& facts) {
    std::uint64_t pos = 8, idat_bytes = 0;
    std::uint64_t width = 0, height = 0;
    unsigned depth = 0, colour_type = 0;
    bool have_header = false;
    unsigned char head[8];
    // The chunks' lengths first, over the whole file (a length past the file is the damage that
    // costs memory), then each chunk's CRC and content.
    for (std::uint64_t at = 8; file.read(at, head, sizeof head);) {
        const std::uint64_t length = big_endian32(head);
        const std::uint64_t left = file.size() - at - 8;  // data and CRC
        if (length + 4 > left) {
            corrupt(shown, "its " + printable(head + 4, 4) + " chunk at byte " + std::to_string(at) + " declares " +
                               std::to_string(length) + " bytes, and " +
                               std::to_string(left >= 4 ? left - 4 : 0) + " remain");
        }
        if (printable(head + 4, 4) == "IEND") break;
        at += 12 + length;
    }
    bool ended = false, data_seen = false;
    while (file.read(pos, head, sizeof head)) {
        const std::uint64_t length = big_endian32(head);
        const std::string type = printable(head + 4, 4);
        if (!crc_matches(file, pos, length)) {
            corrupt(shown, "its " + type + " chunk at byte " + std::to_string(pos) + " fails its CRC");
        }
        read_colour_chunk(shown, file, type, pos, length, data_seen, facts);
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
            data_seen = true;
        } else if (type == "iCCP") {
            facts.png_icc_chunk = true;
            check_png_icc(shown, file, pos + 8, length);
        } else if (type == "IEND") {
            ended = true;
            break;
        }
        pos += 12 + length;
    }
    if (!have_header || width == 0 || height == 0) return;  // the decoder names what is wrong
    if (!ended) corrupt(shown, "it ends at byte " + std::to_string(pos) + " without its IEND chunk");
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


}  // namespace irid::io::header
