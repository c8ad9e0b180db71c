#include "cli_common.h"

#include <irid/error.h>

#include <iostream>

namespace irid::cli {

NumericTable read_stdin_table(int columns, int min_columns) {
    return read_numeric_table(std::cin, "<stdin>", columns, min_columns);
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
    if (!std::cout) throw Error("cannot write to standard output");
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
