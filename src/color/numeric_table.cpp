#include <irid/color/numeric_table.h>
#include <irid/error.h>

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

/// A field that is empty or begins like a number (sign, point or digit) is mistyped or missing
/// data, never a column name: a first line made only of such fields is data even when one fails
/// to parse.
bool looks_numeric(std::string_view field) noexcept {
    field = trim(field);
    return field.empty() ||
           std::string_view("+-.0123456789").find(field.front()) != std::string_view::npos;
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

std::string quoted(std::string_view s) {
    constexpr std::size_t max_shown = 40;
    std::string out = "'";
    out += s.size() > max_shown ? std::string(s.substr(0, max_shown)) + "..." : std::string(s);
    return out + "'";
}

}  // namespace

NumericTable read_numeric_table(std::istream& in, std::string_view source, int columns,
                                int min_columns) {
    NumericTable table;
    std::string line;
    int line_number = 0;
    bool first_content_line = true;
    const auto fail = [&](const std::string& what) {
        throw Error(std::string(source) + ":" + std::to_string(line_number) + ": " + what);
    };
    while (std::getline(in, line)) {
        ++line_number;
        std::string_view content = trim(line);
        constexpr std::string_view utf8_bom = "\xEF\xBB\xBF";
        if (line_number == 1 && content.substr(0, utf8_bom.size()) == utf8_bom) {
            content = trim(content.substr(utf8_bom.size()));
        }
        if (content.empty()) continue;
        const std::vector<std::string_view> fields = split_fields(content);
        std::vector<double> row(fields.size());
        Parse status = Parse::ok;
        std::size_t bad_field = 0;
        bool all_look_numeric = true;
        for (std::size_t i = 0; i < fields.size(); ++i) {
            all_look_numeric = all_look_numeric && looks_numeric(fields[i]);
            const Parse p = parse_number(fields[i], row[i]);
            if (p != Parse::ok && status == Parse::ok) {
                status = p;
                bad_field = i;
            }
        }
        if (first_content_line) {
            first_content_line = false;
            if (status != Parse::ok && !all_look_numeric) {
                table.header = std::string(content);
                continue;
            }
        }
        if (status == Parse::out_of_range) {
            fail("field " + std::to_string(bad_field + 1) + " " + quoted(trim(fields[bad_field])) +
                 " is out of the range of a double");
        }
        if (status != Parse::ok) {
            fail("field " + std::to_string(bad_field + 1) + " " + quoted(trim(fields[bad_field])) +
                 " is not a number");
        }
        for (std::size_t i = 0; i < row.size(); ++i) {
            if (!std::isfinite(row[i])) {
                fail("field " + std::to_string(i + 1) + " " + quoted(trim(fields[i])) +
                     " is not a finite number");
            }
        }
        const int n = static_cast<int>(row.size());
        if (columns > 0 && n != columns) {
            fail("expected " + std::to_string(columns) + " comma-separated numbers, found " +
                 std::to_string(n));
        }
        if (n < min_columns) {
            fail("expected at least " + std::to_string(min_columns) +
                 " comma-separated numbers, found " + std::to_string(n));
        }
        if (columns == 0 && !table.rows.empty() && n != static_cast<int>(table.rows.front().size())) {
            fail("expected " + std::to_string(table.rows.front().size()) +
                 " comma-separated numbers like line " + std::to_string(table.line_numbers.front()) +
                 ", found " + std::to_string(n));
        }
        table.rows.push_back(std::move(row));
        table.line_numbers.push_back(line_number);
    }
    if (in.bad()) throw Error(std::string(source) + ": read error");
    return table;
}

std::string format_shortest(double value) {
    if (value == 0.0) value = 0.0;  // -0 prints as 0
    std::array<char, 32> buffer{};
    const auto [end, ec] = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
    if (ec != std::errc()) return "nan";
    return std::string(buffer.data(), end);
}

}  // namespace irid
