// irid delta-e --metric ciede2000|cie76|cieuv|oklab < pairs.csv
//
// Lines L1,a1,b1,L2,a2,b2 (CIELAB for ciede2000 and cie76, CIELUV for cieuv, Oklab for
// oklab); one colour difference per line.
#include "../cli_common.h"

#include <irid/color.h>

namespace irid::cli {
namespace {

struct DeltaEOptions {
    std::string metric;
};

int run_delta_e(const DeltaEOptions& o) {
    DeltaEMetric metric{};
    try {
        metric = parse_delta_e_metric(o.metric);
    } catch (const Error&) {
        throw UsageError("unknown metric '" + o.metric +
                         "' for --metric; valid names: ciede2000, cie76, cieuv, oklab");
    }
    const NumericTable table = read_stdin_table(6);
    std::string out = "delta_e\n";
    for (std::size_t r = 0; r < table.rows(); ++r) {
        const std::span<const double> v = table.row(r);
        const double d = delta_e(metric, {v[0], v[1], v[2]}, {v[3], v[4], v[5]});
        if (!std::isfinite(d)) {
            throw Error("<stdin>:" + std::to_string(table.line_numbers[r]) +
                        ": the difference overflows; values are too large");
        }
        append_csv_line(out, std::array{d});
    }
    write_stdout(out);
    return exit_success;
}

}  // namespace

void add_delta_e_command(CLI::App& app, Runner& runner) {
    auto options = std::make_shared<DeltaEOptions>();
    CLI::App* cmd = app.add_subcommand(
        "delta-e", "Colour differences of pairs (CSV: L1,a1,b1,L2,a2,b2 on stdin)");
    cmd->add_option("--metric", options->metric, "ciede2000, cie76, cieuv (CIELUV) or oklab")
        ->required();
    cmd->callback([options, &runner] { runner = [options] { return run_delta_e(*options); }; });
}

}  // namespace irid::cli
