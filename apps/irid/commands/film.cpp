// irid film: the reflectance spectrum (or colour) of a film or stack of films.
//
//   irid film --layer water:350 [--ambient air] [--substrate air] [--angle 30]
//             [--polarization s|p|unpolarized] [--wavelengths 380:780:5]       → wavelength_nm,R,T
//   irid film --model thesis --layer 1.33:350 [--phase-change|--no-phase-change] [--K K]
//   irid film --model thesis-multilayer --layer 1.56:100 --periods 12 [--K K]  → wavelength_nm,R
//   irid film --model morpho [--d1 150] [--d2 50] [--n 1.56] [--periods 12] [--blend] [--K K]
//   ... --color [--illuminant D65] [--observer cie1931] [--rgb srgb]            → one colour line
//   ... --color --integration fourier   the exact single film's colour by the Fourier series
//                                       (irid/optics/fourier_film.h); sum (the 1 nm sum) default
//   irid film --model gltf|belcour|cycles --layer 1.33:350 [--ambient air] [--substrate gold]
//             [--angle 30]                                      → one colour line (--color implied)
//
// K defaults to the physical values the renderer uses (the matched |r01| + |r12| for the single
// film, 2/(l+1)² for eq. 25); --K 1 is the thesis as written. The work of a run (wavelengths ×
// layers, the lines written) is checked against the library's limits before anything is computed.
#include "film_options.h"

#include <irid/color.h>
#include <irid/optics/fourier_film.h>

#include <array>
#include <cmath>

#include <fmt/core.h>

namespace irid::cli {
namespace {

struct FilmCommand {
    FilmArguments args;
    bool color = false;
    std::string integration = "sum";
};

/// The colour by the chosen integration; the Fourier series only for what it covers (an exact,
/// unpolarised, lossless single film), a UsageError otherwise.
FilmColor film_color(const FilmCommand& c, const Film& film, const Colorimeter& colorimeter) {
    FilmIntegration integration = FilmIntegration::sum;
    try {
        integration = parse_film_integration(c.integration);
    } catch (const Error& e) {
        throw UsageError(fmt::format("--integration: {}", e.what()));
    }
    if (integration == FilmIntegration::sum) return film.model->color(colorimeter, film.angle_rad);
    if (!c.color) throw UsageError("--integration fourier needs --color (it gives a colour, not a spectrum)");
    const SingleFilm single = [&] {
        try {
            return fourier_single_film(*film.model);
        } catch (const Error& e) {
            throw UsageError(fmt::format("--integration fourier: {}; use --integration sum", e.what()));
        }
    }();
    const FourierFilm fourier(single, fourier_colorimeter_for(single, colorimeter));
    return fourier.color(film.model->thickness_nm(), std::cos(film.angle_rad));
}

int run_renderer_film(const FilmCommand& c) {
    // Colour models: --color is implied, and the colour is read as a Rec.709 reflectance.
    if (c.integration != "sum") {
        throw UsageError("--integration does not apply to --model " + c.args.model +
                         " (the model has its own integration)");
    }
    const RendererFilmRequest r = parse_renderer_film(c.args);
    const FilmColor fc = renderer_film_color(r.model, r.inputs, r.thickness_nm, r.angle_rad);
    write_stdout(color_lines(fc, Colorimeter()));
    return exit_success;
}

int run_film(const FilmCommand& c) {
    if (find_renderer_film_model(c.args.model)) return run_renderer_film(c);
    const Film film = parse_film(c.args, true);
    // Every option is checked, whether or not this run uses it.
    const Colorimeter colorimeter = parse_colorimeter(c.args);
    // The dispersion fits (water, silica) and the metal tables hold over about 200-2000 nm.
    const Range range = parse_range(c.args.wavelengths, "--wavelengths", 200.0, 2000.0, 1000000);
    if (c.integration != "sum" && !c.color) {
        throw UsageError("--integration needs --color (a spectrum is not integrated)");
    }
    if (c.color) {
        film.check_work({}, false);
    } else {
        const std::vector<WorkFactor> lines{
            {"--wavelengths " + c.args.wavelengths, static_cast<double>(range.count())}};
        try {
            check_output_rows(lines);
        } catch (const Error& e) {
            throw UsageError(e.what());
        }
        film.check_work(lines, true);
    }
    std::string out;
    if (c.color) {
        out = color_lines(film_color(c, film, colorimeter), colorimeter);
    } else {
        const bool exact = film.model->has_transmittance();
        out = exact ? "wavelength_nm,R,T\n" : "wavelength_nm,R\n";
        const auto at = film.model->spectrum(film.angle_rad);
        for (const double lambda : range.values()) {
            const Optics o = at(lambda);
            if (exact) append_csv_line(out, std::array{lambda, o.R, o.T});
            else append_csv_line(out, std::array{lambda, o.R});
        }
    }
    write_stdout(out);
    return exit_success;
}

}  // namespace

void add_film_command(CLI::App& app, Runner& runner) {
    auto command = std::make_shared<FilmCommand>();
    CLI::App* cmd = app.add_subcommand(
        "film", "Reflectance spectrum (CSV) or colour of a thin film or stack: the exact optics or "
                "the thesis' models");
    add_film_options(*cmd, command->args, true);
    cmd->add_option("--wavelengths", command->args.wavelengths,
                    "START:END:STEP in nm, within 200-2000 (T is the power entering the substrate: "
                    "what it absorbs, when it absorbs)")
        ->capture_default_str();
    cmd->add_flag("--color", command->color,
                  "Print the colour (X,Y,Z,x,y,L,a,b,R_linear,G_linear,B_linear) instead of the spectrum");
    cmd->add_option("--integration", command->integration,
                    "With --color: sum (the CIE 1 nm sum) or fourier (the exact single film's Airy "
                    "series against the transformed matching functions: one lossless layer, "
                    "unpolarised; within ΔE2000 0.025 of the sum over 0-2000 nm x 0-85 degrees for constant "
                    "indices, the sum itself where the series' model fails; see "
                    "docs/OPTICS.md)")
        ->capture_default_str();
    cmd->callback([command, &runner] { runner = [command] { return run_film(*command); }; });
}

}  // namespace irid::cli
