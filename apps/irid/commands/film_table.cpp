// irid film-table: a colour table like the thesis' §3.3, thickness (× angle) → colour.
//
//   irid film-table --layer water --thickness 0:1500:2 [--angles 0:80:10] [-o table.csv]
//
// One line per (thickness, angle): thickness_nm,angle_deg,cos_theta,X,Y,Z,R_linear,G_linear,
// B_linear (XYZ under the illuminant with white Y = 1; linear RGB unclipped). For the Morpho
// model the table is indexed by angle alone and thickness_nm is eq. 29's effective thickness.
#include "film_options.h"

#include <irid/color.h>
#include <irid/io/output_file.h>

#include <fmt/core.h>

#include <array>
#include <cmath>
#include <numbers>

namespace irid::cli {
namespace {

struct FilmTableCommand {
    FilmArguments args;
    std::string thickness;
    std::string angles;
    std::string output;
};

int run_film_table(const FilmTableCommand& c) {
    const Film film = parse_film(c.args, false);
    const bool morpho = !film.model->has_thickness();
    const Colorimeter colorimeter = parse_colorimeter(c.args);
    if (!morpho && c.thickness.empty()) {
        throw UsageError("--thickness START:END:STEP is required (thickness in nm, >= 0)");
    }
    if (morpho && !c.thickness.empty()) {
        throw UsageError("--thickness does not apply to --model morpho; its table is indexed by --angles");
    }
    const std::optional<Range> thickness_range =
        morpho ? std::nullopt
               : std::optional<Range>(parse_range(c.thickness, "--thickness", 0.0, 1e6, 10000000));
    const std::optional<Range> angle_range =
        c.angles.empty()
            ? std::nullopt
            : std::optional<Range>(parse_range(c.angles, "--angles", 0.0, 90.0, 100000));
    if (angle_range && angle_range->values().back() >= 90.0) {
        throw UsageError("--angles '" + c.angles + "': angles must be < 90 degrees");
    }
    // The table's size is the product of the two ranges: bound it (lines written, spectra
    // computed) before computing anything.
    std::vector<WorkFactor> rows;
    if (thickness_range) {
        rows.push_back(
            {"--thickness " + c.thickness, static_cast<double>(thickness_range->count())});
    }
    if (angle_range) {
        rows.push_back({"--angles " + c.angles, static_cast<double>(angle_range->count())});
    }
    try {
        check_output_rows(rows);
    } catch (const Error& e) {
        throw UsageError(e.what());
    }
    film.check_work(rows, false);
    const std::vector<double> thicknesses =
        thickness_range ? thickness_range->values() : std::vector<double>{0.0};
    const std::vector<double> angles =
        angle_range ? angle_range->values() : std::vector<double>{c.args.angle_deg};

    std::string out = "thickness_nm,angle_deg,cos_theta,X,Y,Z,R_linear,G_linear,B_linear\n";
    std::size_t aliased = 0;
    double first_aliased_nm = 0.0, first_aliased_deg = 0.0;
    for (const double angle_deg : angles) {
        const double angle = angle_deg * std::numbers::pi / 180.0;
        // The film at one angle, prepared once for every thickness.
        const std::unique_ptr<FilmAtAngle> row = film.model->at_angle(angle);
        for (const double t : thicknesses) {
            const FilmColor fc = row->color(t, colorimeter);
            if (row->aliases(t) && aliased++ == 0) {
                first_aliased_nm = t;
                first_aliased_deg = angle_deg;
            }
            const double thickness = film.model->effective_thickness_nm(angle).value_or(t);
            append_csv_line(out, std::array{thickness, angle_deg, std::cos(angle), fc.xyz.X, fc.xyz.Y,
                                            fc.xyz.Z, fc.rgb_linear.r, fc.rgb_linear.g, fc.rgb_linear.b});
        }
    }
    if (aliased > 0) {
        // Said, not hidden: summing these finer would cost up to about 65 times the work the
        // request's limit counts (docs/OPTICS.md, "Where the 1 nm sum aliases").
        fmt::print(stderr,
                   "irid film-table: note: {} of the colours (the first at {} nm, {} deg) are 1 nm sums that alias "
                   "(the film's round trips stay strong past 0.7 x 380^2 nm of path); irid film --color gives each "
                   "one summed finely enough\n",
                   aliased, format_shortest(first_aliased_nm), format_shortest(first_aliased_deg));
    }
    if (c.output.empty() || c.output == "-") write_stdout(out);
    else
        io::write_output_file(c.output, out);
    return exit_success;
}

}  // namespace

void add_film_table_command(CLI::App& app, Runner& runner) {
    auto command = std::make_shared<FilmTableCommand>();
    CLI::App* cmd = app.add_subcommand(
        "film-table", "A colour table (thesis §3.3): film thickness (× angle) → XYZ and linear RGB");
    add_film_options(*cmd, command->args, false);
    cmd->add_option("--thickness", command->thickness, "START:END:STEP of the film's thickness [nm]");
    cmd->add_option("--angles", command->angles,
                    "START:END:STEP of angles of incidence [degrees, < 90]; default: --angle");
    cmd->add_option("-o,--output", command->output, "Output CSV file (written when complete); default stdout");
    cmd->callback([command, &runner] { runner = [command] { return run_film_table(*command); }; });
}

}  // namespace irid::cli
