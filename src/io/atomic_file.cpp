#include <irid/error.h>
#include <irid/io/atomic_file.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <string>
#include <system_error>

#include <unistd.h>

namespace irid::io {
namespace fs = std::filesystem;

namespace {

/// A number unique within the process, so that two atomic writes to the same target (from two
/// threads) never share a temporary file.
unsigned long next_serial() noexcept {
    static std::atomic<unsigned long> serial{0};
    return serial.fetch_add(1, std::memory_order_relaxed);
}

}  // namespace

AtomicFile::AtomicFile(fs::path target) : m_target(std::move(target)) {
    const std::string shown = m_target.string();
    if (m_target.empty()) throw Error("an empty file name was given for writing");
    if (!m_target.has_filename()) throw Error(shown + ": is a directory; give a file name");
    std::error_code ec;
    if (fs::is_directory(m_target, ec)) throw Error(shown + ": is a directory; give a file name");
    const fs::path folder = m_target.parent_path();
    if (!folder.empty() && !fs::is_directory(folder, ec)) {
        throw Error(shown + ": cannot write: the folder " + folder.string() + " does not exist");
    }
    m_temporary = m_target;
    m_temporary += ".tmp-" + std::to_string(::getpid()) + "-" + std::to_string(next_serial());
}

AtomicFile::~AtomicFile() {
    discard();
}

void AtomicFile::discard() noexcept {
    if (m_done) return;
    m_done = true;
    std::error_code ignored;
    fs::remove(m_temporary, ignored);
}

void AtomicFile::commit() {
    if (m_done) throw Error(m_target.string() + ": the file was already committed or discarded");
    std::error_code ec;
    if (!fs::is_regular_file(m_temporary, ec)) {
        discard();
        throw Error(m_target.string() + ": nothing was written (no temporary file " +
                    m_temporary.string() + ")");
    }
    fs::rename(m_temporary, m_target, ec);
    if (ec) {
        discard();
        throw Error(m_target.string() +
                    ": cannot move the finished file into place: " + ec.message());
    }
    m_done = true;
}

void write_text_file_atomically(const fs::path& path, std::string_view text) {
    AtomicFile file(path);
    const std::string shown = path.string();
    std::FILE* out = std::fopen(file.temporary_path().c_str(), "wbx");  // x: never an existing file
    if (out == nullptr) {
        throw Error(shown + ": cannot create a file in its folder: " + std::strerror(errno));
    }
    int error = 0;
    if (!text.empty() && std::fwrite(text.data(), 1, text.size(), out) != text.size())
        error = errno;
    if (std::fflush(out) != 0 && error == 0) error = errno;
    if (std::fclose(out) != 0 && error == 0) error = errno;
    if (error != 0) throw Error(shown + ": writing failed: " + std::strerror(error));
    file.commit();
}

}  // namespace irid::io
