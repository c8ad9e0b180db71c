#include "cli_common.h"

#include <irid/error.h>
#include <irid/parallel.h>
#include <irid/text_input.h>

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <system_error>

namespace irid::cli {

NumericTable read_stdin_table(int columns, int min_columns) {
    return read_numeric_table(read_standard_input(), "<stdin>", columns, min_columns);
}

void append_csv_line(std::string& out, std::span<const double> values) {
    for (std::size_t i = 0; i < values.size(); ++i) {
        if (i > 0) out += ',';
        out += format_shortest(values[i]);
    }
    out += '\n';
}

void write_stdout(const std::string& text) {
    std::cout << text << std::flush;
    if (!std::cout) throw Error(std::string("cannot write to standard output: ") + std::strerror(errno));
}

std::pair<double, double> parse_number_pair(const std::string& option, const std::string& text,
                                            const std::string& what, const std::string& example) {
    const auto number = [](std::string_view s) -> std::optional<double> {
        double v = 0.0;
        const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
        if (s.empty() || ec != std::errc() || end != s.data() + s.size()) return std::nullopt;
        return v;
    };
    const std::size_t comma = text.find(',');
    const std::optional<double> lo = comma == std::string::npos ? std::nullopt : number(std::string_view(text).substr(0, comma));
    const std::optional<double> hi = comma == std::string::npos ? std::nullopt : number(std::string_view(text).substr(comma + 1));
    if (!lo || !hi) {
        throw UsageError(option + " " + quote_untrusted(text) + ": give " + what + " as LO,HI (two numbers, e.g. " +
                         example + ")");
    }
    return {*lo, *hi};
}

CLI::Validator whole_number_in(long long lo, long long hi) {
    const std::string allowed = std::to_string(lo) + " to " + std::to_string(hi);
    return CLI::Validator(
        [lo, hi, allowed](std::string& text) -> std::string {
            long long value = 0;
            const char* end = text.data() + text.size();
            const auto [p, ec] = std::from_chars(text.data(), end, value);
            if (text.empty() || p != end || ec == std::errc::invalid_argument) {
                // A whole number written another way ("1e3", "12.0") is that number.
                double real = 0.0;
                const auto [q, rec] = std::from_chars(text.data(), end, real);
                if (text.empty() || q != end || rec != std::errc() || !std::isfinite(real) || real != std::floor(real))
                    return quote_untrusted(text) + " is not a whole number; allowed: " + allowed;
                if (real < static_cast<double>(lo) || real > static_cast<double>(hi))
                    return quote_untrusted(text) + " is out of range; allowed: " + allowed;
                text = std::to_string(static_cast<long long>(real));
                return {};
            }
            if (ec == std::errc::result_out_of_range || value < lo || value > hi)
                return quote_untrusted(text) + " is out of range; allowed: " + allowed;
            return {};
        },
        "INT in " + allowed);
}

CLI::Option* add_threads_option(CLI::App* cmd, int& threads, const std::string& description) {
    return cmd->add_option("--threads", threads, description)->transform(whole_number_in(0, max_threads))->capture_default_str();
}

bool is_exr_path(const std::string& path) {
    return ascii_lower(std::filesystem::path(path).extension().string()) == ".exr";
}

std::string join(const std::vector<std::string>& names) {
    std::string out;
    for (const std::string& n : names) {
        if (!out.empty()) out += ", ";
        out += n;
    }
    return out;
}

}  // namespace irid::cli
