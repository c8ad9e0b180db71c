// A JPEG's markers read before libjpeg sees the file (header_reader.h).
//
// libjpeg allocates what the frame header declares when decoding starts (a progressive file's
// whole coefficient buffer at once), and fills with grey whatever a file cut short lacks. With
// Huffman coding every 8 × 8 block of every component costs at least one bit in the first scan
// that holds it (a DC difference's code is at least one bit long, and progressive end-of-band
// runs cover AC coefficients only), so the coded data bound the blocks a file can hold.
#include "header_reader.h"

#include <irid/error.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace irid::io::header {
namespace {

struct Frame {
    unsigned marker = 0;
    std::uint64_t width = 0, height = 0;
    /// Horizontal and vertical sampling factors, one pair per component.
    std::vector<std::pair<unsigned, unsigned>> sampling;
};

bool is_frame_marker(unsigned m) noexcept {
    // SOF0–SOF15 (T.81 Table B.1) except DHT (C4), JPG (C8) and DAC (CC).
    return m >= 0xC0 && m <= 0xCF && m != 0xC4 && m != 0xC8 && m != 0xCC;
}

bool is_arithmetic(unsigned m) noexcept { return m >= 0xC9; }
bool is_lossless(unsigned m) noexcept { return m == 0xC3 || m == 0xC7 || m == 0xCB || m == 0xCF; }

/// The least number of coded bits a Huffman-coded frame needs: one per block of a DCT frame
/// (T.81 A.2.4: a component's blocks cover its sampled size rounded up to 8), one per sample of
/// a lossless one.
std::uint64_t least_coded_bits(const Frame& f) {
    unsigned h_max = 1, v_max = 1;
    for (const auto& [h, v] : f.sampling) {
        h_max = std::max(h_max, h);
        v_max = std::max(v_max, v);
    }
    std::uint64_t units = 0;
    for (const auto& [h, v] : f.sampling) {
        const std::uint64_t w = (f.width * h + h_max - 1) / h_max;
        const std::uint64_t rows = (f.height * v + v_max - 1) / v_max;
        units += is_lossless(f.marker) ? w * rows : ((w + 7) / 8) * ((rows + 7) / 8);
    }
    return units;
}

std::string sequence_text(const std::vector<std::pair<unsigned, unsigned>>& chunks) {
    std::string s;
    for (const auto& [sequence, count] : chunks) {
        if (!s.empty()) s += ", ";
        s += std::to_string(sequence) + " of " + std::to_string(count);
    }
    return s;
}

std::string hex_byte(unsigned v) {
    static constexpr char hex[] = "0123456789ABCDEF";
    return std::string{hex[(v >> 4) & 15], hex[v & 15]};
}

/// After the first scan, up to EOI, which must be there: a second frame header (SOF) is what libjpeg's
/// jpeg_finish_decompress stops at ("Invalid JPEG file structure: two SOF markers"), which
/// OpenImageIO 2.4 never calls, so a file whose coded data run on into the headers of another
/// image, decoding as garbage, read as whole. Stuffed bytes (FF 00), restart markers and fill
/// bytes are skipped; so is every segment by its length (the DHT, DQT, DRI and SOS of later scans).
/// A later scan, unless `more_scans`, is what libjpeg stops at too.
void check_after_first_scan(const std::string& shown, Reader& file, std::uint64_t from, bool more_scans) {
    unsigned char chunk[1 << 15];
    std::uint64_t pos = from;
    while (pos + 1 < file.size()) {
        const auto n = static_cast<std::size_t>(std::min<std::uint64_t>(sizeof chunk, file.size() - pos));
        if (!file.read(pos, chunk, n)) break;
        const auto* ff = static_cast<const unsigned char*>(std::memchr(chunk, 0xFF, n));
        if (ff == nullptr) {
            pos += n;
            continue;
        }
        pos += static_cast<std::uint64_t>(ff - chunk);
        unsigned char m[4];
        if (!file.read(pos, m, 2)) break;
        const unsigned marker = m[1];
        if (marker == 0x00 || marker == 0xFF || marker == 0x01 || (marker >= 0xD0 && marker <= 0xD7)) {
            pos += marker == 0xFF ? 1 : 2;
            continue;
        }
        if (marker == 0xD9) return;  // EOI
        // What libjpeg's read_markers knows after a scan (jdmarker.c): frame headers (refused
        // below), DHT, DAC, RSTn, SOS, DQT, DNL, DRI, APPn, COM and TEM; any other stops it
        // ("Unsupported marker type"), and so does a second SOI.
        const bool known = (marker >= 0xC0 && marker <= 0xCF) || (marker >= 0xDA && marker <= 0xDD) ||
                           (marker >= 0xE0 && marker <= 0xEF) || marker == 0xFE;
        if (!known) {
            corrupt(shown, "a marker libjpeg does not know after a scan (0x" + hex_byte(marker) + ") at byte " +
                               std::to_string(pos) + " (libjpeg: " +
                               (marker == 0xD8 ? "two SOI markers" : "unsupported marker type") + ")");
        }
        if (is_frame_marker(marker)) {
            corrupt(shown, "a second frame header (marker 0x" + hex_byte(marker) + ") at byte " + std::to_string(pos) +
                               ", after the image's first scan (libjpeg: two SOF markers)");
        }
        if (marker == 0xDA && !more_scans) {
            corrupt(shown, "a second scan at byte " + std::to_string(pos) +
                               " of an image whose first scan holds every component (libjpeg: didn't expect more "
                               "than one scan)");
        }
        if (!file.read(pos, m, 4)) break;
        const std::uint64_t length = static_cast<std::uint64_t>(m[2]) << 8 | m[3];
        pos += 2 + std::max<std::uint64_t>(length, 2);
    }
    // No EOI: libjpeg's "Premature end of JPEG file", which OpenImageIO reports only while rows
    // remain to be read (an arithmetic-coded file's last rows can be read before it).
    corrupt(shown, "it ends at byte " + std::to_string(file.size()) + " without its EOI marker (libjpeg: premature end "
                                                                        "of JPEG file)");
}

}  // namespace

void check_jpeg(const std::string& shown, Reader& file, const ImageLimits& limits, HeaderFacts& facts) {
    Frame frame;
    std::uint64_t first_scan = 0;
    // APP2 "ICC_PROFILE\0" chunks: (sequence number, count) and the data, in file order.
    std::vector<std::pair<unsigned, unsigned>> chunk_numbers;
    std::string short_segment;  // an ICC_PROFILE segment too short for its header
    unsigned first_scan_components = 0;
    std::vector<std::vector<unsigned char>> chunk_data;
    std::uint64_t pos = 2;
    unsigned char m[4];
    while (first_scan == 0 && file.read(pos, m, 2)) {
        // Between segments libjpeg skips any bytes up to the next marker (next_marker(), with
        // only a warning): so does this, or one stray byte would hide the frame header.
        if (m[0] != 0xFF || m[1] == 0x00) {
            ++pos;
            continue;
        }
        const unsigned marker = m[1];
        if (marker == 0xFF) {  // a fill byte
            ++pos;
            continue;
        }
        if (marker == 0xD9) break;  // the end of the image, before any scan
        if (marker == 0x01 || (marker >= 0xD0 && marker <= 0xD8)) {
            pos += 2;
            continue;
        }
        if (!file.read(pos, m, 4)) break;
        const std::uint64_t length = static_cast<std::uint64_t>(m[2]) << 8 | m[3];
        if (length < 2) break;  // libjpeg names it
        if (is_frame_marker(marker) && frame.marker == 0 && length >= 8) {
            const std::vector<unsigned char> sof = read_bytes(file, pos + 4, length - 2);
            if (sof.size() >= 6) {
                frame.marker = marker;
                frame.height = static_cast<std::uint64_t>(sof[1]) << 8 | sof[2];
                frame.width = static_cast<std::uint64_t>(sof[3]) << 8 | sof[4];
                const std::size_t components = sof[5];
                for (std::size_t c = 0; c < components && 6 + 3 * c + 2 < sof.size(); ++c) {
                    const unsigned factors = sof[6 + 3 * c + 1];
                    frame.sampling.emplace_back(std::max(1u, factors >> 4), std::max(1u, factors & 15u));
                }
            }
        } else if (marker == 0xE2 && length >= 14) {
            std::vector<unsigned char> data = read_bytes(file, pos + 4, length - 2);
            if (data.size() >= 12 && std::memcmp(data.data(), "ICC_PROFILE\0", 12) == 0) {
                if (data.size() < 14 && short_segment.empty()) {
                    // Its sequence number or count is missing: a part of a profile, not no profile.
                    short_segment = "its APP2 ICC_PROFILE segment at byte " + std::to_string(pos) + " holds " +
                                    std::to_string(data.size()) + " bytes, fewer than the 14 of its header "
                                    "(the name, a sequence number and a count)";
                }
                if (data.size() >= 14) {
                    chunk_numbers.emplace_back(data[12], data[13]);
                    chunk_data.emplace_back(data.begin() + 14, data.end());
                }
            }
        } else if (marker == 0xDA) {
            first_scan = pos + 2 + length;
            unsigned char ns = 0;
            if (file.read(pos + 4, &ns, 1)) first_scan_components = ns;
        }
        pos += 2 + length;
    }

    if (frame.marker != 0 && frame.width > 0 && frame.height > 0) {
        check_declared_pixels(shown, frame.width, frame.height, limits);
        // Arithmetic coding can spend less than a bit on a block: such a file is bounded by the
        // limits alone.
        if (!is_arithmetic(frame.marker) && first_scan > 0 && !frame.sampling.empty()) {
            const std::uint64_t bits = least_coded_bits(frame);
            const std::uint64_t coded = first_scan <= file.size() ? file.size() - first_scan : 0;
            if (bits > 8 * coded) {
                corrupt(shown, declared_size_text(frame.width, frame.height) + " need at least " +
                                   std::to_string((bits + 7) / 8) + " bytes of coded data (a bit per " +
                                   (is_lossless(frame.marker) ? "sample" : "8 x 8 block") +
                                   "), and the file holds " + std::to_string(coded) +
                                   " after its first scan header");
            }
        }
    }

    if (first_scan > 0) {
        // libjpeg expects more scans only of a progressive frame, or after a first scan that
        // leaves components out (jdinput.c, has_multiple_scans).
        const bool progressive = frame.marker == 0xC2 || frame.marker == 0xC6 || frame.marker == 0xCA || frame.marker == 0xCE;
        check_after_first_scan(shown, file, first_scan, progressive || first_scan_components < frame.sampling.size());
    }
    if (!short_segment.empty()) {
        facts.icc_damage = short_segment;
        return;
    }
    if (chunk_numbers.empty()) return;
    // ICC.1:2022 Annex B.4: chunks numbered 1 to N, each once, all with the same N.
    const unsigned count = chunk_numbers.front().second;
    std::map<unsigned, std::size_t> by_sequence;
    bool whole = count >= 1 && chunk_numbers.size() == count;
    for (std::size_t i = 0; whole && i < chunk_numbers.size(); ++i) {
        const auto [sequence, n] = chunk_numbers[i];
        whole = n == count && sequence >= 1 && sequence <= count && by_sequence.emplace(sequence, i).second;
    }
    if (!whole) {
        facts.icc_damage = "its " + std::to_string(chunk_numbers.size()) +
                           " APP2 ICC_PROFILE segments are numbered " + sequence_text(chunk_numbers) +
                           "; ICC.1 Annex B.4 numbers N segments 1 to N, each once, with the same N";
        return;
    }
    std::vector<unsigned char> profile;
    for (const auto& [sequence, i] : by_sequence) {
        profile.insert(profile.end(), chunk_data[i].begin(), chunk_data[i].end());
    }
    check_icc(shown, profile);
    facts.container_icc_profile = std::move(profile);
}

}  // namespace irid::io::header
