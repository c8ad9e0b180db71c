// Soap bubbles over a floor: each bubble's film, drained thin at the top and swirled by
// turbulence, and the chequered floor.

#include "world.h"

#include <algorithm>
#include <cmath>

namespace irid::render {

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
    const Material air = material("air", "air");
    m_film = SingleFilm{air, material("soap.film", s.film), air};
    m_epsilon = 1e-7 * extent;
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

Rgb3 World::floor_albedo(Vec3 p) const noexcept {
    const SoapParams& s = m_scene.soap;
    if (s.floor_checker <= 0) return s.floor_albedo;
    // The parity of the cell, in doubles: far hits would overflow an integer cell index.
    const double cell = std::floor(p.x / s.floor_checker) + std::floor(p.z / s.floor_checker);
    return std::fmod(std::abs(cell), 2.0) == 1.0 ? s.floor_albedo_alt : s.floor_albedo;
}
}  // namespace irid::render
