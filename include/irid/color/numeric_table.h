#pragma once

#include <istream>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace irid {

/// A table of finite numbers read from CSV text: the shape every irid command reads.
struct NumericTable {
    /// The first line, when it is not numeric.
    std::optional<std::string> header;
    std::vector<std::vector<double>> rows;
    /// 1-based line number of each row in the source, for messages.
    std::vector<int> line_numbers;
};

/// Reads comma-separated numbers. A first line that is not numeric is a header, unless every
/// field of it is empty or begins like a number (a sign, point or digit: "1e400,0,0",
/// "0x1,2,3", "1,,0"), which is mistyped data and an error rather than silently skipped; a
/// UTF-8 byte-order mark is ignored; blank lines are skipped; numbers too small for a double
/// become 0 (or subnormal), too large ones are errors; every other line must hold `columns` finite numbers (any count ≥ min_columns, the
/// same on every line, when columns is 0). Spaces around fields and a final CR are ignored.
/// Throws irid::Error "<source>:<line>: <what was wrong>" on the first bad line.
[[nodiscard]] NumericTable read_numeric_table(std::istream& in, std::string_view source,
                                              int columns = 0, int min_columns = 1);

/// Shortest decimal text that reads back to the same double (std::to_chars); -0 prints as 0.
[[nodiscard]] std::string format_shortest(double value);

}  // namespace irid
