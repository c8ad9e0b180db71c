// irid delta-e --metric ciede2000|cie76|cieuv|oklab < pairs.csv
//
// Lines L1,a1,b1,L2,a2,b2 (CIELAB for ciede2000 and cie76, CIELUV for cieuv, Oklab for
// oklab); one colour difference per line.
#include "../cli_common.h"

#include <irid/color.h>

namespace irid::cli {
namespace {

enum class Metric { ciede2000, cie76, cieuv, oklab };

struct DeltaEOptions {
    std::string metric;
};

Metric parse_metric(const std::string& name) {
    if (name == "ciede2000") return Metric::ciede2000;
    if (name == "cie76") return Metric::cie76;
    if (name == "cieuv") return Metric::cieuv;
    if (name == "oklab") return Metric::oklab;
    throw UsageError("unknown metric '" + name +
                     "' for --metric; valid names: ciede2000, cie76, cieuv, oklab");
}

double difference(Metric metric, std::span<const double> r) {
    switch (metric) {
        case Metric::ciede2000: return delta_e_2000({r[0], r[1], r[2]}, {r[3], r[4], r[5]});
        case Metric::cie76: return delta_e_76({r[0], r[1], r[2]}, {r[3], r[4], r[5]});
        case Metric::cieuv: return delta_e_uv({r[0], r[1], r[2]}, {r[3], r[4], r[5]});
        case Metric::oklab: return delta_e_ok({r[0], r[1], r[2]}, {r[3], r[4], r[5]});
    }
    return 0.0;
}

int run_delta_e(const DeltaEOptions& o) {
    const Metric metric = parse_metric(o.metric);
    const NumericTable table = read_stdin_table(6);
    std::string out = "delta_e\n";
    for (std::size_t r = 0; r < table.rows(); ++r) {
        const double d = difference(metric, table.row(r));
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
