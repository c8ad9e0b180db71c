// The ACES 2.0 rendering: tonescale, chroma compression and gamut compression in JMh, and the
// per-display tables they read (docs/DISPLAY.md). Constants are the Academy's (aces-core
// Lib.Academy.OutputTransform.ctl, Lib.Academy.Tonescale.ctl) as OpenColorIO 2.4+ implements
// them (src/OpenColorIO/ops/fixedfunction/ACES2).

#include <irid/error.h>
#include <irid/gamut/aces2.h>

#include <fmt/core.h>

#include "aces2_constants.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace irid {
namespace {

using aces2::compression_threshold;
using aces2::cusp_mid_blend;
using aces2::focus_adjust_gain_inv;
using aces2::focus_gain_blend;
using aces2::reference_luminance;
using aces2::smooth_cusps;

// ACES AP0 and AP1 (SMPTE ST 2065-1, Academy S-2014-004) and their white.
constexpr RgbPrimaries ap0{{0.7347, 0.2653}, {0.0, 1.0}, {0.0001, -0.0770}};
constexpr RgbPrimaries ap1{{0.713, 0.293}, {0.165, 0.830}, {0.128, 0.044}};
constexpr Xy aces_white{0.32168, 0.33767};

// Tonescale (Lib.Academy.Tonescale.ctl): contrast g, the toe t_1, 18 % grey at c_d cd/m² for a
// 100 cd/m² peak changing by w_g per stop of peak, the scene value r_hit reaching the peak
// (128 at 100 cd/m², 896 at 10 000 cd/m²).
constexpr double tone_g = 1.15;
constexpr double tone_c = 0.18;
constexpr double tone_c_d = 10.013;
constexpr double tone_w_g = 0.14;
constexpr double tone_t_1 = 0.04;
constexpr double tone_r_hit_min = 128.0;
constexpr double tone_r_hit_max = 896.0;

// Chroma compression.
constexpr double chroma_compress = 2.4;
constexpr double chroma_compress_fact = 3.3;
constexpr double chroma_expand = 1.3;
constexpr double chroma_expand_fact = 0.69;
constexpr double chroma_expand_thr = 0.5;

// Gamut compression (and aces2_constants.h).
constexpr double smooth_m = 0.27;
constexpr double focus_distance = 1.35;
constexpr double focus_distance_scaling = 1.75;

// Table generation (OpenColorIO's): 360 hues; the reach's M searched in steps of 50 to 1300
// and bisected to 1e-2; the corners bisected to 1e-3 in scale; the cusps along the cube's edges
// to 1e-7 in the edge's parameter; the upper hull's γ in steps of 0.4 to 5 and bisected to 1e-5.
constexpr int hue_count = 360;
constexpr double reach_search_step = 50.0;
constexpr double reach_search_max = 1300.0;
constexpr double reach_tolerance = 1e-2;
constexpr double corner_tolerance = 1e-3;
constexpr double cusp_tolerance = 1e-7;
constexpr double gamma_step = 0.4;
constexpr double gamma_max = 5.0;
constexpr double gamma_tolerance = 1e-5;
constexpr std::array<double, 5> gamma_test_positions{0.01, 0.1, 0.5, 0.8, 0.99};
constexpr int corner_count = 6;

double lerp(double a, double b, double t) noexcept { return a + t * (b - a); }

double wrap_hue(double h) noexcept {
    double r = std::fmod(h, 360.0);
    if (r < 0.0) r += 360.0;
    return r;
}

/// The cube's corners in the order red, yellow, green, cyan, blue, magenta.
Vec3 unit_corner(int i) noexcept {
    return {((i + 1) % corner_count) < 3 ? 1.0 : 0.0, ((i + 5) % corner_count) < 3 ? 1.0 : 0.0,
            ((i + 3) % corner_count) < 3 ? 1.0 : 0.0};
}

/// The toe of the chroma compression, x below `limit` raised smoothly (and its inverse).
double toe_forward(double x, double limit, double k1_in, double k2_in) noexcept {
    if (x > limit) return x;
    const double k2 = std::max(k2_in, 0.001);
    const double k1 = std::sqrt(k1_in * k1_in + k2 * k2);
    const double k3 = (limit + k1) / (limit + k2);
    const double minus_b = k3 * x - k1;
    const double minus_ac = k2 * k3 * x;
    return 0.5 * (minus_b + std::sqrt(minus_b * minus_b + 4.0 * minus_ac));
}

double toe_inverse(double x, double limit, double k1_in, double k2_in) noexcept {
    if (x > limit) return x;
    const double k2 = std::max(k2_in, 0.001);
    const double k1 = std::sqrt(k1_in * k1_in + k2 * k2);
    const double k3 = (limit + k1) / (limit + k2);
    return (x * x + k1 * x) / (k3 * (x + k2));
}

double focus_gain(double j, double cusp_j, double limit_j_max, double focus_dist) noexcept {
    const double threshold = lerp(cusp_j, limit_j_max, focus_gain_blend);
    double gain = 1.0;
    if (j > threshold) {
        gain = (limit_j_max - threshold) / std::max(0.0001, limit_j_max - std::min(limit_j_max, j));
        gain = std::pow(std::log10(gain), focus_adjust_gain_inv) + 1.0;
    }
    return limit_j_max * focus_dist * gain;
}

/// Where the compression line through (J, M) meets the J axis.
double solve_j_intersect(double j, double m, double focus_j, double max_j, double slope_gain) noexcept {
    const double a = m / (focus_j * slope_gain);
    if (j < focus_j) {
        const double b = 1.0 - m / slope_gain;
        const double c = -j;
        return 2.0 * c / (-b - std::sqrt(b * b - 4.0 * a * c));
    }
    const double b = -(1.0 + m / slope_gain + max_j * m / (focus_j * slope_gain));
    const double c = max_j * m / slope_gain + j;
    return 2.0 * c / (-b + std::sqrt(b * b - 4.0 * a * c));
}

double compression_slope(double j_intersect, double focus_j, double limit_j_max, double slope_gain) noexcept {
    const double scaler = j_intersect < focus_j ? j_intersect : limit_j_max - j_intersect;
    return scaler * (j_intersect - focus_j) / (focus_j * slope_gain);
}

/// The M where the line J = slope M + J_axis meets the boundary J = J_max (M / M_max)^(1/γ),
/// approximated through a reference intersection (no iteration).
double line_boundary_m(double j_axis, double slope, double inv_gamma, double j_max, double m_max,
                       double j_reference) noexcept {
    const double shifted = j_reference * std::pow(j_axis / j_reference, inv_gamma);
    return shifted / (j_max / m_max - slope);
}

/// A smooth minimum over a cubic polynomial, its width relative to `scale`.
double smooth_min(double a, double b, double scale) noexcept {
    const double s = smooth_cusps * scale;
    const double h = std::max(s - std::abs(a - b), 0.0) / s;
    return std::min(a, b) - h * h * h * s / 6.0;
}

double gamut_boundary_m(double cusp_j, double cusp_m, double j_max, double gamma_top_inv, double gamma_bottom_inv,
                        double j_intersect_source, double slope, double j_intersect_cusp) noexcept {
    const double lower = line_boundary_m(j_intersect_source, slope, gamma_bottom_inv, cusp_j, cusp_m, j_intersect_cusp);
    // The upper hull, flipped about J_max.
    const double upper = line_boundary_m(j_max - j_intersect_source, -slope, gamma_top_inv, j_max - cusp_j, cusp_m,
                                         j_max - j_intersect_cusp);
    return smooth_min(lower, upper, cusp_m);
}

/// The compression of M beyond a threshold toward the gamut boundary, the reach boundary
/// mapped onto it (Reinhard's curve), and its inverse.
double remap_m(double m, double gamut_m, double reach_m, bool inverse) noexcept {
    const double proportion = std::max(gamut_m / reach_m, compression_threshold);
    const double threshold = proportion * gamut_m;
    if (proportion >= 1.0 || m <= threshold) return m;
    const double m_offset = m - threshold;
    const double gamut_offset = gamut_m - threshold;
    const double reach_offset = reach_m - threshold;
    const double scale = reach_offset / (reach_offset / gamut_offset - 1.0);
    const double nd = m_offset / scale;
    if (!inverse) return threshold + scale * nd / (1.0 + nd);
    return threshold + (nd >= 1.0 ? scale : scale * -(nd / (nd - 1.0)));
}

double focus_j_of(double cusp_j, double mid_j, double limit_j_max) noexcept {
    return lerp(cusp_j, mid_j, std::min(1.0, cusp_mid_blend - cusp_j / limit_j_max));
}

}  // namespace

Aces2Rendering::Aces2Rendering(const Aces2Display& display)
    : m_input(ap0, aces_white),
      m_reach_model(ap1, aces_white),
      m_limiting(display.limiting, display.limiting_white) {
    const double peak = display.peak_nits;
    if (!(peak >= 100.0 && peak <= 10000.0))
        throw Error(fmt::format("ACES 2.0: the peak luminance is {} cd/m²; allowed: [100, 10000]", peak));

    // Tonescale.
    Tonescale& t = m_tone;
    t.n = peak;
    t.n_r = reference_luminance;
    t.g = tone_g;
    t.t_1 = tone_t_1;
    const double r_hit = tone_r_hit_min + (tone_r_hit_max - tone_r_hit_min) * std::log(peak / t.n_r) / std::log(100.0);
    const double m_0 = peak / t.n_r;
    const double m_1 = 0.5 * (m_0 + std::sqrt(m_0 * (m_0 + 4.0 * t.t_1)));
    const double u = std::pow((r_hit / m_1) / (r_hit / m_1 + 1.0), t.g);
    const double m = m_1 / u;
    const double w_i = std::log2(peak / 100.0);
    t.c_t = tone_c_d / t.n_r * (1.0 + w_i * tone_w_g);
    const double g_ip = 0.5 * (t.c_t + std::sqrt(t.c_t * (t.c_t + 4.0 * t.t_1)));
    const double g_ipp2 = -(m_1 * std::pow(g_ip / m, 1.0 / t.g)) / (std::pow(g_ip / m, 1.0 / t.g) - 1.0);
    const double w_2 = tone_c / g_ipp2;
    t.s_2 = w_2 * m_1 * reference_luminance;
    t.u_2 = std::pow((r_hit / m_1) / (r_hit / m_1 + w_2), t.g);
    t.m_2 = m_1 / t.u_2;
    t.inverse_limit = peak / (t.u_2 * t.n_r);
    t.forward_limit = 8.0 * r_hit;
    t.log_peak = std::log10(peak / t.n_r);

    m_limit_j_max = m_input.y_to_j(peak);
    m_model_gamma_inv = 1.0 / m_input.exponent();

    // Chroma compression.
    m_compr = chroma_compress + chroma_compress * chroma_compress_fact * t.log_peak;
    m_sat = std::max(0.2, chroma_expand - chroma_expand * chroma_expand_fact * t.log_peak);
    m_sat_thr = chroma_expand_thr / peak;
    m_chroma_scale = std::pow(0.03379 * peak, 0.30596) - 0.45135;

    // Gamut compression.
    m_mid_j = m_input.y_to_j(t.c_t * reference_luminance);
    m_focus_dist = focus_distance + focus_distance * focus_distance_scaling * t.log_peak;
    m_lower_hull_gamma_inv = 1.0 / (1.14 + 0.07 * t.log_peak);
    build_tables(display);
}

double Aces2Rendering::tonescale_forward(double j) const noexcept {
    const Tonescale& t = m_tone;
    const double y = m_input.j_to_y(std::abs(j));
    const double f = t.m_2 * std::pow(y / (y + t.s_2), t.g);
    const double y_ts = std::max(0.0, f * f / (f + t.t_1)) * t.n_r;
    return std::copysign(m_input.y_to_j(y_ts), j);
}

double Aces2Rendering::tonescale_inverse(double j) const noexcept {
    const Tonescale& t = m_tone;
    const double y_ts = m_input.j_to_y(std::abs(j));
    const double z = std::clamp(y_ts / reference_luminance, 0.0, t.inverse_limit);
    const double f = (z + std::sqrt(z * (4.0 * t.t_1 + z))) / 2.0;
    const double y = t.s_2 / (std::pow(t.m_2 / f, 1.0 / t.g) - 1.0);
    return std::copysign(m_input.y_to_j(y), j);
}

double Aces2Rendering::m_norm(double h) const noexcept {
    // The hue-dependent normalisation of M (a Fourier fit over hue, aces-core).
    const double r = h * (std::numbers::pi / 180.0);
    const double a = std::cos(r), b = std::sin(r);
    const double cos2 = a * a - b * b, sin2 = 2.0 * a * b;
    const double cos3 = 4.0 * a * a * a - 3.0 * a, sin3 = 3.0 * b - 4.0 * b * b * b;
    const auto& c = aces2::m_norm_coefficients;
    const double m = c[0] + c[1] * a + c[2] * cos2 + c[3] * cos3 + c[4] * b + c[5] * sin2 + c[6] * sin3;
    return m * m_chroma_scale;
}

double Aces2Rendering::reach_m(double h) const noexcept {
    const double w = wrap_hue(h);
    const int lo = std::clamp(static_cast<int>(w), 0, hue_count - 1);
    const int hi = (lo + 1) % hue_count;
    return lerp(m_reach[static_cast<std::size_t>(lo)], m_reach[static_cast<std::size_t>(hi)], w - lo);
}

Aces2Jmh Aces2Rendering::tonescale_and_chroma_forward(const Aces2Jmh& jmh) const noexcept {
    const double j_ts = tonescale_forward(jmh.J);
    double m = jmh.M;
    if (m != 0.0) {
        const double nj = j_ts / m_limit_j_max;
        const double snj = std::max(0.0, 1.0 - nj);
        const double norm = m_norm(jmh.h);
        const double limit = std::pow(nj, m_model_gamma_inv) * reach_m(jmh.h) / norm;
        m = m * std::pow(j_ts / jmh.J, m_model_gamma_inv) / norm;
        m = limit - toe_forward(limit - m, limit - 0.001, snj * m_sat, std::sqrt(nj * nj + m_sat_thr));
        m = toe_forward(m, limit, nj * m_compr, snj);
        m *= norm;
    }
    return {j_ts, m, jmh.h};
}

Aces2Jmh Aces2Rendering::tonescale_and_chroma_inverse(const Aces2Jmh& jmh) const noexcept {
    const double j = tonescale_inverse(jmh.J);
    double m = jmh.M;
    if (m != 0.0) {
        const double nj = jmh.J / m_limit_j_max;
        const double snj = std::max(0.0, 1.0 - nj);
        const double norm = m_norm(jmh.h);
        const double limit = std::pow(nj, m_model_gamma_inv) * reach_m(jmh.h) / norm;
        m = m / norm;
        m = toe_inverse(m, limit, nj * m_compr, snj);
        m = limit - toe_inverse(limit - m, limit - 0.001, snj * m_sat, std::sqrt(nj * nj + m_sat_thr));
        m *= norm;
        m *= std::pow(jmh.J / j, -m_model_gamma_inv);
    }
    return {j, m, jmh.h};
}

Aces2Rendering::Cusp Aces2Rendering::cusp_at(double h) const noexcept {
    // The first table hue at or above h (the table's ends wrap below 0 and above 360).
    const auto it = std::lower_bound(m_hues.begin() + 1, m_hues.end() - 1, h);
    const auto hi = static_cast<std::size_t>(it - m_hues.begin());
    const double t = (h - m_hues[hi - 1]) / (m_hues[hi] - m_hues[hi - 1]);
    Cusp c;
    c.J = lerp(m_cusps[hi - 1][0], m_cusps[hi][0], t);
    c.M = lerp(m_cusps[hi - 1][1], m_cusps[hi][1], t);
    c.gamma_top_inv = lerp(m_cusps[hi - 1][2], m_cusps[hi][2], t);
    c.focus_j = focus_j_of(c.J, m_mid_j, m_limit_j_max);
    c.analytical_threshold = lerp(c.J, m_limit_j_max, focus_gain_blend);
    return c;
}

Aces2Jmh Aces2Rendering::compress(const Aces2Jmh& jmh, double jx, const Cusp& cusp, double reach,
                                  bool inverse) const noexcept {
    if (jmh.J <= 0.0) return {0.0, 0.0, jmh.h};
    if (jmh.M <= 0.0 || jmh.J > m_limit_j_max) return {jmh.J, 0.0, jmh.h};
    const double slope_gain = focus_gain(jx, cusp.J, m_limit_j_max, m_focus_dist);
    const double j_source = solve_j_intersect(jmh.J, jmh.M, cusp.focus_j, m_limit_j_max, slope_gain);
    const double slope = compression_slope(j_source, cusp.focus_j, m_limit_j_max, slope_gain);
    const double j_cusp = solve_j_intersect(cusp.J, cusp.M, cusp.focus_j, m_limit_j_max, slope_gain);
    const double gamut_m = gamut_boundary_m(cusp.J, cusp.M, m_limit_j_max, cusp.gamma_top_inv,
                                            m_lower_hull_gamma_inv, j_source, slope, j_cusp);
    if (gamut_m <= 0.0) return {jmh.J, 0.0, jmh.h};
    const double reach_boundary = line_boundary_m(j_source, slope, m_model_gamma_inv, m_limit_j_max, reach, m_limit_j_max);
    const double m = remap_m(jmh.M, gamut_m, reach_boundary, inverse);
    return {j_source + m * slope, m, jmh.h};
}

Aces2Jmh Aces2Rendering::gamut_compress_forward(const Aces2Jmh& jmh) const noexcept {
    return compress(jmh, jmh.J, cusp_at(jmh.h), reach_m(jmh.h), false);
}

Aces2Jmh Aces2Rendering::gamut_compress_inverse(const Aces2Jmh& jmh) const noexcept {
    const Cusp cusp = cusp_at(jmh.h);
    const double reach = reach_m(jmh.h);
    double jx = jmh.J;
    // Above the cusp's threshold the focus gain depends on the source J, which is unknown. The
    // Academy's inverse takes one step of the fixed point jx = J(inverse at jx), and only where
    // the display's J is above the threshold (a source above it can show below it). irid
    // iterates from every J to convergence, which makes the inverse exact (docs/DISPLAY.md).
    for (int k = 0; k < aces2_inverse_focus_iterations; ++k) {
        const double next = compress(jmh, jx, cusp, reach, true).J;
        const bool done = std::abs(next - jx) <= 1e-13 * std::max(1.0, std::abs(jx));
        jx = next;
        if (done) break;
    }
    return compress(jmh, jx, cusp, reach, true);
}

Vec3 Aces2Rendering::forward(const Vec3& aces) const noexcept {
    const Aces2Jmh jmh = m_input.rgb_to_jmh(aces);
    return m_limiting.jmh_to_rgb(gamut_compress_forward(tonescale_and_chroma_forward(jmh)));
}

Vec3 Aces2Rendering::inverse(const Vec3& display) const noexcept {
    const Aces2Jmh jmh = m_limiting.rgb_to_jmh(display);
    return m_input.jmh_to_rgb(tonescale_and_chroma_inverse(gamut_compress_inverse(jmh)));
}

// --- Tables ---------------------------------------------------------------------------------

void Aces2Rendering::build_tables(const Aces2Display& display) {
    const double peak = display.peak_nits;

    // The reach gamut's M at limit_j_max per whole degree: the largest M whose AP1 RGB has no
    // negative channel, searched in steps then bisected.
    m_reach.assign(hue_count, 0.0);
    for (int i = 0; i < hue_count; ++i) {
        const double hue = i;
        const auto outside = [&](double m) {
            const Vec3 rgb = m_reach_model.jmh_to_rgb({m_limit_j_max, m, hue});
            return rgb[0] < 0.0 || rgb[1] < 0.0 || rgb[2] < 0.0;
        };
        double low = 0.0, high = reach_search_step;
        while (!outside(high) && high < reach_search_max) {
            low = high;
            high += reach_search_step;
        }
        while (high - low > reach_tolerance) {
            const double mid = 0.5 * (low + high);
            (outside(mid) ? high : low) = mid;
        }
        m_reach[static_cast<std::size_t>(i)] = high;
    }

    // The corners, as cycles with the lowest hue first and the ends wrapped: the reach gamut's
    // (scaled until J reaches limit_j_max) and the limiting gamut's (at the peak).
    struct Corners {
        std::array<Vec3, corner_count + 2> rgb{};
        std::array<Aces2Jmh, corner_count + 2> jmh{};
    };
    const auto cycle = [](std::array<Vec3, corner_count> rgb, std::array<Aces2Jmh, corner_count> jmh) {
        int first = 0;
        for (int i = 1; i < corner_count; ++i)
            if (jmh[static_cast<std::size_t>(i)].h < jmh[static_cast<std::size_t>(first)].h) first = i;
        Corners c;
        for (int i = 0; i < corner_count; ++i) {
            c.rgb[static_cast<std::size_t>(i + 1)] = rgb[static_cast<std::size_t>((i + first) % corner_count)];
            c.jmh[static_cast<std::size_t>(i + 1)] = jmh[static_cast<std::size_t>((i + first) % corner_count)];
        }
        c.rgb[0] = c.rgb[corner_count];
        c.jmh[0] = c.jmh[corner_count];
        c.rgb[corner_count + 1] = c.rgb[1];
        c.jmh[corner_count + 1] = c.jmh[1];
        c.jmh[0].h -= 360.0;
        c.jmh[corner_count + 1].h += 360.0;
        return c;
    };
    std::array<Vec3, corner_count> rgb{};
    std::array<Aces2Jmh, corner_count> jmh{};
    const double limit_a = m_reach_model.j_to_a(m_limit_j_max);
    for (int i = 0; i < corner_count; ++i) {
        const Vec3 v = unit_corner(i);
        double lower = 0.0, upper = m_tone.forward_limit;
        while (upper - lower > corner_tolerance) {
            const double test = 0.5 * (lower + upper);
            const double a = m_reach_model.rgb_to_aab({test * v[0], test * v[1], test * v[2]})[0];
            (a < limit_a ? lower : upper) = test;
            if (a == limit_a) break;
        }
        rgb[static_cast<std::size_t>(i)] = {upper * v[0], upper * v[1], upper * v[2]};
        jmh[static_cast<std::size_t>(i)] = m_reach_model.rgb_to_jmh(rgb[static_cast<std::size_t>(i)]);
    }
    const Corners reach = cycle(rgb, jmh);
    for (int i = 0; i < corner_count; ++i) {
        const Vec3 v = unit_corner(i);
        const double s = peak / reference_luminance;
        rgb[static_cast<std::size_t>(i)] = {s * v[0], s * v[1], s * v[2]};
        jmh[static_cast<std::size_t>(i)] = m_limiting.rgb_to_jmh(rgb[static_cast<std::size_t>(i)]);
    }
    const Corners limiting = cycle(rgb, jmh);

    // The corners' hues, merged and made unique.
    std::vector<double> corner_hues;
    {
        int r = 1, l = 1;
        while (r <= corner_count || l <= corner_count) {
            const double rh = r <= corner_count ? reach.jmh[static_cast<std::size_t>(r)].h : 1e300;
            const double lh = l <= corner_count ? limiting.jmh[static_cast<std::size_t>(l)].h : 1e300;
            if (rh == lh) {
                corner_hues.push_back(rh);
                ++r;
                ++l;
            } else if (rh < lh) {
                corner_hues.push_back(rh);
                ++r;
            } else {
                corner_hues.push_back(lh);
                ++l;
            }
        }
    }

    // The hue table: 360 hues as even as possible, every corner hue exactly among them, each
    // corner at the index nearest its hue (OpenColorIO's allocation, collisions moved apart).
    const int unique = static_cast<int>(corner_hues.size());
    std::vector<int> index(static_cast<std::size_t>(unique), 0);
    {
        int last = -1;
        int min_index = corner_hues[0] == 0.0 ? 0 : 1;
        for (int k = 0; k < unique; ++k) {
            int nominal = std::min(std::max(static_cast<int>(std::round(corner_hues[static_cast<std::size_t>(k)])), min_index),
                                   hue_count - 1);
            if (last == nominal) {
                if (k > 1 && index[static_cast<std::size_t>(k - 2)] != index[static_cast<std::size_t>(k - 1)] - 1)
                    index[static_cast<std::size_t>(k - 1)] -= 1;
                else
                    nominal += 1;
            }
            index[static_cast<std::size_t>(k)] = std::min(nominal, hue_count - 1);
            last = min_index = nominal;
        }
    }
    m_hues.assign(hue_count + 2, 0.0);
    {
        int filled = 0;
        const auto interval = [&](int samples, double lower, double upper) {
            const double delta = (upper - lower) / samples;
            for (int i = 0; i < samples; ++i) m_hues[static_cast<std::size_t>(filled + 1 + i)] = lower + i * delta;
            filled += samples;
        };
        interval(index[0], 0.0, corner_hues[0]);
        for (int k = 1; k < unique; ++k)
            interval(index[static_cast<std::size_t>(k)] - index[static_cast<std::size_t>(k - 1)],
                     corner_hues[static_cast<std::size_t>(k - 1)], corner_hues[static_cast<std::size_t>(k)]);
        interval(hue_count - filled, corner_hues[static_cast<std::size_t>(unique - 1)], 360.0);
        m_hues[0] = m_hues[hue_count] - 360.0;
        m_hues[hue_count + 1] = m_hues[1] + 360.0;
    }

    // The limiting gamut's cusp per table hue: bisected along the cube's edge between the two
    // corners whose hues enclose it.
    m_cusps.assign(hue_count + 2, Vec3{});
    double previous_corner = 0.0, previous_t = 0.0;
    for (int i = 1; i <= hue_count; ++i) {
        const double hue = m_hues[static_cast<std::size_t>(i)];
        int upper = 1;
        for (int c = 1; c < corner_count + 2; ++c) {
            if (limiting.jmh[static_cast<std::size_t>(c)].h > hue) {
                upper = c;
                break;
            }
        }
        const int lower = upper - 1;
        double cusp_j = 0.0, cusp_m = 0.0;
        if (limiting.jmh[static_cast<std::size_t>(lower)].h == hue) {
            cusp_j = limiting.jmh[static_cast<std::size_t>(lower)].J;
            cusp_m = limiting.jmh[static_cast<std::size_t>(lower)].M;
        } else {
            const Vec3& a = limiting.rgb[static_cast<std::size_t>(lower)];
            const Vec3& b = limiting.rgb[static_cast<std::size_t>(upper)];
            const double h_lower = limiting.jmh[static_cast<std::size_t>(lower)].h;
            const double h_upper = limiting.jmh[static_cast<std::size_t>(upper)].h;
            const auto at = [&](double t) {
                return m_limiting.rgb_to_jmh({lerp(a[0], b[0], t), lerp(a[1], b[1], t), lerp(a[2], b[2], t)});
            };
            double lo_t = upper == previous_corner ? previous_t : 0.0, hi_t = 1.0;
            while (hi_t - lo_t > cusp_tolerance) {
                const double t = 0.5 * (lo_t + hi_t);
                const double h = at(t).h;
                if (h < h_lower)
                    hi_t = t;
                else if (h >= h_upper)
                    lo_t = t;
                else if (h > hue)
                    hi_t = t;
                else
                    lo_t = t;
            }
            const double t = 0.5 * (lo_t + hi_t);
            const Aces2Jmh c = at(t);
            cusp_j = c.J;
            cusp_m = c.M;
            previous_corner = upper;
            previous_t = t;
        }
        m_cusps[static_cast<std::size_t>(i)] = {cusp_j, cusp_m * (1.0 + smooth_m * smooth_cusps), 0.0};
    }

    // The upper hull's γ per hue: the smallest γ (to 1e-5) whose boundary lies outside the
    // limiting cube at five heights between the cusp and limit_j_max.
    for (int i = 1; i <= hue_count; ++i) {
        Vec3& cusp = m_cusps[static_cast<std::size_t>(i)];
        const double hue = m_hues[static_cast<std::size_t>(i)];
        const double focus_j = focus_j_of(cusp[0], m_mid_j, m_limit_j_max);
        const auto fits = [&](double gamma) {
            for (const double position : gamma_test_positions) {
                const double test_j = lerp(cusp[0], m_limit_j_max, position);
                const double gain = focus_gain(test_j, cusp[0], m_limit_j_max, m_focus_dist);
                const double j_source = solve_j_intersect(test_j, cusp[1], focus_j, m_limit_j_max, gain);
                const double slope = compression_slope(j_source, focus_j, m_limit_j_max, gain);
                const double j_cusp = solve_j_intersect(cusp[0], cusp[1], focus_j, m_limit_j_max, gain);
                const double m = gamut_boundary_m(cusp[0], cusp[1], m_limit_j_max, 1.0 / gamma,
                                                  m_lower_hull_gamma_inv, j_source, slope, j_cusp);
                const Vec3 edge = m_limiting.jmh_to_rgb({j_source + slope * m, m, hue});
                const double s = reference_luminance / peak;
                if (!(edge[0] * s > 1.0 || edge[1] * s > 1.0 || edge[2] * s > 1.0)) return false;
            }
            return true;
        };
        double low = 0.0, high = gamma_step;
        while (!fits(high) && high < gamma_max) {
            low = high;
            high += gamma_step;
        }
        while (high - low > gamma_tolerance) {
            const double mid = 0.5 * (low + high);
            if (fits(mid)) {
                high = mid;
                cusp[2] = 1.0 / high;
            } else {
                low = mid;
            }
        }
    }
    m_cusps[0] = m_cusps[hue_count];
    m_cusps[hue_count + 1] = m_cusps[1];
}

}  // namespace irid
