// The oil slick (Smits 1990 §3.5): a film of oil on wet or dry pavement, its thickness from
// turbulence, and the pavement's bumps and albedo.

#include "world.h"

#include <algorithm>
#include <cmath>

namespace irid::render {

void World::build_oil_slick() {
    const OilParams& o = m_scene.oil;
    m_ground.emplace(Vec3{0, o.center[1], 0}, Vec3{0, 1, 0});
    const Material substrate = o.substrate == "wet"
                                   ? material("oil.substrate", "water")
                                   : Material::constant("asphalt", o.asphalt_index);
    m_film = SingleFilm{material("air", "air"),
                        material("oil.film", o.film), substrate};
    m_max_thickness_nm = o.max_thickness_nm;
    m_epsilon = 1e-7 * std::max(1.0, o.radius);
}

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
}  // namespace irid::render
