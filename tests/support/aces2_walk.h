#pragma once

// Bright scene colours for the ACES 2.0 highlight walks (tests/gamut/aces2_highlight_walk_test.cpp
// and tests/exchange/display_image_walk_test.cpp): ACES2065-1 float triples whose luminance lies
// where the tonescaled J approaches the peak's J. Half are log-uniform from the grey shown at half
// the peak to 1.2 times the grey that first reaches the peak; a quarter lie within 1 % of that grey
// and a quarter within a millionth (where J is a float step from the peak's). Chromaticities run
// from the AP1 white to AP1's boundary, most of them pale (saturation u², a uniform u).

#include <irid/color/rgb.h>
#include <irid/gamut/aces2.h>
#include <irid/gamut/aces2_display.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

namespace irid::test {

inline std::vector<float> bright_colours(const Aces2Output& out, std::size_t count,
                                         std::uint64_t seed) {
    // ACES AP1 and AP0 with the ACES white (SMPTE ST 2065-1, Academy S-2014-004).
    const RgbPrimaries ap0{{0.7347, 0.2653}, {0.0, 1.0}, {0.0001, -0.0770}};
    const RgbPrimaries ap1{{0.713, 0.293}, {0.165, 0.830}, {0.128, 0.044}};
    const Xy white{0.32168, 0.33767};
    const Mat3 ap1_to_xyz = rgb_to_xyz_matrix(ap1, white);
    const Mat3 ap1_to_ap0 = inverse(rgb_to_xyz_matrix(ap0, white)) * ap1_to_xyz;

    const Aces2Rendering& r = out.rendering();
    const Aces2JmhModel& model = r.input_model();
    const double peak = out.spec().peak_nits;
    // Scene greys (1.0 = 100 cd/m²): shown at half the peak, and first shown at the peak.
    const double half = model.j_to_y(r.tonescale_inverse(model.y_to_j(0.5 * peak))) / 100.0;
    const double full = model.j_to_y(r.tonescale_inverse(r.limit_j_max())) / 100.0;
    const double top = std::min(1.2 * full, r.forward_limit());

    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::vector<float> colours;
    colours.reserve(3 * count);
    for (std::size_t i = 0; i < count; ++i) {
        double y = 0.0;
        switch (i % 4) {
            case 0:
            case 1: y = half * std::pow(top / half, u(rng)); break;
            case 2: y = full * (1.0 + 1e-2 * (2.0 * u(rng) - 1.0)); break;
            default: y = full * (1.0 + 1e-6 * (2.0 * u(rng) - 1.0)); break;
        }
        const double s = u(rng) * u(rng);
        const int side = static_cast<int>(3.0 * u(rng)) % 3;
        const double t = u(rng);
        Vec3 edge{};
        edge[side] = 1.0 - t;
        edge[(side + 1) % 3] = t;
        Vec3 c{};
        for (int k = 0; k < 3; ++k) c[k] = (1.0 - s) + s * edge[k];
        const double luminance = (ap1_to_xyz * c)[1];
        for (double& v : c) v *= y / luminance;
        const Vec3 aces = ap1_to_ap0 * c;
        colours.insert(colours.end(), {static_cast<float>(aces[0]), static_cast<float>(aces[1]),
                                       static_cast<float>(aces[2])});
    }
    return colours;
}

}  // namespace irid::test
