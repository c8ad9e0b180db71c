#include "world.h"

#include <irid/error.h>
#include <irid/io/image.h>
#include <irid/optics/film_builder.h>
#include <irid/optics/material.h>

#include <fmt/core.h>

#include <algorithm>
#include <chrono>
#include <cmath>

// The world's frame: the camera, the lights' set-up, the scene's colour tables, the film's
// colour over a footprint, and the ray queries over every scene's geometry. Each scene's own
// parts are in oil_slick_scene.cpp, soap_bubbles_scene.cpp and morpho_scene.cpp, the sky and
// sun in environment.cpp.

namespace irid::render {
namespace {

Camera make_camera(const Scene& s) {
    try {
        return Camera(to_vec(s.camera.eye), to_vec(s.camera.look_at), to_vec(s.camera.up),
                      s.camera.fov_deg,
                      static_cast<double>(s.image.width) / static_cast<double>(s.image.height));
    } catch (const Error& e) {
        throw Error(fmt::format("{}: camera: {}", s.source, e.what()));
    }
}

/// Stratified point on the hemisphere around +y for the mean sky, with cos θ weights.
template <class F>
Rgb3 cosine_weighted_mean(F&& radiance) {
    constexpr int rings = 24, sectors = 48;
    Rgb3 sum{0, 0, 0};
    double weight = 0;
    for (int i = 0; i < rings; ++i) {
        const double cos_t = (i + 0.5) / rings;  // uniform in cos θ, weighted by cos θ below
        const double sin_t = std::sqrt(1 - cos_t * cos_t);
        for (int j = 0; j < sectors; ++j) {
            const double phi = 2 * pi * (j + 0.5) / sectors;
            const Rgb3 l = radiance(Vec3{sin_t * std::cos(phi), cos_t, sin_t * std::sin(phi)});
            for (int c = 0; c < 3; ++c) sum[c] += cos_t * l[c];
            weight += cos_t;
        }
    }
    return {sum[0] / weight, sum[1] / weight, sum[2] / weight};
}

double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

Material World::material(const std::string& key, const std::string& text) const {
    try {
        return parse_material(text);
    } catch (const Error& e) {
        throw Error(fmt::format("{}: '{}': {}", m_scene.source, key, e.what()));
    }
}

World::World(const Scene& scene)
    : m_scene(scene),
      m_camera(make_camera(scene)),
      m_basis(std::make_unique<SpectralBasis>()),
      m_noise(scene.render.seed),
      m_noise2(scene.render.seed ^ 0x9e3779b97f4a7c15ULL) {
    const LightParams& l = scene.light;
    m_sun = normalize(to_vec(l.sun_direction));
    m_cos_sun_radius = std::cos(l.sun_radius_deg * pi / 180.0);
    // The disc's radiance gives the stated irradiance π·E (E as a multiple of the white's
    // radiance) over its solid angle 2π(1 − cos r).
    m_sun_radiance = pi * l.sun_intensity / (2 * pi * (1 - m_cos_sun_radius));
    if (l.sky == SkyModel::preetham && l.environment_image.empty()) build_preetham();

    if (!l.environment_image.empty()) {
        const std::filesystem::path path = scene.directory / l.environment_image;
        io::Image img = io::read_image(path);
        if (img.channels < 3)
            throw Error(fmt::format("{}: light.environment_image '{}' has {} channel(s); RGB is "
                                    "required",
                                    scene.source, path.string(), img.channels));
        if (img.stored_integer) {  // encoded sRGB values: decode to linear
            for (std::size_t i = 0; i < img.pixel_count(); ++i)
                for (int c = 0; c < 3; ++c) {
                    float& v = img.pixels[i * img.channels + c];
                    v = static_cast<float>(srgb().transfer().decode(v));
                }
        }
        m_environment = std::move(img);
    }
    // The sky's mean radiance (without the sun's disc, which diffuse_light adds directly).
    m_ambient = cosine_weighted_mean([&](Vec3 d) {
        Rgb3 e = environment(d);
        if (dot(d, m_sun) >= m_cos_sun_radius)
            for (int c = 0; c < 3; ++c) e[c] -= m_sun_radiance * m_sun_rgb[c];
        return e;
    });
    // The Preetham sky's ground: a diffuse albedo under the sun and the sky of a horizontal
    // surface (radiance = albedo × irradiance / π, in the units of diffuse_light).
    if (m_sky) {
        const double sun = l.sun_intensity * std::max(0.0, m_sun.y);
        for (int c = 0; c < 3; ++c)
            m_ground_radiance[c] = l.ground_albedo[c] * (sun * m_sun_rgb[c] + m_ambient[c]);
    }

    switch (scene.kind) {
        case SceneKind::oil_slick: build_oil_slick(); break;
        case SceneKind::soap_bubbles: build_soap_bubbles(); break;
        case SceneKind::morpho: build_morpho(); break;
    }
    const auto start = std::chrono::steady_clock::now();
    build_tables();
    m_table_seconds = seconds_since(start);
}

void World::build_tables() {
    const RenderParams& rp = m_scene.render;
    const Colorimeter& col = m_basis->colorimeter();
    if (m_film) {
        const bool exact = rp.optics == OpticsModel::exact;
        m_film_model = build_film(single_film_spec(exact ? FilmModelKind::exact : FilmModelKind::thesis, *m_film));
        if (rp.path == ColorPath::fourier) {
            m_fourier_film.emplace(*m_film, fourier_colorimeter_for(*m_film, col));
            return;
        }
        if (rp.path != ColorPath::table) return;
        // 2 nm × 41 rows of cos θ: the exact table keeps lookups within ΔE2000 0.36 over 0–80°
        // (docs/OPTICS.md).
        m_film_table.emplace(
            std::max(m_max_thickness_nm, 10.0) + 20.0, 2.0, 0.02, 41,
            [&, model = m_film_model](double cos_theta, const std::vector<double>& ts) {
                std::vector<Rgb3> out(ts.size());
                const auto row = model->at_angle(std::acos(std::clamp(cos_theta, 0.0, 1.0)));
                for (std::size_t i = 0; i < ts.size(); ++i) {
                    const Rgb c = row->color(ts[i], col).rgb_linear;
                    out[i] = {c.r, c.g, c.b};
                }
                return out;
            });
        return;
    }
    if (m_scene.kind == SceneKind::morpho) build_wing_tables();
}

namespace {

/// Thicknesses over a footprint: up to 8 spread evenly across it (one without a footprint).
int footprint_thicknesses(const ThicknessSample& t, std::array<double, 8>& ts) noexcept {
    const int n = t.footprint_nm > 1.0 ? std::clamp(static_cast<int>(t.footprint_nm / 4.0) + 1, 2, 8) : 1;
    for (int k = 0; k < n; ++k)
        ts[k] = n == 1 ? t.t_nm : std::max(0.0, t.t_nm + t.footprint_nm * ((k + 0.5) / n - 0.5));
    return n;
}

}  // namespace

Rgb3 World::film_fourier(const ThicknessSample& t, double cos_theta) const noexcept {
    std::array<double, 8> ts{};
    const int n = footprint_thicknesses(t, ts);
    // As film_spectrum: stay just short of grazing incidence.
    const double c = std::clamp(cos_theta, 1e-6, 1.0);
    Xyz sum;
    for (int k = 0; k < n; ++k) {
        const Xyz x = m_fourier_film->xyz(ts[k], c);
        sum.X += x.X / n;
        sum.Y += x.Y / n;
        sum.Z += x.Z / n;
    }
    const Rgb rgb = m_basis->colorimeter().linear_rgb(sum);
    return {rgb.r, rgb.g, rgb.b};
}

void World::film_spectrum(const ThicknessSample& t, double cos_theta, SpectralCarrier& out) const {
    // Grazing incidence itself (cos θ = 0) carries no light into the film; stay just short of it.
    const double angle = std::acos(std::clamp(cos_theta, 1e-6, 1.0));
    // Over the footprint, the mean of up to 8 thicknesses spread evenly across it.
    std::array<double, 8> ts{};
    const int n = footprint_thicknesses(t, ts);
    out.v.fill(0.0);
    const std::unique_ptr<FilmAtAngle> film = m_film_model->at_angle(angle);
    DenseValues r;
    for (int k = 0; k < n; ++k) {
        film->reflectance(ts[k], r);
        for (int i = 0; i < dense_sample_count; ++i) out.v[i] += r[i] / n;
    }
}

bool World::intersect(const Ray& ray, double t_min, double t_max, Hit& hit) const noexcept {
    bool found = false;
    SurfaceHit h;
    if (m_ground && m_ground->intersect(ray, t_min, t_max, h)) {
        t_max = h.t;
        hit.surface = h;
        hit.kind = m_scene.kind == SceneKind::oil_slick
                       ? SurfaceKind::pavement
                       : (m_scene.kind == SceneKind::soap_bubbles ? SurfaceKind::floor
                                                                  : SurfaceKind::background);
        found = true;
    }
    for (std::size_t i = 0; i < m_bubbles.size(); ++i) {
        if (m_bubbles[i].intersect(ray, t_min, t_max, h)) {
            t_max = h.t;
            hit.surface = h;
            hit.kind = SurfaceKind::bubble;
            hit.index = static_cast<int>(i);
            found = true;
        }
    }
    const auto body_hit = [&](const auto& shape) {
        if (!shape.intersect(ray, t_min, t_max, h)) return;
        t_max = h.t;
        hit.surface = h;
        hit.kind = SurfaceKind::body;
        found = true;
    };
    for (const Sphere& s : m_body) body_hit(s);
    for (const Ellipsoid& e : m_body_parts) body_hit(e);
    for (const SphereChain& chain : m_antennae) {
        if (!chain.bounds.intersect(ray, t_min, t_max)) continue;
        for (const Sphere& s : chain.spheres) body_hit(s);
    }
    for (std::size_t i = 0; i < m_wings.size(); ++i) {
        const Wing& w = m_wings[i];
        const double denom = dot(ray.direction, w.normal);
        if (std::abs(denom) < 1e-12) continue;
        const double t = dot(w.origin - ray.origin, w.normal) / denom;
        if (!(t > t_min && t < t_max)) continue;
        const Vec3 p = ray.at(t);
        const Vec3 d = p - w.origin;
        double margin = 1;
        if (!w.contains(dot(d, w.axis_a), dot(d, w.axis_b), margin)) continue;
        t_max = t;
        hit.surface = SurfaceHit{};
        hit.surface.t = t;
        hit.surface.position = p;
        hit.surface.normal = w.normal;
        hit.surface.shading_normal = w.normal;
        hit.kind = SurfaceKind::wing;
        hit.index = static_cast<int>(i);
        hit.margin_distance = margin;
        hit.vein = w.vein_cover(dot(d, w.axis_a), dot(d, w.axis_b));
        found = true;
    }
    if (m_wing_mesh && m_wing_mesh->intersect(ray, t_min, t_max, h)) {
        hit.surface = h;
        hit.kind = SurfaceKind::wing_mesh;
        hit.margin_distance = 1;
        found = true;
    }
    return found;
}

bool World::sun_blocked(Vec3 p) const noexcept {
    const Ray r{p, m_sun};
    const double far = std::numeric_limits<double>::infinity();
    SurfaceHit h;
    for (const Sphere& s : m_body)
        if (s.intersect(r, m_epsilon, far, h)) return true;
    for (const Ellipsoid& e : m_body_parts)
        if (e.intersect(r, m_epsilon, far, h)) return true;
    for (const SphereChain& chain : m_antennae) {
        if (!chain.bounds.intersect(r, m_epsilon, far)) continue;
        for (const Sphere& s : chain.spheres)
            if (s.intersect(r, m_epsilon, far, h)) return true;
    }
    for (const Wing& w : m_wings) {
        const double denom = dot(r.direction, w.normal);
        if (std::abs(denom) < 1e-12) continue;
        const double t = dot(w.origin - r.origin, w.normal) / denom;
        if (!(t > m_epsilon)) continue;
        const Vec3 d = r.at(t) - w.origin;
        double margin = 1;
        if (w.contains(dot(d, w.axis_a), dot(d, w.axis_b), margin)) return true;
    }
    if (m_wing_mesh && m_wing_mesh->occluded(r, m_epsilon, far)) return true;
    return false;
}

}  // namespace irid::render
