#include <irid/color/numeric_table.h>
#include <irid/error.h>
#include <irid/text_input.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <string>
#include <system_error>

namespace irid {
namespace {

std::string_view trim(std::string_view s) noexcept {
    const auto first = s.find_first_not_of(" \t\r");
    if (first == std::string_view::npos) return {};
    const auto last = s.find_last_not_of(" \t\r");
    return s.substr(first, last - first + 1);
}

enum class Parse { ok, not_a_number, out_of_range };

/// Parses a whole field as a double (no trailing text allowed). Values too small for a double
/// underflow to zero or a subnormal, as strtod does; values too large are out of range.
Parse parse_number(std::string_view field, double& value) {
    field = trim(field);
    if (!field.empty() && field.front() == '+') {
        field.remove_prefix(1);
        if (!field.empty() && (field.front() == '-' || field.front() == '+')) return Parse::not_a_number;
    }
    if (field.empty()) return Parse::not_a_number;
    const auto [end, ec] = std::from_chars(field.data(), field.data() + field.size(), value);
    if (end != field.data() + field.size()) return Parse::not_a_number;
    if (ec == std::errc::result_out_of_range) {
        const std::string text(field);
        value = std::strtod(text.c_str(), nullptr);
        return std::isinf(value) ? Parse::out_of_range : Parse::ok;
    }
    return ec == std::errc() ? Parse::ok : Parse::not_a_number;
}

std::vector<std::string_view> split_fields(std::string_view line) {
    std::vector<std::string_view> fields;
    std::size_t start = 0;
    while (true) {
        const auto comma = line.find(',', start);
        if (comma == std::string_view::npos) {
            fields.push_back(line.substr(start));
            return fields;
        }
        fields.push_back(line.substr(start, comma - start));
        start = comma + 1;
    }
}

/// A header's field: a name, which begins with an ASCII letter or a character beyond ASCII (a
/// UTF-8 letter such as λ or Δ) and is no number ("nan" and "inf" are numbers).
bool is_name(std::string_view field, Parse parsed) noexcept {
    field = trim(field);
    if (field.empty() || parsed != Parse::not_a_number) return false;
    const auto first = static_cast<unsigned char>(field.front());
    return (first >= 'A' && first <= 'Z') || (first >= 'a' && first <= 'z') || first >= 0x80;
}

/// What line 1 may hold, for its error: "3 numbers separated by commas, or a header of 3 names
/// (each beginning with a letter)".
std::string first_line_shape(int columns, int min_columns) {
    const std::string count = columns > 0      ? std::to_string(columns) + " "
                              : min_columns > 1 ? "at least " + std::to_string(min_columns) + " "
                                                : "";
    return count + "numbers separated by commas, or a header of " + count + "names (each beginning with a letter)";
}

}  // namespace

NumericTable read_numeric_table(std::string_view text, std::string_view source, int columns,
                                int min_columns) {
    NumericTable table;
    int line_number = 0;
    bool first_content_line = true;
    std::size_t header_columns = 0;  // the header's names, when there is one
    int header_line = 0;
    const auto fail = [&](const std::string& what) {
        throw Error(std::string(source) + ":" + std::to_string(line_number) + ": " + what);
    };
    const auto field_error = [&](std::size_t i, std::string_view field, const std::string& what) {
        fail("field " + std::to_string(i + 1) + " " + quote_untrusted(trim(field)) + " " + what);
    };
    std::vector<double> row;
    std::size_t start = 0;
    while (start < text.size()) {
        std::size_t end = text.find('\n', start);
        if (end == std::string_view::npos) end = text.size();
        std::string_view content = trim(text.substr(start, end - start));
        start = end + 1;
        ++line_number;
        constexpr std::string_view utf8_bom = "\xEF\xBB\xBF";
        if (line_number == 1 && content.substr(0, utf8_bom.size()) == utf8_bom) {
            content = trim(content.substr(utf8_bom.size()));
        }
        if (content.empty()) continue;
        const std::vector<std::string_view> fields = split_fields(content);
        row.assign(fields.size(), 0.0);
        Parse status = Parse::ok;
        std::size_t bad_field = 0;
        bool all_names = true;
        for (std::size_t i = 0; i < fields.size(); ++i) {
            const Parse p = parse_number(fields[i], row[i]);
            // A value too large for a double is still a number (mistyped data, not a name).
            all_names = all_names && is_name(fields[i], p);
            if (p != Parse::ok && status == Parse::ok) {
                status = p;
                bad_field = i;
            }
        }
        const bool first_line = first_content_line;
        first_content_line = false;
        if (first_line) {
            // A header names every column: a name per field, as many fields as a row holds.
            const std::size_t n = fields.size();
            const bool shaped = columns > 0 ? n == static_cast<std::size_t>(columns)
                                            : n >= static_cast<std::size_t>(std::max(min_columns, 1));
            if (all_names && shaped) {
                table.header = std::string(content);
                header_columns = n;
                header_line = line_number;
                continue;
            }
        }
        if (status == Parse::out_of_range) {
            field_error(bad_field, fields[bad_field], "is out of the range of a double");
        }
        if (status != Parse::ok) {
            field_error(bad_field, fields[bad_field],
                        first_line ? "is not a number; line " + std::to_string(line_number) + " holds " +
                                         first_line_shape(columns, min_columns)
                                   : std::string("is not a number"));
        }
        for (std::size_t i = 0; i < row.size(); ++i) {
            if (!std::isfinite(row[i])) field_error(i, fields[i], "is not a finite number");
        }
        const std::size_t n = row.size();
        if (columns > 0 && n != static_cast<std::size_t>(columns)) {
            fail("expected " + std::to_string(columns) + " comma-separated numbers, found " +
                 std::to_string(n));
        }
        if (n < static_cast<std::size_t>(std::max(min_columns, 1))) {
            fail("expected at least " + std::to_string(min_columns) +
                 " comma-separated numbers, found " + std::to_string(n));
        }
        if (header_columns != 0 && n != header_columns) {
            fail("expected " + std::to_string(header_columns) + " comma-separated numbers like the header's names on line " +
                 std::to_string(header_line) + ", found " + std::to_string(n));
        }
        if (table.empty()) {
            table.columns = n;
        } else if (n != table.columns) {
            fail("expected " + std::to_string(table.columns) +
                 " comma-separated numbers like line " + std::to_string(table.line_numbers.front()) +
                 ", found " + std::to_string(n));
        }
        if (table.values.size() + n > max_table_values) {
            throw Error(std::string(source) + ": more than " + std::to_string(max_table_values) +
                        " numbers (at line " + std::to_string(line_number) +
                        "); a table holds at most " + std::to_string(max_table_values));
        }
        table.values.insert(table.values.end(), row.begin(), row.end());
        table.line_numbers.push_back(line_number);
    }
    return table;
}

NumericTable read_numeric_table(std::istream& in, std::string_view source, int columns,
                                int min_columns) {
    std::string text;
    constexpr std::size_t chunk = 1 << 16;
    while (in) {
        const std::size_t used = text.size();
        text.resize(used + chunk);
        in.read(text.data() + used, static_cast<std::streamsize>(chunk));
        text.resize(used + static_cast<std::size_t>(in.gcount()));
        if (text.size() > max_text_input_bytes) {
            throw Error(std::string(source) + ": more than " +
                        std::to_string(max_text_input_bytes >> 20) + " MiB; irid reads up to " +
                        std::to_string(max_text_input_bytes >> 20) + " MiB of text");
        }
    }
    if (in.bad()) throw Error(std::string(source) + ": read error");
    return read_numeric_table(std::string_view(text), source, columns, min_columns);
}

std::string format_shortest(double value) {
    if (value == 0.0) value = 0.0;  // -0 prints as 0
    std::array<char, 32> buffer{};
    const auto [end, ec] = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
    if (ec != std::errc()) return "nan";
    return std::string(buffer.data(), end);
}

}  // namespace irid
