#include <irid/error.h>
#include <irid/text_input.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <string>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace irid {
namespace {

std::string reason(int error) { return std::strerror(error); }

std::string size_text(std::size_t bytes) {
    if (bytes % (std::size_t{1} << 20) == 0) return std::to_string(bytes >> 20) + " MiB";
    return std::to_string(bytes) + " bytes";
}

/// Reads `fd` to its end into `out`; returns 0, or the errno of a failed read; sets `too_long`
/// when more than max_bytes arrive (and stops reading).
int read_all(int fd, std::size_t max_bytes, std::string& out, bool& too_long) {
    too_long = false;
    constexpr std::size_t chunk = 1 << 16;
    for (;;) {
        const std::size_t used = out.size();
        out.resize(used + chunk);
        const ssize_t n = ::read(fd, out.data() + used, chunk);
        if (n < 0) {
            out.resize(used);
            if (errno == EINTR) continue;
            return errno;
        }
        out.resize(used + static_cast<std::size_t>(n));
        if (n == 0) return 0;
        if (out.size() > max_bytes) {
            too_long = true;
            return 0;
        }
    }
}

/// The length of the UTF-8 sequence starting at s[i] when it is valid and not a C1 control
/// (U+0080-U+009F, which some terminals obey), else 0.
std::size_t utf8_length(std::string_view s, std::size_t i) noexcept {
    const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(s[k]); };
    const unsigned char b = byte(i);
    std::size_t n = 0;
    unsigned code = 0;
    if (b >= 0xC2 && b <= 0xDF) {
        n = 2;
        code = b & 0x1Fu;
    } else if (b >= 0xE0 && b <= 0xEF) {
        n = 3;
        code = b & 0x0Fu;
    } else if (b >= 0xF0 && b <= 0xF4) {
        n = 4;
        code = b & 0x07u;
    } else {
        return 0;
    }
    if (i + n > s.size()) return 0;
    for (std::size_t k = 1; k < n; ++k) {
        if ((byte(i + k) & 0xC0u) != 0x80u) return 0;
        code = (code << 6) | (byte(i + k) & 0x3Fu);
    }
    // Overlong forms, surrogates and code points beyond U+10FFFF are not UTF-8.
    if ((n == 3 && code < 0x800) || (n == 4 && (code < 0x10000 || code > 0x10FFFF)) ||
        (code >= 0xD800 && code <= 0xDFFF))
        return 0;
    if (code >= 0x80 && code <= 0x9F) return 0;
    return n;
}

/// Escapes for one byte that is not printed as is.
void append_escape(std::string& out, unsigned char b) {
    switch (b) {
        case '\n': out += "\\n"; return;
        case '\r': out += "\\r"; return;
        case '\t': out += "\\t"; return;
        default: {
            char buffer[8];
            std::snprintf(buffer, sizeof buffer, "\\x%02x", static_cast<unsigned>(b));
            out += buffer;
        }
    }
}

/// Appends s with escapes; stops after max_chars characters (returns false when it stopped).
bool append_escaped(std::string& out, std::string_view s, std::size_t max_chars, bool keep_lines,
                    bool quote) {
    std::size_t chars = 0;
    for (std::size_t i = 0; i < s.size();) {
        if (chars == max_chars) return false;
        ++chars;
        const auto b = static_cast<unsigned char>(s[i]);
        if (b >= 0x80) {
            const std::size_t n = utf8_length(s, i);
            if (n == 0) {
                append_escape(out, b);
                ++i;
            } else {
                out.append(s.substr(i, n));
                i += n;
            }
            continue;
        }
        if ((b == '\n' || b == '\t') && keep_lines) {
            out += static_cast<char>(b);
        } else if (b < 0x20 || b == 0x7F) {
            append_escape(out, b);
        } else if (quote && (b == '\'' || b == '\\')) {
            out += '\\';
            out += static_cast<char>(b);
        } else {
            out += static_cast<char>(b);
        }
        ++i;
    }
    return true;
}

}  // namespace

std::string read_text_file(const std::filesystem::path& path, std::string_view what,
                           StreamInput streams, std::size_t max_bytes) {
    const std::string shown = path.string();
    const std::string expected(what);
    // O_NONBLOCK: opening a FIFO must not wait for a writer before we know what it is.
    int fd = -1;
    do {
        fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NOCTTY | O_NONBLOCK);
    } while (fd < 0 && errno == EINTR);
    if (fd < 0) {
        const int error = errno;
        if (error == ENOENT) throw Error(shown + ": no such file; expected a " + expected);
        throw Error(shown + ": cannot open the " + expected + ": " + reason(error));
    }
    struct Closer {
        int fd;
        ~Closer() { ::close(fd); }
    } closer{fd};
    struct stat st {};
    if (::fstat(fd, &st) != 0) throw Error(shown + ": cannot read: " + reason(errno));
    if (S_ISDIR(st.st_mode)) throw Error(shown + ": is a directory; expected a " + expected);
    const bool stream = S_ISFIFO(st.st_mode) || S_ISCHR(st.st_mode);
    if (!S_ISREG(st.st_mode) && !(stream && streams == StreamInput::accept)) {
        throw Error(shown + ": is not a regular file (" +
                    (S_ISFIFO(st.st_mode)  ? "a FIFO"
                     : S_ISCHR(st.st_mode) ? "a character device"
                     : S_ISBLK(st.st_mode) ? "a block device"
                                           : "a socket") +
                    "); expected a " + expected);
    }
    if (S_ISREG(st.st_mode) && static_cast<std::size_t>(st.st_size) > max_bytes) {
        throw Error(shown + ": " + std::to_string(st.st_size) + " bytes; a " + expected +
                    " is read up to " + size_text(max_bytes));
    }
    // Blocking reads from here on (a FIFO now waits for its writer's data, as it should).
    const int flags = ::fcntl(fd, F_GETFL);
    if (flags >= 0) (void)::fcntl(fd, F_SETFL, flags & ~O_NONBLOCK);
    std::string text;
    bool too_long = false;
    if (const int error = read_all(fd, max_bytes, text, too_long); error != 0)
        throw Error(shown + ": read error: " + reason(error));
    if (too_long) {
        throw Error(shown + ": more than " + size_text(max_bytes) + "; a " + expected +
                    " is read up to " + size_text(max_bytes));
    }
    return text;
}

std::string read_standard_input(std::size_t max_bytes) {
    struct stat st {};
    if (::fstat(STDIN_FILENO, &st) != 0) {
        throw Error(errno == EBADF ? std::string("<stdin>: standard input is closed")
                                   : "<stdin>: cannot read: " + reason(errno));
    }
    if (S_ISDIR(st.st_mode)) throw Error("<stdin>: standard input is a directory");
    std::string text;
    bool too_long = false;
    if (const int error = read_all(STDIN_FILENO, max_bytes, text, too_long); error != 0)
        throw Error("<stdin>: read error: " + reason(error));
    if (too_long) {
        throw Error("<stdin>: more than " + size_text(max_bytes) + " of input; irid reads up to " +
                    size_text(max_bytes) + " from standard input (use an image for more colours)");
    }
    return text;
}

std::string ascii_lower(std::string_view s) {
    std::string out(s);
    for (char& c : out)
        if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
    return out;
}

std::string quote_untrusted(std::string_view text, std::size_t max_chars) {
    std::string out = "'";
    const bool whole = append_escaped(out, text, max_chars, false, true);
    out += whole ? "'" : "...'";
    return out;
}

std::string terminal_safe(std::string_view message) {
    std::string out;
    out.reserve(message.size());
    (void)append_escaped(out, message, std::string_view::npos, true, false);
    return out;
}

}  // namespace irid
