#include "film_options.h"

#include <irid/color.h>

#include <fmt/core.h>

#include <array>
#include <charconv>
#include <cmath>
#include <numbers>

namespace irid::cli {
namespace {

constexpr double degrees_to_radians = std::numbers::pi / 180.0;

/// A whole string as a finite double, or nothing.
std::optional<double> parse_double(std::string_view s) {
    while (!s.empty() && s.front() == ' ') s.remove_prefix(1);
    while (!s.empty() && s.back() == ' ') s.remove_suffix(1);
    if (!s.empty() && s.front() == '+') s.remove_prefix(1);
    double v = 0.0;
    const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    if (s.empty() || ec != std::errc() || end != s.data() + s.size() || !std::isfinite(v)) {
        return std::nullopt;
    }
    return v;
}

/// One layer of the --layer option: material and thickness (absent for "N" alone).
struct LayerArgument {
    Material material;
    std::optional<double> thickness_nm;
};

Material parse_medium(const std::string& text, const std::string& option) {
    try {
        return parse_material(text);
    } catch (const Error& e) {
        throw UsageError(option + ": " + e.what());
    }
}

LayerArgument parse_layer(const std::string& text, int number, bool thickness_required) {
    const std::string option = "--layer " + std::to_string(number) + " '" + text + "'";
    const auto colon = text.rfind(':');
    if (colon == std::string::npos) {
        if (thickness_required) {
            throw UsageError(option + ": expected INDEX:THICKNESS, e.g. 1.33:350 or water:350 "
                                      "(thickness in nm, >= 0)");
        }
        return {parse_medium(text, option), std::nullopt};
    }
    const std::optional<double> t = parse_double(std::string_view(text).substr(colon + 1));
    if (!t || *t < 0.0) {
        throw UsageError(option + ": thickness '" + text.substr(colon + 1) +
                         "' must be a number of nm >= 0");
    }
    if (*t > 1e6) {
        throw UsageError(option + ": thickness " + format_shortest(*t) + " nm must be <= 1e6 nm (1 mm)");
    }
    return {parse_medium(text.substr(0, colon), option), *t};
}

FilmModelKind parse_model(const std::string& name) {
    if (find_renderer_film_model(name)) {
        throw UsageError("--model " + name +
                         " is a renderer's colour model: it gives a colour, not a spectrum or a "
                         "table (use `irid film --model " + name + " --layer ...`)");
    }
    try {
        return parse_film_model(name);
    } catch (const UnknownNameError&) {
        throw UsageError("--model '" + name +
                         "' is unknown; valid: exact, thesis, thesis-multilayer, morpho (and, "
                         "for irid film, the renderers' gltf, belcour, cycles)");
    }
}

}  // namespace

std::size_t Range::count() const {
    return static_cast<std::size_t>(std::floor((end - start) / step + 1e-9)) + 1;
}

std::vector<double> Range::values() const {
    std::vector<double> v;
    const std::size_t n = count();
    v.reserve(n);
    for (std::size_t i = 0; i < n; ++i) v.push_back(start + step * static_cast<double>(i));
    return v;
}

Range parse_range(const std::string& text, const char* option, double minimum, double maximum,
                  std::size_t max_count) {
    const auto fail = [&](const std::string& why) {
        throw UsageError(std::string(option) + " '" + text + "': " + why);
    };
    const auto first = text.find(':');
    const auto second = first == std::string::npos ? first : text.find(':', first + 1);
    if (second == std::string::npos) fail("expected START:END:STEP");
    const auto start = parse_double(std::string_view(text).substr(0, first));
    const auto end = parse_double(std::string_view(text).substr(first + 1, second - first - 1));
    const auto step = parse_double(std::string_view(text).substr(second + 1));
    if (!start || !end || !step) fail("START, END and STEP must be numbers");
    if (*start < minimum || *end > maximum) {
        fail("values must lie in [" + format_shortest(minimum) + ", " + format_shortest(maximum) +
             (maximum == 90.0 ? ")" : "]"));
    }
    if (*end < *start) fail("the range is reversed: END must be >= START");
    if (!(*step > 0.0)) fail("STEP must be > 0");
    const double count = std::floor((*end - *start) / *step + 1e-9) + 1.0;
    if (count > static_cast<double>(max_count)) {
        fail("more than " + std::to_string(max_count) + " values; use a larger STEP");
    }
    return {*start, *end, *step};
}

void add_film_options(CLI::App& cmd, FilmArguments& a, bool thickness_required) {
    a.command = &cmd;
    cmd.add_option("--model", a.model,
                   "exact, thesis (eq. 21/22), thesis-multilayer (eq. 25/26), morpho (eq. 29); irid "
                   "film also: gltf, belcour, cycles (renderers' colour models)")
        ->capture_default_str();
    cmd.add_option("--ambient", a.ambient,
                   "Index of the ambient medium: 1.33, 1.5+0.02i (n+ik) or a material name")
        ->capture_default_str();
    cmd.add_option("--substrate", a.substrate, "Index of the substrate (same forms)")
        ->capture_default_str();
    cmd.add_option("--layer", a.layers,
                   thickness_required ? "A film INDEX:THICKNESS (nm), from the ambient side; repeatable"
                                      : "The film INDEX (its :THICKNESS is ignored: --thickness varies it)");
    cmd.add_option("--angle", a.angle_deg, "Angle of incidence in the ambient [degrees, 0 <= angle < 90]")
        ->capture_default_str();
    cmd.add_option("--polarization", a.polarization, "s, p or unpolarized (exact model)")
        ->capture_default_str();
    cmd.add_flag("--phase-change", a.phase_change, "Thesis model: force eq. 21 (a π phase change)");
    cmd.add_flag("--no-phase-change", a.no_phase_change, "Thesis model: force eq. 22");
    cmd.add_option("--K", a.k,
                   "The thesis' amplitude factor K (> 0); --K 1 is the thesis as written. Default: "
                   "the physical K the renderer and film-error use: for --model thesis the matched "
                   "K = |r01| + |r12| (normal-incidence Fresnel amplitudes of the film's two faces "
                   "at 555 nm; 0.286 for water in air), so eq. 21/22 peak where the exact film "
                   "does; for thesis-multilayer and morpho K = 2/(l+1)^2, l = --periods (0.0118 "
                   "for 12), so eq. 25 peaks at 1");
    cmd.add_option("--periods", a.periods, "Number of films l in eq. 25 (thesis-multilayer; morpho default 12)");
    cmd.add_option("--d1", a.d1_nm, "Morpho: path in air per period d1 [nm]")->capture_default_str();
    cmd.add_option("--d2", a.d2_nm, "Morpho: chitin mullion thickness d2 [nm]")->capture_default_str();
    cmd.add_option("--n", a.n, "Morpho: index of chitin (>= 1)")->capture_default_str();
    cmd.add_flag("--blend", a.blend, "Morpho: average over thicknesses 50..150 nm (thesis §3.7)");
    cmd.add_option("--blend-vary", a.blend_vary,
                   "Morpho blend: d1 (the spacing; keeps the wing blue as in Figure 9) or d2 (the chitin)")
        ->capture_default_str();
    cmd.add_option("--illuminant", a.illuminant, "D65, D50, A, E, D<CCT>, blackbody:<T>")
        ->capture_default_str();
    cmd.add_option("--observer", a.observer, "cie1931 or cie1964")->capture_default_str();
    cmd.add_option("--rgb", a.rgb,
                   "RGB space of the linear RGB: srgb, display-p3, rec2020, adobe-rgb, smpte-c, ntsc1953")
        ->capture_default_str();
}

Film parse_film(const FilmArguments& a, bool thickness_required) {
    Film f;
    const FilmModelKind kind = parse_model(a.model);
    const Material ambient = parse_medium(a.ambient, "--ambient");
    const Material substrate = parse_medium(a.substrate, "--substrate");
    std::vector<LayerArgument> layers;
    if (!ambient.is_lossless()) {
        throw UsageError("--ambient '" + a.ambient + "' absorbs (k > 0); the ambient must have k = 0");
    }
    for (std::size_t i = 0; i < a.layers.size(); ++i) {
        layers.push_back(parse_layer(a.layers[i], static_cast<int>(i) + 1, thickness_required));
    }
    if (!(a.angle_deg >= 0.0 && a.angle_deg < 90.0)) {
        throw UsageError("--angle " + format_shortest(a.angle_deg) + " must be in [0, 90) degrees");
    }
    f.angle_rad = a.angle_deg * degrees_to_radians;
    Polarization polarization = Polarization::unpolarized;
    if (a.polarization == "s") polarization = Polarization::s;
    else if (a.polarization == "p") polarization = Polarization::p;
    else if (a.polarization == "unpolarized") polarization = Polarization::unpolarized;
    else throw UsageError("--polarization '" + a.polarization + "' is unknown; valid: s, p, unpolarized");
    if (a.phase_change && a.no_phase_change) {
        throw UsageError("--phase-change and --no-phase-change exclude each other");
    }
    std::optional<bool> phase_change;
    if (a.phase_change) phase_change = true;
    if (a.no_phase_change) phase_change = false;
    const auto given = [&](const char* option) {
        return a.command && a.command->count(option) > 0;
    };
    if (given("--K") && !(a.k > 0.0 && std::isfinite(a.k))) {
        throw UsageError("--K " + format_shortest(a.k) + " must be a finite number > 0");
    }
    // The thesis' closed forms take real indices: an absorbing film or substrate is refused, as
    // the renderer refuses absorbing films, rather than its k silently dropped.
    const auto thesis_material = [](const Material& m, const char* role,
                                    const std::string& option) {
        try {
            check_thesis_material(m, role);
        } catch (const Error& e) {
            throw UsageError(option + ": " + e.what() + "; use --model exact");
        }
    };
    const auto layer_option = [&](std::size_t i) {
        return "--layer " + std::to_string(i + 1) + " '" + a.layers[i] + "'";
    };
    try {
        check_thesis_periods(a.periods);
    } catch (const Error& e) {
        throw UsageError(std::string("--") + e.what());
    }
    // Options of another model are refused rather than silently ignored.
    const auto refuse = [&](std::initializer_list<const char*> options) {
        for (const char* option : options) {
            if (given(option)) {
                throw UsageError(std::string(option) + " does not apply to --model " + a.model);
            }
        }
    };
    switch (kind) {
        case FilmModelKind::exact:
            refuse({"--phase-change", "--no-phase-change", "--K", "--periods", "--d1", "--d2", "--n", "--blend",
                    "--blend-vary"});
            break;
        case FilmModelKind::thesis:
            refuse({"--polarization", "--periods", "--d1", "--d2", "--n", "--blend", "--blend-vary"});
            break;
        case FilmModelKind::thesis_multilayer:
            // Eq. 26 assumes air around the films.
            refuse({"--ambient", "--substrate", "--polarization", "--phase-change", "--no-phase-change",
                    "--d1", "--d2", "--n", "--blend", "--blend-vary"});
            break;
        case FilmModelKind::morpho:
            refuse({"--ambient", "--substrate", "--polarization", "--phase-change", "--no-phase-change",
                    "--layer"});
            break;
    }

    const auto need_layers = [&](std::size_t count, const char* model) {
        if (layers.size() != count) {
            throw UsageError(std::string("--model ") + model + " takes exactly " +
                             std::to_string(count) + " --layer, found " + std::to_string(layers.size()));
        }
    };
    // Anything the checks above leave to the library is still an option's error (exit 2).
    try {
    switch (kind) {
        case FilmModelKind::exact:
            if (layers.empty() && thickness_required) {
                throw UsageError("--layer is required: give at least one INDEX:THICKNESS");
            }
            if (!thickness_required) need_layers(1, "exact (film-table)");
            {
                std::vector<Layer> stack;
                for (const LayerArgument& l : layers) stack.push_back({l.material, l.thickness_nm.value_or(0.0)});
                f.model = std::make_shared<ExactFilm>(ambient, std::move(stack), substrate, polarization);
            }
            break;
        case FilmModelKind::thesis:
            need_layers(1, "thesis");
            thesis_material(layers.front().material, "film", layer_option(0));
            thesis_material(substrate, "substrate", "--substrate '" + a.substrate + "'");
            f.model = std::make_shared<ThesisFilm>(
                SingleFilm{ambient, layers.front().material, substrate},
                layers.front().thickness_nm.value_or(0.0),
                given("--K") ? std::optional<double>(a.k) : std::nullopt, phase_change);
            break;
        case FilmModelKind::thesis_multilayer:
            need_layers(1, "thesis-multilayer");
            if (!given("--periods")) throw UsageError("--periods is required with --model thesis-multilayer");
            thesis_material(layers.front().material, "film", layer_option(0));
            f.model = std::make_shared<ThesisMultilayerFilm>(
                layers.front().material, layers.front().thickness_nm.value_or(0.0), a.periods,
                given("--K") ? std::optional<double>(a.k) : std::nullopt);
            break;
        case FilmModelKind::morpho: {
            if (!(std::isfinite(a.d1_nm) && a.d1_nm >= 0.0 && a.d1_nm <= 1e6)) {
                throw UsageError("--d1 " + format_shortest(a.d1_nm) + " must be a thickness in [0, 1e6] nm");
            }
            if (!(std::isfinite(a.d2_nm) && a.d2_nm >= 0.0 && a.d2_nm <= 1e6)) {
                throw UsageError("--d2 " + format_shortest(a.d2_nm) + " must be a thickness in [0, 1e6] nm");
            }
            if (!(std::isfinite(a.n) && a.n >= 1.0)) {
                throw UsageError("--n " + format_shortest(a.n) +
                                 " must be >= 1 (eq. 29 assumes the wing is in air)");
            }
            const MorphoParameters wing{a.d1_nm, a.d2_nm, a.n, a.periods,
                                        given("--K") ? a.k : thesis_unit_peak_k(a.periods)};
            try {
                validate_morpho(wing);
            } catch (const Error& e) {
                throw UsageError(e.what());
            }
            if (a.blend_vary != "d1" && a.blend_vary != "d2") {
                throw UsageError("--blend-vary '" + a.blend_vary + "' is unknown; valid: d1, d2");
            }
            if (given("--blend-vary") && !a.blend) throw UsageError("--blend-vary needs --blend");
            std::optional<MorphoBlend> blend;
            if (a.blend) {
                blend = MorphoBlend{};
                blend->varies = a.blend_vary == "d2" ? MorphoBlendThickness::d2 : MorphoBlendThickness::d1;
            }
            f.model = std::make_shared<MorphoFilm>(wing, blend);
            break;
        }
    }
    } catch (const UsageError&) {
        throw;
    } catch (const Error& e) {
        throw UsageError(e.what());
    }
    return f;
}

void require_default_colorimeter(const FilmArguments& a, bool rgb, const std::string& what) {
    const FilmArguments defaults;
    const auto check = [&](const char* option, const std::string& value, const std::string& standard) {
        if (value != standard) {
            throw UsageError(fmt::format("{} '{}' does not apply: {} (only {} {})", option, value,
                                         what, option, standard));
        }
    };
    check("--illuminant", a.illuminant, defaults.illuminant);
    check("--observer", a.observer, defaults.observer);
    if (rgb) check("--rgb", a.rgb, defaults.rgb);
}

RendererFilmRequest parse_renderer_film(const FilmArguments& a) {
    RendererFilmRequest r;
    r.model = parse_renderer_film_model(a.model);
    const auto given = [&](const char* option) { return a.command && a.command->count(option) > 0; };
    for (const char* option : {"--polarization", "--phase-change", "--no-phase-change", "--K", "--periods",
                               "--d1", "--d2", "--n", "--blend", "--blend-vary", "--wavelengths"}) {
        if (given(option)) {
            throw UsageError(fmt::format("{} does not apply to --model {} (a colour model: no spectrum, "
                                         "unpolarised)",
                                         option, a.model));
        }
    }
    require_default_colorimeter(a, true,
                                "the renderers' film models have fixed sensitivities (CIE 1931 2°, "
                                "linear Rec.709, white D65)");
    const Material ambient = parse_medium(a.ambient, "--ambient");
    const Material substrate = parse_medium(a.substrate, "--substrate");
    if (!ambient.is_lossless()) {
        throw UsageError("--ambient '" + a.ambient + "' absorbs (k > 0); the ambient must have k = 0");
    }
    if (a.layers.size() != 1) {
        throw UsageError(fmt::format("--model {} takes exactly 1 --layer INDEX:THICKNESS, found {}", a.model,
                                     a.layers.size()));
    }
    const LayerArgument layer = parse_layer(a.layers.front(), 1, true);
    if (!layer.material.is_lossless()) {
        throw UsageError(fmt::format("--layer 1 '{}': the film absorbs (k > 0); --model {} takes a real "
                                     "film index (use --model exact)",
                                     a.layers.front(), a.model));
    }
    if (!(a.angle_deg >= 0.0 && a.angle_deg < 90.0)) {
        throw UsageError("--angle " + format_shortest(a.angle_deg) + " must be in [0, 90) degrees");
    }
    try {
        r.inputs = renderer_film_inputs({ambient, layer.material, substrate});
    } catch (const Error& e) {
        throw UsageError(e.what());
    }
    r.thickness_nm = layer.thickness_nm.value_or(0.0);
    r.angle_rad = a.angle_deg * degrees_to_radians;
    return r;
}

std::string color_lines(const FilmColor& c, const Colorimeter& colorimeter) {
    const Xy xy = xyz_to_xy(c.xyz, xyz_to_xy(colorimeter.white()));
    const Lab lab = colorimeter.lab(c.xyz);
    std::string out = "X,Y,Z,x,y,L,a,b,R_linear,G_linear,B_linear\n";
    append_csv_line(out, std::array{c.xyz.X, c.xyz.Y, c.xyz.Z, xy.x, xy.y, lab.L, lab.a, lab.b,
                                    c.rgb_linear.r, c.rgb_linear.g, c.rgb_linear.b});
    return out;
}

Colorimeter parse_colorimeter(const FilmArguments& a) {
    const RgbSpace* rgb = find_rgb_space(a.rgb);
    if (rgb == nullptr) {
        throw UsageError("--rgb '" + a.rgb +
                         "' is unknown; valid: srgb, display-p3, rec2020, adobe-rgb, smpte-c, ntsc1953");
    }
    const auto checked = [](const char* option, auto&& parse) {
        try {
            return parse();
        } catch (const Error& e) {
            throw UsageError(std::string(option) + ": " + e.what());
        }
    };
    const DenseSpectrum illuminant = checked("--illuminant", [&] { return illuminant_by_name(a.illuminant); });
    const Observer observer = checked("--observer", [&] { return parse_observer(a.observer); });
    return Colorimeter(illuminant, observer, *rgb);
}

void Film::check_work(std::vector<WorkFactor> spectra, bool at_wavelengths) const {
    try {
        model->check_work(std::move(spectra), at_wavelengths, {"--layer", "--blend"});
    } catch (const Error& e) {
        throw UsageError(e.what());
    }
}

}  // namespace irid::cli
