#include "world.h"

#include <irid/color/illuminant.h>
#include <irid/error.h>
#include <irid/io/image.h>
#include <irid/optics/film.h>
#include <irid/optics/film_builder.h>
#include <irid/optics/material.h>
#include <irid/optics/thesis_models.h>

#include <fmt/core.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>

namespace irid::render {
namespace {

constexpr double pi = std::numbers::pi;

Vec3 to_vec(const Vec3Param& v) { return {v[0], v[1], v[2]}; }

Camera make_camera(const Scene& s) {
    try {
        return Camera(to_vec(s.camera.eye), to_vec(s.camera.look_at), to_vec(s.camera.up),
                      s.camera.fov_deg,
                      static_cast<double>(s.image.width) / static_cast<double>(s.image.height));
    } catch (const Error& e) {
        throw Error(fmt::format("{}: camera: {}", s.source, e.what()));
    }
}

Material material_of(const Scene& s, const std::string& key, const std::string& text) {
    try {
        return parse_material(text);
    } catch (const Error& e) {
        throw Error(fmt::format("{}: '{}': {}", s.source, key, e.what()));
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

void World::build_preetham() {
    const LightParams& l = m_scene.light;
    try {
        m_sky.emplace(l.turbidity, std::array<double, 3>{m_sun.x, m_sun.y, m_sun.z});
    } catch (const Error& e) {
        throw Error(fmt::format("{}: light: {}", m_scene.source, e.what()));
    }
    // The daylight basis relative to D65, the spectral carrier's unit, and its XYZ.
    const DenseSpectrum d65 = illuminant_d65();
    const std::array<DenseSpectrum, 3> basis = daylight_basis();
    for (int k = 0; k < 3; ++k) {
        for (int i = 0; i < dense_sample_count; ++i) m_daylight[k].v[i] = basis[k][i] / d65[i];
        m_daylight_xyz[k] = m_basis->xyz(m_daylight[k]);
    }
    // The sun's colour from the same paper, at the sun's zenith angle and the sky's turbidity,
    // normalised to Y = 1: sun_intensity keeps its meaning.
    const DenseSpectrum sun = preetham_sun_radiance(l.turbidity, m_sky->sun_zenith());
    SpectralCarrier s;
    for (int i = 0; i < dense_sample_count; ++i) s.v[i] = sun[i] / d65[i];
    const Xyz c = m_basis->xyz(s);
    m_sun_spectrum = s * (1.0 / c.Y);
    const Rgb rgb = m_basis->colorimeter().linear_rgb({c.X / c.Y, 1.0, c.Z / c.Y});
    m_sun_rgb = {rgb.r, rgb.g, rgb.b};
}

World::SkyWeights World::sky_weights(Vec3 d) const noexcept {
    const Xyy c = m_sky->xyy({d.x, d.y, d.z});
    // Sky chromaticities lie near the daylight locus; daylight_weights refuses only far from it.
    Xy xy{c.x, c.y};
    if (!(0.0241 + 0.2562 * xy.x - 0.7341 * xy.y < -0.01)) xy = {0.3127, 0.3290};
    const DaylightWeights w = daylight_weights(xy);
    const double y = m_daylight_xyz[0].Y + w.m1 * m_daylight_xyz[1].Y + w.m2 * m_daylight_xyz[2].Y;
    const double target = c.Y * m_scene.light.sky_scale * m_scene.light.environment_intensity;
    return {y > 0 ? target / y : 0.0, w.m1, w.m2};
}

void World::environment_spectrum(Vec3 d, SpectralCarrier& out, bool with_sun) const noexcept {
    if (!m_sky) {
        out = m_basis->from_rgb(environment(d, with_sun));
        return;
    }
    if (d.y >= 0) {
        const SkyWeights w = sky_weights(d);
        for (int i = 0; i < dense_sample_count; ++i)
            out.v[i] = w.k * (m_daylight[0].v[i] + w.m1 * m_daylight[1].v[i] + w.m2 * m_daylight[2].v[i]);
    } else {
        out = m_basis->from_rgb(m_ground_radiance);
    }
    if (with_sun && dot(d, m_sun) >= m_cos_sun_radius) out += m_sun_spectrum * m_sun_radiance;
}

double World::sun_lobe(Vec3 r, double sigma) const noexcept {
    const double s = std::acos(std::clamp(m_cos_sun_radius, -1.0, 1.0));
    // The von Mises–Fisher density on the sphere, κ/(2π (1 − e^{−2κ})) e^{κ (cos δ − 1)}: the
    // spherical Gaussian of angular variance 1/κ, normalised over the whole sphere.
    const double kappa = 1.0 / (sigma * sigma + 0.25 * s * s);
    // 1 − cos δ as |r − sun|²/2 for unit vectors: accurate near the sun.
    const Vec3 e = r - m_sun;
    const double one_minus_cos = 0.5 * dot(e, e);
    const double solid_angle = 2.0 * pi * (1.0 - m_cos_sun_radius);
    return m_sun_radiance * solid_angle * kappa / (2.0 * pi * -std::expm1(-2.0 * kappa)) *
           std::exp(-kappa * one_minus_cos);
}

void World::sun_glint_spectrum(Vec3 r, double sigma, SpectralCarrier& out) const noexcept {
    const double w = sun_lobe(r, sigma);
    if (m_sky) out = m_sun_spectrum * w;
    else out = m_basis->from_rgb({m_sun_rgb[0] * w, m_sun_rgb[1] * w, m_sun_rgb[2] * w});
}

void World::build_oil_slick() {
    const OilParams& o = m_scene.oil;
    m_ground.emplace(Vec3{0, o.center[1], 0}, Vec3{0, 1, 0});
    const Material substrate = o.substrate == "wet"
                                   ? material_of(m_scene, "oil.substrate", "water")
                                   : Material::constant("asphalt", o.asphalt_index);
    m_film = SingleFilm{material_of(m_scene, "air", "air"),
                        material_of(m_scene, "oil.film", o.film), substrate};
    m_max_thickness_nm = o.max_thickness_nm;
    m_epsilon = 1e-7 * std::max(1.0, o.radius);
}

void World::build_soap_bubbles() {
    const SoapParams& s = m_scene.soap;
    double extent = 1;
    for (const BubbleParams& b : s.bubbles) {
        m_bubbles.emplace_back(to_vec(b.center), b.radius);
        m_max_thickness_nm = std::max(m_max_thickness_nm,
                                      std::max(b.top_thickness_nm, b.bottom_thickness_nm) +
                                          1.5 * b.turbulence_nm);
        extent = std::max(extent, b.radius);
    }
    m_ground.emplace(Vec3{0, s.floor_y, 0}, Vec3{0, 1, 0});
    const Material air = material_of(m_scene, "air", "air");
    m_film = SingleFilm{air, material_of(m_scene, "soap.film", s.film), air};
    m_epsilon = 1e-7 * extent;
}

void World::build_morpho() {
    const MorphoSceneParams& m = m_scene.morpho;
    m_wing_params = MorphoParameters{m.d1_nm, m.d2_nm, m.n_chitin, m.periods,
                                     2.0 / ((m.periods + 1.0) * (m.periods + 1.0))};
    m_wing_blend = MorphoBlend{m.blend_min_nm, m.blend_max_nm, m.blend_samples,
                               MorphoBlendThickness::d1};
    const double half = 0.5 * m.span;
    // The ground under the butterfly.
    m_ground.emplace(Vec3{0, -0.35 * half, 0}, Vec3{0, 1, 0});
    if (!m.wing_mesh.empty()) {
        m_wing_mesh = TriangleMesh::read_obj(m_scene.directory / m.wing_mesh);
    } else {
        build_morpho_wings(half);
    }
    // The body along z, head towards −z: head, thorax and abdomen as ellipsoids, two eyes, and
    // two clubbed antennae as chains of overlapping spheres. Proportions after photographs of
    // Morpho peleides (dorsal view): the thorax about 0.12 of the span long, the abdomen about
    // 0.2, the antennae about half the forewing's length.
    const auto part = [&](double z, Vec3 axes) {
        m_body_parts.emplace_back(Vec3{0, 0.01 * half, z * half}, axes * half);
    };
    part(-0.255, {0.040, 0.036, 0.040});   // head
    part(-0.120, {0.070, 0.060, 0.110});   // thorax
    part(0.200, {0.045, 0.040, 0.240});    // abdomen
    for (int side = -1; side <= 1; side += 2) {
        m_body.emplace_back(Vec3{side * 0.032 * half, 0.022 * half, -0.272 * half}, 0.017 * half);  // eye
        SphereChain antenna;
        const Vec3 root{side * 0.014 * half, 0.035 * half, -0.29 * half};
        const Vec3 tip{side * 0.20 * half, 0.09 * half, -0.74 * half};
        const double r = 0.0055 * half;
        const int count = static_cast<int>(std::ceil(length(tip - root) / (0.8 * r)));
        for (int k = 0; k <= count; ++k) {
            const double f = static_cast<double>(k) / count;
            // A gentle outward bow, and the club: the last 12 % thicken to 2.2 r.
            const Vec3 bow = Vec3{side * 0.025 * half, 0, 0} * std::sin(pi * f);
            const double club = f > 0.88 ? 1.0 + 1.2 * std::sin(pi * (f - 0.88) / 0.24) : 1.0;
            antenna.spheres.emplace_back(root + f * (tip - root) + bow, r * club);
            antenna.bounds.expand(antenna.spheres.back().bounds());
        }
        m_antennae.push_back(std::move(antenna));
    }
    m_epsilon = 1e-7 * half;
}

namespace {

using Point2 = std::array<double, 2>;

/// A closed Catmull–Rom spline through control points (uniform parameter, tension ½), `per`
/// points per segment; segment k runs from control k to k + 1 (the last back to the first).
std::vector<Point2> closed_spline(const std::vector<Point2>& c, int per) {
    std::vector<Point2> out;
    const std::size_t n = c.size();
    for (std::size_t k = 0; k < n; ++k) {
        const Point2& p0 = c[(k + n - 1) % n];
        const Point2& p1 = c[k];
        const Point2& p2 = c[(k + 1) % n];
        const Point2& p3 = c[(k + 2) % n];
        for (int j = 0; j < per; ++j) {
            const double t = static_cast<double>(j) / per, t2 = t * t, t3 = t2 * t;
            Point2 q{};
            for (int a = 0; a < 2; ++a) {
                q[a] = 0.5 * (2.0 * p1[a] + (p2[a] - p0[a]) * t + (2.0 * p0[a] - 5.0 * p1[a] + 4.0 * p2[a] - p3[a]) * t2 +
                              (3.0 * p1[a] - p0[a] - 3.0 * p2[a] + p3[a]) * t3);
            }
            out.push_back(q);
        }
    }
    return out;
}

}  // namespace

void World::build_morpho_wings(double half) {
    // Procedural outlines of a Morpho's right fore- and hindwing (a outward along the span, b
    // towards the head), in units of the half span, drawn after dorsal photographs of Morpho
    // peleides and M. menelaus: a long, nearly straight costa (leading edge), a rounded apex, a
    // slightly concave outer margin, and a broad hindwing whose outer edge is scalloped. The
    // last control point back to the first is the root edge, along the body: not margin.
    const std::vector<Point2> fore = {{0.06, 0.10}, {0.32, 0.25}, {0.62, 0.37}, {0.86, 0.45}, {0.98, 0.42},
                                      {1.00, 0.33}, {0.93, 0.18}, {0.84, 0.02}, {0.72, -0.12},
                                      {0.55, -0.19}, {0.32, -0.17}, {0.08, -0.05}};
    const std::vector<Point2> hind = {{0.06, -0.03}, {0.36, -0.12}, {0.60, -0.17}, {0.74, -0.27},
                                      {0.78, -0.42}, {0.72, -0.58}, {0.60, -0.72}, {0.44, -0.81},
                                      {0.28, -0.80}, {0.15, -0.66}, {0.07, -0.40}};
    constexpr int per = 12;
    const double tilt = m_scene.morpho.dihedral_deg * pi / 180.0;
    for (int side = -1; side <= 1; side += 2) {
        for (const auto* controls : {&fore, &hind}) {
            Wing w;
            w.forewing = controls == &fore;
            w.origin = Vec3{side * 0.04 * half, 0, 0};
            // Tilted up by the dihedral about the body axis (z).
            w.axis_a = Vec3{side * std::cos(tilt), std::sin(tilt), 0};
            w.axis_b = Vec3{0, 0, -1};
            w.normal = normalize(cross(w.axis_b, w.axis_a));
            if (w.normal.y < 0) w.normal = -w.normal;
            std::vector<Point2> outline = closed_spline(*controls, per);
            const std::size_t n = outline.size();
            const std::size_t root_edges = per;  // the last segment, control n−1 back to 0
            w.outer_edge.assign(n, true);
            for (std::size_t e = n - root_edges; e < n; ++e) w.outer_edge[e] = false;
            Point2 centre{};
            for (const Point2& c : *controls) {
                centre[0] += c[0] / static_cast<double>(controls->size());
                centre[1] += c[1] / static_cast<double>(controls->size());
            }
            if (!w.forewing) {
                // Scallops: the outer edge pulled in between its 7 vein ends, by up to 1.2 % of
                // the half span.
                const std::size_t first = per, last = n - 2 * per;  // from the costa's end to the inner margin
                for (std::size_t e = first; e <= last; ++e) {
                    const double f = static_cast<double>(e - first) / static_cast<double>(last - first);
                    const double pull = 0.012 * (0.5 - 0.5 * std::cos(2.0 * pi * 7.0 * f));
                    const double dx = centre[0] - outline[e][0], dy = centre[1] - outline[e][1];
                    const double len = std::hypot(dx, dy);
                    outline[e][0] += pull * dx / len;
                    outline[e][1] += pull * dy / len;
                }
            }
            // Veins from the wing's root to points spread along its outer edge, bending at the
            // end of the discal cell (40 % of the way); the costal vein runs near the leading
            // edge and is hidden in the margin.
            const Point2 root{0.5 * ((*controls)[0][0] + controls->back()[0]),
                              0.5 * ((*controls)[0][1] + controls->back()[1])};
            const int veins = w.forewing ? 9 : 8;
            for (int v = 0; v < veins; ++v) {
                const double f = (v + 0.5) / veins;
                const auto e = static_cast<std::size_t>(per + f * static_cast<double>(n - 3 * per));
                const Point2 end = outline[e];
                const Point2 bend{root[0] + 0.4 * (end[0] - root[0]) + 0.03 * (centre[0] - end[0]),
                                  root[1] + 0.4 * (end[1] - root[1]) + 0.03 * (centre[1] - end[1])};
                w.veins.push_back({root, bend});
                w.veins.push_back({bend, end});
            }
            w.vein_half_width = 0.003 * half;
            w.vein_start = 0.3 * half;
            for (const Point2& p : outline) w.outline.push_back({p[0] * half, p[1] * half});
            for (auto& seg : w.veins) {
                for (Point2& p : seg) p = {p[0] * half, p[1] * half};
            }
            w.length = half;
            w.bounds = {w.outline[0][0], w.outline[0][0], w.outline[0][1], w.outline[0][1]};
            for (const auto& p : w.outline) {
                w.bounds[0] = std::min(w.bounds[0], p[0]);
                w.bounds[1] = std::max(w.bounds[1], p[0]);
                w.bounds[2] = std::min(w.bounds[2], p[1]);
                w.bounds[3] = std::max(w.bounds[3], p[1]);
            }
            m_wings.push_back(std::move(w));
        }
    }
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
    if (m_scene.kind != SceneKind::morpho) return;
    // The wing: the reflectance spectrum at an angle, thesis (eq. 25 with eq. 29, blended) or
    // exact (the transfer matrix of l chitin layers d₂ separated by air gaps d₁).
    const MorphoSceneParams& m = m_scene.morpho;
    const MorphoParameters wing = m_wing_params;
    const MorphoBlend blend = m_wing_blend;
    const bool exact = rp.optics == OpticsModel::exact;
    const Material air = material_of(m_scene, "air", "air");
    const Material chitin = Material::constant("chitin", m.n_chitin);
    auto spectrum_at = [=](double theta_deg) {
        std::array<double, dense_sample_count> s{};
        const double theta = std::min(theta_deg, 89.9) * pi / 180.0;
        if (!exact) {
            MorphoFilm(wing, m.blend ? std::optional<MorphoBlend>(blend) : std::nullopt)
                .at_angle(theta)
                ->reflectance(0.0, s);
            return s;
        }
        // The exact wing: l chitin layers d₂ separated by air gaps d₁, the blend's mean over d₁.
        const int samples = m.blend ? blend.samples : 1;
        DenseValues one;
        for (int b = 0; b < samples; ++b) {
            const double d1 = m.blend ? blend.min_nm + (blend.max_nm - blend.min_nm) * b /
                                                           (samples - 1.0)
                                      : wing.d1_nm;
            std::vector<Layer> layers;
            for (int p = 0; p < wing.periods; ++p) {
                layers.push_back({chitin, wing.d2_nm});
                if (p + 1 < wing.periods) layers.push_back({air, d1});
            }
            ExactFilm(air, std::move(layers), air).at_angle(theta)->reflectance(wing.d2_nm, one);
            for (int i = 0; i < dense_sample_count; ++i) s[i] += one[i] / samples;
        }
        return s;
    };
    if (rp.path == ColorPath::table || rp.path == ColorPath::fourier) {
        m_wing_rgb = AngleTable<Rgb3>(1.0, [&](double theta_deg) {
            const auto s = spectrum_at(theta_deg);
            const Rgb c = col.linear_rgb(
                col.xyz_of([&](double lambda) { return s[static_cast<int>(lambda) - lambda_min_nm]; }));
            return Rgb3{c.r, c.g, c.b};
        });
    } else if (exact) {
        m_wing_spectra =
            AngleTable<std::array<double, dense_sample_count>>(1.0, spectrum_at);
    }
}

void World::wing_spectrum(double theta_deg, SpectralCarrier& out) const noexcept {
    if (m_scene.render.optics == OpticsModel::exact) {
        out.v = m_wing_spectra.at(theta_deg);
        return;
    }
    const double theta = std::clamp(theta_deg, 0.0, 90.0) * pi / 180.0;
    for (int i = 0; i < dense_sample_count; ++i) {
        const double lambda = lambda_min_nm + i;
        out.v[i] = m_scene.morpho.blend
                       ? morpho_blend_reflectance_continuous(m_wing_params, m_wing_blend, lambda, theta)
                       : morpho_reflectance(m_wing_params, lambda, theta);
    }
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

// --- Geometry ------------------------------------------------------------------------------

namespace {

/// Distance from (a, b) to the segment p–q.
double segment_distance(double a, double b, const std::array<double, 2>& p, const std::array<double, 2>& q) {
    const double ex = q[0] - p[0], ey = q[1] - p[1];
    const double len2 = ex * ex + ey * ey;
    const double s = len2 > 0 ? std::clamp(((a - p[0]) * ex + (b - p[1]) * ey) / len2, 0.0, 1.0) : 0.0;
    return std::hypot(a - (p[0] + s * ex), b - (p[1] + s * ey));
}

/// Crossing-number test and the distance to the outer edges, in the wing's 2-D coordinates.
bool inside_wing(const Wing& w, double a, double b, double& margin) {
    if (a < w.bounds[0] || a > w.bounds[1] || b < w.bounds[2] || b > w.bounds[3]) return false;
    bool inside = false;
    double best = std::numeric_limits<double>::infinity();
    const std::size_t n = w.outline.size();
    for (std::size_t i = 0; i < n; ++i) {
        const auto& p = w.outline[i];
        const auto& q = w.outline[(i + 1) % n];
        if ((p[1] > b) != (q[1] > b)) {
            const double x = p[0] + (b - p[1]) * (q[0] - p[0]) / (q[1] - p[1]);
            if (a < x) inside = !inside;
        }
    }
    if (!inside) return false;
    for (std::size_t i = 0; i < n; ++i) {
        const auto& p = w.outline[i];
        const auto& q = w.outline[(i + 1) % n];
        if (w.outer_edge[i]) best = std::min(best, segment_distance(a, b, p, q));
    }
    margin = best / w.length;
    // The forewing's black border is about twice as wide at the apex as near the body.
    if (w.forewing) {
        const double f = std::clamp(a / w.length, 0.0, 1.0);
        margin /= 0.7 + 1.3 * f * f;
    }
    return true;
}

/// How much of a vein covers (a, b): 1 within its half-width, falling smoothly to 0 at twice it;
/// near the root, where the veins converge under the body's hair, they fade out.
double vein_cover(const Wing& w, double a, double b) {
    double d = std::numeric_limits<double>::infinity();
    for (const auto& seg : w.veins) d = std::min(d, segment_distance(a, b, seg[0], seg[1]));
    const auto smooth = [](double x) {
        x = std::clamp(x, 0.0, 1.0);
        return x * x * (3.0 - 2.0 * x);
    };
    const double from_root = std::hypot(a - w.veins.front()[0][0], b - w.veins.front()[0][1]);
    return smooth((2.0 * w.vein_half_width - d) / w.vein_half_width) *
           smooth((from_root - 0.5 * w.vein_start) / (0.5 * w.vein_start));
}

}  // namespace

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
        if (!inside_wing(w, dot(d, w.axis_a), dot(d, w.axis_b), margin)) continue;
        t_max = t;
        hit.surface = SurfaceHit{};
        hit.surface.t = t;
        hit.surface.position = p;
        hit.surface.normal = w.normal;
        hit.surface.shading_normal = w.normal;
        hit.kind = SurfaceKind::wing;
        hit.index = static_cast<int>(i);
        hit.margin_distance = margin;
        hit.vein = vein_cover(w, dot(d, w.axis_a), dot(d, w.axis_b));
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
        if (inside_wing(w, dot(d, w.axis_a), dot(d, w.axis_b), margin)) return true;
    }
    if (m_wing_mesh && m_wing_mesh->occluded(r, m_epsilon, far)) return true;
    return false;
}

// --- Light -----------------------------------------------------------------------------------

Rgb3 World::environment(Vec3 d, bool with_sun) const noexcept {
    const LightParams& l = m_scene.light;
    Rgb3 e;
    if (m_sky) {
        if (d.y >= 0) {
            // The sky's XYZ from the same daylight spectrum the spectral path carries.
            const SkyWeights w = sky_weights(d);
            Xyz c;
            for (int k = 0; k < 3; ++k) {
                const double f = k == 0 ? 1.0 : (k == 1 ? w.m1 : w.m2);
                c.X += w.k * f * m_daylight_xyz[k].X;
                c.Y += w.k * f * m_daylight_xyz[k].Y;
                c.Z += w.k * f * m_daylight_xyz[k].Z;
            }
            const Rgb rgb = m_basis->colorimeter().linear_rgb(c);
            e = {rgb.r, rgb.g, rgb.b};
        } else {
            e = m_ground_radiance;
        }
    } else if (m_environment) {
        const io::Image& img = *m_environment;
        const double u = std::atan2(d.x, -d.z) / (2 * pi) + 0.5;
        const double v = std::acos(std::clamp(d.y, -1.0, 1.0)) / pi;
        const int x = std::clamp(static_cast<int>(u * img.width), 0, img.width - 1);
        const int y = std::clamp(static_cast<int>(v * img.height), 0, img.height - 1);
        for (int c = 0; c < 3; ++c) {
            const double s = img.at(x, y, c);
            e[c] = std::isfinite(s) ? std::max(0.0, s) : 0.0;
        }
    } else if (d.y >= 0) {
        const double f = std::pow(d.y, 0.45);
        for (int c = 0; c < 3; ++c) e[c] = l.sky_horizon[c] + f * (l.sky_zenith[c] - l.sky_horizon[c]);
    } else {
        e = l.ground;  // the ground below the horizon
    }
    if (!m_sky)
        for (double& v : e) v *= l.environment_intensity;
    if (with_sun && dot(d, m_sun) >= m_cos_sun_radius)
        for (int c = 0; c < 3; ++c) e[c] += m_sun_radiance * m_sun_rgb[c];
    return e;
}

Rgb3 World::diffuse_light(Vec3 p, Vec3 n) const noexcept {
    const double cos_sun = dot(n, m_sun);
    const double sun = cos_sun > 0 && !sun_blocked(p) ? m_scene.light.sun_intensity * cos_sun : 0.0;
    // The sky seen by a tilted surface: all of it facing up, about half facing sideways.
    const double sky = 0.5 + 0.5 * std::clamp(n.y, -1.0, 1.0);
    return {sun * m_sun_rgb[0] + sky * m_ambient[0], sun * m_sun_rgb[1] + sky * m_ambient[1],
            sun * m_sun_rgb[2] + sky * m_ambient[2]};
}

// --- Textures --------------------------------------------------------------------------------

void World::pavement(Vec3 p, Vec3& normal, Rgb3& albedo) const noexcept {
    const PavementParams& v = m_scene.pavement;
    const double f = v.bump_frequency;
    // Two noise calls set the bumps' scale and their roughness (Smits 1990 §3.5), then the
    // bumps themselves and fine bumps on top, all through the gradient dnoise.
    const double scale = m_noise.noise(p.x * f * 0.21, 0.5, p.z * f * 0.21);
    const double rough = m_noise2.noise(p.x * f * 0.13, 1.5, p.z * f * 0.13);
    const double freq = f * (0.5 + std::clamp(scale, 0.0, 1.5));
    const NoiseGradient g1 = m_noise.dnoise(p.x * freq, 2.5, p.z * freq);
    const double ff = v.fine_frequency;
    const NoiseGradient g2 = m_noise2.dnoise(p.x * ff, 7.5, p.z * ff);
    const double a1 = v.bump_height * std::clamp(rough, 0.0, 1.5);
    const double sx = a1 * g1.x + v.fine_height * g2.x;
    const double sz = a1 * g1.z + v.fine_height * g2.z;
    normal = normalize(Vec3{-sx, 1.0, -sz});
    const double grain = m_noise.noise(p.x * ff * 0.7, 11.5, p.z * ff * 0.7);
    const double m = std::clamp(1.0 + v.albedo_variation * (2.0 * grain - 1.0), 0.0, 2.0);
    albedo = {std::min(1.0, v.albedo[0] * m), std::min(1.0, v.albedo[1] * m),
              std::min(1.0, v.albedo[2] * m)};
}

double World::oil_thickness_nm(Vec3 p) const noexcept {
    const OilParams& o = m_scene.oil;
    const double x = (p.x - o.center[0]) / o.radius;
    const double y = (p.z - o.center[2]) / o.radius;
    const double s = o.turbulence_scale;
    const double turb = m_noise.turbulence(x * s + 17.25, y * s + 3.5, 0.5);
    const double t = o.max_thickness_nm * std::exp(-o.k1 * (x * x + y * y + o.k2 * turb));
    return t >= o.min_thickness_nm ? t : 0.0;
}

double World::bubble_thickness_nm(int bubble, Vec3 p) const noexcept {
    const BubbleParams& b = m_scene.soap.bubbles[bubble];
    const Vec3 local = (p - to_vec(b.center)) / b.radius;
    const double h = std::clamp(0.5 * (local.y + 1.0), 0.0, 1.0);  // 0 bottom, 1 top
    const double depth = 1.0 - h;
    const double base = b.top_thickness_nm +
                        (b.bottom_thickness_nm - b.top_thickness_nm) * std::pow(depth, b.profile_exponent);
    const double s = b.turbulence_scale;
    const double o = 31.7 * (bubble + 1);  // each bubble its own part of the noise
    // Turbulence (mean about 1) swirls the bands; it fades towards the top, where the film
    // has drained to the black film.
    const double turb = m_noise.turbulence(local.x * s + o, local.y * s, local.z * s) - 1.0;
    const double swirl = b.turbulence_nm * turb * std::min(1.0, 3.0 * depth);
    return std::max(0.0, base + swirl);
}

Vec3 World::wing_normal(Vec3 p, Vec3 n) const noexcept {
    const MorphoSceneParams& m = m_scene.morpho;
    const double f = m.bump_frequency;
    const NoiseGradient g = m_noise.dnoise(p.x * f, p.y * f, p.z * f);
    Vec3 grad{g.x, g.y, g.z};
    grad = grad - dot(grad, n) * n;
    return normalize(n - m.bump_height * grad);
}

Rgb3 World::floor_albedo(Vec3 p) const noexcept {
    const SoapParams& s = m_scene.soap;
    if (s.floor_checker <= 0) return s.floor_albedo;
    // The parity of the cell, in doubles: far hits would overflow an integer cell index.
    const double cell = std::floor(p.x / s.floor_checker) + std::floor(p.z / s.floor_checker);
    return std::fmod(std::abs(cell), 2.0) == 1.0 ? s.floor_albedo_alt : s.floor_albedo;
}

Rgb3 World::background_albedo(Vec3 p) const noexcept {
    const Rgb3& a = m_scene.morpho.background_albedo;
    const double t = m_noise2.turbulence(p.x * 1.7, 0.3, p.z * 1.7) * 0.5;  // about 0–1
    const double m = std::clamp(0.55 + 0.9 * (t - 0.5), 0.2, 1.6);
    return {std::min(1.0, a[0] * m), std::min(1.0, a[1] * m), std::min(1.0, a[2] * m)};
}

}  // namespace irid::render
