#pragma once

// Options shared by `irid film` and `irid film-table`: the film (model, media, layers, angle),
// the colour settings, and their parsing into library objects. Every value is checked when it is
// parsed and a bad one is a UsageError naming the option and the allowed range (exit 2).

#include "../cli_common.h"

#include <irid/optics/film.h>

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
/// Parses and checks --illuminant, --observer, --rgb.
[[nodiscard]] Colorimeter parse_colorimeter(const FilmArguments& a);
/// Parses START:END:STEP for `option`: start >= minimum, end >= start, step > 0, at most
/// max_count values. Throws UsageError naming the option.
[[nodiscard]] Range parse_range(const std::string& text, const char* option, double minimum,
                                double maximum, std::size_t max_count);

}  // namespace irid::cli
