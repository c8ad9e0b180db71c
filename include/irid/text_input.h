#pragma once

// Text that irid reads from files and streams it did not write (CSV tables, spectra, material
// tables, scene JSON, OBJ meshes, standard input): read with stated limits, and quoted safely
// when a message has to show a piece of it.

#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>

namespace irid {

/// The most text read from one file or stream: 256 MiB.
inline constexpr std::size_t max_text_input_bytes = std::size_t{256} << 20;

/// Whether read_text_file accepts a FIFO or a character device (`/dev/stdin`, a process
/// substitution `<(...)`). Paths named inside files irid reads (a scene's mesh or environment
/// image) take regular files only: a FIFO there would block until someone writes to it.
enum class StreamInput { refuse, accept };

/// Reads a whole file. `what` names what it should be, for messages ("scene file", "OBJ mesh").
/// Throws irid::Error naming the path when it does not exist, is a directory, is not a regular
/// file (unless `streams` accepts FIFOs and character devices), cannot be read (with the system's
/// reason), or holds more than `max_bytes`.
[[nodiscard]] std::string read_text_file(const std::filesystem::path& path, std::string_view what,
                                         StreamInput streams = StreamInput::refuse,
                                         std::size_t max_bytes = max_text_input_bytes);

/// Reads all of standard input. Throws irid::Error "<stdin>: ..." when standard input is closed,
/// is a directory, a read fails (with the system's reason), or it holds more than `max_bytes`.
[[nodiscard]] std::string read_standard_input(std::size_t max_bytes = max_text_input_bytes);

/// `s` with the ASCII letters A-Z made lower case (names are compared this way; other bytes,
/// UTF-8 included, are kept as they are).
[[nodiscard]] std::string ascii_lower(std::string_view s);

/// A piece of untrusted input for a message: in single quotes, with control characters, quotes,
/// backslashes and bytes that are not UTF-8 written as escapes (\n, \t, \\, \', \x1b), and cut
/// to at most `max_chars` characters followed by "..." (inside the quotes) when longer. Nothing
/// it returns can move a terminal's cursor or change its colours.
[[nodiscard]] std::string quote_untrusted(std::string_view text, std::size_t max_chars = 40);

/// A whole message made safe for a terminal: as quote_untrusted's escapes but for line breaks
/// and tabs, which are kept, and with no quotes added or length limit.
[[nodiscard]] std::string terminal_safe(std::string_view message);

}  // namespace irid
