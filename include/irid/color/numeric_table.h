#pragma once

#include <istream>
#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace irid {

/// A table of finite numbers read from CSV text: the shape every irid command reads.
struct NumericTable {
    /// The first line, when it is a header (it names every column: see read_numeric_table).
    std::optional<std::string> header;
    /// Numbers per row; every row has as many.
    std::size_t columns = 0;
    /// The numbers row by row: row r is values[r × columns, (r + 1) × columns).
    std::vector<double> values;
    /// 1-based line number of each row in the source, for messages.
    std::vector<int> line_numbers;

    [[nodiscard]] std::size_t rows() const noexcept { return line_numbers.size(); }
    [[nodiscard]] bool empty() const noexcept { return line_numbers.empty(); }
    [[nodiscard]] std::span<const double> row(std::size_t r) const noexcept {
        return {values.data() + r * columns, columns};
    }
};

/// The most numbers one table holds: 2^25 (256 MiB of doubles; 11 million colours). Larger
/// batches belong in an image or, from Python, an array.
inline constexpr std::size_t max_table_values = std::size_t{1} << 25;

/// Reads comma-separated numbers. The first non-blank line is a header, and is skipped, when it
/// names the columns: every field is a name (it begins with an ASCII letter or a character beyond
/// ASCII, as λ or Δ, and is no number: "nan" and "inf" are numbers), and there are as many as a
/// row holds (`columns` when it is above 0, else at least `min_columns`); the rows below must then
/// hold as many numbers as it has names. Any other first line is data: "R,G,B" is a header, but
/// "0.1,abc,0.3" (a bad field), "0.1;0.2;0.3" and "0.1 0.2 0.3" (other separators: one field),
/// "R;G;B" where 3 columns are read, "#R,G,B" and "_x,y" are errors at that line, whose message
/// adds what it may hold ("line 1 holds 3 numbers separated by commas, or a header of 3 names
/// (each beginning with a letter)"). A header alone is an empty table. A UTF-8 byte-order mark
/// is ignored; blank lines are skipped; numbers too small
/// for a double become 0 (or subnormal), too large ones are errors; every other line must hold
/// `columns` finite numbers (any count >= min_columns, the same on every line, when columns is
/// 0). Spaces around fields and a final CR are ignored. Throws irid::Error
/// "<source>:<line>: <what was wrong>" on the first bad line, quoting at most 40 characters of the
/// field with control characters escaped, and "<source>: ..." when the table would hold more than
/// max_table_values numbers.
[[nodiscard]] NumericTable read_numeric_table(std::string_view text, std::string_view source,
                                              int columns = 0, int min_columns = 1);
/// The same from a stream, read to its end (at most max_text_input_bytes, irid/text_input.h);
/// throws irid::Error "<source>: read error" when the stream fails.
[[nodiscard]] NumericTable read_numeric_table(std::istream& in, std::string_view source,
                                              int columns = 0, int min_columns = 1);

/// Shortest decimal text that reads back to the same double (std::to_chars); -0 prints as 0.
[[nodiscard]] std::string format_shortest(double value);

}  // namespace irid
