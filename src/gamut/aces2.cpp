// The ACES 2.0 rendering per colour: the JMh model's stages in order, tonescale, chroma
// compression and gamut compression, forward and inverse (docs/DISPLAY.md). The per-display
// tables they read are built by aces2_tables.cpp. Constants are the Academy's (aces-core
// Lib.Academy.OutputTransform.ctl, Lib.Academy.Tonescale.ctl) as OpenColorIO 2.4.2+ implements
// them (src/OpenColorIO/ops/fixedfunction/ACES2).

#include <irid/error.h>
#include <irid/gamut/aces2.h>

#include <fmt/core.h>

#include "aces2_geometry.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace irid {
namespace {

using aces2::compression_threshold;
using aces2::lerp;
using aces2::reference_luminance;

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

// Gamut compression (and aces2_constants.h): the focus distance and its growth with the peak.
constexpr double focus_distance = 1.35;
constexpr double focus_distance_scaling = 1.75;

double wrap_hue(double h) noexcept {
    double r = std::fmod(h, 360.0);
    if (r < 0.0) r += 360.0;
    return r;
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

/// The compression of M beyond a threshold toward the gamut boundary: Reinhard's curve
/// threshold + s x / (s + x) of the excess x, its scale s set so that the reach boundary lands on
/// the gamut boundary; and its inverse threshold + s x / (s − x), which for x >= s (no colour
/// compresses that far) returns the asymptote threshold + s, as the Academy's does. OpenColorIO
/// writes both through the ratio x / s, which overflows to NaN where the gamut boundary's M is
/// next to 0 (at the peak's J); this form is the same function and finite there.
double remap_m(double m, double gamut_m, double reach_m, bool inverse, bool* beyond) noexcept {
    const double proportion = std::max(gamut_m / reach_m, compression_threshold);
    const double threshold = proportion * gamut_m;
    if (proportion >= 1.0 || m <= threshold) return m;
    const double m_offset = m - threshold;
    const double gamut_offset = gamut_m - threshold;
    const double reach_offset = reach_m - threshold;
    const double scale = reach_offset * gamut_offset / (reach_offset - gamut_offset);
    if (!inverse) return threshold + scale * m_offset / (scale + m_offset);
    // Beyond the asymptote by more than rounding (1e-9 of M's unit, which J and M share).
    if (m_offset >= scale + 1e-9 && beyond != nullptr) *beyond = true;
    return threshold + (m_offset >= scale ? scale : scale * m_offset / (scale - m_offset));
}

}  // namespace

Aces2Rendering::Aces2Rendering(const Aces2Display& display)
    : m_input(aces2::ap0, aces2::aces_white),
      m_reach_model(aces2::ap1, aces2::aces_white),
      m_limiting(display.limiting, display.limiting_white) {
    const double peak = display.peak_nits;
    if (!(peak >= 100.0 && peak <= 10000.0))
        throw Error(
            fmt::format("ACES 2.0: the peak luminance is {} cd/m²; allowed: [100, 10000]", peak));

    // Tonescale.
    Tonescale& t = m_tone;
    t.n = peak;
    t.n_r = reference_luminance;
    t.g = tone_g;
    t.t_1 = tone_t_1;
    const double r_hit = tone_r_hit_min + (tone_r_hit_max - tone_r_hit_min) *
                                              std::log(peak / t.n_r) / std::log(100.0);
    const double m_0 = peak / t.n_r;
    const double m_1 = 0.5 * (m_0 + std::sqrt(m_0 * (m_0 + 4.0 * t.t_1)));
    const double u = std::pow((r_hit / m_1) / (r_hit / m_1 + 1.0), t.g);
    const double m = m_1 / u;
    const double w_i = std::log2(peak / 100.0);
    t.c_t = tone_c_d / t.n_r * (1.0 + w_i * tone_w_g);
    const double g_ip = 0.5 * (t.c_t + std::sqrt(t.c_t * (t.c_t + 4.0 * t.t_1)));
    const double g_ipp2 =
        -(m_1 * std::pow(g_ip / m, 1.0 / t.g)) / (std::pow(g_ip / m, 1.0 / t.g) - 1.0);
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
    const double m =
        c[0] + c[1] * a + c[2] * cos2 + c[3] * cos3 + c[4] * b + c[5] * sin2 + c[6] * sin3;
    return m * m_chroma_scale;
}

double Aces2Rendering::reach_m(double h) const noexcept {
    const double w = wrap_hue(h);
    const int lo = std::clamp(static_cast<int>(w), 0, aces2::table_hues - 1);
    const int hi = (lo + 1) % aces2::table_hues;
    return lerp(m_reach[static_cast<std::size_t>(lo)], m_reach[static_cast<std::size_t>(hi)],
                w - lo);
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
        m = limit -
            toe_forward(limit - m, limit - 0.001, snj * m_sat, std::sqrt(nj * nj + m_sat_thr));
        m = toe_forward(m, limit, nj * m_compr, snj);
        m *= norm;
    }
    return {j_ts, m, jmh.h};
}

Aces2Jmh Aces2Rendering::tonescale_and_chroma_inverse(const Aces2Jmh& jmh) const noexcept {
    return solve_tonescale_and_chroma_inverse(jmh, nullptr);
}

Aces2Jmh Aces2Rendering::solve_tonescale_and_chroma_inverse(const Aces2Jmh& jmh,
                                                            bool* exact) const noexcept {
    const double j = tonescale_inverse(jmh.J);
    double m = jmh.M;
    bool inside = true;
    if (m != 0.0) {
        const double nj = jmh.J / m_limit_j_max;
        const double snj = std::max(0.0, 1.0 - nj);
        const double norm = m_norm(jmh.h);
        const double limit = std::pow(nj, m_model_gamma_inv) * reach_m(jmh.h) / norm;
        m = m / norm;
        m = toe_inverse(m, limit, nj * m_compr, snj);
        // The expansion's toe gives values above -k2 only (it tends to -k2 as its argument
        // falls): M beyond limit + k2 is more than the chroma compression ever gives.
        const double k2 = std::sqrt(nj * nj + m_sat_thr);
        inside = limit - m > -std::max(k2, 0.001) * (1.0 - 1e-9);
        m = limit - toe_inverse(limit - m, limit - 0.001, snj * m_sat, k2);
        m *= norm;
        m *= std::pow(jmh.J / j, -m_model_gamma_inv);
    }
    if (exact != nullptr) *exact = inside;
    return {j, m, jmh.h};
}

std::size_t Aces2Rendering::hue_interval(double h) const noexcept {
    // OpenColorIO's search (lookup_hue_interval): a bisection from the entry of h's whole degree
    // within m_hue_search of it. That window can exclude the interval that holds h (its lower
    // end is one entry short where an entry lies above its whole degree); the bisection then
    // ends on the neighbouring interval, and cusp_at extrapolates it, as OpenColorIO does
    // (docs/DISPLAY.md, "Where irid follows OpenColorIO's code").
    const int nominal = 1 + static_cast<int>(std::clamp(h, 0.0, double(aces2::table_hues)));
    int lo = std::max(0, nominal + m_hue_search[0]);
    int hi = std::min(aces2::table_hues + 1, nominal + m_hue_search[1]);
    int i = nominal;
    while (lo + 1 < hi) {
        (h > m_hues[static_cast<std::size_t>(i)] ? lo : hi) = i;
        i = (lo + hi) / 2;
    }
    return static_cast<std::size_t>(std::max(1, hi));
}

Aces2Rendering::Cusp Aces2Rendering::cusp_at(double h) const noexcept {
    const std::size_t hi = hue_interval(h);
    const double t = (h - m_hues[hi - 1]) / (m_hues[hi] - m_hues[hi - 1]);
    Cusp c;
    c.J = lerp(m_cusps[hi - 1][0], m_cusps[hi][0], t);
    c.M = lerp(m_cusps[hi - 1][1], m_cusps[hi][1], t);
    c.gamma_top_inv = lerp(m_cusps[hi - 1][2], m_cusps[hi][2], t);
    c.focus_j = aces2::focus_j_of(c.J, m_mid_j, m_limit_j_max);
    c.analytical_threshold = aces2::focus_threshold(c.J, m_limit_j_max);
    return c;
}

Aces2Jmh Aces2Rendering::compress(const Aces2Jmh& jmh, double jx, const Cusp& cusp, double reach,
                                  bool inverse, bool* beyond) const noexcept {
    if (jmh.J <= 0.0) return {0.0, 0.0, jmh.h};
    if (jmh.M <= 0.0 || jmh.J > m_limit_j_max) return {jmh.J, 0.0, jmh.h};
    const double slope_gain =
        aces2::focus_gain(jx, cusp.analytical_threshold, m_limit_j_max, m_focus_dist);
    const double j_source =
        aces2::solve_j_intersect(jmh.J, jmh.M, cusp.focus_j, m_limit_j_max, slope_gain);
    const double slope =
        aces2::compression_slope(j_source, cusp.focus_j, m_limit_j_max, slope_gain);
    const double j_cusp =
        aces2::solve_j_intersect(cusp.J, cusp.M, cusp.focus_j, m_limit_j_max, slope_gain);
    const double gamut_m =
        aces2::gamut_boundary_m(cusp.J, cusp.M, m_limit_j_max, cusp.gamma_top_inv,
                                m_lower_hull_gamma_inv, j_source, slope, j_cusp);
    if (gamut_m <= 0.0) {
        // The hull's estimate has no M at this J: the forward takes every M to 0 here, so an
        // inverse of M > 0 has no source.
        if (inverse && beyond != nullptr && jmh.M > 1e-9) *beyond = true;
        return {jmh.J, 0.0, jmh.h};
    }
    const double reach_boundary = aces2::line_boundary_m(j_source, slope, m_model_gamma_inv,
                                                         m_limit_j_max, reach, m_limit_j_max);
    const double m = remap_m(jmh.M, gamut_m, reach_boundary, inverse, beyond);
    return {j_source + m * slope, m, jmh.h};
}

Aces2Jmh Aces2Rendering::gamut_compress_forward(const Aces2Jmh& jmh) const noexcept {
    return compress(jmh, jmh.J, cusp_at(jmh.h), reach_m(jmh.h), false);
}

Aces2Jmh Aces2Rendering::gamut_compress_inverse(const Aces2Jmh& jmh) const noexcept {
    return solve_gamut_inverse(jmh, nullptr);
}

Aces2Jmh Aces2Rendering::solve_gamut_inverse(const Aces2Jmh& jmh, bool* exact) const noexcept {
    const Cusp cusp = cusp_at(jmh.h);
    const double reach = reach_m(jmh.h);
    double jx = jmh.J;
    // Above the cusp's threshold the focus gain depends on the source J, which is unknown. The
    // Academy's inverse takes one step of the fixed point jx = J(inverse at jx), and only where
    // the display's J is above the threshold (a source above it can show below it). irid
    // iterates from every J to convergence, which makes the inverse exact (docs/DISPLAY.md).
    bool converged = false;
    for (int k = 0; k < aces2_inverse_focus_iterations && !converged; ++k) {
        const double next = compress(jmh, jx, cusp, reach, true).J;
        converged = std::abs(next - jx) <= 1e-13 * std::max(1.0, std::abs(jx));
        jx = next;
    }
    bool beyond = false;
    const Aces2Jmh source = compress(jmh, jx, cusp, reach, true, &beyond);
    if (exact != nullptr) *exact = converged && !beyond;
    return source;
}

bool Aces2Rendering::reaches(const Vec3& display) const noexcept {
    const Aces2Jmh jmh = m_limiting.rgb_to_jmh(display);
    // Above the peak's J (but for rounding: the white's J is the peak's to 1e-12) the tonescale
    // has no source; the compression's asymptote bounds M.
    const double top = m_limit_j_max * (1.0 + 1e-12);
    if (jmh.J > top) return false;
    bool exact = false;
    const Aces2Jmh toned = solve_gamut_inverse(jmh, &exact);
    if (!exact || toned.J > top) return false;
    (void)solve_tonescale_and_chroma_inverse(toned, &exact);
    return exact;
}

Vec3 Aces2Rendering::forward(const Vec3& aces) const noexcept {
    const Aces2Jmh jmh = m_input.rgb_to_jmh(aces);
    return m_limiting.jmh_to_rgb(gamut_compress_forward(tonescale_and_chroma_forward(jmh)));
}

Vec3 Aces2Rendering::inverse(const Vec3& display) const noexcept {
    const Aces2Jmh jmh = m_limiting.rgb_to_jmh(display);
    return m_input.jmh_to_rgb(tonescale_and_chroma_inverse(solve_gamut_inverse(jmh, nullptr)));
}

}  // namespace irid
