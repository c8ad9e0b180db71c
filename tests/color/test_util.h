#pragma once

// Helpers shared by the colour tests: reading the reference CSVs in data/.
#include <irid/color/numeric_table.h>

#include <fstream>
#include <stdexcept>
#include <string>

namespace irid::test {

/// Reads data/<name> (header skipped) as a numeric table.
inline NumericTable read_data_table(const std::string& name) {
    const std::string path = std::string(IRID_DATA_DIR) + "/" + name;
    std::ifstream in(path);
    if (!in) throw std::runtime_error("cannot open " + path);
    return read_numeric_table(in, path);
}

}  // namespace irid::test
