// irid film-error: how far the thesis' single-film model (eq. 21/22 with eq. 24) is from the
// exact Airy model, in CIEDE2000, over thickness × angle, for a soap film and oil on water.
//
//   irid film-error [--film soap|oil-on-water|all] [--thickness 0:1500:5] [--angles 0:80:5]
//                   [--K matched|VALUE] [--illuminant D65] [--observer cie1931]
#include "film_options.h"

#include <irid/color.h>

#include <fmt/core.h>

#include <charconv>

namespace irid::cli {
namespace {

struct FilmErrorCommand {
    std::string film = "all";
    std::string thickness = "0:1500:5";
    std::string angles = "0:80:5";
    std::string k = "matched";
    FilmArguments colour;
};

std::string report(const ErrorStudyResult& r, bool k_matched) {
    std::string s = fmt::format("== {} (K = {:.4f}{}) ==\n", r.name, r.k,
                                k_matched ? ", matched: |r01| + |r12| at normal incidence" : "");
    s += fmt::format("samples {}  mean {:.3f}  median {:.3f}  p95 {:.3f}  max {:.3f}\n", r.samples,
                     r.mean, r.median, r.p95, r.max);
    s += fmt::format("worst: thickness {} nm at {} degrees\n", format_shortest(r.worst_thickness_nm),
                     format_shortest(r.worst_angle_deg));
    s += "angle_deg,mean_delta_e2000,max_delta_e2000\n";
    for (std::size_t i = 0; i < r.angles_deg.size(); ++i) {
        s += fmt::format("{},{:.3f},{:.3f}\n", format_shortest(r.angles_deg[i]), r.mean_by_angle[i],
                         r.max_by_angle[i]);
    }
    s += "thickness_band_nm,mean_delta_e2000\n";
    for (std::size_t b = 0; b < r.mean_by_thickness_band.size(); ++b) {
        s += fmt::format("{}-{},{:.3f}\n", b * 100, (b + 1) * 100, r.mean_by_thickness_band[b]);
    }
    return s;
}

int run_film_error(const FilmErrorCommand& c) {
    const Colorimeter colorimeter = parse_colorimeter(c.colour);
    const Range thickness = parse_range(c.thickness, "--thickness", 0.0, 1e5, 100000);
    const Range angles = parse_range(c.angles, "--angles", 0.0, 90.0, 10000);
    if (thickness.start != 0.0 || angles.start != 0.0) {
        throw UsageError("--thickness and --angles start at 0 (the study covers 0..END)");
    }
    if (angles.end >= 90.0) throw UsageError("--angles: END must be < 90 degrees");
    ErrorStudyOptions options{thickness.end, thickness.step, angles.end, angles.step, std::nullopt};
    if (c.k != "matched") {
        double k = 0.0;
        const auto [end, ec] = std::from_chars(c.k.data(), c.k.data() + c.k.size(), k);
        if (ec != std::errc() || end != c.k.data() + c.k.size() || !(k > 0.0 && std::isfinite(k))) {
            throw UsageError("--K '" + c.k + "' must be 'matched' or a number > 0");
        }
        options.k = k;
    }
    const Material air = *find_material("air");
    const Material water = *find_material("water");
    const std::pair<std::string, SingleFilm> films[] = {
        {"soap", {air, water, air}},
        {"oil-on-water", {air, *find_material("mineral-oil"), water}},
    };
    if (c.film != "all" && c.film != "soap" && c.film != "oil-on-water") {
        throw UsageError("--film '" + c.film + "' is unknown; valid: soap, oil-on-water, all");
    }
    // The grid is the product of --thickness and --angles (and both films for --film all): its
    // total work is checked before any study runs.
    try {
        validate_error_study(options, c.film == "all" ? 2.0 : 1.0, "--thickness " + c.thickness,
                             "--angles " + c.angles, "--film all");
    } catch (const Error& e) {
        throw UsageError(e.what());
    }
    std::string out;
    for (const auto& [name, film] : films) {
        if (c.film != "all" && c.film != name) continue;
        if (!out.empty()) out += "\n";
        out += report(thesis_error_study(name, film, colorimeter, options), !options.k);
    }
    write_stdout(out);
    return exit_success;
}

}  // namespace

void add_film_error_command(CLI::App& app, Runner& runner) {
    auto command = std::make_shared<FilmErrorCommand>();
    CLI::App* cmd = app.add_subcommand(
        "film-error", "CIEDE2000 between the thesis' single-film model and the exact Airy model");
    cmd->add_option("--film", command->film, "soap, oil-on-water or all")->capture_default_str();
    cmd->add_option("--thickness", command->thickness, "0:END:STEP [nm]")->capture_default_str();
    cmd->add_option("--angles", command->angles, "0:END:STEP [degrees, END < 90]")->capture_default_str();
    cmd->add_option("--K", command->k, "The thesis' amplitude: 'matched' or a number")
        ->capture_default_str();
    cmd->add_option("--illuminant", command->colour.illuminant, "D65, D50, A, E, D<CCT>")
        ->capture_default_str();
    cmd->add_option("--observer", command->colour.observer, "cie1931 or cie1964")->capture_default_str();
    cmd->callback([command, &runner] { runner = [command] { return run_film_error(*command); }; });
}

}  // namespace irid::cli
