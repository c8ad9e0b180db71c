#pragma once

// Options shared by `irid film` and `irid film-table`: the film (model, media, layers, angle),
// the colour settings, and their parsing into library objects. Every value is checked when it is
// parsed and a bad one is a UsageError naming the option and the allowed range (exit 2).

#include "../cli_common.h"

#include <irid/optics/film_color.h>
#include <irid/optics/material.h>
#include <irid/optics/multilayer.h>
#include <irid/optics/thesis_models.h>

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace irid::cli {

enum class FilmModel { exact, thesis, thesis_multilayer, morpho };

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
    /// --K when given; otherwise the model's physical default (see Film::k).
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

/// One layer of the --layer option: material and thickness (absent for "N" alone).
struct LayerArgument {
    Material material;
    std::optional<double> thickness_nm;
};

/// The parsed film: everything checked.
struct Film {
    FilmModel model = FilmModel::exact;
    Material ambient = Material::constant("air", 1.0);
    Material substrate = Material::constant("air", 1.0);
    std::vector<LayerArgument> layers;
    double angle_rad = 0.0;
    Polarization polarization = Polarization::unpolarized;
    std::optional<bool> phase_change;
    /// The thesis' K: --K when given, otherwise thesis_matched_k of the film (--model thesis)
    /// or thesis_unit_peak_k of the periods (thesis-multilayer, morpho), the values the renderer
    /// and `irid film-error` use. Unused by the exact model.
    double k = 1.0;
    int periods = 12;
    MorphoParameters morpho;
    std::optional<MorphoBlend> blend;

    /// Reflectance (and transmittance, exact model only) as a function of wavelength [nm] at an
    /// angle, for the film with the varied thickness (the single layer's, or the multilayer's
    /// period) replaced when given. The stack is built once, here, not per wavelength.
    [[nodiscard]] std::function<Optics(double)> spectrum(
        double angle_rad, std::optional<double> thickness_nm = std::nullopt) const;
    /// The colour at 1 nm over 360-830 nm.
    [[nodiscard]] FilmColor color(const Colorimeter& colorimeter, double angle_rad,
                                  std::optional<double> thickness_nm = std::nullopt) const;
    /// The eq. 29 effective thickness (Morpho) at an angle.
    [[nodiscard]] double morpho_thickness_nm(double angle_rad) const;
    /// Checks the work of a request against the library's limits before anything is computed:
    /// colours (color(), one spectrum on the 1 nm grid each) for the product of `spectra`, or,
    /// with `at_wavelengths`, spectrum() at the product of `spectra` (the --wavelengths). The
    /// film adds what each wavelength costs (its layers, a blend's samples). Throws UsageError
    /// naming the factors, the total and the limit.
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
