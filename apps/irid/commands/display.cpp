// irid display --view aces2 --display NAME [--from SPACE] [--to xyz|SPACE] [--inverse] < CSV
// irid display --list
//
// Scene colours (CSV triples on stdin; ACES2065-1 by default) through a display transform to
// CIE XYZ of the display (1.0 = 100 cd/m²) or an RGB space's linear or encoded values; with
// --inverse, display values (XYZ by default) back to scene values (ACES2065-1 by default). The
// transform and its displays are the library's (irid/gamut/display_transform.h).
#include "../cli_common.h"
#include "../spaces.h"

#include <irid/color/numeric_table.h>
#include <irid/error.h>
#include <irid/gamut/aces2_display.h>
#include <irid/gamut/display_transform.h>

#include <fmt/core.h>

#include <cmath>
#include <string>

namespace irid::cli {
namespace {

struct DisplayOptions {
    std::string view = "aces2";
    std::string display;
    std::string from;
    std::string to;
    bool inverse = false;
    bool list = false;
};

std::string primaries_text(const RgbPrimaries& p) {
    return fmt::format("{} {} {} {} {} {}", format_shortest(p.red.x), format_shortest(p.red.y),
                       format_shortest(p.green.x), format_shortest(p.green.y), format_shortest(p.blue.x),
                       format_shortest(p.blue.y));
}

int run_list() {
    std::string out = "display,peak_nits,limiting_primaries,limiting_white,encoding_primaries,encoding_white,"
                      "linear_scale\n";
    for (const Aces2DisplaySpec& d : aces2_displays()) {
        // The nominal peak: the cinema presets render for 1/0.48 of it and scale back.
        out += fmt::format("{},{},{},{} {},{},{},{}\n", d.name, format_shortest(d.peak_nits * d.linear_scale),
                           primaries_text(d.limiting), format_shortest(d.limiting_white.x),
                           format_shortest(d.limiting_white.y),
                           d.encoding_xyz ? std::string("CIE XYZ") : primaries_text(d.encoding),
                           d.encoding_xyz ? std::string("E")
                                          : format_shortest(d.encoding_white.x) + " " +
                                                format_shortest(d.encoding_white.y),
                           format_shortest(d.linear_scale));
    }
    write_stdout(out);
    return exit_success;
}

int run_display(const DisplayOptions& o) {
    if (o.list) return run_list();
    if (o.display.empty()) throw UsageError("--display is required (irid display --list names them)");
    DisplayTransformOptions t;
    t.view = o.view;
    t.display = o.display;
    t.inverse = o.inverse;
    t.source = !o.from.empty() ? o.from : (o.inverse ? "xyz" : "aces2065-1");
    t.target = !o.to.empty() ? o.to : (o.inverse ? "aces2065-1" : "xyz");
    const Space target = parse_space(t.target, "--to");
    (void)parse_space(t.source, "--from");
    std::unique_ptr<DisplayTransform> transform;
    try {
        transform = std::make_unique<DisplayTransform>(t);
    } catch (const Error& e) {
        throw UsageError(e.what());  // an unknown view or display, or a space on the wrong side
    }
    const NumericTable table = read_stdin_table(3);
    std::string out = std::string(header_of(target)) + "\n";
    for (std::size_t r = 0; r < table.rows(); ++r) {
        const std::span<const double> row = table.row(r);
        Vec3 result{};
        try {
            result = (*transform)({row[0], row[1], row[2]});
        } catch (const Error& e) {
            throw Error("<stdin>:" + std::to_string(table.line_numbers[r]) + ": " + e.what());
        }
        append_csv_line(out, result);
    }
    write_stdout(out);
    return exit_success;
}

}  // namespace

void add_display_command(CLI::App& app, Runner& runner) {
    auto options = std::make_shared<DisplayOptions>();
    CLI::App* cmd = app.add_subcommand(
        "display", "Scene colours (CSV on stdin) through a display transform (ACES 2.0), or back with --inverse");
    cmd->add_option("--view", options->view, "The view: " + join(display_views()))->capture_default_str();
    cmd->add_option("--display", options->display, "The display (irid display --list)");
    cmd->add_option("--from", options->from,
                    "Input space (default aces2065-1; with --inverse xyz): " + join(space_names()));
    cmd->add_option("--to", options->to,
                    "Output space: xyz (1.0 = 100 cd/m²) or an RGB space (default xyz; with --inverse aces2065-1)");
    cmd->add_flag("--inverse", options->inverse, "Display values back to scene values");
    cmd->add_flag("--list", options->list, "List the displays: peak, limiting and encoding primaries and whites");
    cmd->callback([options, &runner] { runner = [options] { return run_display(*options); }; });
}

}  // namespace irid::cli
