// The deflate data of a TIFF's strips or tiles inflated as libtiff inflates them (tif_zip.c,
// ZIPDecode), before OpenImageIO reads the file: OpenImageIO 2.4 inflates deflate strips itself,
// in parallel, and fills a strip that fails to inflate with black without a word.
#include "header_reader.h"

#include <irid/error.h>

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include <zlib.h>

namespace irid::io::header {
namespace {

/// Why unit `u` fails to inflate, or nothing.
std::optional<std::string> inflate_failure(const Reader& file, const CodedUnit& u, std::vector<unsigned char>& input,
                                           std::vector<unsigned char>& output) {
    if (u.expected == 0) return std::nullopt;
    z_stream z{};
    if (inflateInit(&z) != Z_OK) return std::string("zlib could not start inflating");
    std::uint64_t read = 0, produced = 0;
    const char* message = nullptr;
    while (produced < u.expected) {
        if (z.avail_in == 0 && read < u.count) {
            const auto want = static_cast<std::size_t>(std::min<std::uint64_t>(input.size(), u.count - read));
            // Every unit lies inside the file (check_tiff checked it first).
            if (!file.read_unbuffered(u.offset + read, input.data(), want)) break;
            const std::size_t got = want;
            read += got;
            z.next_in = input.data();
            z.avail_in = static_cast<uInt>(got);
        }
        const auto room = static_cast<uInt>(std::min<std::uint64_t>(output.size(), u.expected - produced));
        z.next_out = output.data();
        z.avail_out = room;
        const int status = inflate(&z, Z_NO_FLUSH);
        produced += room - z.avail_out;
        if (status == Z_NEED_DICT || status == Z_DATA_ERROR || status == Z_MEM_ERROR || status == Z_STREAM_ERROR) {
            message = z.msg != nullptr ? z.msg : "invalid data";
            break;
        }
        if (status == Z_STREAM_END) break;
        if (status == Z_BUF_ERROR && z.avail_in == 0 && read >= u.count) break;  // the data ran out
    }
    inflateEnd(&z);
    const std::string holds = std::to_string(produced) + " of the " + std::to_string(u.expected) + " bytes it holds";
    if (message != nullptr) {
        return std::string("deflate data are damaged (zlib: ") + message + ")" +
               (produced < u.expected ? " after " + holds : std::string());
    }
    if (produced < u.expected) return "deflate data end after " + holds;
    return std::nullopt;
}

}  // namespace

void check_deflate_units(const std::string& shown, const Reader& file, const std::vector<CodedUnit>& units,
                         const char* unit) {
    // Units are inflated on several threads (OpenImageIO inflates them in parallel too); the
    // failure reported is the first unit's that fails, whatever the threads' order.
    std::atomic<std::size_t> next{0}, first_failure{units.size()};
    std::mutex mutex;
    std::string reason;
    const auto work = [&] {
        std::vector<unsigned char> input(1 << 16), output(1 << 16);
        for (std::size_t i = next++; i < first_failure.load(); i = next++) {
            if (std::optional<std::string> why = inflate_failure(file, units[i], input, output)) {
                const std::lock_guard<std::mutex> lock(mutex);
                if (i < first_failure.load()) {
                    first_failure = i;
                    reason = std::move(*why);
                }
            }
        }
    };
    std::uint64_t total = 0;
    for (const CodedUnit& u : units) total += u.expected;
    const unsigned hardware = std::max(1u, std::thread::hardware_concurrency());
    // A thread per 4 MiB of pixels, up to one per core: small files stay on this thread.
    const auto helpers = static_cast<unsigned>(std::min<std::uint64_t>(hardware, total >> 22));
    std::vector<std::thread> threads;
    for (unsigned t = 1; t < helpers; ++t) threads.emplace_back(work);
    work();
    for (std::thread& t : threads) t.join();
    if (first_failure.load() < units.size()) {
        corrupt(shown, std::string("its ") + unit + " " + std::to_string(first_failure.load()) + "'s " + reason);
    }
}

}  // namespace irid::io::header
