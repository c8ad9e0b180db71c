// Scene files: JSON → Scene, every value checked once with its key path and allowed range.
#include <irid/color/rgb.h>
#include <irid/error.h>
#include <irid/gamut/aces2_display.h>
#include <irid/gamut/clip.h>
#include <irid/gamut/tone.h>
#include <irid/optics/material.h>
#include <irid/render/scene.h>
#include <irid/render/sky.h>
#include <irid/text_input.h>

#include "builtin_scenes.h"  // generated from scenes/*.json (cmake/EmbedScenes.cmake)
#include "json_reader.h"

#include <fmt/core.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace irid::render {
namespace {

using json::Json;
using json::ObjectReader;

/// A film's material: a name or an index ("1.45"); it must be lossless, because the renderer
/// takes the film's transmittance as 1 − R.
void read_film(const ObjectReader& r, std::string_view key, std::string& out) {
    if (const Json* v = r.find(key); v && v->is_number()) {
        out = v->dump();
    } else {
        r.text(key, out);
    }
    Material m = Material::constant("air", 1.0);
    try {
        m = parse_material(out);
    } catch (const Error& e) {
        r.fail(r.key_path(key), e.what());
    }
    if (!m.is_lossless())
        r.fail(r.key_path(key), fmt::format("is {}, an absorbing material; a film must be "
                                            "lossless (k = 0), because its transmittance is "
                                            "taken as 1 − R",
                                            quote_untrusted(out)));
}

/// Bounds shared by the readers: positions within ±1e4 scene units, colours within [0, 100].
constexpr double coordinate_limit = 1.0e4;
constexpr double albedo_max = 1.0;
constexpr double light_max = 100.0;
/// Film thicknesses up to 100 µm: far beyond visible interference.
constexpr double thickness_limit_nm = 1.0e5;

void read_image(const Json& j, const std::string& source, ImageParams& p) {
    ObjectReader r(j, "image", source, {"width", "height", "spp"});
    r.integer("width", p.width, 1, max_image_side);
    r.integer("height", p.height, 1, max_image_side);
    r.integer("spp", p.spp, 1, max_spp);
    const long long samples = static_cast<long long>(p.width) * p.height * p.spp;
    if (samples > max_samples && static_cast<long long>(p.width) * p.height <= max_pixels)
        r.fail("image.spp", fmt::format("is {}: {}×{}×{} = {} samples; at most {} are allowed (the "
                                        "renderer keeps every sample until it filters them)",
                                        p.spp, p.width, p.height, p.spp, samples, max_samples));
    if (static_cast<long long>(p.width) * p.height > max_pixels)
        r.fail("image", fmt::format("is {}×{} = {} pixels; at most {} pixels are allowed", p.width,
                                    p.height, static_cast<long long>(p.width) * p.height,
                                    max_pixels));
}

void read_camera(const Json& j, const std::string& source, CameraParams& p) {
    ObjectReader r(j, "camera", source, {"eye", "look_at", "up", "fov_deg"});
    r.vec3("eye", p.eye, -coordinate_limit, coordinate_limit);
    r.vec3("look_at", p.look_at, -coordinate_limit, coordinate_limit);
    r.vec3("up", p.up, -coordinate_limit, coordinate_limit);
    r.number("fov_deg", p.fov_deg, 1.0, 170.0);
    if (p.eye == p.look_at) r.fail("camera.look_at", "must differ from camera.eye");
}

}  // namespace

std::string_view color_path_name(ColorPath path) noexcept {
    switch (path) {
        case ColorPath::table: return "table";
        case ColorPath::spectral: return "spectral";
        case ColorPath::fourier: return "fourier";
    }
    return "table";
}

std::string_view view_transform_name(ViewTransform view) noexcept {
    switch (view) {
        case ViewTransform::rolloff: return "rolloff";
        case ViewTransform::thesis: return "thesis";
        case ViewTransform::aces2: return "aces2";
    }
    return "rolloff";
}

namespace {

void read_render(const Json& j, const std::string& source, RenderParams& p) {
    ObjectReader r(j, "render", source,
                   {"path", "optics", "antialias", "max_depth", "seed", "space", "clip",
                    "exposure", "view", "rolloff_knee", "display", "filter_radius", "filter_sigma"});
    r.choice("path", p.path,
             {{"table", ColorPath::table}, {"spectral", ColorPath::spectral}, {"fourier", ColorPath::fourier}});
    r.choice("optics", p.optics, {{"thesis", OpticsModel::thesis}, {"exact", OpticsModel::exact}});
    if (p.path == ColorPath::fourier && p.optics != OpticsModel::exact) {
        r.fail("render.path", "is \"fourier\", the exact film's colour; it needs render.optics \"exact\"");
    }
    r.choice("antialias", p.antialias,
             {{"none", FilmAntialias::none}, {"footprint", FilmAntialias::footprint}});
    r.integer("max_depth", p.max_depth, 1, 32);
    if (const Json* v = r.find("seed")) {
        if (!v->is_number_unsigned())
            r.fail("render.seed", "must be an integer in [0, 18446744073709551615]");
        p.seed = v->get<std::uint64_t>();
    }
    r.choice("view", p.view,
             {{"rolloff", ViewTransform::rolloff}, {"thesis", ViewTransform::thesis}, {"aces2", ViewTransform::aces2}});
    if (r.find("display") != nullptr) {
        if (p.view != ViewTransform::aces2) r.fail("render.display", "applies to render.view \"aces2\" only");
        r.text("display", p.display);
    }
    if (p.view == ViewTransform::aces2) {
        try {
            p.display = aces2_display(p.display).name;
        } catch (const Error& e) {
            r.fail("render.display", e.what());
        }
        if (r.find("space") == nullptr) {
            const RgbSpace* encoding = default_display_encoding(aces2_display(p.display));
            if (encoding == nullptr)
                r.fail("render.display", fmt::format("\"{}\" has no RGB encoding of its own; set render.space",
                                                     p.display));
            p.space = encoding->name();
        }
    }
    r.text("space", p.space);
    if (!find_rgb_space(p.space)) {
        r.fail("render.space", fmt::format("is \"{}\"; allowed: {}", p.space, fmt::join(rgb_space_names(), ", ")));
    }
    std::string clip(clip_method_name(p.clip));
    r.text("clip", clip);
    try {
        p.clip = parse_clip_method(clip);
    } catch (const Error& e) {
        r.fail("render.clip", e.what());
    }
    r.number("exposure", p.exposure, 0.0, 1.0e3);
    r.number("rolloff_knee", p.rolloff_knee, 0.0, HighlightRolloff::max_knee);
    r.number("filter_radius", p.filter_radius, 0.5, 4.0);
    r.number("filter_sigma", p.filter_sigma, 0.1, 4.0);
}

void read_light(const Json& j, const std::string& source, LightParams& p) {
    ObjectReader r(j, "light", source,
                   {"sky", "turbidity", "sky_scale", "sun_direction", "sun_intensity", "sun_radius_deg",
                    "sky_zenith", "sky_horizon", "ground", "ground_albedo", "environment_image",
                    "environment_intensity"});
    r.choice("sky", p.sky, {{"gradient", SkyModel::gradient}, {"preetham", SkyModel::preetham}});
    r.number("turbidity", p.turbidity, PreethamSky::min_turbidity, PreethamSky::max_turbidity);
    r.positive("sky_scale", p.sky_scale, light_max);
    r.vec3("sun_direction", p.sun_direction, -1.0e3, 1.0e3);
    const auto& d = p.sun_direction;
    if (d[0] * d[0] + d[1] * d[1] + d[2] * d[2] < 1e-12)
        r.fail("light.sun_direction", "must not be the zero vector");
    if (p.sky == SkyModel::preetham && !(d[1] > 1e-9 * std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2])))
        r.fail("light.sun_direction",
               fmt::format("is [{}, {}, {}]; with light.sky = preetham the sun must be above the "
                           "horizon (y > 0)",
                           d[0], d[1], d[2]));
    r.number("sun_intensity", p.sun_intensity, 0.0, light_max);
    r.number("sun_radius_deg", p.sun_radius_deg, 0.1, 20.0);
    r.vec3("sky_zenith", p.sky_zenith, 0.0, light_max);
    r.vec3("sky_horizon", p.sky_horizon, 0.0, light_max);
    r.vec3("ground", p.ground, 0.0, light_max);
    r.vec3("ground_albedo", p.ground_albedo, 0.0, albedo_max);
    r.text("environment_image", p.environment_image);
    r.number("environment_intensity", p.environment_intensity, 0.0, light_max);
}

void read_oil(const Json& j, const std::string& source, OilParams& p) {
    ObjectReader r(j, "oil", source,
                   {"center", "radius", "max_thickness_nm", "k1", "k2", "turbulence_scale",
                    "min_thickness_nm", "film", "substrate", "asphalt_index"});
    r.vec3("center", p.center, -coordinate_limit, coordinate_limit);
    r.positive("radius", p.radius, coordinate_limit);
    r.number("max_thickness_nm", p.max_thickness_nm, 0.0, thickness_limit_nm);
    r.number("k1", p.k1, 0.0, 100.0);
    r.number("k2", p.k2, 0.0, 100.0);
    r.number("turbulence_scale", p.turbulence_scale, 0.0, 1.0e3);
    r.number("min_thickness_nm", p.min_thickness_nm, 0.0, thickness_limit_nm);
    read_film(r, "film", p.film);
    r.choice("substrate", p.substrate, {{"wet", std::string("wet")}, {"dry", std::string("dry")}});
    r.number("asphalt_index", p.asphalt_index, 1.0, 3.0);
}

void read_pavement(const Json& j, const std::string& source, PavementParams& p) {
    ObjectReader r(j, "pavement", source,
                   {"albedo", "bump_frequency", "bump_height", "fine_frequency", "fine_height",
                    "albedo_variation", "roughness_deg"});
    r.vec3("albedo", p.albedo, 0.0, albedo_max);
    r.number("bump_frequency", p.bump_frequency, 0.0, 1.0e4);
    r.number("bump_height", p.bump_height, 0.0, 1.0);
    r.number("fine_frequency", p.fine_frequency, 0.0, 1.0e5);
    r.number("fine_height", p.fine_height, 0.0, 1.0);
    r.number("albedo_variation", p.albedo_variation, 0.0, 1.0);
    r.number("roughness_deg", p.roughness_deg, 0.0, 20.0);
}

void read_bubble(const Json& j, const std::string& path, const std::string& source,
                 BubbleParams& p) {
    ObjectReader r(j, path, source,
                   {"center", "radius", "top_thickness_nm", "bottom_thickness_nm",
                    "profile_exponent", "turbulence_nm", "turbulence_scale"});
    r.vec3("center", p.center, -coordinate_limit, coordinate_limit);
    r.positive("radius", p.radius, coordinate_limit);
    r.number("top_thickness_nm", p.top_thickness_nm, 0.0, thickness_limit_nm);
    r.number("bottom_thickness_nm", p.bottom_thickness_nm, 0.0, thickness_limit_nm);
    r.number("profile_exponent", p.profile_exponent, 0.05, 20.0);
    r.number("turbulence_nm", p.turbulence_nm, 0.0, thickness_limit_nm);
    r.number("turbulence_scale", p.turbulence_scale, 0.0, 1.0e3);
}

void read_soap(const Json& j, const std::string& source, SoapParams& p) {
    ObjectReader r(j, "soap", source,
                   {"bubbles", "film", "floor_y", "floor_albedo", "floor_albedo_alt",
                    "floor_checker"});
    if (const Json* b = r.find("bubbles")) {
        if (!b->is_array() || b->empty() || b->size() > static_cast<std::size_t>(max_bubbles))
            r.fail("soap.bubbles",
                   fmt::format("must be an array of 1 to {} bubble objects", max_bubbles));
        p.bubbles.assign(b->size(), BubbleParams{});
        for (std::size_t i = 0; i < b->size(); ++i)
            read_bubble((*b)[i], fmt::format("soap.bubbles.{}", i), source, p.bubbles[i]);
    }
    read_film(r, "film", p.film);
    r.number("floor_y", p.floor_y, -coordinate_limit, coordinate_limit);
    r.vec3("floor_albedo", p.floor_albedo, 0.0, albedo_max);
    r.vec3("floor_albedo_alt", p.floor_albedo_alt, 0.0, albedo_max);
    r.number("floor_checker", p.floor_checker, 0.0, coordinate_limit);
}

void read_morpho(const Json& j, const std::string& source, MorphoSceneParams& p) {
    ObjectReader r(j, "morpho", source,
                   {"d1_nm", "d2_nm", "n_chitin", "periods", "blend", "blend_min_nm",
                    "blend_max_nm", "blend_samples", "dihedral_deg", "span", "bump_height",
                    "bump_frequency", "base_albedo", "margin", "body_albedo",
                    "background_albedo", "wing_mesh"});
    r.number("d1_nm", p.d1_nm, 0.0, 1.0e4);
    r.number("d2_nm", p.d2_nm, 0.0, 1.0e4);
    r.number("n_chitin", p.n_chitin, 1.0, 4.0);
    r.integer("periods", p.periods, 1, 100);
    r.boolean("blend", p.blend);
    r.number("blend_min_nm", p.blend_min_nm, 0.0, 1.0e4);
    r.number("blend_max_nm", p.blend_max_nm, 0.0, 1.0e4);
    r.integer("blend_samples", p.blend_samples, 2, 201);
    if (p.blend_min_nm > p.blend_max_nm)
        r.fail("morpho.blend_min_nm",
               fmt::format("is {} nm; it must not exceed morpho.blend_max_nm ({} nm)",
                           p.blend_min_nm, p.blend_max_nm));
    r.number("dihedral_deg", p.dihedral_deg, -80.0, 80.0);
    r.positive("span", p.span, coordinate_limit);
    r.number("bump_height", p.bump_height, 0.0, 1.0);
    r.number("bump_frequency", p.bump_frequency, 0.0, 1.0e4);
    r.vec3("base_albedo", p.base_albedo, 0.0, albedo_max);
    r.number("margin", p.margin, 0.0, 0.5);
    r.vec3("body_albedo", p.body_albedo, 0.0, albedo_max);
    r.vec3("background_albedo", p.background_albedo, 0.0, albedo_max);
    r.text("wing_mesh", p.wing_mesh);
}

/// The sections a scene of one kind reads: the common ones and its own. A section of another
/// kind would be read and then ignored, so it is refused, whether the file or an override
/// brings it.
void check_sections(const Json& root, SceneKind kind, const std::string& source,
                    const std::vector<std::string>& sections_in_text,
                    const std::vector<std::string>& overrides) {
    struct Owner {
        std::string_view section;
        SceneKind kind;
    };
    static constexpr Owner owned[] = {{"oil", SceneKind::oil_slick},
                                      {"pavement", SceneKind::oil_slick},
                                      {"soap", SceneKind::soap_bubbles},
                                      {"morpho", SceneKind::morpho}};
    std::string valid = "scene, image, camera, render, light";
    for (const Owner& o : owned)
        if (o.kind == kind) valid += ", " + std::string(o.section);
    for (const Owner& o : owned) {
        if (o.kind == kind || !root.contains(std::string(o.section))) continue;
        const std::string what = fmt::format(
            "'{}' is a section of the {} scene; this scene is {}, whose sections are {}",
            o.section, scene_kind_name(o.kind), scene_kind_name(kind), valid);
        if (std::find(sections_in_text.begin(), sections_in_text.end(), o.section) !=
            sections_in_text.end())
            throw Error(fmt::format("{}: {}", source, what));
        for (const std::string& assignment : overrides) {
            if (assignment.rfind(std::string(o.section) + ".", 0) == 0 ||
                assignment.rfind(std::string(o.section) + "=", 0) == 0)
                throw Error(fmt::format("{}: the override {}: {}", source,
                                        quote_untrusted(assignment, 60), what));
        }
        throw Error(fmt::format("{}: {}", source, what));
    }
}

}  // namespace

std::string_view scene_kind_name(SceneKind kind) noexcept {
    switch (kind) {
        case SceneKind::oil_slick: return "oil-slick";
        case SceneKind::soap_bubbles: return "soap-bubbles";
        case SceneKind::morpho: return "morpho";
    }
    return "?";
}

std::vector<std::string> builtin_scene_names() {
    std::vector<std::string> names;
    for (const auto& s : detail::builtin_scenes) names.emplace_back(s.name);
    return names;
}

std::optional<std::string_view> builtin_scene_json(std::string_view name) {
    for (const auto& s : detail::builtin_scenes)
        if (s.name == name) return s.json;
    return std::nullopt;
}

Scene parse_scene(std::string_view json_text, const std::string& source,
                  const std::filesystem::path& directory,
                  const std::vector<std::string>& overrides) {
    Json root;
    try {
        root = Json::parse(json_text.begin(), json_text.end(), nullptr, true,
                           /*ignore_comments=*/true);
    } catch (const Json::out_of_range&) {
        // A number beyond a double: nlohmann gives no position; find it.
        json::check_text(json_text, source);
        throw Error(fmt::format("{}: a number in the JSON is beyond the range of a double", source));
    } catch (const Json::parse_error& e) {
        // e.what() is "[json.exception.parse_error.101] parse error at line L, column C: ...";
        // keep its explanation after the position, and give the position ourselves.
        std::string why = e.what();
        const auto colon = why.find(": ");
        if (colon != std::string::npos) why = why.substr(colon + 2);
        throw Error(fmt::format("{}: JSON syntax error at {}: {}", source,
                                json::line_column(json_text, e.byte), why));
    }
    json::check_text(json_text, source);
    std::vector<std::string> sections_in_text;
    if (root.is_object())
        for (const auto& item : root.items()) sections_in_text.push_back(item.key());
    for (const auto& o : overrides) json::apply_override(root, o, source);

    Scene scene;
    scene.source = source;
    scene.directory = directory;
    ObjectReader r(root, "", source,
                   {"scene", "image", "camera", "render", "light", "oil", "pavement", "soap",
                    "morpho"});
    if (!r.find("scene"))
        r.fail("scene", "is missing; allowed: oil-slick, soap-bubbles, morpho");
    r.choice("scene", scene.kind,
             {{"oil-slick", SceneKind::oil_slick},
              {"soap-bubbles", SceneKind::soap_bubbles},
              {"morpho", SceneKind::morpho}});
    check_sections(root, scene.kind, source, sections_in_text, overrides);
    if (scene.kind == SceneKind::soap_bubbles) scene.soap.bubbles.assign(1, BubbleParams{});
    if (const Json* v = r.find("image")) read_image(*v, source, scene.image);
    if (const Json* v = r.find("camera")) read_camera(*v, source, scene.camera);
    if (const Json* v = r.find("render")) read_render(*v, source, scene.render);
    if (const Json* v = r.find("light")) read_light(*v, source, scene.light);
    if (const Json* v = r.find("oil")) read_oil(*v, source, scene.oil);
    if (const Json* v = r.find("pavement")) read_pavement(*v, source, scene.pavement);
    if (const Json* v = r.find("soap")) read_soap(*v, source, scene.soap);
    if (const Json* v = r.find("morpho")) read_morpho(*v, source, scene.morpho);
    if (const double work = morpho_table_work(scene); work > max_morpho_table_work) {
        const MorphoSceneParams& m = scene.morpho;
        throw Error(fmt::format(
            "{}: morpho.periods = {} and morpho.blend_samples = {} with render.optics = exact ask "
            "for {:.3g} layer evaluations before the first ray (91 angles x {} x 471 wavelengths "
            "x {} layers); the limit is {:.3g}, about 80 s on one core: lower morpho.periods or "
            "morpho.blend_samples, or set render.optics = thesis",
            source, m.periods, m.blend_samples, work, m.blend ? m.blend_samples : 1,
            2 * m.periods - 1, max_morpho_table_work));
    }
    return scene;
}

std::vector<std::string> image_size_overrides(const Scene& shape, std::optional<int> width,
                                              std::optional<int> height) {
    if (width.has_value() != height.has_value()) {
        const double aspect = static_cast<double>(shape.image.width) / static_cast<double>(shape.image.height);
        const auto rounded = [](double v) {
            return static_cast<int>(std::clamp(std::lround(v), 1L, static_cast<long>(max_image_side)));
        };
        if (width) height = rounded(*width / aspect);
        else width = rounded(*height * aspect);
    }
    std::vector<std::string> out;
    if (width) out.push_back(fmt::format("image.width={}", *width));
    if (height) out.push_back(fmt::format("image.height={}", *height));
    return out;
}

double morpho_table_work(const Scene& scene) noexcept {
    if (scene.kind != SceneKind::morpho || scene.render.optics != OpticsModel::exact) return 0;
    const MorphoSceneParams& m = scene.morpho;
    constexpr double angles = 91, wavelengths = 471;  // AngleTable at 1°, 360-830 nm at 1 nm
    return angles * (m.blend ? m.blend_samples : 1) * wavelengths * (2.0 * m.periods - 1.0);
}

Scene load_scene(const std::string& name_or_path, const std::vector<std::string>& overrides) {
    if (const auto builtin = builtin_scene_json(name_or_path))
        return parse_scene(*builtin, name_or_path, {}, overrides);
    const std::filesystem::path path(name_or_path);
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) {
        throw Error(fmt::format("cannot read scene {}: not a built-in scene ({}) and no such file",
                                quote_untrusted(name_or_path, 80),
                                fmt::join(builtin_scene_names(), ", ")));
    }
    // A scene named on the command line may come through a pipe (`irid render <(...)`).
    constexpr std::size_t max_scene_bytes = 16u << 20;
    const std::string text =
        read_text_file(path, "scene file (JSON)", StreamInput::accept, max_scene_bytes);
    return parse_scene(text, name_or_path, path.parent_path(), overrides);
}

}  // namespace irid::render
