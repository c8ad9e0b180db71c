// The per-display tables of the ACES 2.0 rendering (aces2.h): the reach gamut's M per degree at
// the peak's J, the hue table (360 hues as even as possible, the cube's corners among them), the
// limiting gamut's cusp per hue, and the upper hull's γ fitted per hue.
//
// OpenColorIO 2.4.2+'s generation (src/OpenColorIO/ops/fixedfunction/ACES2/Transform.cpp:
// make_reach_m_table, make_uniform_hue_gamut_table, make_upper_hull_gamma,
// determine_hue_linearity_search_range), with its searches, steps and tolerances, in its float
// arithmetic: the searches end where float rounding decides, and the γ fit in particular moves
// by up to 2e-4 between float and double, which moves outputs by up to 1e-4 (docs/DISPLAY.md).
// So the model these searches evaluate is OpenColorIO's float JMh model (FloatModel below:
// its matrices built in double and rounded to float, the limiting primaries given as floats, as
// its FixedFunction's parameters are); each colour is then rendered in double from the tables.

#include <irid/gamut/aces2.h>

#include "aces2_geometry.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace irid {
namespace {

using aces2::table_hues;

/// The cusp's M is scaled by 1 + smooth_m · smooth_cusps, the smooth minimum's reach at the cusp.
constexpr float smooth_m = 0.27f;

// The searches: the reach's M in steps of 50 to 1300, bisected to 1e-2; the corners bisected to
// 1e-3 in scale; the cusps along the cube's edges to 1e-7 in the edge's parameter; the upper
// hull's γ in steps of 0.4 to 5, bisected to 1e-5, tested at five heights between the cusp and
// the peak's J.
constexpr float reach_search_step = 50.0f;
constexpr float reach_search_max = 1300.0f;
constexpr float reach_tolerance = 1e-2f;
constexpr float corner_tolerance = 1e-3f;
constexpr float cusp_tolerance = 1e-7f;
constexpr float gamma_step = 0.4f;
constexpr float gamma_max = 5.0f;
constexpr float gamma_tolerance = 1e-5f;
constexpr std::array<float, 5> gamma_test_positions{0.01f, 0.1f, 0.5f, 0.8f, 0.99f};
constexpr int corner_count = 6;

using F3 = std::array<float, 3>;
using F33 = std::array<float, 9>;  // row-major

F33 to_float(const Mat3& m) noexcept {
    F33 f{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            f[static_cast<std::size_t>(3 * i + j)] = static_cast<float>(m[i][j]);
    return f;
}

Mat3 to_double(const F33& f) noexcept {
    Mat3 m;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) m[i][j] = f[static_cast<std::size_t>(3 * i + j)];
    return m;
}

/// m v, each row summed left to right as OpenColorIO's mult_f3_f33 does.
F3 apply(const F33& m, const F3& v) noexcept {
    return {v[0] * m[0] + v[1] * m[1] + v[2] * m[2], v[0] * m[3] + v[1] * m[4] + v[2] * m[5],
            v[0] * m[6] + v[1] * m[7] + v[2] * m[8]};
}

F33 product(const F33& a, const F33& b) noexcept {
    F33 r{};
    for (std::size_t i = 0; i < 3; ++i)
        for (std::size_t j = 0; j < 3; ++j)
            r[3 * i + j] = a[3 * i] * b[j] + a[3 * i + 1] * b[3 + j] + a[3 * i + 2] * b[6 + j];
    return r;
}

F33 diagonal(const F3& d) noexcept {
    return {d[0], 0.f, 0.f, 0.f, d[1], 0.f, 0.f, 0.f, d[2]};
}

/// Inverted in double, as OpenColorIO's invert_f33 does, and rounded to float.
F33 inverted(const F33& m) {
    return to_float(inverse(to_double(m), "ACES 2.0 table model"));
}

float round_to_float(double x) noexcept {
    return static_cast<float>(x);
}

/// The response normalised to 1 (F_L folded into the cone matrix), mirrored, and its inverse
/// taken at most response_inverse_share.
float response(float v) noexcept {
    const float f = std::pow(std::abs(v), static_cast<float>(aces2::response_exponent));
    return std::copysign(f / (static_cast<float>(aces2::response_offset) + f), v);
}

float response_inverse(float v) noexcept {
    const float r = std::min(std::abs(v), static_cast<float>(aces2::response_inverse_share));
    const float f = static_cast<float>(aces2::response_offset) * r / (1.0f - r);
    return std::copysign(std::pow(f, 1.0f / static_cast<float>(aces2::response_exponent)), v);
}

constexpr float pi_f = 3.14159265358979f;  // OpenColorIO's ACES2 PI, a float

/// The JMh model of one set of primaries as OpenColorIO's init_JMhParams builds it in float.
struct FloatModel {
    F33 to_cone{}, from_cone{}, to_aab{}, from_aab{};
    float cz = 0, cz_inv = 0, fl_n = 0, a_w_j_inv = 0;

    FloatModel(const RgbPrimaries& primaries, const Xy& white) {
        const F33 xyz_to_cam =
            to_float(inverse(aces2::primary_matrix(aces2::cone_primaries, aces2::cone_white)));
        const F33 rgb_to_xyz = to_float(aces2::primary_matrix(primaries, white));
        const float ref = static_cast<float>(aces2::reference_luminance);
        const F3 white_xyz = apply(rgb_to_xyz, {ref, ref, ref});
        const F3 white_cam = apply(xyz_to_cam, white_xyz);
        const float l_a = static_cast<float>(aces2::adapting_luminance);
        const float k = 1.f / (5.f * l_a + 1.f);
        const float k4 = k * k * k * k;
        const float f_l = 0.2f * k4 * (5.f * l_a) +
                          0.1f * std::pow(1.f - k4, 2.f) * std::pow(5.f * l_a, 1.f / 3.f);
        fl_n = f_l / ref;
        cz = static_cast<float>(aces2::surround_c) *
             (1.48f + std::sqrt(static_cast<float>(aces2::background_y) / ref));
        cz_inv = 1.0f / cz;
        const F3 gains{fl_n * white_xyz[1] / white_cam[0], fl_n * white_xyz[1] / white_cam[1],
                       fl_n * white_xyz[1] / white_cam[2]};
        const F3 white_response{response(gains[0] * white_cam[0]),
                                response(gains[1] * white_cam[1]),
                                response(gains[2] * white_cam[2])};
        const float scale = static_cast<float>(aces2::response_scale);
        F33 opponent{2.0f,         1.0f,        1.0f / 20.0f, 1.0f,        -12.0f / 11.0f,
                     1.0f / 11.0f, 1.0f / 9.0f, 1.0f / 9.0f,  -2.0f / 9.0f};
        opponent = product(diagonal({scale, scale, scale}), opponent);
        const float a_w = opponent[0] * white_response[0] + opponent[1] * white_response[1] +
                          opponent[2] * white_response[2];
        a_w_j_inv = 1.0f / response(f_l);
        to_cone = product(diagonal(gains),
                          product(product(xyz_to_cam, rgb_to_xyz), diagonal({ref, ref, ref})));
        from_cone = inverted(to_cone);
        const float nc = 43.f * static_cast<float>(aces2::surround_nc);
        to_aab = {opponent[0] / a_w, opponent[1] / a_w, opponent[2] / a_w,
                  opponent[3] * nc,  opponent[4] * nc,  opponent[5] * nc,
                  opponent[6] * nc,  opponent[7] * nc,  opponent[8] * nc};
        from_aab = inverted(to_aab);
    }

    [[nodiscard]] F3 rgb_to_aab(const F3& rgb) const noexcept {
        const F3 c = apply(to_cone, rgb);
        return apply(to_aab, {response(c[0]), response(c[1]), response(c[2])});
    }
    [[nodiscard]] F3 rgb_to_jmh(const F3& rgb) const noexcept {
        const F3 aab = rgb_to_aab(rgb);
        if (aab[0] <= 0.f) return {0.f, 0.f, 0.f};
        float h = 180.0f * std::atan2(aab[2], aab[1]) / pi_f;
        if (h < 0.f) h += 360.f;
        return {static_cast<float>(aces2::j_scale) * std::pow(aab[0], cz),
                std::sqrt(aab[1] * aab[1] + aab[2] * aab[2]), h};
    }
    [[nodiscard]] float j_to_a(float j) const noexcept {
        return std::pow(j * (1.0f / static_cast<float>(aces2::j_scale)), cz_inv);
    }
    [[nodiscard]] F3 jmh_to_rgb(const F3& jmh) const noexcept {
        const float h = pi_f * jmh[2] / 180.0f;
        const F3 r = apply(from_aab, {j_to_a(jmh[0]), jmh[1] * std::cos(h), jmh[1] * std::sin(h)});
        return apply(from_cone,
                     {response_inverse(r[0]), response_inverse(r[1]), response_inverse(r[2])});
    }
    /// The J of an achromatic luminance (the white is 100).
    [[nodiscard]] float y_to_j(float y) const noexcept {
        return static_cast<float>(aces2::j_scale) * std::pow(response(y * fl_n) * a_w_j_inv, cz);
    }
};

/// The cube's corners in the order red, yellow, green, cyan, blue, magenta.
F3 unit_corner(int i) noexcept {
    return {((i + 1) % corner_count) < 3 ? 1.f : 0.f, ((i + 5) % corner_count) < 3 ? 1.f : 0.f,
            ((i + 3) % corner_count) < 3 ? 1.f : 0.f};
}

/// Six corners' RGB and JMh as a cycle: the lowest hue at [1], the ends wrapped below 0 and above
/// 360.
struct Corners {
    std::array<F3, corner_count + 2> rgb{}, jmh{};
};

Corners cycle(const std::array<F3, corner_count>& rgb, const std::array<F3, corner_count>& jmh) {
    std::size_t first = 0;
    for (std::size_t i = 1; i < corner_count; ++i)
        if (jmh[i][2] < jmh[first][2]) first = i;
    Corners c;
    for (std::size_t i = 0; i < corner_count; ++i) {
        c.rgb[i + 1] = rgb[(i + first) % corner_count];
        c.jmh[i + 1] = jmh[(i + first) % corner_count];
    }
    c.rgb[0] = c.rgb[corner_count];
    c.jmh[0] = c.jmh[corner_count];
    c.rgb[corner_count + 1] = c.rgb[1];
    c.jmh[corner_count + 1] = c.jmh[1];
    c.jmh[0][2] -= 360.f;
    c.jmh[corner_count + 1][2] += 360.f;
    return c;
}

/// The parameters of the searches, in float as OpenColorIO computes them.
struct FloatParameters {
    float peak = 0, limit_j = 0, mid_j = 0, focus_dist = 0, lower_gamma_inv = 0, forward_limit = 0;
};

}  // namespace

void Aces2Rendering::build_tables(const Aces2Display& display) {
    // The limiting primaries as floats (OpenColorIO's FixedFunction parameters are).
    const auto as_float = [](const Xy& c) { return Xy{round_to_float(c.x), round_to_float(c.y)}; };
    const FloatModel input(aces2::ap0, aces2::aces_white);
    const FloatModel reach_model(aces2::ap1, aces2::aces_white);
    const FloatModel limiting({as_float(display.limiting.red), as_float(display.limiting.green),
                               as_float(display.limiting.blue)},
                              as_float(display.limiting_white));
    FloatParameters f;
    f.peak = round_to_float(display.peak_nits);
    {
        // What the tables read of init_ToneScaleParams, init_SharedCompressionParams and
        // init_GamutCompressParams (the constants are aces2.cpp's), in float.
        const float n = f.peak, n_r = 100.0f, c_d = 10.013f, w_g = 0.14f;
        const float r_hit =
            128.f + (896.f - 128.f) * (std::log(n / n_r) / std::log(10000.f / 100.f));
        const float w_i = std::log(n / 100.f) / std::log(2.f);
        const float c_t = c_d / n_r * (1.f + w_i * w_g);
        const float log_peak = std::log10(n / n_r);
        f.forward_limit = 8.0f * r_hit;
        f.limit_j = input.y_to_j(f.peak);
        f.mid_j = input.y_to_j(c_t * 100.f);
        f.focus_dist = 1.35f + 1.35f * 1.75f * log_peak;
        f.lower_gamma_inv = 1.0f / (1.14f + 0.07f * log_peak);
    }

    // The reach gamut's M at limit_j per whole degree: the largest M whose AP1 RGB has no
    // negative channel, searched in steps then bisected.
    m_reach.assign(table_hues, 0.0);
    for (int i = 0; i < table_hues; ++i) {
        const float hue = static_cast<float>(i);
        const auto outside = [&](float m) {
            const F3 rgb = reach_model.jmh_to_rgb({f.limit_j, m, hue});
            return rgb[0] < 0.f || rgb[1] < 0.f || rgb[2] < 0.f;
        };
        float low = 0.f, high = reach_search_step;
        while (!outside(high) && high < reach_search_max) {
            low = high;
            high += reach_search_step;
        }
        while (high - low > reach_tolerance) {
            const float mid = (high + low) / 2.f;
            (outside(mid) ? high : low) = mid;
        }
        m_reach[static_cast<std::size_t>(i)] = high;
    }

    // The corners: the reach gamut's (scaled until its A reaches that of limit_j) and the
    // limiting gamut's (at the peak).
    std::array<F3, corner_count> rgb{}, jmh{};
    const float limit_a = reach_model.j_to_a(f.limit_j);
    for (std::size_t i = 0; i < corner_count; ++i) {
        const F3 v = unit_corner(static_cast<int>(i));
        float lower = 0.f, upper = f.forward_limit;
        while (upper - lower > corner_tolerance) {
            const float test = (lower + upper) / 2.f;
            const float a = reach_model.rgb_to_aab({test * v[0], test * v[1], test * v[2]})[0];
            (a < limit_a ? lower : upper) = test;
            if (a == limit_a) break;
        }
        jmh[i] = reach_model.rgb_to_jmh({upper * v[0], upper * v[1], upper * v[2]});
    }
    const Corners reach = cycle(rgb, jmh);
    for (std::size_t i = 0; i < corner_count; ++i) {
        const F3 v = unit_corner(static_cast<int>(i));
        const float s = f.peak / static_cast<float>(aces2::reference_luminance);
        rgb[i] = {s * v[0], s * v[1], s * v[2]};
        jmh[i] = limiting.rgb_to_jmh(rgb[i]);
    }
    const Corners corners = cycle(rgb, jmh);

    // The corners' hues, merged and made unique.
    std::vector<float> corner_hues;
    for (std::size_t r = 1, l = 1; r <= corner_count || l <= corner_count;) {
        const float rh = reach.jmh[r][2], lh = corners.jmh[l][2];  // [7] is above every hue
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

    // The hue table: 360 hues as even as possible, every corner hue exactly among them, each
    // corner at the index nearest its hue (OpenColorIO's allocation, collisions moved apart).
    const std::size_t unique = corner_hues.size();
    std::vector<int> index(unique, 0);
    {
        int last = -1;
        int min_index = corner_hues[0] == 0.f ? 0 : 1;
        for (std::size_t k = 0; k < unique; ++k) {
            int nominal = std::min(
                std::max(static_cast<int>(std::round(corner_hues[k])), min_index), table_hues - 1);
            if (last == nominal) {
                if (k > 1 && index[k - 2] != index[k - 1] - 1)
                    index[k - 1] -= 1;
                else
                    nominal += 1;
            }
            index[k] = std::min(nominal, table_hues - 1);
            last = min_index = nominal;
        }
    }
    std::vector<float> hues(table_hues + 2, 0.f);
    {
        int filled = 0;
        const auto interval = [&](int samples, float lower, float upper) {
            const float delta = (upper - lower) / static_cast<float>(samples);
            for (int i = 0; i < samples; ++i)
                hues[static_cast<std::size_t>(filled + 1 + i)] =
                    lower + static_cast<float>(i) * delta;
            filled += samples;
        };
        interval(index[0], 0.f, corner_hues[0]);
        for (std::size_t k = 1; k < unique; ++k)
            interval(index[k] - index[k - 1], corner_hues[k - 1], corner_hues[k]);
        interval(table_hues - filled, corner_hues[unique - 1], 360.f);
        hues[0] = hues[table_hues] - 360.f;
        hues[table_hues + 1] = hues[1] + 360.f;
    }
    m_hues.assign(hues.begin(), hues.end());

    // The window of hue_interval's search: how far each entry lies from the entry of its whole
    // degree, below (padded by 0) and above (padded by 1).
    m_hue_search = {0, 1};
    for (int i = 1; i <= table_hues; ++i) {
        const int delta = i - (1 + static_cast<int>(hues[static_cast<std::size_t>(i)]));
        m_hue_search[0] = std::min(m_hue_search[0], delta);
        m_hue_search[1] = std::max(m_hue_search[1], delta + 1);
    }

    // The limiting gamut's cusp per table hue: bisected along the cube's edge between the two
    // corners whose hues enclose it, going on from the last cusp's edge parameter.
    std::vector<std::array<float, 2>> cusps(table_hues + 2);
    int previous_corner = 0;
    float previous_t = 0.f;
    for (std::size_t i = 1; i <= table_hues; ++i) {
        const float hue = hues[i];
        std::size_t upper = 1;
        for (std::size_t c = 1; c < corner_count + 2; ++c) {
            if (corners.jmh[c][2] > hue) {
                upper = c;
                break;
            }
        }
        const std::size_t lower = upper - 1;
        if (corners.jmh[lower][2] == hue) {
            cusps[i] = {corners.jmh[lower][0], corners.jmh[lower][1]};
        } else {
            const F3& a = corners.rgb[lower];
            const F3& b = corners.rgb[upper];
            const auto at = [&](float t) {
                return limiting.rgb_to_jmh({aces2::lerp(a[0], b[0], t), aces2::lerp(a[1], b[1], t),
                                            aces2::lerp(a[2], b[2], t)});
            };
            float lo_t = static_cast<int>(upper) == previous_corner ? previous_t : 0.f, hi_t = 1.f;
            while (hi_t - lo_t > cusp_tolerance) {
                const float t = (lo_t + hi_t) / 2.f;
                const float h = at(t)[2];
                if (h < corners.jmh[lower][2])
                    hi_t = t;
                else if (h >= corners.jmh[upper][2])
                    lo_t = t;
                else if (h > hue)
                    hi_t = t;
                else
                    lo_t = t;
            }
            const float t = (lo_t + hi_t) / 2.f;
            const F3 c = at(t);
            cusps[i] = {c[0], c[1]};
            previous_corner = static_cast<int>(upper);
            previous_t = t;
        }
        cusps[i][1] *= 1.f + smooth_m * static_cast<float>(aces2::smooth_cusps);
    }

    // The upper hull's γ per hue: the smallest γ (to 1e-5) whose boundary lies outside the
    // limiting cube at five heights between the cusp and limit_j.
    std::vector<float> gamma_inv(table_hues + 2, 0.f);
    const float top = f.peak / static_cast<float>(aces2::reference_luminance);
    for (std::size_t i = 1; i <= table_hues; ++i) {
        const float cusp_j = cusps[i][0], cusp_m = cusps[i][1];
        const float focus_j = aces2::focus_j_of(cusp_j, f.mid_j, f.limit_j);
        const float threshold = aces2::focus_threshold(cusp_j, f.limit_j);
        struct Test {
            float j_source, slope, j_cusp;
        };
        std::array<Test, gamma_test_positions.size()> tests{};
        for (std::size_t k = 0; k < tests.size(); ++k) {
            const float test_j = aces2::lerp(cusp_j, f.limit_j, gamma_test_positions[k]);
            const float gain = aces2::focus_gain(test_j, threshold, f.limit_j, f.focus_dist);
            const float j_source =
                aces2::solve_j_intersect(test_j, cusp_m, focus_j, f.limit_j, gain);
            tests[k] = {j_source, aces2::compression_slope(j_source, focus_j, f.limit_j, gain),
                        aces2::solve_j_intersect(cusp_j, cusp_m, focus_j, f.limit_j, gain)};
        }
        const auto fits = [&](float gamma) {
            for (const Test& t : tests) {
                const float m =
                    aces2::gamut_boundary_m(cusp_j, cusp_m, f.limit_j, 1.0f / gamma,
                                            f.lower_gamma_inv, t.j_source, t.slope, t.j_cusp);
                const F3 edge = limiting.jmh_to_rgb({t.j_source + t.slope * m, m, hues[i]});
                if (!(edge[0] > top || edge[1] > top || edge[2] > top)) return false;
            }
            return true;
        };
        float low = 0.f, high = gamma_step;
        while (!fits(high) && high < gamma_max) {
            low = high;
            high += gamma_step;
        }
        while (high - low > gamma_tolerance) {
            const float mid = (high + low) / 2.f;
            (fits(mid) ? high : low) = mid;
        }
        gamma_inv[i] = 1.0f / high;
    }

    m_cusps.assign(table_hues + 2, Vec3{});
    for (std::size_t i = 1; i <= table_hues; ++i)
        m_cusps[i] = {cusps[i][0], cusps[i][1], gamma_inv[i]};
    m_cusps[0] = m_cusps[table_hues];
    m_cusps[table_hues + 1] = m_cusps[1];
}

}  // namespace irid
