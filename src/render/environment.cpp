// The light around every scene: the Preetham-Shirley-Smits sky and sun (spectral and RGB),
// the sun's glint lobe, the uniform or image environment, and the diffuse light on a surface.

#include "world.h"

#include <irid/color/illuminant.h>
#include <irid/error.h>

#include <fmt/core.h>

#include <algorithm>
#include <cmath>

namespace irid::render {
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
    if (!(0.0241 + 0.2562 * xy.x - 0.7341 * xy.y < -0.01)) xy = d65_xy;
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

}  // namespace irid::render
