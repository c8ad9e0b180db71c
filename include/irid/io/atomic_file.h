#pragma once

// Files that appear only when complete (DESIGN.md: "output files are written to a temporary
// name and renamed when complete"). The data go into a temporary file in the destination's
// folder, which is renamed over the destination once everything is written; rename(2) within
// one folder is atomic, so another process sees either the old file (or none) or the whole
// new one, never a partial file. On any failure the temporary file is removed and the
// destination is left as it was. (Durability across a power loss is not promised: nothing is
// fsync'd.)

#include <filesystem>
#include <string_view>

namespace irid::io {

/// The temporary file behind an atomic write. Construct it, write to temporary_path() by any
/// means (a stream, OpenImageIO, ...), then commit(). If commit() is never reached (an
/// exception, an early return) the destructor removes the temporary file.
///
///     irid::io::AtomicFile file("out.csv");
///     write_everything_to(file.temporary_path());
///     file.commit();
class AtomicFile {
public:
    /// Chooses a temporary name next to `target` ("<name>.tmp-<pid>-<n>", unique within the
    /// process). Nothing is created yet. Throws irid::Error naming `target` when it is empty,
    /// names a directory, or its folder does not exist.
    explicit AtomicFile(std::filesystem::path target);
    ~AtomicFile();
    AtomicFile(const AtomicFile&) = delete;
    AtomicFile& operator=(const AtomicFile&) = delete;
    AtomicFile(AtomicFile&&) = delete;
    AtomicFile& operator=(AtomicFile&&) = delete;

    [[nodiscard]] const std::filesystem::path& target() const noexcept { return m_target; }
    [[nodiscard]] const std::filesystem::path& temporary_path() const noexcept {
        return m_temporary;
    }

    /// Renames the finished temporary file over the target (replacing an existing file).
    /// Throws irid::Error naming the target when the temporary file is missing or the rename
    /// fails; the temporary file is removed either way.
    void commit();
    /// Removes the temporary file now (if any); the target is left untouched.
    void discard() noexcept;

private:
    std::filesystem::path m_target;
    std::filesystem::path m_temporary;
    bool m_done = false;
};

/// Writes `text` to `path` atomically (as above). Throws irid::Error naming the path when the
/// folder is missing or not writable, the path is a directory, or writing fails (disk full);
/// then neither the file nor a temporary file is left behind.
void write_text_file_atomically(const std::filesystem::path& path, std::string_view text);

}  // namespace irid::io
