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
    cmd.add_option("--periods", a.periods, "Number of films l in eq. 25 (thesis-multilayer; morpho default 12)")
        ->transform(whole_number_in(thesis_min_periods, thesis_max_periods));
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
    // The command line's syntax becomes a FilmSpec; which options each model takes, the layer
    // counts and the defaults are the library's (build_film).
    const auto given = [&](const char* option) { return a.command && a.command->count(option) > 0; };
    FilmSpec spec;
    spec.model = parse_model(a.model);
    spec.thickness_required = thickness_required;
    if (given("--ambient")) spec.ambient = parse_medium(a.ambient, "--ambient");
    if (given("--substrate")) spec.substrate = parse_medium(a.substrate, "--substrate");
    for (std::size_t i = 0; i < a.layers.size(); ++i) {
        LayerArgument l = parse_layer(a.layers[i], static_cast<int>(i) + 1, thickness_required);
        spec.layers.push_back({std::move(l.material), l.thickness_nm});
    }
    if (!(a.angle_deg >= 0.0 && a.angle_deg < 90.0)) {
        throw UsageError("--angle " + format_shortest(a.angle_deg) + " must be in [0, 90) degrees");
    }
    if (given("--polarization")) {
        if (a.polarization == "s") spec.polarization = Polarization::s;
        else if (a.polarization == "p") spec.polarization = Polarization::p;
        else if (a.polarization == "unpolarized") spec.polarization = Polarization::unpolarized;
        else throw UsageError("--polarization '" + a.polarization + "' is unknown; valid: s, p, unpolarized");
    }
    if (a.phase_change && a.no_phase_change) {
        throw UsageError("--phase-change and --no-phase-change exclude each other");
    }
    if (a.phase_change) spec.phase_change = true;
    if (a.no_phase_change) spec.phase_change = false;
    if (given("--K")) spec.k = a.k;
    if (given("--periods")) spec.periods = a.periods;
    if (given("--d1")) spec.d1_nm = a.d1_nm;
    if (given("--d2")) spec.d2_nm = a.d2_nm;
    if (given("--n")) spec.n = a.n;
    spec.blend = a.blend;
    if (given("--blend-vary")) {
        if (a.blend_vary != "d1" && a.blend_vary != "d2") {
            throw UsageError("--blend-vary '" + a.blend_vary + "' is unknown; valid: d1, d2");
        }
        spec.blend_varies = a.blend_vary == "d2" ? MorphoBlendThickness::d2 : MorphoBlendThickness::d1;
    }
    FilmSpecNames names = command_line_film_names();
    if (a.no_phase_change) names.phase_change = "--no-phase-change";
    names.layer = [&a](std::size_t i) { return "--layer " + std::to_string(i + 1) + " '" + a.layers[i] + "'"; };
    Film f;
    f.angle_rad = a.angle_deg * degrees_to_radians;
    try {
        f.model = build_film(spec, names);
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
