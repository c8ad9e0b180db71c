// irid film-error: how far a film model is from the exact Airy model, in CIEDE2000, over
// thickness × angle. The thesis' single-film model (eq. 21/22 with eq. 24, the default) for a soap
// film and oil on water; or the renderers' models (gltf, belcour, cycles) and the thesis' over the
// grid of film indices 1.2, 1.33, 1.5, 2.0 on air, water, glass and gold.
//
//   irid film-error [--model thesis] [--film soap|oil-on-water|all] [--thickness 0:1500:5]
//                   [--angles 0:80:5] [--K matched|VALUE] [--illuminant D65] [--observer cie1931]
//   irid film-error --model thesis|gltf|belcour|cycles --film grid|NAME [--thickness 0:2000:5]
//                   [--angles 0:85:5]
#include "film_options.h"

#include <irid/color.h>
#include <irid/optics/film_error_study.h>

#include <fmt/core.h>

#include <charconv>
#include <optional>

namespace irid::cli {
namespace {

struct FilmErrorCommand {
    std::string model = "thesis";
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

ErrorStudyOptions parse_options(const FilmErrorCommand& c) {
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
    return options;
}

std::string percent(double fraction) { return fmt::format("{:.1f}", 100.0 * fraction); }

std::string region_report(const std::string& model, const FilmErrorRegions& f) {
    const ErrorStudyResult& r = f.summary;
    std::string s = fmt::format("== {}: {} ==\n", model, r.name);
    s += fmt::format("samples {}  mean {:.3f}  median {:.3f}  p95 {:.3f}  max {:.3f}\n", r.samples, r.mean,
                     r.median, r.p95, r.max);
    s += fmt::format("worst: thickness {} nm at {} degrees\n", format_shortest(r.worst_thickness_nm),
                     format_shortest(r.worst_angle_deg));
    s += fmt::format("above 2: {} % of samples  above 5: {} %\n", percent(f.above_2), percent(f.above_5));
    s += "angle_deg,mean_delta_e2000,max_delta_e2000,percent_above_2,percent_above_5\n";
    for (std::size_t i = 0; i < r.angles_deg.size(); ++i) {
        s += fmt::format("{},{:.3f},{:.3f},{},{}\n", format_shortest(r.angles_deg[i]), r.mean_by_angle[i],
                         r.max_by_angle[i], percent(f.above_2_by_angle[i]), percent(f.above_5_by_angle[i]));
    }
    s += "thickness_band_nm,mean_delta_e2000,percent_above_2,percent_above_5\n";
    for (std::size_t b = 0; b < r.mean_by_thickness_band.size(); ++b) {
        s += fmt::format("{}-{},{:.3f},{},{}\n", b * 100, (b + 1) * 100, r.mean_by_thickness_band[b],
                         percent(f.above_2_by_band[b]), percent(f.above_5_by_band[b]));
    }
    return s;
}

/// The grid study (or one of its films, or soap / oil-on-water) for any model, with the regions
/// where it fails and a summary table at the end.
int run_grid_study(const FilmErrorCommand& c, const std::optional<RendererFilmModel>& renderer,
                   bool fourier, const ErrorStudyOptions& options) {
    std::vector<StudyFilm> films;
    for (StudyFilm& f : renderer_study_films()) {
        if (c.film == "grid" || c.film == f.name) films.push_back(std::move(f));
    }
    const Material air = *find_material("air");
    const Material water = *find_material("water");
    if (c.film == "soap" || c.film == "all") films.push_back({"soap", {air, water, air}, false});
    if (c.film == "oil-on-water" || c.film == "all") {
        films.push_back({"oil-on-water", {air, *find_material("mineral-oil"), water}, false});
    }
    if (films.empty()) {
        std::string valid = "grid, all, soap, oil-on-water";
        for (const StudyFilm& f : renderer_study_films()) valid += ", " + f.name;
        throw UsageError(fmt::format("--film '{}' is unknown; valid: {}", c.film, valid));
    }
    try {
        const auto validate = renderer || fourier ? validate_renderer_error_study : validate_error_study;
        validate(options, static_cast<double>(films.size()), "--thickness " + c.thickness,
                 "--angles " + c.angles, "--film " + c.film);
    } catch (const Error& e) {
        throw UsageError(e.what());
    }
    std::string out;
    if (renderer) {
        const Rgb w = renderer_sensitivity_white(*renderer);
        const Xyz white = srgb().to_xyz(w);
        const Xyz& ref = srgb().white_xyz();
        out += fmt::format(
            "limits: reflecting nothing gives RGB 0,0,0; reflecting everything (the sensitivity at "
            "OPD 0) gives RGB {:.4f},{:.4f},{:.4f}, ΔE2000 {:.2f} from the D65 white\n\n",
            w.r, w.g, w.b,
            delta_e_2000(xyz_to_lab(white, ref), xyz_to_lab(ref, ref)));
    }
    std::string table = "model,film,mean,median,p95,max,worst_thickness_nm,worst_angle_deg,percent_above_2,percent_above_5\n";
    for (const StudyFilm& f : films) {
        if (!renderer && !fourier && f.metal) {
            out += fmt::format("== thesis: {} ==\nn/a: the thesis' closed forms take real indices and "
                               "gold absorbs\n\n",
                               f.name);
            table += fmt::format("thesis,{},n/a,n/a,n/a,n/a,n/a,n/a,n/a,n/a\n", f.name);
            continue;
        }
        const FilmErrorMap map = renderer  ? renderer_film_error_map(*renderer, f.film, options)
                                 : fourier ? fourier_film_error_map(f.film, options)
                                           : thesis_film_error_map(f.film, options);
        const FilmErrorRegions regions = summarize_film_error(f.name, map);
        out += region_report(c.model, regions) + "\n";
        const ErrorStudyResult& r = regions.summary;
        table += fmt::format("{},{},{:.3f},{:.3f},{:.3f},{:.3f},{},{},{},{}\n", c.model, f.name, r.mean,
                             r.median, r.p95, r.max, format_shortest(r.worst_thickness_nm),
                             format_shortest(r.worst_angle_deg), percent(regions.above_2),
                             percent(regions.above_5));
    }
    write_stdout(out + "== summary ==\n" + table);
    return exit_success;
}

int run_film_error(const FilmErrorCommand& c) {
    const auto given = [&](const char* option) {
        return c.colour.command && c.colour.command->count(option) > 0;
    };
    std::optional<RendererFilmModel> renderer;
    const bool fourier = c.model == "fourier";
    if (c.model != "thesis" && !fourier) {
        renderer = find_renderer_film_model(c.model);
        if (!renderer) {
            throw UsageError("--model '" + c.model +
                             "' is unknown; valid: thesis, gltf, belcour, cycles, fourier");
        }
    }
    const bool other = renderer || fourier;
    const bool grid = other || (c.film != "soap" && c.film != "oil-on-water" && c.film != "all");
    if (grid) {
        if (other && given("--K")) throw UsageError("--K does not apply to --model " + c.model);
        require_default_colorimeter(c.colour, false,
                                    "the grid study compares under D65 and CIE 1931 2° (the "
                                    "renderers' fixed sensitivities)");
        FilmErrorCommand g = c;
        if (!given("--film") && other) g.film = "grid";
        if (!given("--thickness")) g.thickness = "0:2000:5";
        if (!given("--angles")) g.angles = "0:85:5";
        ErrorStudyOptions options = parse_options(g);
        return run_grid_study(g, renderer, fourier, options);
    }
    const Colorimeter colorimeter = parse_colorimeter(c.colour);
    ErrorStudyOptions options = parse_options(c);
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
        "film-error",
        "CIEDE2000 between a film model (the thesis' single film, or a renderer's) and the exact "
        "Airy model");
    command->colour.command = cmd;
    cmd->add_option("--model", command->model,
                    "thesis (eq. 21/22), gltf (KHR_materials_iridescence), belcour (Belcour & Barla "
                    "2017), cycles (Blender Cycles) or fourier (irid's exact Fourier film colour, "
                    "--integration fourier)")
        ->capture_default_str();
    cmd->add_option("--film", command->film,
                    "soap, oil-on-water, all (the two), grid (film indices 1.2, 1.33, 1.5, 2 on air, "
                    "water, glass, gold; the default for gltf, belcour, cycles, fourier) or one of the "
                    "grid's films, e.g. n1.33-on-air")
        ->capture_default_str();
    cmd->add_option("--thickness", command->thickness, "0:END:STEP [nm] (the grid's default: 0:2000:5)")
        ->capture_default_str();
    cmd->add_option("--angles", command->angles,
                    "0:END:STEP [degrees, END < 90] (the grid's default: 0:85:5)")
        ->capture_default_str();
    cmd->add_option("--K", command->k, "The thesis' amplitude: 'matched' or a number")
        ->capture_default_str();
    cmd->add_option("--illuminant", command->colour.illuminant, "D65, D50, A, E, D<CCT>")
        ->capture_default_str();
    cmd->add_option("--observer", command->colour.observer, "cie1931 or cie1964")->capture_default_str();
    cmd->callback([command, &runner] { runner = [command] { return run_film_error(*command); }; });
}

}  // namespace irid::cli
