#pragma once

// One way to build a film model from what a caller gives: the model and its parameters, each
// given or left out. The rules live here once: which parameters each model takes (the others
// are refused, never silently ignored), how many layers it needs, and the defaults of the ones
// left out. `irid film`, `irid film-table` and Python's irid.Film translate their own syntax into
// a FilmSpec and build through it; the models' constructors check the values themselves.

#include <irid/optics/film.h>
#include <irid/optics/material.h>
#include <irid/optics/thesis_models.h>

#include <cstddef>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace irid {

/// One layer as given: its material and, unless a table varies it, its thickness [nm].
struct FilmLayerSpec {
    Material material;
    std::optional<double> thickness_nm;
};

/// A film as asked for. Every parameter but the model is optional: left out, it takes the
/// model's default; given to a model that does not take it, build_film refuses it.
struct FilmSpec {
    FilmModelKind model = FilmModelKind::exact;
    /// Both air when left out. exact, thesis.
    std::optional<Material> ambient, substrate;
    /// From the ambient side. exact: one or more (exactly one where a table varies the
    /// thickness); thesis, thesis-multilayer: exactly one; morpho: none.
    std::vector<FilmLayerSpec> layers;
    /// exact (unpolarised when left out).
    std::optional<Polarization> polarization;
    /// thesis: force eq. 21 (true) or eq. 22 (false); left out, eq. 19 decides per wavelength.
    std::optional<bool> phase_change;
    /// The thesis' amplitude K: thesis (thesis_matched_k when left out), thesis-multilayer and
    /// morpho (thesis_unit_peak_k(periods) when left out).
    std::optional<double> k;
    /// thesis-multilayer (required), morpho (12 when left out).
    std::optional<int> periods;
    /// morpho: the air path d1 and the chitin d2 of a period [nm], chitin's index n (150, 50 and
    /// 1.56 when left out; the thesis' Figure 9).
    std::optional<double> d1_nm, d2_nm, n;
    /// morpho: blend over the thickness that `blend_varies` names (d1 unless given), from
    /// blend_min_nm to blend_max_nm in blend_samples steps (MorphoBlend's defaults; §3.7).
    bool blend = false;
    std::optional<MorphoBlendThickness> blend_varies;
    std::optional<double> blend_min_nm, blend_max_nm;
    std::optional<int> blend_samples;
    /// Whether every layer must carry its thickness (false where a table varies it).
    bool thickness_required = true;
};

/// The spec of one film between an ambient and a substrate (for the exact or the thesis' model),
/// its thickness given, or left to a table or a renderer to vary.
[[nodiscard]] FilmSpec single_film_spec(FilmModelKind model, const SingleFilm& film,
                                        std::optional<double> thickness_nm = std::nullopt);

/// How the caller names each parameter in messages: Python's keywords by default, the command
/// line's options in command_line_film_names().
struct FilmSpecNames {
    std::string model = "model", ambient = "ambient", substrate = "substrate", layers = "layers",
                polarization = "polarization", phase_change = "phase_change", k = "k",
                periods = "periods", d1 = "d1", d2 = "d2", n = "n", blend = "blend",
                blend_vary = "blend_vary", blend_range = "blend_min, blend_max, blend_samples";
    /// The i-th layer (from 0) as the caller gave it: "layers[0]" by default.
    std::function<std::string(std::size_t)> layer;
};
[[nodiscard]] FilmSpecNames command_line_film_names();

/// The model the spec asks for. Throws irid::Error naming the parameter (in the caller's names):
/// a parameter the model does not take ("--K does not apply to --model exact"), a layer count
/// the model does not allow, a required parameter left out, a value out of its range (an
/// absorbing film for the thesis' closed forms, a Morpho thickness outside [0, 1e6] nm, ...).
[[nodiscard]] std::shared_ptr<FilmModel> build_film(const FilmSpec& spec, const FilmSpecNames& names = {});

}  // namespace irid
