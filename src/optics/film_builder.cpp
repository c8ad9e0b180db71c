#include <irid/color/numeric_table.h>
#include <irid/error.h>
#include <irid/optics/film_builder.h>
#include <irid/optics/film_color.h>

#include <fmt/core.h>

#include <cmath>
#include <utility>
#include <vector>

namespace irid {
namespace {

/// The parameters of a spec that a model may refuse.
enum class Parameter { ambient, substrate, layers, polarization, phase_change, k, periods, d1, d2, n, blend, blend_vary };

bool given(const FilmSpec& s, Parameter p) {
    switch (p) {
        case Parameter::ambient: return s.ambient.has_value();
        case Parameter::substrate: return s.substrate.has_value();
        case Parameter::layers: return !s.layers.empty();
        case Parameter::polarization: return s.polarization.has_value();
        case Parameter::phase_change: return s.phase_change.has_value();
        case Parameter::k: return s.k.has_value();
        case Parameter::periods: return s.periods.has_value();
        case Parameter::d1: return s.d1_nm.has_value();
        case Parameter::d2: return s.d2_nm.has_value();
        case Parameter::n: return s.n.has_value();
        case Parameter::blend: return s.blend || s.blend_min_nm || s.blend_max_nm || s.blend_samples;
        case Parameter::blend_vary: return s.blend_varies.has_value();
    }
    return false;
}

const std::string& name_of(const FilmSpecNames& names, Parameter p) {
    switch (p) {
        case Parameter::ambient: return names.ambient;
        case Parameter::substrate: return names.substrate;
        case Parameter::layers: return names.layers;
        case Parameter::polarization: return names.polarization;
        case Parameter::phase_change: return names.phase_change;
        case Parameter::k: return names.k;
        case Parameter::periods: return names.periods;
        case Parameter::d1: return names.d1;
        case Parameter::d2: return names.d2;
        case Parameter::n: return names.n;
        case Parameter::blend: return names.blend;
        case Parameter::blend_vary: return names.blend_vary;
    }
    return names.model;
}

/// What each model refuses: the parameters of the other models.
std::vector<Parameter> refused_by(FilmModelKind kind) {
    using P = Parameter;
    switch (kind) {
        case FilmModelKind::exact:
            return {P::phase_change, P::k, P::periods, P::d1, P::d2, P::n, P::blend, P::blend_vary};
        case FilmModelKind::thesis: return {P::polarization, P::periods, P::d1, P::d2, P::n, P::blend, P::blend_vary};
        case FilmModelKind::thesis_multilayer:
            // Eq. 26 assumes air around the films.
            return {P::ambient, P::substrate, P::polarization, P::phase_change, P::d1, P::d2, P::n, P::blend,
                    P::blend_vary};
        case FilmModelKind::morpho:
            return {P::ambient, P::substrate, P::layers, P::polarization, P::phase_change};
    }
    return {};
}

std::string layer_name(const FilmSpecNames& names, std::size_t i) {
    return names.layer ? names.layer(i) : fmt::format("{}[{}]", names.layers, i);
}

}  // namespace

FilmSpec single_film_spec(FilmModelKind model, const SingleFilm& film, std::optional<double> thickness_nm) {
    FilmSpec spec;
    spec.model = model;
    spec.ambient = film.ambient;
    spec.substrate = film.substrate;
    spec.layers.push_back({film.film, thickness_nm});
    spec.thickness_required = thickness_nm.has_value();
    return spec;
}

FilmSpecNames command_line_film_names() {
    FilmSpecNames n;
    n.model = "--model";
    n.ambient = "--ambient";
    n.substrate = "--substrate";
    n.layers = "--layer";
    n.polarization = "--polarization";
    n.phase_change = "--phase-change";
    n.k = "--K";
    n.periods = "--periods";
    n.d1 = "--d1";
    n.d2 = "--d2";
    n.n = "--n";
    n.blend = "--blend";
    n.blend_vary = "--blend-vary";
    return n;
}

std::shared_ptr<FilmModel> build_film(const FilmSpec& spec, const FilmSpecNames& names) {
    const std::string model = std::string(film_model_name(spec.model));
    for (const Parameter p : refused_by(spec.model)) {
        if (given(spec, p)) {
            throw Error(fmt::format("{} does not apply to {} {}", name_of(names, p), names.model, model));
        }
    }
    if (spec.ambient && !spec.ambient->is_lossless()) {
        throw Error(fmt::format("{} '{}' absorbs (k > 0); the ambient must have k = 0", names.ambient,
                                spec.ambient->name()));
    }
    if (spec.k && !(*spec.k > 0.0 && std::isfinite(*spec.k))) {
        throw Error(fmt::format("{} {} must be a finite number > 0", names.k, format_shortest(*spec.k)));
    }
    if (spec.blend_varies && !spec.blend) {
        throw Error(fmt::format("{} needs {}", names.blend_vary, names.blend));
    }
    if ((spec.blend_min_nm || spec.blend_max_nm || spec.blend_samples) && !spec.blend) {
        throw Error(fmt::format("{} need {}", names.blend_range, names.blend));
    }
    // "periods 0 must be in 1..1000000 (...)" in the caller's name for periods.
    const auto check_periods = [&](int periods) {
        try {
            check_thesis_periods(periods);
        } catch (const Error& e) {
            const std::string what = e.what();
            throw Error(names.periods + what.substr(what.find(' ')));
        }
    };
    const auto need_layers = [&](std::size_t count) {
        if (spec.layers.size() != count) {
            throw Error(fmt::format("{} {} takes exactly {} {}, found {}", names.model, model, count, names.layers,
                                    spec.layers.size()));
        }
    };
    const auto thickness = [&](std::size_t i) {
        const auto& t = spec.layers[i].thickness_nm;
        if (!t && spec.thickness_required) {
            throw Error(fmt::format("{}: the thickness is required", layer_name(names, i)));
        }
        return t.value_or(0.0);
    };
    // The thesis' closed forms take real indices: an absorbing film or substrate is refused, as
    // the renderer refuses absorbing films, rather than its k silently dropped.
    const auto thesis_material = [&](const Material& m, const char* role, const std::string& name) {
        try {
            check_thesis_material(m, role);
        } catch (const Error& e) {
            throw Error(fmt::format("{}: {}; use {} exact", name, e.what(), names.model));
        }
    };
    const Material air = *find_material("air");
    const Material ambient = spec.ambient.value_or(air), substrate = spec.substrate.value_or(air);
    switch (spec.model) {
        case FilmModelKind::exact: {
            if (spec.layers.empty()) {
                throw Error(fmt::format("{} is required: give at least one layer", names.layers));
            }
            if (!spec.thickness_required) need_layers(1);
            std::vector<Layer> stack;
            for (std::size_t i = 0; i < spec.layers.size(); ++i) stack.push_back({spec.layers[i].material, thickness(i)});
            return std::make_shared<ExactFilm>(ambient, std::move(stack), substrate,
                                               spec.polarization.value_or(Polarization::unpolarized));
        }
        case FilmModelKind::thesis: {
            need_layers(1);
            const Material& film = spec.layers.front().material;
            thesis_material(film, "film", layer_name(names, 0));
            thesis_material(substrate, "substrate", fmt::format("{} '{}'", names.substrate, substrate.name()));
            return std::make_shared<ThesisFilm>(SingleFilm{ambient, film, substrate}, thickness(0), spec.k,
                                                spec.phase_change);
        }
        case FilmModelKind::thesis_multilayer: {
            need_layers(1);
            if (!spec.periods) throw Error(fmt::format("{} is required with {} {}", names.periods, names.model, model));
            check_periods(*spec.periods);
            const Material& film = spec.layers.front().material;
            thesis_material(film, "film", layer_name(names, 0));
            return std::make_shared<ThesisMultilayerFilm>(film, thickness(0), *spec.periods, spec.k);
        }
        case FilmModelKind::morpho: {
            const double d1 = spec.d1_nm.value_or(150.0), d2 = spec.d2_nm.value_or(50.0);
            const double n = spec.n.value_or(1.56);
            const int periods = spec.periods.value_or(12);
            for (const auto& [value, name] : {std::pair{d1, &names.d1}, std::pair{d2, &names.d2}}) {
                if (!(std::isfinite(value) && value >= 0.0 && value <= 1e6)) {
                    throw Error(fmt::format("{} {} must be a thickness in [0, 1e6] nm", *name, format_shortest(value)));
                }
            }
            if (!(std::isfinite(n) && n >= 1.0)) {
                throw Error(fmt::format("{} {} must be >= 1 (eq. 29 assumes the wing is in air)", names.n,
                                        format_shortest(n)));
            }
            check_periods(periods);
            std::optional<MorphoBlend> blend;
            if (spec.blend) {
                blend = MorphoBlend{};
                blend->varies = spec.blend_varies.value_or(MorphoBlendThickness::d1);
                blend->min_nm = spec.blend_min_nm.value_or(blend->min_nm);
                blend->max_nm = spec.blend_max_nm.value_or(blend->max_nm);
                blend->samples = spec.blend_samples.value_or(blend->samples);
            }
            return std::make_shared<MorphoFilm>(
                MorphoParameters{d1, d2, n, periods, spec.k ? *spec.k : thesis_unit_peak_k(periods)}, blend);
        }
    }
    throw Error("film: unknown model");
}

}  // namespace irid
