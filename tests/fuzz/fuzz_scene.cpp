// Fuzz harness: scene files and --set overrides (irid::render::parse_scene,
// include/irid/render/scene.h). Parsing and validation only: nothing is rendered.
//
// Input: byte 0 picks the mode. Even: the rest is a scene's JSON text. Odd: (byte 0 >> 1) % 3
// picks a built-in scene (oil-slick, soap-bubbles, morpho) and the rest is split at newlines into
// up to 8 "key.path=value" overrides applied to it, as `irid render NAME --set ...` does.
// Checked on every scene read: the limits scene.h states (image side, pixels, samples per pixel,
// samples, bubbles), a known RGB space and clip method, lossless film materials, a non-zero sun
// direction, finite numbers.
#include "fuzz_support.h"

#include <irid/color/rgb.h>
#include <irid/error.h>
#include <irid/gamut/aces2_display.h>
#include <irid/gamut/clip.h>
#include <irid/optics/material.h>
#include <irid/render/scene.h>

#include <cmath>
#include <string>
#include <string_view>
#include <vector>

namespace {

namespace render = irid::render;

bool finite3(const std::array<double, 3>& v) {
    return std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]);
}

void check_film(const std::string& name) {
    try {
        IRID_FUZZ_REQUIRE(irid::parse_material(name).is_lossless(), "film '" + name + "' absorbs");
    } catch (const irid::Error& e) {
        IRID_FUZZ_REQUIRE(false,
                          "film '" + name + "' was accepted but does not parse: " + e.what());
    }
}

void check_scene(const render::Scene& s) {
    const auto& im = s.image;
    IRID_FUZZ_REQUIRE(im.width >= 1 && im.width <= render::max_image_side, "image.width");
    IRID_FUZZ_REQUIRE(im.height >= 1 && im.height <= render::max_image_side, "image.height");
    IRID_FUZZ_REQUIRE(1LL * im.width * im.height <= render::max_pixels, "pixels");
    IRID_FUZZ_REQUIRE(im.spp >= 1 && im.spp <= render::max_spp, "image.spp");
    IRID_FUZZ_REQUIRE(1LL * im.width * im.height * im.spp <= render::max_samples, "samples");
    IRID_FUZZ_REQUIRE(irid::find_rgb_space(s.render.space) != nullptr,
                      "render.space '" + s.render.space + "'");
    // An aces2 view keeps a display that names itself (custom ones in their normalised form).
    if (s.render.view == render::ViewTransform::aces2) {
        try {
            IRID_FUZZ_REQUIRE(irid::aces2_display(s.render.display).name == s.render.display,
                              "render.display does not round-trip through its name");
        } catch (const irid::Error& e) {
            IRID_FUZZ_REQUIRE(false, "render.display stored a display without a name: " + std::string(e.what()));
        }
    }
    // The clip is parsed once when read: what was stored is a method that names itself.
    try {
        IRID_FUZZ_REQUIRE(irid::parse_clip_method(irid::clip_method_name(s.render.clip)) == s.render.clip,
                          "render.clip does not round-trip through its name");
    } catch (const irid::Error& e) {
        IRID_FUZZ_REQUIRE(false, "render.clip stored a method without a name: " + std::string(e.what()));
    }
    IRID_FUZZ_REQUIRE(s.render.max_depth >= 1, "render.max_depth");
    IRID_FUZZ_REQUIRE(std::isfinite(s.render.exposure) && std::isfinite(s.render.filter_radius) &&
                          std::isfinite(s.render.filter_sigma),
                      "render numbers finite");
    IRID_FUZZ_REQUIRE(finite3(s.camera.eye) && finite3(s.camera.look_at) && finite3(s.camera.up) &&
                          std::isfinite(s.camera.fov_deg) && s.camera.eye != s.camera.look_at,
                      "camera");
    const auto& d = s.light.sun_direction;
    const double len = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    // scene.h says "normalised when read"; the reader only refuses the zero vector and the
    // renderer normalises it (world.cpp), so only that is checked.
    IRID_FUZZ_REQUIRE(finite3(d) && len >= 1e-6,
                      "light.sun_direction: length " + std::to_string(len));
    IRID_FUZZ_REQUIRE(s.soap.bubbles.size() <= static_cast<std::size_t>(render::max_bubbles),
                      "bubbles");
    if (s.kind == render::SceneKind::soap_bubbles) {
        IRID_FUZZ_REQUIRE(!s.soap.bubbles.empty(), "a soap-bubbles scene without bubbles");
    }
    for (const auto& b : s.soap.bubbles) {
        IRID_FUZZ_REQUIRE(finite3(b.center) && std::isfinite(b.radius) && b.radius > 0.0, "bubble");
    }
    check_film(s.oil.film);
    check_film(s.soap.film);
    IRID_FUZZ_REQUIRE(s.morpho.periods >= 1 && s.morpho.blend_samples >= 2 &&
                          s.morpho.blend_min_nm <= s.morpho.blend_max_nm,
                      "morpho");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    irid::fuzz::Bytes bytes(data, size);
    const std::uint8_t mode = bytes.byte();
    const std::string_view rest = bytes.rest();
    try {
        if ((mode & 1) == 0) {
            check_scene(render::parse_scene(rest, "<fuzz>", "/nonexistent-irid-fuzz"));
        } else {
            static const std::vector<std::string> names = render::builtin_scene_names();
            IRID_FUZZ_REQUIRE(names.size() == 3, "three built-in scenes");
            const std::string& name = names[(mode >> 1) % names.size()];
            const auto json = render::builtin_scene_json(name);
            IRID_FUZZ_REQUIRE(json.has_value(), "built-in scene " + name);
            std::vector<std::string> overrides;
            std::size_t start = 0;
            while (start <= rest.size() && overrides.size() < 8) {
                const std::size_t nl = rest.find('\n', start);
                const std::size_t end = nl == std::string_view::npos ? rest.size() : nl;
                overrides.emplace_back(rest.substr(start, end - start));
                if (nl == std::string_view::npos) break;
                start = nl + 1;
            }
            check_scene(render::parse_scene(*json, name, {}, overrides));
        }
    } catch (const irid::Error&) {
    }
    return 0;
}
