#include "cli_common.h"

#include <irid/error.h>

#include <filesystem>
#include <fstream>
#include <iostream>

#include <unistd.h>

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

void write_file_atomically(const std::string& path, const std::string& text) {
    namespace fs = std::filesystem;
    const fs::path target(path);
    if (fs::is_directory(target)) throw Error(path + ": is a directory; give a file name");
    fs::path temporary = target;
    temporary += ".tmp-" + std::to_string(::getpid());
    {
        std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
        if (!out) throw Error(path + ": cannot create " + temporary.string() + " for writing");
        out << text;
        out.flush();
        if (!out) {
            out.close();
            std::error_code ignored;
            fs::remove(temporary, ignored);
            throw Error(path + ": writing failed (disk full?)");
        }
    }
    std::error_code ec;
    fs::rename(temporary, target, ec);
    if (ec) {
        std::error_code ignored;
        fs::remove(temporary, ignored);
        throw Error(path + ": cannot rename the finished file into place: " + ec.message());
    }
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
