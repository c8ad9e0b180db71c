#pragma once

// Options shared by `irid film` and `irid film-table`: the film (model, media, layers, angle),
// the colour settings, and their parsing into library objects. Every value is checked when it is
// parsed and a bad one is a UsageError naming the option and the allowed range (exit 2).

#include "../cli_common.h"

#include <irid/optics/film.h>
#include <irid/optics/film_builder.h>
#include <irid/optics/renderer_films.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace irid::cli {

/// A START:END:STEP range as given on the command line.
struct Range {
    double start = 0.0, end = 0.0, step = 1.0;
    /// start, start + step, ... up to end (inclusive within rounding).
    [[nodiscard]] std::vector<double> values() const;
    /// How many values values() holds, without making them.
    [[nodiscard]] std::size_t count() const;
};

/// The raw option strings, as CLI11 fills them.
struct FilmArguments {
    std::string model = "exact";
    std::string ambient = "air";
    std::string substrate = "air";
    std::vector<std::string> layers;
    double angle_deg = 0.0;
    std::string polarization = "unpolarized";
    std::string wavelengths = "380:780:5";
    bool phase_change = false;
    bool no_phase_change = false;
    /// --K when given; otherwise the model's physical default (ThesisFilm, ThesisMultilayerFilm).
    double k = 1.0;
    int periods = 12;
    double d1_nm = 150.0, d2_nm = 50.0, n = 1.56;
    bool blend = false;
    std::string blend_vary = "d1";
    std::string illuminant = "D65";
    std::string observer = "cie1931";
    std::string rgb = "srgb";
    /// The command the options belong to, to ask which were given.
    const CLI::App* command = nullptr;
};

/// Registers the film options on a command.
void add_film_options(CLI::App& cmd, FilmArguments& a, bool thickness_required);

/// The parsed film options: the library's film model (irid/optics/film.h) and the angle.
struct Film {
    std::shared_ptr<const FilmModel> model;
    double angle_rad = 0.0;

    /// FilmModel::check_work with the options' names, a UsageError when over the limits.
    void check_work(std::vector<WorkFactor> spectra, bool at_wavelengths) const;
};

/// Parses and checks the film options. `thickness_required`: every --layer needs :THICKNESS.
[[nodiscard]] Film parse_film(const FilmArguments& a, bool thickness_required);
/// A renderer's film model (`--model gltf|belcour|cycles`): one real film on a base.
struct RendererFilmRequest {
    RendererFilmModel model = RendererFilmModel::gltf;
    RendererFilmInputs inputs;
    double thickness_nm = 0.0;
    double angle_rad = 0.0;
};
/// Parses and checks the film options for a renderer's model: exactly one --layer INDEX:THICKNESS
/// of a real film; the options of the other models are refused, and so are --illuminant,
/// --observer and --rgb other than their defaults (the models' sensitivities are fixed: CIE 1931,
/// linear Rec.709, white D65).
[[nodiscard]] RendererFilmRequest parse_renderer_film(const FilmArguments& a);
/// Throws UsageError unless --illuminant, --observer (and --rgb, when `rgb`) keep their defaults:
/// `what` says why ("the renderers' film models have fixed sensitivities").
void require_default_colorimeter(const FilmArguments& a, bool rgb, const std::string& what);
/// The header and line of a colour: X,Y,Z,x,y,L,a,b,R_linear,G_linear,B_linear.
[[nodiscard]] std::string color_lines(const FilmColor& c, const Colorimeter& colorimeter);

/// Parses and checks --illuminant, --observer, --rgb.
[[nodiscard]] Colorimeter parse_colorimeter(const FilmArguments& a);
/// Parses START:END:STEP for `option`: start >= minimum, end >= start, step > 0, at most
/// max_count values. Throws UsageError naming the option.
[[nodiscard]] Range parse_range(const std::string& text, const char* option, double minimum,
                                double maximum, std::size_t max_count);

}  // namespace irid::cli
