#pragma once

// Output files that are never half-written and never replace what they should not.
//
// Where a command writes (`-o PATH`, an image OUT, a gallery folder's files), the path is
// resolved once, when the output is opened:
// - a new path, or an existing regular file: the data go into a temporary file created with
//   O_EXCL in the destination's folder, which is renamed over the destination once everything is
//   written and closed without error; rename(2) within one folder is atomic, so another process
//   sees the old file (or none) or the whole new one, never a partial file. An existing file keeps
//   its permission bits (and its owner and group where the process may set them); a new one gets
//   0666 less the umask, as any program's new file.
// - a symbolic link: followed (to any depth, up to 40 links) and its final target replaced as
//   above; the link itself stays a link.
// - a character device (a terminal, /dev/null) or a FIFO, and /dev/stdout, /dev/stderr,
//   /dev/fd/N, /proc/self/fd/N: written straight into (the open descriptor itself for the
//   /dev/fd forms, so `>> log` keeps appending). Such a write cannot be undone: on failure the
//   bytes written so far stay written, and the error is reported all the same.
// - a directory, a block device or a socket: refused, before anything is written.
// On any failure (a full disk, an I/O error, a failed close or rename) irid::Error names the
// path as given and the operating system's reason, the temporary file is removed and an existing
// destination is left exactly as it was. (Durability across a power loss is not promised:
// nothing is fsync'd.)

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace irid::io {

/// What opening an output for a path does.
enum class OutputKind {
    /// A regular file is created (or an existing one replaced) through a temporary file.
    file,
    /// A character device, a FIFO or an open descriptor, written straight into.
    stream,
};

/// Where a write to `target` would go, found without creating or opening anything (to check
/// the outputs of a long job before it starts). Throws irid::Error, naming `target`, for every
/// case OutputFile refuses: an empty name, a directory, a missing folder, a block device, a
/// socket, a loop of symbolic links.
struct OutputTarget {
    OutputKind kind = OutputKind::file;
    /// The path that is created or replaced (links followed); for a stream, the path opened.
    std::filesystem::path resolved;
    /// For /dev/stdout, /dev/fd/N, /proc/self/fd/N: the descriptor written to; else -1.
    int descriptor = -1;
};
[[nodiscard]] OutputTarget check_output_path(const std::filesystem::path& target);

/// An output being written: construct it (which creates the temporary file or opens the
/// stream), write(), then commit(). If commit() is never reached (an exception, an early
/// return) the destructor removes the temporary file and leaves the destination as it was.
///
///     irid::io::OutputFile file("out.csv");
///     file.write("R,G,B\n");
///     file.commit();
class OutputFile {
public:
    /// Throws irid::Error naming `target` as check_output_path does, or when the temporary file
    /// or the stream cannot be opened (with the system's reason).
    explicit OutputFile(std::filesystem::path target);
    ~OutputFile();
    OutputFile(const OutputFile&) = delete;
    OutputFile& operator=(const OutputFile&) = delete;
    OutputFile(OutputFile&&) = delete;
    OutputFile& operator=(OutputFile&&) = delete;

    /// The path as given (every message names it).
    [[nodiscard]] const std::filesystem::path& target() const noexcept { return m_target; }
    [[nodiscard]] OutputKind kind() const noexcept { return m_kind; }
    /// The file renamed over at commit (links followed), and whether it existed (for a stream:
    /// the path opened, and false).
    [[nodiscard]] const std::filesystem::path& destination() const noexcept { return m_final; }
    [[nodiscard]] bool replaces() const noexcept { return m_replaces; }
    /// True when bytes can be written at any offset (write_at): a regular temporary file.
    [[nodiscard]] bool seekable() const noexcept { return m_kind == OutputKind::file; }

    /// Appends bytes. Throws irid::Error "<target>: writing failed: <reason>" (a full disk, an
    /// I/O error, a closed pipe); after a failure the output cannot be committed.
    void write(std::string_view bytes);
    void write(const void* data, std::size_t size);
    /// Writes bytes at `offset` (for formats that go back to fill in an index); only when
    /// seekable(). Throws as write().
    void write_at(const void* data, std::size_t size, std::uint64_t offset);
    /// Reads back up to `size` bytes written at `offset` (a TIFF writer rereads its directory);
    /// only when seekable(). Returns the bytes read (fewer at the end of what was written).
    [[nodiscard]] std::size_t read_at(void* data, std::size_t size, std::uint64_t offset);

    /// Finishes: closes the file, gives it the destination's permissions and renames it into
    /// place (a stream is closed). Throws irid::Error naming the target when anything fails; the
    /// destination is then as it was (for a stream: as far as it was written).
    void commit();
    /// Abandons the output now: the temporary file is removed (a stream is closed).
    void discard() noexcept;

private:
    /// Writes all of the bytes at the end (offset null) or at *offset; throws as write().
    void write_bytes(const void* data, std::size_t size, const std::uint64_t* offset);

    std::filesystem::path m_target;
    OutputKind m_kind = OutputKind::file;
    std::filesystem::path m_final;      // the file renamed over (links followed)
    std::filesystem::path m_temporary;  // the temporary file beside it
    int m_fd = -1;
    bool m_owns_fd = true;
    bool m_replaces = false;            // an existing file is replaced: keep its mode
    unsigned m_mode = 0;                // its permission bits
    unsigned m_uid = 0, m_gid = 0;
    bool m_failed = false;
    bool m_done = false;
};

/// Writes `bytes` to `path` as an OutputFile (above): the whole file or, on failure,
/// irid::Error naming the path and the destination as it was.
void write_output_file(const std::filesystem::path& path, std::string_view bytes);

/// Writes files, each a name inside the folder and its bytes, into a folder (created if
/// missing) as a set: every file is written to its temporary name before any is renamed into
/// place, and the existing files are kept aside (a hard link, or a copy where the file system
/// has none) until the last rename, so a failure at any point (a full disk, a refused path, a
/// failed rename) leaves the old set or, once all are in place, the new one, never a mix:
/// files already renamed are put back or removed. (A crash in between is not covered: nothing is
/// fsync'd.) `before_rename(i)` runs before file i is renamed into place; tests inject a failure
/// there. Returns the paths written.
std::vector<std::filesystem::path> write_output_files(
    const std::filesystem::path& folder, const std::vector<std::pair<std::string, std::string>>& files,
    const std::function<void(std::size_t)>& before_rename = {});

}  // namespace irid::io
