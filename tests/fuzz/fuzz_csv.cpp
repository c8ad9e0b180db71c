// Fuzz harness: the numeric CSV reader behind every command that reads CSV
// (irid::read_numeric_table, include/irid/color/numeric_table.h), through its std::istream form.
//
// Input: byte 0 picks the shape the callers use: 3 columns (convert, clip, material files),
// 6 columns (delta-e), any count >= 2 (xyz), any count >= 1; the rest is the CSV text (with or
// without a header line: the text decides). Checked on every table read:
// - rows x columns values, one line number per row, increasing, >= 1; the required width;
// - every value finite; format_shortest(v) reads back to v;
// - the table written back as CSV (format_shortest, the header kept) reads back to the same
//   table: same header, same values;
// - for the xyz shape, the spectra the xyz command builds from it (PiecewiseLinearSpectrum,
//   resampled, reflectance_to_xyz under D65) are built without error when the wavelengths
//   increase, or refused with irid::Error.
#include "fuzz_support.h"

#include <irid/color/illuminant.h>
#include <irid/color/numeric_table.h>
#include <irid/color/observer.h>
#include <irid/color/spectrum.h>
#include <irid/error.h>

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <string>
#include <system_error>
#include <vector>

namespace {

using irid::fuzz::Bytes;

struct Shape {
    int columns;
    int min_columns;
};
constexpr Shape shapes[] = {{3, 1}, {6, 1}, {0, 2}, {0, 1}};

void check_round_trip_number(double v) {
    const std::string text = irid::format_shortest(v);
    double back = 0.0;
    auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), back);
    // libstdc++'s from_chars reports subnormals as out of range; strtod reads them (as irid does).
    if (ec == std::errc::result_out_of_range) {
        char* stop = nullptr;
        back = std::strtod(text.c_str(), &stop);
        end = stop;
        ec = std::errc();
    }
    IRID_FUZZ_REQUIRE(
        ec == std::errc() && end == text.data() + text.size() && back == v,
        "format_shortest(" + std::to_string(v) + ") = '" + text + "' does not read back");
}

void check_table(const irid::NumericTable& t, const Shape& shape) {
    IRID_FUZZ_REQUIRE(t.values.size() == t.rows() * t.columns, "rows x columns values");
    IRID_FUZZ_REQUIRE(t.values.size() <= irid::max_table_values, "at most max_table_values");
    if (!t.empty()) {
        if (shape.columns > 0) {
            IRID_FUZZ_REQUIRE(static_cast<int>(t.columns) == shape.columns, "row width");
        }
        IRID_FUZZ_REQUIRE(static_cast<int>(t.columns) >= shape.min_columns, "row min width");
    }
    int previous_line = t.header ? 1 : 0;
    for (std::size_t r = 0; r < t.rows(); ++r) {
        IRID_FUZZ_REQUIRE(t.line_numbers[r] > previous_line, "line numbers increase");
        previous_line = t.line_numbers[r];
        for (const double v : t.row(r)) {
            IRID_FUZZ_REQUIRE(std::isfinite(v), "a value is not finite");
            check_round_trip_number(v);
        }
    }
}

/// The table written back as CSV reads back to the same table.
void check_rewrite(const irid::NumericTable& t, const Shape& shape) {
    // With a byte-order mark first, as a header that itself begins with one (U+FEFF read as
    // text after the mark) would otherwise lose it.
    std::string text = "\xEF\xBB\xBF";
    if (t.header) text += *t.header + "\n";
    for (std::size_t r = 0; r < t.rows(); ++r) {
        const auto row = t.row(r);
        for (std::size_t i = 0; i < row.size(); ++i) {
            if (i > 0) text += ',';
            text += irid::format_shortest(row[i]);
        }
        text += '\n';
    }
    std::istringstream in(text);
    irid::NumericTable again;
    try {
        again = irid::read_numeric_table(in, "rewritten", shape.columns, shape.min_columns);
    } catch (const irid::Error& e) {
        IRID_FUZZ_REQUIRE(false, std::string("the table written back does not read: ") + e.what() +
                                     "\n--- text:\n" + text);
    }
    IRID_FUZZ_REQUIRE(again.header == t.header, "the header changed when written back");
    IRID_FUZZ_REQUIRE(again.columns == t.columns && again.values == t.values,
                      "the values changed when written back");
}

/// What `irid xyz` does with a table of the (0, 2) shape.
void xyz_like(const irid::NumericTable& t) {
    if (t.rows() < 2) return;
    std::vector<double> lambda;
    for (std::size_t r = 0; r < t.rows(); ++r) {
        const double l = t.row(r)[0];
        if (!(l > 0.0) || (!lambda.empty() && !(l > lambda.back()))) return;
        lambda.push_back(l);
    }
    static const irid::DenseSpectrum d65 = irid::illuminant_d65();
    for (std::size_t c = 1; c < t.columns; ++c) {
        std::vector<double> values;
        for (std::size_t r = 0; r < t.rows(); ++r) values.push_back(t.row(r)[c]);
        const irid::PiecewiseLinearSpectrum s(lambda, std::move(values),
                                              irid::Extrapolation::hold_ends);
        (void)irid::reflectance_to_xyz(irid::DenseSpectrum::resample(s), d65);
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    Bytes bytes(data, size);
    const Shape shape = shapes[bytes.pick(std::size(shapes))];
    std::istringstream in{std::string(bytes.rest())};
    irid::NumericTable table;
    try {
        table = irid::read_numeric_table(in, "<fuzz>", shape.columns, shape.min_columns);
    } catch (const irid::Error&) {
        return 0;
    }
    check_table(table, shape);
    check_rewrite(table, shape);
    if (shape.columns == 0 && shape.min_columns == 2) {
        try {
            xyz_like(table);
        } catch (const irid::Error&) {
        }
    }
    return 0;
}
