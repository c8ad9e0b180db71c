// A TIFF's first directory read before libtiff sees the file (header_reader.h): classic TIFF
// (TIFF 6.0) and BigTIFF (8-byte offsets and counts).
//
// libtiff trusts a directory's strip (or tile) offsets and byte counts, and OpenImageIO fills
// what a strip lacks with black. The directory says how many bytes the image data take and how
// many the pixels need; a compression expands its data by at most a known factor, so a file of a
// few hundred bytes cannot declare gigabytes of pixels. The offset and count arrays are read as
// streams (they may hold a value per byte of the file), never stored.
#include "header_reader.h"

#include <irid/error.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace irid::io::header {
namespace {

/// A TIFF compression irid bounds: the most it expands its data, and its name for messages.
struct Expansion {
    double factor;
    const char* name;
};

/// Nothing for a compression irid knows no bound of.
std::optional<Expansion> max_expansion(std::uint64_t compression) {
    switch (compression) {
        case 1:
            return Expansion{1.0, "uncompressed data"};
        case 8:
        case 32946:  // deflate: at most 1032-fold (zlib's FAQ, "What's the maximum compression ratio?")
            return Expansion{1032.0, "deflate"};
        case 5:  // LZW (TIFF 6.0 §13): a code of at least 9 bits stands for at most 4096 bytes
            return Expansion{4096.0 * 8.0 / 9.0, "LZW"};
        case 32773:  // PackBits (TIFF 6.0 §9): two bytes repeat one byte at most 128 times
            return Expansion{64.0, "PackBits"};
        default:
            return std::nullopt;
    }
}

/// Bytes of one value of a TIFF field type (TIFF 6.0 §2 and BigTIFF's 16-18), 0 for an unknown one.
std::uint64_t type_size(std::uint32_t type) {
    static constexpr std::uint64_t sizes[] = {0, 1, 1, 2, 4, 8, 1, 1, 2, 4, 8, 4, 8, 4, 0, 0, 8, 8, 8};
    return type < 19 ? sizes[type] : 0;
}

/// The integer types (BYTE, SHORT, LONG, SBYTE, SSHORT, SLONG, IFD, LONG8, SLONG8, IFD8).
bool is_integer_type(std::uint32_t type) {
    return type == 1 || type == 3 || type == 4 || type == 6 || type == 8 || type == 9 || type == 13 ||
           type == 16 || type == 17 || type == 18;
}
bool is_signed_type(std::uint32_t type) { return type == 6 || type == 8 || type == 9 || type == 17; }

/// The layout of a directory entry: classic TIFF (12 bytes, 4-byte count and value) or BigTIFF
/// (20 bytes, 8-byte count and value).
struct Layout {
    bool little = true;
    bool big = false;

    [[nodiscard]] std::uint64_t uint(const unsigned char* q, int bytes) const {
        std::uint64_t v = 0;
        for (int i = 0; i < bytes; ++i) {
            const std::uint64_t b = q[little ? i : bytes - 1 - i];
            v |= b << (8 * i);
        }
        return v;
    }
    [[nodiscard]] int entry_size() const { return big ? 20 : 12; }
    [[nodiscard]] int field_size() const { return big ? 8 : 4; }
    [[nodiscard]] std::uint64_t count(const unsigned char* e) const { return uint(e + 4, field_size()); }
    [[nodiscard]] const unsigned char* value(const unsigned char* e) const { return e + 4 + field_size(); }
};

/// One entry's integer values, read one at a time from the entry or from the file.
class Values {
public:
    /// `reader` reads the file (a reader of its own per array read side by side with another).
    Values(const Layout& layout, Reader& reader, const unsigned char* entry, std::uint64_t entry_at)
        : m_layout(layout),
          m_type(static_cast<std::uint32_t>(layout.uint(entry + 2, 2))),
          m_count(layout.count(entry)),
          m_size(type_size(m_type)),
          m_reader(reader) {
        const std::uint64_t bytes = m_count * m_size;
        const bool inline_values = m_size != 0 && m_count <= 64 && bytes <= static_cast<std::uint64_t>(layout.field_size());
        m_at = inline_values ? entry_at + 4 + static_cast<std::uint64_t>(layout.field_size())
                             : layout.uint(layout.value(entry), layout.field_size());
    }
    [[nodiscard]] bool integers() const { return is_integer_type(m_type) && m_size != 0; }
    [[nodiscard]] std::uint64_t count() const { return m_count; }
    [[nodiscard]] std::uint64_t at() const { return m_at; }
    /// The bytes the values take (count × size).
    [[nodiscard]] std::uint64_t bytes() const { return m_count * m_size; }
    /// The values lie inside the file (count × size bytes from at()).
    [[nodiscard]] bool inside() const {
        return m_count <= m_reader.size() && m_at <= m_reader.size() && m_count * m_size <= m_reader.size() - m_at;
    }
    /// The i-th value (i < count(), inside()); a negative signed one as nothing.
    [[nodiscard]] std::optional<std::uint64_t> get(std::uint64_t i) {
        unsigned char q[8];
        if (!m_reader.read(m_at + i * m_size, q, static_cast<std::size_t>(m_size))) return std::nullopt;
        const std::uint64_t v = m_layout.uint(q, static_cast<int>(m_size));
        if (is_signed_type(m_type) && (v >> (8 * m_size - 1)) != 0) return std::nullopt;
        return v;
    }

private:
    Layout m_layout;
    std::uint32_t m_type;
    std::uint64_t m_count;
    std::uint64_t m_size;
    Reader& m_reader;
    std::uint64_t m_at = 0;
};

/// Bytes of the file that are not image data: its header, its directory, arrays the directory
/// points at.
struct Reserved {
    std::uint64_t offset;
    std::uint64_t count;
    const char* what;
};

std::string byte_range(std::uint64_t offset, std::uint64_t count) {
    return "bytes " + std::to_string(offset) + " to " + std::to_string(offset + count - 1);
}

/// Throws when two strips (tiles) share bytes, or a strip lies on the header or the directory:
/// libtiff decodes whatever an offset points at, so a small file whose strips all point at one
/// stream could declare gigabytes of pixels past the bound on the coded bytes.
void check_no_overlap(const std::string& shown, const std::vector<CodedUnit>& units, const char* unit,
                      const std::vector<Reserved>& reserved) {
    std::vector<std::size_t> order;
    order.reserve(units.size());
    for (std::size_t i = 0; i < units.size(); ++i) {
        if (units[i].count > 0) order.push_back(i);
    }
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        return units[a].offset < units[b].offset || (units[a].offset == units[b].offset && a < b);
    });
    for (std::size_t k = 1; k < order.size(); ++k) {
        const CodedUnit& before = units[order[k - 1]];
        const CodedUnit& after = units[order[k]];
        if (before.offset + before.count > after.offset) {
            corrupt(shown, std::string("its ") + unit + " " + std::to_string(order[k]) + " (" +
                               byte_range(after.offset, after.count) + ") overlaps its " + unit + " " +
                               std::to_string(order[k - 1]) + " (" + byte_range(before.offset, before.count) + ")");
        }
    }
    for (const Reserved& r : reserved) {
        if (r.count == 0) continue;
        // The first unit that ends past r's start; sorted by offset, and disjoint, units also end in order.
        const auto it = std::partition_point(order.begin(), order.end(), [&](std::size_t i) {
            return units[i].offset + units[i].count <= r.offset;
        });
        if (it != order.end() && units[*it].offset < r.offset + r.count) {
            corrupt(shown, std::string("its ") + unit + " " + std::to_string(*it) + " (" +
                               byte_range(units[*it].offset, units[*it].count) + ") lies on " + r.what + " (" +
                               byte_range(r.offset, r.count) + ")");
        }
    }
}

/// The bytes each strip (tile) decodes to, as libtiff counts them (tif_strip.c, TIFFVStripSize
/// and TIFFVTileSize): whole rows of the unit, the last strip of a plane holding what rows
/// remain; subsampled YCbCr (TIFF 6.0 §21) stores each block of h × v pixels as h v luma and 2
/// chroma samples. Units past those the image needs, and layouts irid cannot size, stay 0.
void set_decoded_sizes(std::vector<CodedUnit>& units, std::uint64_t width, std::uint64_t height,
                       std::uint64_t samples, std::uint64_t bits, std::uint64_t planar, std::uint64_t sub_h,
                       std::uint64_t sub_v, std::uint64_t unit_width, std::uint64_t unit_rows, bool tiled) {
    if (bits == 0 || bits > 64 || samples == 0 || samples > 64 || unit_width == 0 || unit_rows == 0) return;
    const bool separate = planar == 2;
    const std::uint64_t per_unit = separate ? 1 : samples;
    const bool subsampled = !separate && samples == 3 && (sub_h > 1 || sub_v > 1);
    const auto ceil_div = [](std::uint64_t a, std::uint64_t b) { return (a + b - 1) / b; };
    const auto size = [&](std::uint64_t rows) -> std::uint64_t {
        if (subsampled) {
            const std::uint64_t row_samples = ceil_div(unit_width, sub_h) * (sub_h * sub_v + 2);
            return ceil_div(rows, sub_v) * ceil_div(row_samples * bits, 8);
        }
        return rows * ceil_div(unit_width * per_unit * bits, 8);
    };
    const std::uint64_t down = ceil_div(height, std::min(unit_rows, height));
    const std::uint64_t across = tiled ? ceil_div(width, unit_width) : 1;
    const std::uint64_t per_plane = down * across;
    const std::uint64_t needed = per_plane * (separate ? samples : 1);
    for (std::uint64_t i = 0; i < units.size() && i < needed; ++i) {
        const std::uint64_t row = (i % per_plane) / across;
        const std::uint64_t rows = tiled ? unit_rows : std::min(unit_rows, height - row * std::min(unit_rows, height));
        units[i].expected = size(rows);
    }
}

/// The predictor a compressed TIFF declares, as libtiff's PredictorSetup (tif_predict.c) takes
/// it before decoding the first strip, which OpenImageIO ignores: horizontal differencing (2) of
/// 8, 16, 32 or 64-bit samples, floating-point (3) of IEEE floats of 16, 24, 32 or 64 bits.
void check_predictor(const std::string& shown, std::uint64_t compression, std::uint64_t predictor, std::uint64_t bits,
                     std::uint64_t sample_format) {
    const bool predicted = compression == 5 || compression == 8 || compression == 32946;  // LZW, deflate
    if (!predicted || predictor == 1) return;
    if (predictor == 2 && (bits == 8 || bits == 16 || bits == 32 || bits == 64)) return;
    if (predictor == 3 && sample_format == 3 && (bits == 16 || bits == 24 || bits == 32 || bits == 64)) return;
    corrupt(shown, "its predictor " + std::to_string(predictor) + " cannot apply to " + std::to_string(bits) +
                       "-bit samples of format " + std::to_string(sample_format) +
                       " (libtiff takes horizontal differencing, 2, of 8, 16, 32 or 64 bits, and floating-point "
                       "prediction, 3, of 16, 24, 32 or 64-bit floats)");
}

/// The ICC profile tag: its bytes as stored, whatever their integer type (a writer may type them
/// UNDEFINED, BYTE or LONG; libtiff keeps only the first two). A tag past the file, of a
/// non-integer type, or a second tag holding another profile is damage (facts.icc_damage).
void read_icc_tag(const std::string& shown, Reader& file, const Values& values, std::uint32_t type,
                  HeaderFacts& facts) {
    if (!facts.icc_damage.empty()) return;
    const std::uint64_t size = type_size(type) * values.count();
    if (size == 0 || values.count() > file.size() || !values.inside()) {
        facts.icc_damage = "its ICC profile tag (34675) declares " +
                           (values.count() > file.size() ? std::to_string(values.count()) + " values"
                                                         : std::to_string(size) + " bytes") +
                           " at byte " + std::to_string(values.at()) + ", and the file holds " +
                           std::to_string(file.size());
        return;
    }
    if (!is_integer_type(type) && type != 7) {
        facts.icc_damage = "its ICC profile tag (34675) is of TIFF type " + std::to_string(type) +
                           ", not bytes or integers";
        facts.container_icc_profile.clear();
        return;
    }
    std::vector<unsigned char> profile = read_bytes(file, values.at(), size);
    check_icc(shown, profile);
    if (!facts.container_icc_profile.empty() && facts.container_icc_profile != profile) {
        facts.icc_damage = "its directory holds two ICC profile tags (34675) with different profiles (" +
                           std::to_string(facts.container_icc_profile.size()) + " and " +
                           std::to_string(profile.size()) + " bytes)";
        facts.container_icc_profile.clear();
        return;
    }
    facts.container_icc_profile = std::move(profile);
}

}  // namespace

void check_tiff(const std::string& shown, Reader& file, const ImageLimits& limits, HeaderFacts& facts) {
    unsigned char head[16];
    if (!file.read(0, head, 8)) return;
    Layout layout;
    layout.little = head[0] == 'I';
    layout.big = layout.uint(head + 2, 2) == 43;
    std::uint64_t ifd = 0;
    if (layout.big) {
        if (!file.read(0, head, 16)) return;
        ifd = layout.uint(head + 8, 8);
    } else {
        ifd = layout.uint(head + 4, 4);
    }
    unsigned char count_bytes[8];
    const int count_size = layout.big ? 8 : 2;
    if (!file.read(ifd, count_bytes, static_cast<std::size_t>(count_size))) return;  // libtiff names it
    const std::uint64_t entries = layout.uint(count_bytes, count_size);
    const std::uint64_t first = ifd + static_cast<std::uint64_t>(count_size);

    std::uint64_t width = 0, height = 0, samples = 1, bits = 1, compression = 1, photometric = 2;
    std::uint64_t sub_h = 2, sub_v = 2;  // YCbCrSubsampling's default (TIFF 6.0 §21)
    std::uint64_t rows_per_strip = UINT32_MAX, planar = 1, tile_width = 0, tile_length = 0;
    std::uint64_t predictor = 1, sample_format = 1;
    std::optional<std::uint64_t> offsets_entry, counts_entry;
    const char* unit = "strip";
    unsigned char e[20];
    for (std::uint64_t i = 0; i < entries; ++i) {
        const std::uint64_t at = first + static_cast<std::uint64_t>(layout.entry_size()) * i;
        if (!file.read(at, e, static_cast<std::size_t>(layout.entry_size()))) return;
        const auto tag = static_cast<std::uint32_t>(layout.uint(e, 2));
        Values values(layout, file, e, at);
        if (tag == 34675) {  // the ICC profile (TIFF/EP, ICC.1 Annex B.3)
            read_icc_tag(shown, file, values, static_cast<std::uint32_t>(layout.uint(e + 2, 2)), facts);
            continue;
        }
        const bool array = tag == 273 || tag == 279 || tag == 324 || tag == 325;
        const bool scalar = tag == 256 || tag == 257 || tag == 258 || tag == 259 || tag == 262 || tag == 277 ||
                            tag == 278 || tag == 284 || tag == 317 || tag == 322 || tag == 323 || tag == 339 ||
                            tag == 530;
        if (!array && !scalar) continue;
        if (!values.integers() || values.count() == 0) continue;  // libtiff names a wrong type
        if (!values.inside()) {
            corrupt(shown, "its TIFF tag " + std::to_string(tag) + " declares " + std::to_string(values.count()) +
                               " values at byte " + std::to_string(values.at()) + ", past the file's " +
                               std::to_string(file.size()) + " bytes");
        }
        if (array) {
            (tag == 273 || tag == 324 ? offsets_entry : counts_entry) = at;
            if (tag == 324 || tag == 325) unit = "tile";
            continue;
        }
        const std::optional<std::uint64_t> v = values.get(0);
        if (!v) continue;
        switch (tag) {
            case 256: width = *v; break;
            case 257: height = *v; break;
            case 258: bits = *v; break;
            case 259: compression = *v; break;
            case 262: photometric = *v; break;
            case 277: samples = *v; break;
            case 278: rows_per_strip = *v; break;
            case 284: planar = *v; break;
            case 317: predictor = *v; break;
            case 339: sample_format = *v; break;
            case 322: tile_width = *v; break;
            case 323: tile_length = *v; break;
            case 530:
                sub_h = std::max<std::uint64_t>(*v, 1);
                if (const auto w = values.count() > 1 ? values.get(1) : std::nullopt) sub_v = std::max<std::uint64_t>(*w, 1);
                break;
            default: break;
        }
    }
    if (width == 0 || height == 0) return;
    check_declared_pixels(shown, width, height, limits);
    check_predictor(shown, compression, predictor, bits, sample_format);
    if (!offsets_entry || !counts_entry) return;

    // Every strip (or tile) inside the file, its bytes summed, both arrays read side by side.
    Reader offsets_file(file.fd(), file.size()), counts_file(file.fd(), file.size());
    unsigned char offsets_bytes[20], counts_bytes[20];
    if (!file.read(*offsets_entry, offsets_bytes, static_cast<std::size_t>(layout.entry_size())) ||
        !file.read(*counts_entry, counts_bytes, static_cast<std::size_t>(layout.entry_size()))) {
        return;
    }
    Values offsets(layout, offsets_file, offsets_bytes, *offsets_entry);
    Values counts(layout, counts_file, counts_bytes, *counts_entry);
    std::uint64_t coded = 0;
    const std::uint64_t n = std::min(offsets.count(), counts.count());
    std::vector<CodedUnit> units;  // at most one per 2 bytes of the file (inside() above)
    units.reserve(static_cast<std::size_t>(n));
    for (std::uint64_t i = 0; i < n; ++i) {
        const std::optional<std::uint64_t> offset = offsets.get(i), count = counts.get(i);
        if (!offset || !count) {
            corrupt(shown, std::string("its ") + unit + " " + std::to_string(i) + " has a negative offset or byte count");
        }
        if (*offset > file.size() || *count > file.size() - *offset) {
            corrupt(shown, std::string("its ") + unit + " " + std::to_string(i) + " declares " +
                               std::to_string(*count) + " bytes at byte " + std::to_string(*offset) +
                               ", and the file holds " + std::to_string(file.size()));
        }
        coded += *count;
        units.push_back(CodedUnit{*offset, *count, 0});
    }
    // The file's header and directory, and the arrays outside it, are no image data.
    const std::uint64_t directory_end = first + static_cast<std::uint64_t>(layout.entry_size()) * entries +
                                        static_cast<std::uint64_t>(layout.field_size());
    check_no_overlap(shown, units, unit,
                     {{0, layout.big ? 16u : 8u, "the file's header"},
                      {ifd, directory_end - ifd, "its directory"},
                      {offsets.at(), offsets.bytes(), "its offsets array"},
                      {counts.at(), counts.bytes(), "its byte-count array"}});
    const std::optional<Expansion> expansion = max_expansion(compression);
    if (!expansion || n == 0) return;
    // Bytes the pixels take uncompressed; subsampled YCbCr (photometric 6) stores each block of
    // h × v pixels as h v luma and 2 chroma samples (TIFF 6.0 §21).
    const auto w = static_cast<double>(width), h = static_cast<double>(height);
    const double bytes_per_sample = static_cast<double>(bits) / 8.0;
    const bool subsampled = photometric == 6 && samples == 3 && (sub_h > 1 || sub_v > 1);
    const double needed = subsampled
                              ? std::ceil(w / static_cast<double>(sub_h)) * std::ceil(h / static_cast<double>(sub_v)) *
                                    static_cast<double>(sub_h * sub_v + 2) * bytes_per_sample
                              : w * h * static_cast<double>(samples) * bytes_per_sample;
    if (needed > expansion->factor * static_cast<double>(coded) + 1024.0) {
        corrupt(shown, declared_size_text(width, height) + " of " + std::to_string(samples) + " samples at " +
                           std::to_string(bits) + " bits need " +
                           std::to_string(static_cast<std::uint64_t>(needed)) + " bytes, and its " +
                           std::to_string(coded) + " bytes of " + expansion->name +
                           " cannot hold them" +
                           (compression == 1 ? std::string()
                                             : " (they expand at most " + std::to_string(static_cast<int>(expansion->factor)) + "-fold)"));
    }
    // The bound above is cheap; inflating every strip is not.
    if (compression == 8 || compression == 32946) {
        const bool tiled = tile_width > 0 && tile_length > 0;
        set_decoded_sizes(units, width, height, samples, bits, planar, photometric == 6 ? sub_h : 1,
                          photometric == 6 ? sub_v : 1, tiled ? tile_width : width,
                          tiled ? tile_length : rows_per_strip, tiled);
        check_deflate_units(shown, file, units, unit);
    }
}

}  // namespace irid::io::header
