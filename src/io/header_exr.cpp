// An OpenEXR file's header(s) and chunk table read before OpenEXR sees the file
// (header_reader.h; the layout of openexr.com, "OpenEXR File Layout").
#include "header_reader.h"

#include <irid/error.h>

#include <algorithm>
#include <cstdint>
#include <optional>
#include <string>

namespace irid::io::header {
namespace {

/// What the first part's header says about its chunks.
struct ExrLayout {
    std::int64_t x0 = 0, y0 = 0, x1 = -1, y1 = -1;  // the data window
    int compression = -1;
    bool tiled = false;
    std::uint32_t tile_w = 0, tile_h = 0;
    int level_mode = -1;  // 0: one level
    bool has_window = false;
};

/// Scanlines per chunk by compression (OpenEXR's ImfCompression.h): none, RLE, ZIPS 1; ZIP and
/// PXR24 16; PIZ, B44, B44A and DWAA 32; DWAB 256.
int lines_per_chunk(int compression) {
    static constexpr int lines[] = {1, 1, 1, 16, 32, 16, 32, 32, 32, 256};
    return compression >= 0 && compression < 10 ? lines[compression] : 0;
}

/// The chunk table of a single-part scanline or single-level tiled file: every chunk inside the
/// file, after the table, starting with the coordinates of its place in the image and a size that
/// fits. OpenEXR reads a file whose table points elsewhere as incomplete, and OpenImageIO 2.4 then
/// passes on the lines it could not find as zeros.
void check_chunk_table(const std::string& shown, Reader& file, std::uint64_t table, const ExrLayout& l) {
    const std::int64_t width = l.x1 - l.x0 + 1, height = l.y1 - l.y0 + 1;
    if (!l.has_window || width < 1 || height < 1 || l.compression < 0) return;
    std::uint64_t chunks = 0;
    std::int64_t across = 1, lines = 1;
    if (l.tiled) {
        if (l.level_mode != 0 || l.tile_w == 0 || l.tile_h == 0) return;  // mipmaps: not checked
        across = (width + l.tile_w - 1) / l.tile_w;
        chunks = static_cast<std::uint64_t>(across * ((height + l.tile_h - 1) / l.tile_h));
    } else {
        lines = lines_per_chunk(l.compression);
        if (lines == 0) return;
        chunks = static_cast<std::uint64_t>((height + lines - 1) / lines);
    }
    const std::uint64_t table_end = table + 8 * chunks;
    if (table_end > file.size()) {
        corrupt(shown, "its table of " + std::to_string(chunks) + " chunks runs past the file's " +
                           std::to_string(file.size()) + " bytes");
    }
    const int head = l.tiled ? 20 : 8;  // tile x, y, level x, y and size; or line y and size
    for (std::uint64_t i = 0; i < chunks; ++i) {
        unsigned char v[8], c[20];
        if (!file.read(table + 8 * i, v, 8)) return;
        const std::uint64_t at = static_cast<std::uint64_t>(little_endian32(v)) |
                                 static_cast<std::uint64_t>(little_endian32(v + 4)) << 32;
        const std::string which = "its chunk " + std::to_string(i);
        if (at < table_end || at > file.size() || file.size() - at < static_cast<std::uint64_t>(head)) {
            corrupt(shown, which + " lies at byte " + std::to_string(at) + ", outside the data (bytes " +
                               std::to_string(table_end) + " to " + std::to_string(file.size()) + ")");
        }
        if (!file.read_unbuffered(at, c, static_cast<std::size_t>(head))) return;
        const auto int32 = [&](int k) { return static_cast<std::int64_t>(static_cast<std::int32_t>(little_endian32(c + k))); };
        const std::uint64_t size = little_endian32(c + head - 4);
        if (size > file.size() - at - static_cast<std::uint64_t>(head)) {
            corrupt(shown, which + " at byte " + std::to_string(at) + " declares " + std::to_string(size) +
                               " bytes, past the end of the file");
        }
        if (l.tiled) {
            const auto tx = static_cast<std::int64_t>(i) % across, ty = static_cast<std::int64_t>(i) / across;
            if (int32(0) != tx || int32(4) != ty || int32(8) != 0 || int32(12) != 0) {
                corrupt(shown, which + " at byte " + std::to_string(at) + " holds tile " + std::to_string(int32(0)) +
                                   ", " + std::to_string(int32(4)) + " where tile " + std::to_string(tx) + ", " +
                                   std::to_string(ty) + " belongs");
            }
        } else if (const std::int64_t y = l.y0 + static_cast<std::int64_t>(i) * lines; int32(0) != y) {
            corrupt(shown, which + " at byte " + std::to_string(at) + " holds line " + std::to_string(int32(0)) +
                               " where line " + std::to_string(y) + " belongs");
        }
    }
}

/// OpenEXR (the file layout of openexr.com, "OpenEXR File Layout"): every attribute of the
/// header(s) must fit in the file, and the first part's data window within the limits.
}  // namespace

void check_exr(const std::string& shown, Reader& file, const ImageLimits& limits) {
    unsigned char version[4];
    if (!file.read(4, version, sizeof version)) return;
    const bool multipart = (version[1] & 0x10) != 0;  // flag bit 12
    const bool deep = (version[1] & 0x08) != 0;       // flag bit 11
    ExrLayout layout;
    layout.tiled = (version[1] & 0x02) != 0;          // flag bit 9: a single-part tiled file
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
            if (!multipart && !deep) check_chunk_table(shown, file, pos, layout);
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
                layout.x0 = signed32(0);
                layout.y0 = signed32(4);
                layout.x1 = signed32(8);
                layout.y1 = signed32(12);
                layout.has_window = true;
            }
        } else if (part == 0 && name == "compression" && type == "compression" && size == 1) {
            unsigned char c = 0;
            if (file.read(after_type + 4, &c, 1)) layout.compression = c;
        } else if (part == 0 && name == "tiles" && type == "tiledesc" && size == 9) {
            unsigned char t[9];
            if (file.read(after_type + 4, t, sizeof t)) {
                layout.tile_w = little_endian32(t);
                layout.tile_h = little_endian32(t + 4);
                layout.level_mode = t[8] & 0x0F;
            }
        }
        pos = after_type + 4 + size;
    }
}

}  // namespace irid::io::header
