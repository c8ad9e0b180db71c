// The Morpho: the butterfly's wings (outlines, veins and dark margins), its body, the wing's
// reflectance over angle (the thesis' model or the exact stack of chitin lamellae), and the
// background under it.

#include "world.h"

#include <irid/optics/material.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace irid::render {
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

void World::build_wing_tables() {
    const RenderParams& rp = m_scene.render;
    const Colorimeter& col = m_basis->colorimeter();
    // The wing: the reflectance spectrum at an angle, thesis (eq. 25 with eq. 29, blended) or
    // exact (the transfer matrix of l chitin layers d₂ separated by air gaps d₁).
    const MorphoSceneParams& m = m_scene.morpho;
    const MorphoParameters wing = m_wing_params;
    const MorphoBlend blend = m_wing_blend;
    const bool exact = rp.optics == OpticsModel::exact;
    const Material air = material("air", "air");
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
double vein_cover_at(const Wing& w, double a, double b) {
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

bool Wing::contains(double a, double b, double& margin) const {
    return inside_wing(*this, a, b, margin);
}

double Wing::vein_cover(double a, double b) const { return vein_cover_at(*this, a, b); }

Vec3 World::wing_normal(Vec3 p, Vec3 n) const noexcept {
    const MorphoSceneParams& m = m_scene.morpho;
    const double f = m.bump_frequency;
    const NoiseGradient g = m_noise.dnoise(p.x * f, p.y * f, p.z * f);
    Vec3 grad{g.x, g.y, g.z};
    grad = grad - dot(grad, n) * n;
    return normalize(n - m.bump_height * grad);
}

Rgb3 World::background_albedo(Vec3 p) const noexcept {
    const Rgb3& a = m_scene.morpho.background_albedo;
    const double t = m_noise2.turbulence(p.x * 1.7, 0.3, p.z * 1.7) * 0.5;  // about 0–1
    const double m = std::clamp(0.55 + 0.9 * (t - 0.5), 0.2, 1.6);
    return {std::min(1.0, a[0] * m), std::min(1.0, a[1] * m), std::min(1.0, a[2] * m)};
}
}  // namespace irid::render
