// The JMh model of ACES 2.0: Hellwig, Stolitzka & Fairchild 2022's simplification of CAM16,
// with the Academy's viewing conditions, cone primaries and a response mirrored for negatives.

#include <irid/color/matrix.h>
#include <irid/gamut/aces2.h>

#include "aces2_constants.h"

#include <cmath>
#include <numbers>

namespace irid {
namespace {

using aces2::adapting_luminance;
using aces2::background_y;
using aces2::cone_primaries;
using aces2::cone_white;
using aces2::j_scale;
using aces2::reference_luminance;
using aces2::response_exponent;
using aces2::response_offset;
using aces2::response_scale;
using aces2::surround_c;
using aces2::surround_nc;

/// The response to a cone signal c >= 0.
double response(double c, double fl_n) noexcept {
    const double f = std::pow(c * fl_n, response_exponent);
    return response_scale * f / (response_offset + f);
}

/// Its inverse for r >= 0, r taken at most response_inverse_share of response_scale (where the
/// response diverges; OpenColorIO 2.4.2+'s limit, aces2_constants.h).
double response_inverse(double r, double fl_n) noexcept {
    const double limited = std::min(r, aces2::response_inverse_share * response_scale);
    const double f = response_offset * limited / (response_scale - limited);
    return std::pow(f, 1.0 / response_exponent) / fl_n;
}

double mirrored_response(double c, double fl_n) noexcept {
    return std::copysign(response(std::abs(c), fl_n), c);
}

double mirrored_response_inverse(double r, double fl_n) noexcept {
    return std::copysign(response_inverse(std::abs(r), fl_n), r);
}

Mat3 scaled_rows(const Mat3& m, const Vec3& s) noexcept {
    Mat3 r = m;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) r[i][j] *= s[i];
    return r;
}

}  // namespace

Mat3 aces2::primary_matrix(const RgbPrimaries& p, const Xy& white) {
    const auto column = [](const Xy& c) { return Vec3{c.x / c.y, 1.0, (1.0 - c.x - c.y) / c.y}; };
    const Mat3 primaries = Mat3::from_columns(column(p.red), column(p.green), column(p.blue));
    const Vec3 s = inverse(primaries, "ACES 2.0 primaries") * column(white);
    return primaries * Mat3::diagonal(s);
}

Aces2JmhModel::Aces2JmhModel(const RgbPrimaries& primaries, const Xy& white) {
    const Mat3 xyz_to_cone =
        inverse(aces2::primary_matrix(cone_primaries, cone_white), "ACES 2.0 cone primaries");
    const Mat3 rgb_to_xyz = rgb_to_xyz_matrix(primaries, white);
    const Mat3 rgb_to_cone = xyz_to_cone * rgb_to_xyz;
    // The white at the reference luminance, and the von Kries gains D that make it equal cone
    // signals (complete adaptation, D = 1).
    const Vec3 white_xyz =
        rgb_to_xyz * Vec3{reference_luminance, reference_luminance, reference_luminance};
    const Vec3 white_cone = xyz_to_cone * white_xyz;
    const Vec3 gains{white_xyz[1] / white_cone[0], white_xyz[1] / white_cone[1],
                     white_xyz[1] / white_cone[2]};

    // F_L of CAM16 at L_A (Hellwig 2022, eq. 3-4).
    const double k = 1.0 / (5.0 * adapting_luminance + 1.0);
    const double k4 = k * k * k * k;
    const double fl = 0.2 * k4 * (5.0 * adapting_luminance) +
                      0.1 * (1.0 - k4) * (1.0 - k4) * std::cbrt(5.0 * adapting_luminance);
    m_fl_n = fl / reference_luminance;
    m_cz = surround_c * (1.48 + std::sqrt(background_y / reference_luminance));

    m_rgb_to_cone =
        scaled_rows(rgb_to_cone, {gains[0] * reference_luminance, gains[1] * reference_luminance,
                                  gains[2] * reference_luminance});
    m_cone_to_rgb = inverse(m_rgb_to_cone, "ACES 2.0 RGB to cone matrix");

    // The adapted white's cone signals are all Y_w; its achromatic response A_w.
    const double white_response = response(white_xyz[1], m_fl_n);
    const double a_w = (2.0 + 1.0 + 1.0 / 20.0) * white_response;
    Mat3 opponent;
    opponent.m = {{{2.0, 1.0, 1.0 / 20.0},
                   {1.0, -12.0 / 11.0, 1.0 / 11.0},
                   {1.0 / 9.0, 1.0 / 9.0, -2.0 / 9.0}}};
    m_cone_to_aab = scaled_rows(opponent, {1.0 / a_w, 43.0 * surround_nc, 43.0 * surround_nc});
    m_aab_to_cone = inverse(m_cone_to_aab, "ACES 2.0 opponent matrix");
    m_a_w_j = response(reference_luminance, m_fl_n);
}

Vec3 Aces2JmhModel::rgb_to_aab(const Vec3& rgb) const noexcept {
    const Vec3 c = m_rgb_to_cone * rgb;
    return m_cone_to_aab * Vec3{mirrored_response(c[0], m_fl_n), mirrored_response(c[1], m_fl_n),
                                mirrored_response(c[2], m_fl_n)};
}

Vec3 Aces2JmhModel::aab_to_rgb(const Vec3& aab) const noexcept {
    const Vec3 r = m_aab_to_cone * aab;
    return m_cone_to_rgb * Vec3{mirrored_response_inverse(r[0], m_fl_n),
                                mirrored_response_inverse(r[1], m_fl_n),
                                mirrored_response_inverse(r[2], m_fl_n)};
}

Aces2Jmh Aces2JmhModel::aab_to_jmh(const Vec3& aab) const noexcept {
    if (!(aab[0] > 0.0)) return {};
    double h = std::atan2(aab[2], aab[1]) * (180.0 / std::numbers::pi);
    if (h < 0.0) h += 360.0;
    if (h >= 360.0) h -= 360.0;
    return {a_to_j(aab[0]), std::hypot(aab[1], aab[2]), h};
}

Vec3 Aces2JmhModel::jmh_to_aab(const Aces2Jmh& jmh) const noexcept {
    const double h = jmh.h * (std::numbers::pi / 180.0);
    return {j_to_a(jmh.J), jmh.M * std::cos(h), jmh.M * std::sin(h)};
}

double Aces2JmhModel::j_to_a(double j) const noexcept {
    return std::pow(j / j_scale, 1.0 / m_cz);
}

double Aces2JmhModel::a_to_j(double a) const noexcept {
    return j_scale * std::pow(a, m_cz);
}

double Aces2JmhModel::y_to_j(double y) const noexcept {
    return std::copysign(a_to_j(response(std::abs(y), m_fl_n) / m_a_w_j), y);
}

double Aces2JmhModel::j_to_y(double j) const noexcept {
    return std::copysign(response_inverse(m_a_w_j * j_to_a(std::abs(j)), m_fl_n), j);
}

}  // namespace irid
