#pragma once

// Shared by the libFuzzer harnesses of tests/fuzz: the failure rule, reading parameters from the
// fuzz bytes, and scratch files for APIs that take a path.
//
// A harness reports a broken contract with fuzz::require(), which prints what was wrong and
// traps (libFuzzer records the input as a crash; the replay driver dies the same way). irid's
// contract is that bad input throws irid::Error (include/irid/error.h: "the one exception type
// irid throws"), so the harnesses catch irid::Error only: any other exception escapes and is a
// finding too.

#include <sys/mman.h>
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>
#include <string_view>
#include <system_error>

namespace irid::fuzz {

/// Traps unless `ok`, after printing `what` (and the harness' file and line) to stderr.
#define IRID_FUZZ_REQUIRE(ok, what)                                                        \
    do {                                                                                   \
        if (!(ok)) ::irid::fuzz::fail(__FILE__, __LINE__, #ok, std::string(what).c_str()); \
    } while (false)

[[noreturn]] inline void fail(const char* file, int line, const char* condition, const char* what) {
    std::fprintf(stderr, "\n== irid fuzz: contract broken at %s:%d: %s\n== %s\n", file, line,
                 condition, what);
    std::fflush(stderr);
    __builtin_trap();
}

/// Takes parameters from the front of the fuzz input; past the end every value is 0.
class Bytes {
public:
    Bytes(const std::uint8_t* data, std::size_t size) noexcept : m_data(data), m_size(size) {}

    [[nodiscard]] std::uint8_t byte() noexcept {
        if (m_size == 0) return 0;
        --m_size;
        return *m_data++;
    }
    /// A value in [0, n) (n > 0).
    [[nodiscard]] std::size_t pick(std::size_t n) noexcept { return byte() % n; }
    /// Raw bit pattern of a float (any: NaN, Inf, subnormal), 0 past the end.
    [[nodiscard]] float raw_float() noexcept {
        std::uint32_t bits = 0;
        for (int i = 0; i < 4; ++i) bits |= static_cast<std::uint32_t>(byte()) << (8 * i);
        float f;
        std::memcpy(&f, &bits, sizeof f);
        return f;
    }
    [[nodiscard]] const std::uint8_t* data() const noexcept { return m_data; }
    [[nodiscard]] std::size_t size() const noexcept { return m_size; }
    [[nodiscard]] std::string_view rest() const noexcept {
        return {reinterpret_cast<const char*>(m_data), m_size};
    }

private:
    const std::uint8_t* m_data;
    std::size_t m_size;
};

/// A scratch folder for the process, removed at exit: inside $IRID_FUZZ_SCRATCH when set
/// (scripts/fuzz sets it, and removes it, so that a crash, which skips this destructor, leaves
/// nothing behind), else in /dev/shm (RAM), else /tmp.
class ScratchDir {
public:
    static const std::filesystem::path& path() {
        static const ScratchDir dir;
        return dir.m_path;
    }

private:
    ScratchDir() {
        const char* base = std::getenv("IRID_FUZZ_SCRATCH");
        std::string pattern = base != nullptr && *base != '\0'            ? std::string(base)
                              : std::filesystem::is_directory("/dev/shm") ? std::string("/dev/shm")
                                                                          : std::string("/tmp");
        pattern += "/irid-fuzz-XXXXXX";
        if (mkdtemp(pattern.data()) == nullptr) {
            std::perror("irid fuzz: mkdtemp");
            std::abort();
        }
        m_path = pattern;
    }
    ~ScratchDir() {
        std::error_code ec;
        std::filesystem::remove_all(m_path, ec);
    }
    std::filesystem::path m_path;
};

/// Writes the bytes to a file of the scratch folder and returns its path.
inline std::filesystem::path write_scratch(const std::string& name, const std::uint8_t* data,
                                           std::size_t size) {
    const std::filesystem::path file = ScratchDir::path() / name;
    std::FILE* f = std::fopen(file.c_str(), "wb");
    if (f == nullptr || (size > 0 && std::fwrite(data, 1, size, f) != size) ||
        std::fclose(f) != 0) {
        std::perror("irid fuzz: writing a scratch file");
        std::abort();
    }
    return file;
}

/// An anonymous in-memory file (memfd) reachable by the path /proc/self/fd/N: for APIs that
/// take a path and do not care about its extension. Rewritten for every input.
class MemFile {
public:
    MemFile() {
        m_fd = memfd_create("irid-fuzz", 0);
        if (m_fd < 0) {
            std::perror("irid fuzz: memfd_create");
            std::abort();
        }
        m_path = "/proc/self/fd/" + std::to_string(m_fd);
    }
    MemFile(const MemFile&) = delete;
    MemFile& operator=(const MemFile&) = delete;
    ~MemFile() { close(m_fd); }

    /// Replaces the contents; returns the path.
    const std::filesystem::path& write(const std::uint8_t* data, std::size_t size) {
        std::size_t done = 0;
        if (ftruncate(m_fd, 0) != 0) std::abort();
        while (done < size) {
            const ssize_t n = pwrite(m_fd, data + done, size - done, static_cast<off_t>(done));
            if (n <= 0) {
                std::perror("irid fuzz: writing the memfd");
                std::abort();
            }
            done += static_cast<std::size_t>(n);
        }
        return m_path;
    }

private:
    int m_fd = -1;
    std::filesystem::path m_path;
};

}  // namespace irid::fuzz
