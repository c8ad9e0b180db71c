#include <irid/error.h>
#include <irid/io/output_file.h>

#include <atomic>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <memory>
#include <optional>
#include <string>
#include <system_error>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace irid::io {
namespace fs = std::filesystem;

namespace {

/// Symbolic links followed before giving up (Linux's own limit for path resolution, MAXSYMLINKS).
constexpr int max_link_hops = 40;

std::string system_reason(int error) { return std::strerror(error); }

bool all_digits(const std::string& s) noexcept {
    if (s.empty() || s.size() > 9) return false;
    for (const char c : s) {
        if (c < '0' || c > '9') return false;
    }
    return true;
}

/// N when `p` names this process's open descriptor N: /proc/self/fd/N, /proc/<our pid>/fd/N and
/// anything that resolves to its folder (/dev/fd/N). /dev/stdout and /dev/stderr are links to
/// /proc/self/fd/1 and 2 and arrive here after one hop.
std::optional<int> own_descriptor(const fs::path& p) {
    const std::string name = p.filename().string();
    if (!all_digits(name)) return std::nullopt;
    std::error_code ec;
    const fs::path folder = fs::canonical(p.parent_path().empty() ? fs::path(".") : p.parent_path(), ec);
    if (ec) return std::nullopt;
    const fs::path own = fs::path("/proc") / std::to_string(::getpid()) / "fd";
    if (folder != own) return std::nullopt;
    return std::stoi(name);
}

const char* kind_of(mode_t mode) noexcept {
    if (S_ISDIR(mode)) return "a directory";
    if (S_ISBLK(mode)) return "a block device";
    if (S_ISSOCK(mode)) return "a socket";
    return "not a regular file";
}

/// A name for a temporary file: short (a long destination name must still fit in NAME_MAX),
/// hidden, and unlikely to collide (O_EXCL settles any collision).
std::string temporary_name() {
    static std::atomic<std::uint64_t> serial{0};
    std::uint64_t x = static_cast<std::uint64_t>(
                          std::chrono::steady_clock::now().time_since_epoch().count()) ^
                      (static_cast<std::uint64_t>(::getpid()) << 40) ^
                      (serial.fetch_add(1, std::memory_order_relaxed) * 0x9E3779B97F4A7C15ull);
    // SplitMix64's finaliser (Steele, Lea & Flood 2014) spreads the bits.
    x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
    x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
    x ^= x >> 31;
    static constexpr char alphabet[] = "abcdefghijklmnopqrstuvwxyz0123456789";
    std::string name = ".irid-";
    for (int i = 0; i < 10; ++i) {
        name += alphabet[x % 36];
        x /= 36;
    }
    return name;
}

}  // namespace

OutputTarget check_output_path(const fs::path& target) {
    const std::string shown = target.string();
    if (target.empty()) throw Error("an empty file name was given for writing");
    fs::path p = target;
    for (int hop = 0;; ++hop) {
        if (const std::optional<int> fd = own_descriptor(p)) {
            return {OutputKind::stream, p, *fd};
        }
        struct stat st {};
        if (::lstat(p.c_str(), &st) != 0) {
            const int error = errno;
            if (error != ENOENT) throw Error(shown + ": cannot write: " + system_reason(error));
            if (!p.has_filename()) throw Error(shown + ": names a folder; give a file name");
            const fs::path folder = p.parent_path().empty() ? fs::path(".") : p.parent_path();
            struct stat fst {};
            if (::stat(folder.c_str(), &fst) != 0) {
                throw Error(shown + ": cannot write: the folder " + folder.string() +
                            (errno == ENOENT ? " does not exist" : ": " + system_reason(errno)));
            }
            if (!S_ISDIR(fst.st_mode))
                throw Error(shown + ": cannot write: " + folder.string() + " is not a folder");
            return {OutputKind::file, p, -1};
        }
        if (S_ISLNK(st.st_mode)) {
            if (hop >= max_link_hops)
                throw Error(shown + ": cannot write: more than 40 symbolic links to follow");
            std::error_code ec;
            const fs::path link = fs::read_symlink(p, ec);
            if (ec) throw Error(shown + ": cannot read the symbolic link: " + ec.message());
            p = link.is_absolute() ? link : p.parent_path() / link;
            continue;
        }
        if (S_ISREG(st.st_mode)) return {OutputKind::file, p, -1};
        if (S_ISCHR(st.st_mode) || S_ISFIFO(st.st_mode)) return {OutputKind::stream, p, -1};
        if (S_ISDIR(st.st_mode)) throw Error(shown + ": is a directory; give a file name");
        throw Error(shown + ": is " + kind_of(st.st_mode) +
                    "; irid writes regular files, character devices and FIFOs");
    }
}

OutputFile::OutputFile(fs::path target) : m_target(std::move(target)) {
    const std::string shown = m_target.string();
    const OutputTarget t = check_output_path(m_target);
    m_kind = t.kind;
    m_final = t.resolved;
    if (t.kind == OutputKind::stream) {
        if (t.descriptor >= 0) {
            const int flags = ::fcntl(t.descriptor, F_GETFL);
            if (flags < 0) {
                throw Error(shown + ": cannot write: descriptor " + std::to_string(t.descriptor) +
                            " is not open");
            }
            if ((flags & O_ACCMODE) == O_RDONLY) {
                throw Error(shown + ": cannot write: descriptor " + std::to_string(t.descriptor) +
                            " is open for reading only");
            }
            m_fd = t.descriptor;
            m_owns_fd = false;
            return;
        }
        // A FIFO blocks here until a reader opens it, as it does for any writer.
        do {
            m_fd = ::open(t.resolved.c_str(), O_WRONLY | O_NOCTTY | O_CLOEXEC);
        } while (m_fd < 0 && errno == EINTR);
        if (m_fd < 0) throw Error(shown + ": cannot open for writing: " + system_reason(errno));
        return;
    }
    struct stat st {};
    if (::stat(m_final.c_str(), &st) == 0 && S_ISREG(st.st_mode)) {
        m_replaces = true;
        m_mode = st.st_mode & 07777;
        m_uid = st.st_uid;
        m_gid = st.st_gid;
    }
    const fs::path folder = m_final.parent_path();
    for (int attempt = 0; attempt < 100 && m_fd < 0; ++attempt) {
        m_temporary = folder / temporary_name();
        // 0666 less the umask, as for any new file; an existing file's mode is set at commit.
        m_fd = ::open(m_temporary.c_str(), O_RDWR | O_CREAT | O_EXCL | O_CLOEXEC | O_NOFOLLOW,
                      0666);
        if (m_fd < 0 && errno != EEXIST) {
            const int error = errno;
            m_temporary.clear();
            throw Error(shown + ": cannot create a file in " +
                        (folder.empty() ? std::string("the current folder") : folder.string()) +
                        ": " + system_reason(error));
        }
    }
    if (m_fd < 0) {
        m_temporary.clear();
        throw Error(shown + ": cannot create a temporary file beside it (100 names taken)");
    }
}

OutputFile::~OutputFile() { discard(); }

void OutputFile::write(std::string_view bytes) { write(bytes.data(), bytes.size()); }

void OutputFile::write(const void* data, std::size_t size) { write_bytes(data, size, nullptr); }

void OutputFile::write_at(const void* data, std::size_t size, std::uint64_t offset) {
    if (!seekable()) throw Error(m_target.string() + ": cannot write at an offset into a stream");
    write_bytes(data, size, &offset);
}

void OutputFile::write_bytes(const void* data, std::size_t size, const std::uint64_t* offset) {
    if (m_done || m_fd < 0) throw Error(m_target.string() + ": the output is already closed");
    const char* p = static_cast<const char*>(data);
    std::uint64_t at = offset != nullptr ? *offset : 0;
    while (size > 0) {
        const ssize_t n = offset != nullptr ? ::pwrite(m_fd, p, size, static_cast<off_t>(at))
                                            : ::write(m_fd, p, size);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) {
            m_failed = true;
            throw Error(m_target.string() + ": writing failed: " +
                        system_reason(n < 0 ? errno : EIO));
        }
        p += n;
        size -= static_cast<std::size_t>(n);
        at += static_cast<std::uint64_t>(n);
    }
}

std::size_t OutputFile::read_at(void* data, std::size_t size, std::uint64_t offset) {
    if (m_done || m_fd < 0 || !seekable()) return 0;
    char* p = static_cast<char*>(data);
    std::size_t done = 0;
    while (done < size) {
        const ssize_t n = ::pread(m_fd, p + done, size - done, static_cast<off_t>(offset + done));
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) break;
        done += static_cast<std::size_t>(n);
    }
    return done;
}

void OutputFile::commit() {
    const std::string shown = m_target.string();
    if (m_done) throw Error(shown + ": the file was already committed or discarded");
    if (m_failed) {
        discard();
        throw Error(shown + ": writing failed earlier; nothing was committed");
    }
    if (m_kind == OutputKind::stream) {
        const int fd = m_fd;
        m_fd = -1;
        m_done = true;
        if (m_owns_fd && ::close(fd) != 0 && errno != EINTR)
            throw Error(shown + ": writing failed: " + system_reason(errno));
        return;
    }
    if (m_replaces) {
        // The owner first (it may clear set-id bits), then the permission bits. Only a
        // privileged process may give a file away; otherwise the new file is the writer's.
        if (m_uid != ::geteuid() || m_gid != ::getegid()) (void)::fchown(m_fd, m_uid, m_gid);
        if (::fchmod(m_fd, static_cast<mode_t>(m_mode)) != 0) {
            const int error = errno;
            discard();
            throw Error(shown + ": cannot keep the file's permissions: " + system_reason(error));
        }
    }
    const int fd = m_fd;
    m_fd = -1;
    if (::close(fd) != 0 && errno != EINTR) {
        const int error = errno;
        discard();
        throw Error(shown + ": writing failed: " + system_reason(error));
    }
    if (::rename(m_temporary.c_str(), m_final.c_str()) != 0) {
        const int error = errno;
        discard();
        throw Error(shown + ": cannot move the finished file into place: " +
                    system_reason(error));
    }
    m_done = true;
}

void OutputFile::discard() noexcept {
    if (m_done) return;
    m_done = true;
    if (m_fd >= 0 && m_owns_fd) ::close(m_fd);
    m_fd = -1;
    if (!m_temporary.empty()) ::unlink(m_temporary.c_str());
}

void write_output_file(const fs::path& path, std::string_view bytes) {
    OutputFile file(path);
    file.write(bytes);
    file.commit();
}

namespace {

/// An existing destination kept aside while a set of files replaces it.
struct KeptAside {
    fs::path destination, saved;
};

/// Keeps `destination` aside under a fresh name beside it: a hard link, or a copy where the file
/// system makes none. Throws irid::Error naming the file.
KeptAside keep_aside(const fs::path& destination) {
    for (int attempt = 0; attempt < 100; ++attempt) {
        const fs::path saved = destination.parent_path() / temporary_name();
        if (::link(destination.c_str(), saved.c_str()) == 0) return {destination, saved};
        if (errno == EEXIST) continue;
        std::error_code ec;
        if (fs::copy_file(destination, saved, fs::copy_options::none, ec)) return {destination, saved};
        if (ec == std::errc::file_exists) continue;
        throw Error(destination.string() + ": cannot keep the old file aside while the set is replaced: " +
                    ec.message());
    }
    throw Error(destination.string() + ": cannot keep the old file aside (100 names taken)");
}

}  // namespace

std::vector<fs::path> write_output_files(const fs::path& folder,
                                         const std::vector<std::pair<std::string, std::string>>& files,
                                         const std::function<void(std::size_t)>& before_rename) {
    std::error_code ec;
    fs::create_directories(folder, ec);
    if (ec) throw Error("cannot make the folder " + folder.string() + ": " + ec.message());
    std::vector<std::unique_ptr<OutputFile>> outputs;
    std::vector<fs::path> paths;
    for (const auto& [name, bytes] : files) {
        paths.push_back(folder / name);
        outputs.push_back(std::make_unique<OutputFile>(paths.back()));
        outputs.back()->write(bytes);
    }
    std::vector<std::optional<KeptAside>> kept(outputs.size());
    const auto drop_kept = [&kept] {
        for (auto& k : kept) {
            if (k) (void)::unlink(k->saved.c_str());
        }
    };
    try {
        for (std::size_t i = 0; i < outputs.size(); ++i) {
            if (outputs[i]->replaces()) kept[i] = keep_aside(outputs[i]->destination());
        }
    } catch (...) {
        drop_kept();
        throw;
    }
    std::size_t renamed = 0;
    try {
        for (; renamed < outputs.size(); ++renamed) {
            if (before_rename) before_rename(renamed);
            outputs[renamed]->commit();
        }
    } catch (const std::exception& e) {
        // Put the old set back: the files already renamed are restored from what was kept
        // aside (a rename, atomic), or removed where there was none.
        std::string unrestored;
        for (std::size_t j = 0; j < renamed; ++j) {
            if (kept[j]) {
                if (::rename(kept[j]->saved.c_str(), kept[j]->destination.c_str()) != 0) {
                    // The old file stays under its saved name: never removed.
                    unrestored += "; the old " + kept[j]->destination.string() + " is kept as " +
                                  kept[j]->saved.string();
                }
                kept[j].reset();
            } else if (outputs[j]->kind() == OutputKind::file) {
                (void)::unlink(outputs[j]->destination().c_str());
            }
        }
        drop_kept();
        throw Error(std::string(e.what()) +
                    (unrestored.empty() ? "; the folder's files were left as they were" : unrestored));
    }
    drop_kept();
    return paths;
}

}  // namespace irid::io
