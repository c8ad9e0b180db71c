// irid xyz [--illuminant D65] [--observer cie1931|cie1964] < spectra.csv
//
// First column: wavelength in nm; every further column: one reflectance spectrum (any
// spacing, strictly increasing wavelengths). Each is resampled to 1 nm (linear, ends held as
// CIE 015:2018 §7.2.2 advises) and integrated under the illuminant; white Y = 1.
#include "../cli_common.h"

#include <irid/color.h>

namespace irid::cli {
namespace {

struct XyzOptions {
    std::string illuminant = "D65";
    std::string observer = "cie1931";
};

int run_xyz(const XyzOptions& o) {
    DenseSpectrum illuminant;
    Observer observer{};
    try {
        illuminant = illuminant_by_name(o.illuminant);
        observer = parse_observer(o.observer);
    } catch (const Error& e) {
        throw UsageError(e.what());
    }

    const NumericTable table = read_stdin_table(0, 2);
    std::string out = "X,Y,Z\n";
    // No input, no spectra: the header alone, as convert, clip and delta-e answer empty input.
    if (table.empty()) {
        write_stdout(out);
        return exit_success;
    }
    if (table.rows() < 2) {
        throw Error("<stdin>:" + std::to_string(table.line_numbers.front()) +
                    ": a spectrum needs at least two wavelengths, found 1");
    }
    std::vector<double> lambda;
    lambda.reserve(table.rows());
    for (std::size_t r = 0; r < table.rows(); ++r) {
        const double l = table.row(r)[0];
        const std::string where = "<stdin>:" + std::to_string(table.line_numbers[r]) + ": ";
        if (!(l > 0.0)) throw Error(where + "wavelength " + format_shortest(l) + " nm must be positive");
        if (!lambda.empty() && !(l > lambda.back())) {
            throw Error(where + "wavelength " + format_shortest(l) +
                        " nm must be greater than the previous line's " +
                        format_shortest(lambda.back()) + " nm");
        }
        lambda.push_back(l);
    }
    if (lambda.back() < lambda_min_nm || lambda.front() > lambda_max_nm) {
        throw Error("<stdin>: the wavelengths " + format_shortest(lambda.front()) + "-" +
                    format_shortest(lambda.back()) + " nm do not overlap the visible range " +
                    "360-830 nm");
    }

    for (std::size_t c = 1; c < table.columns; ++c) {
        std::vector<double> values(table.rows());
        for (std::size_t r = 0; r < table.rows(); ++r) values[r] = table.row(r)[c];
        Xyz xyz;
        try {
            xyz = sampled_reflectance_to_xyz(lambda, values, illuminant, observer);
        } catch (const Error& e) {
            throw Error("<stdin>: spectrum column " + std::to_string(c + 1) + ": " + e.what());
        }
        append_csv_line(out, std::array{xyz.X, xyz.Y, xyz.Z});
    }
    write_stdout(out);
    return exit_success;
}

}  // namespace

void add_xyz_command(CLI::App& app, Runner& runner) {
    auto options = std::make_shared<XyzOptions>();
    CLI::App* cmd = app.add_subcommand(
        "xyz", "Tristimulus values of reflectance spectra (CSV: wavelength_nm, then one column "
               "per spectrum) under an illuminant, white Y = 1");
    cmd->add_option("--illuminant", options->illuminant,
                    "D50, D55, D65, D75, A, E, D<CCT> (4000-25000 K), blackbody:<T>")
        ->capture_default_str();
    cmd->add_option("--observer", options->observer, "cie1931 (2 degree) or cie1964 (10 degree)")
        ->capture_default_str();
    cmd->callback([options, &runner] { runner = [options] { return run_xyz(*options); }; });
}

}  // namespace irid::cli
