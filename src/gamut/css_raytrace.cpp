// css-raytrace: the CSS Color 4 "Ray Trace" gamut mapping, in double (the reference of the
// float kernel in batch_simd_css.cpp).
//
// Source: CSS Color Module Level 4, Editor's Draft, §13.2 "CSS Gamut Mapping to an RGB
// Destination", "The Ray Trace Gamut Mapping" (#GMA-Raytrace) and its "Sample Pseudocode for the
// Ray Trace Gamut Mapping" (#pseudo-raytrace) with the "cast a ray" algorithm and footnotes 1–8,
// as corrected by csswg-drafts issue 14029 (pull request 14080): the final clip is of
// origin_rgb (not of the undefined "current"), a ray component is used when abs(d) > 1e-12
// (not <), and the anchor bounds and the parallel threshold are 1e-12 for 64-bit numbers and
// 1e-6 for 32-bit ones.
//
// What this library decides where the pseudocode speaks of a generic destination:
// - "white" and "black" are the gamut's extremes (max, max, max) and (0, 0, 0), and the lightness
//   test compares with the Oklab L of that white (1 for the D65 spaces' white to rounding,
//   cbrt(max) at an HDR peak), as GamutClipper::css does (clip.h).
// - The destination's bounds are [0, max] on every channel (footnotes 2 and 6), and the anchor
//   bounds low = 0 + 1e-12 and high = 1 − 1e-12 scale with the cube: 1e-12 max and
//   (1 − 1e-12) max (footnote 1: "small relative to the unit type").
// - "between low and high" is strict (low < x < high), as colorjs.io's toGamutRayTrace
//   (src/toGamut.js) reads it.
// - "in gamut" (which CSS Color 4 leaves to the implementation) is this library's rule of
//   clip.h: a colour within oklab_rounding_tolerance × max of the cube is on it to within
//   rounding and comes back clamped (moved by at most that much). Taken literally, the ray trace
//   moves such a colour next to the white by up to 1.3e-3 (sRGB (0.99868, 1 + 2e-16, 1) →
//   (1, 0.99964, 0.99893): the anchor and the colour lie within rounding of the top faces,
//   where a ray's direction is rounding), which clip.h's contract for every method forbids.

#include <irid/color/spaces.h>
#include <irid/gamut/clip.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>

namespace irid {
namespace {

/// Footnotes 1 and 7 of the pseudocode: the 64-bit thresholds.
constexpr double raytrace_epsilon = 1e-12;

/// "Cast a ray" (CSS Color 4, #pseudo-raytrace): the slab intersection of the ray from `start`
/// to `end` with the box [0, max]³, favouring the first intersection in the direction
/// start → end (footnote 8); nothing when there is none (the ray misses the box, a component
/// parallel to a face lies outside it, or start and end coincide).
std::optional<std::array<double, 3>> cast_ray(const std::array<double, 3>& start,
                                              const std::array<double, 3>& end,
                                              double max) noexcept {
    double tfar = std::numeric_limits<double>::infinity();
    double tnear = -std::numeric_limits<double>::infinity();
    std::array<double, 3> direction{};
    for (std::size_t i = 0; i < 3; ++i) {
        const double a = start[i], b = end[i];
        const double d = b - a;
        direction[i] = d;
        if (std::abs(d) > raytrace_epsilon) {  // issue 14029: '>' (the draft had '<')
            const double inv_d = 1.0 / d;
            const double t1 = (0.0 - a) * inv_d;
            const double t2 = (max - a) * inv_d;
            tnear = std::max(std::min(t1, t2), tnear);
            tfar = std::min(std::max(t1, t2), tfar);
        } else if (a < 0.0 || a > max) {
            return std::nullopt;  // parallel to the slab and outside it
        }
    }
    if (tnear > tfar || tfar < 0.0) return std::nullopt;
    if (tnear < 0.0) tnear = tfar;
    if (std::isinf(tnear)) return std::nullopt;
    return std::array<double, 3>{start[0] + direction[0] * tnear, start[1] + direction[1] * tnear,
                                 start[2] + direction[2] * tnear};
}

}  // namespace

Rgb GamutClipper::css_raytrace(const Rgb& origin, Branches* branches) const noexcept {
    const double max = m_gamut.max();
    // Steps 2–4: OkLCh of the origin; the lightness range maps to white or black.
    const Oklch origin_lch = oklab_to_oklch(to_oklab(origin));
    if (origin_lch.L >= m_white_oklab_l) {
        take(branches, 1);
        return {max, max, max};
    }
    if (origin_lch.L <= 0.0) {
        take(branches, 2);
        return {0.0, 0.0, 0.0};
    }
    const double tol = oklab_rounding_tolerance * max;
    if (origin.r >= -tol && origin.g >= -tol && origin.b >= -tol && origin.r <= max + tol &&
        origin.g <= max + tol && origin.b <= max + tol) {
        take(branches, 3);
        return clamp(origin);
    }
    const double l_origin = origin_lch.L;
    const double h_origin = origin_lch.h;
    const auto to_array = [](const Rgb& c) { return std::array<double, 3>{c.r, c.g, c.b}; };
    // The anchor: OkLCh(l_origin, 0, h_origin) in linear destination RGB.
    std::array<double, 3> anchor = to_array(from_oklab(oklch_to_oklab({l_origin, 0.0, h_origin})));
    std::array<double, 3> origin_rgb = to_array(from_oklab(oklch_to_oklab(origin_lch)));
    const auto in_gamut = [&](const std::array<double, 3>& c) {
        return m_gamut.contains({c[0], c[1], c[2]});
    };
    if (!in_gamut(origin_rgb)) {
        const double low = 0.0 + raytrace_epsilon * max;
        const double high = max - raytrace_epsilon * max;
        std::array<double, 3> last = origin_rgb;
        for (int i = 0; i < 4; ++i) {
            if (i > 0) {
                // Back onto the chroma reduction path (footnote 3): the origin's L and h.
                Oklch current = oklab_to_oklch(to_oklab({origin_rgb[0], origin_rgb[1], origin_rgb[2]}));
                current.L = l_origin;
                current.h = h_origin;
                origin_rgb = to_array(from_oklab(oklch_to_oklab(current)));
            }
            const std::optional<std::array<double, 3>> intersection =
                cast_ray(anchor, origin_rgb, max);
            if (!intersection) {
                take(branches, 4);
                origin_rgb = last;  // footnote 5
                break;
            }
            if (i > 0 && low < origin_rgb[0] && origin_rgb[0] < high && low < origin_rgb[1] &&
                origin_rgb[1] < high && low < origin_rgb[2] && origin_rgb[2] < high) {
                take(branches, 5);
                anchor = origin_rgb;  // footnote 4: below the surface, a closer anchor
            }
            // The face the ray reached: the channel nearest a bound, and which bound.
            std::uint64_t face = 0;
            double nearest = std::numeric_limits<double>::infinity();
            for (std::size_t k = 0; k < 3; ++k) {
                for (const double bound : {0.0, max}) {
                    const double d = std::abs((*intersection)[k] - bound);
                    if (d < nearest) {
                        nearest = d;
                        face = 2 * k + (bound > 0.0 ? 1 : 0);
                    }
                }
            }
            take(branches, 6 + face);
            origin_rgb = *intersection;
            last = *intersection;
        }
    }
    // The final clip (issue 14029: of origin_rgb).
    return clamp({origin_rgb[0], origin_rgb[1], origin_rgb[2]});
}

}  // namespace irid
