// irid convert --from SPACE --to SPACE [--white NAME] [--adaptation METHOD]
//
// One colour per line on stdin, the same colours in the other space on stdout. XYZ is relative
// to the reference white given by --white (Y = 1); CIELUV and CIELAB use that white. RGB
// spaces and Oklab have whites of their own (Oklab: D65); where it differs from --white the XYZ
// is chromatically adapted between the two (Bradford unless --adaptation says otherwise).
#include "../cli_common.h"
#include "../spaces.h"

#include <irid/color.h>

#include <cmath>
#include <string>

namespace irid::cli {
namespace {

struct ConvertOptions {
    std::string from;
    std::string to;
    std::string white = "D65";
    std::string adaptation = "bradford";
};

int run_convert(const ConvertOptions& o) {
    const Space from = parse_space(o.from, "--from");
    const Space to = parse_space(o.to, "--to");
    const Xy white = parse_white(o.white);
    const ChromaticAdaptation cat = parse_adaptation(o.adaptation);
    const Converter convert(from, to, white, cat);

    const NumericTable table = read_stdin_table(3);
    std::string out = std::string(header_of(to)) + "\n";
    for (std::size_t r = 0; r < table.rows(); ++r) {
        const std::span<const double> row = table.row(r);
        Vec3 result{};
        try {
            result = convert({row[0], row[1], row[2]});
        } catch (const Error& e) {
            throw Error("<stdin>:" + std::to_string(table.line_numbers[r]) + ": " + e.what());
        }
        for (int i = 0; i < 3; ++i) {
            if (!std::isfinite(result[i])) {
                throw Error("<stdin>:" + std::to_string(table.line_numbers[r]) + ": the colour (" +
                            format_shortest(row[0]) + ", " + format_shortest(row[1]) + ", " +
                            format_shortest(row[2]) + ") has no finite value in " + o.to);
            }
        }
        append_csv_line(out, result);
    }
    write_stdout(out);
    return exit_success;
}

}  // namespace

void add_convert_command(CLI::App& app, Runner& runner) {
    auto options = std::make_shared<ConvertOptions>();
    CLI::App* cmd = app.add_subcommand(
        "convert", "Convert colours (CSV triples on stdin) from one colour space to another");
    cmd->add_option("--from", options->from, "Source space: " + join(space_names()))->required();
    cmd->add_option("--to", options->to, "Destination space (same names)")->required();
    cmd->add_option("--white", options->white,
                    "Reference white of XYZ, CIELUV and CIELAB: " + join(white_point_names()) +
                        " or x,y")
        ->capture_default_str();
    cmd->add_option("--adaptation", options->adaptation,
                    "Chromatic adaptation where whites differ: bradford, cat02, von-kries, none")
        ->capture_default_str();
    cmd->callback([options, &runner] { runner = [options] { return run_convert(*options); }; });
}

}  // namespace irid::cli
