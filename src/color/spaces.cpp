#include <irid/color/spaces.h>

#include <cmath>
#include <numbers>

namespace irid {
namespace {

constexpr double degrees_per_radian = 180.0 / std::numbers::pi;

/// CIELAB's f(t): cube root above ε, the linear segment κ t / 116 + 16/116 below.
double lab_f(double t) noexcept {
    return t > cie_epsilon ? std::cbrt(t) : (cie_kappa * t + 16.0) / 116.0;
}

double lab_f_inverse(double f) noexcept {
    const double f3 = f * f * f;
    return f3 > cie_epsilon ? f3 : (116.0 * f - 16.0) / cie_kappa;
}

}  // namespace

double hue_degrees(double a, double b) noexcept {
    if (a == 0.0 && b == 0.0) return 0.0;
    double h = std::atan2(b, a) * degrees_per_radian;
    if (h < 0.0) h += 360.0;
    if (h >= 360.0) h -= 360.0;  // atan2 of a tiny negative b rounds to exactly 360 after +360
    return h;
}

Xy xyz_to_xy(const Xyz& c, const Xy& black_chromaticity) noexcept {
    const double sum = c.X + c.Y + c.Z;
    if (sum == 0.0) return black_chromaticity;
    return {c.X / sum, c.Y / sum};
}

Xyz xy_to_xyz(const Xy& c, double Y) noexcept {
    if (c.y == 0.0) return {0.0, 0.0, 0.0};
    const double k = Y / c.y;
    return {c.x * k, Y, (1.0 - c.x - c.y) * k};
}

Xyy xyz_to_xyy(const Xyz& c, const Xy& black_chromaticity) noexcept {
    const Xy xy = xyz_to_xy(c, black_chromaticity);
    return {xy.x, xy.y, c.Y};
}

Xyz xyy_to_xyz(const Xyy& c) noexcept { return xy_to_xyz({c.x, c.y}, c.Y); }

UvPrime xyz_to_uv_prime(const Xyz& c, const UvPrime& black_uv) noexcept {
    const double d = c.X + 15.0 * c.Y + 3.0 * c.Z;
    if (d == 0.0) return black_uv;
    return {4.0 * c.X / d, 9.0 * c.Y / d};
}

UvPrime xy_to_uv_prime(const Xy& c) noexcept {
    const double d = -2.0 * c.x + 12.0 * c.y + 3.0;
    return {4.0 * c.x / d, 9.0 * c.y / d};
}

Xy uv_prime_to_xy(const UvPrime& c) noexcept {
    const double d = 6.0 * c.u - 16.0 * c.v + 12.0;
    return {9.0 * c.u / d, 4.0 * c.v / d};
}

double cie_lightness(double relative_luminance) noexcept {
    return 116.0 * lab_f(relative_luminance) - 16.0;
}

double cie_lightness_to_relative_luminance(double L) noexcept {
    return lab_f_inverse((L + 16.0) / 116.0);
}

Luv xyz_to_luv(const Xyz& c, const Xyz& white) noexcept {
    const UvPrime n = xyz_to_uv_prime(white);
    const UvPrime uv = xyz_to_uv_prime(c, n);
    const double L = cie_lightness(c.Y / white.Y);
    return {L, 13.0 * L * (uv.u - n.u), 13.0 * L * (uv.v - n.v)};
}

Xyz luv_to_xyz(const Luv& c, const Xyz& white) noexcept {
    if (c.L == 0.0) return {0.0, 0.0, 0.0};
    const UvPrime n = xyz_to_uv_prime(white);
    const double u = c.u / (13.0 * c.L) + n.u;
    const double v = c.v / (13.0 * c.L) + n.v;
    const double Y = white.Y * cie_lightness_to_relative_luminance(c.L);
    if (v == 0.0) return {0.0, Y, 0.0};
    // From u' = 4X/d and v' = 9Y/d with d = X + 15Y + 3Z.
    const double d = 9.0 * Y / v;
    const double X = u * d / 4.0;
    const double Z = (d - X - 15.0 * Y) / 3.0;
    return {X, Y, Z};
}

Lab xyz_to_lab(const Xyz& c, const Xyz& white) noexcept {
    const double fx = lab_f(c.X / white.X);
    const double fy = lab_f(c.Y / white.Y);
    const double fz = lab_f(c.Z / white.Z);
    return {116.0 * fy - 16.0, 500.0 * (fx - fy), 200.0 * (fy - fz)};
}

Xyz lab_to_xyz(const Lab& c, const Xyz& white) noexcept {
    const double fy = (c.L + 16.0) / 116.0;
    const double fx = fy + c.a / 500.0;
    const double fz = fy - c.b / 200.0;
    return {white.X * lab_f_inverse(fx), white.Y * lab_f_inverse(fy), white.Z * lab_f_inverse(fz)};
}

LchUv luv_to_lch(const Luv& c) noexcept { return {c.L, std::hypot(c.u, c.v), hue_degrees(c.u, c.v)}; }

Luv lch_to_luv(const LchUv& c) noexcept {
    const double h = c.h / degrees_per_radian;
    return {c.L, c.C * std::cos(h), c.C * std::sin(h)};
}

LchAb lab_to_lch(const Lab& c) noexcept { return {c.L, std::hypot(c.a, c.b), hue_degrees(c.a, c.b)}; }

Lab lch_to_lab(const LchAb& c) noexcept {
    const double h = c.h / degrees_per_radian;
    return {c.L, c.C * std::cos(h), c.C * std::sin(h)};
}

double saturation_uv(const Xyz& c, const Xyz& white) noexcept {
    const UvPrime n = xyz_to_uv_prime(white);
    const UvPrime uv = xyz_to_uv_prime(c, n);
    return 13.0 * std::hypot(uv.u - n.u, uv.v - n.v);
}

Oklab xyz_to_oklab(const Xyz& c) noexcept {
    const Vec3 lms = oklab_m1 * Vec3{c.X, c.Y, c.Z};
    const Vec3 lab = oklab_m2 * Vec3{std::cbrt(lms[0]), std::cbrt(lms[1]), std::cbrt(lms[2])};
    return {lab[0], lab[1], lab[2]};
}

Xyz oklab_to_xyz(const Oklab& c) noexcept {
    const Vec3 lms_root = oklab_m2_inverse * Vec3{c.L, c.a, c.b};
    const Vec3 lms{lms_root[0] * lms_root[0] * lms_root[0], lms_root[1] * lms_root[1] * lms_root[1],
                   lms_root[2] * lms_root[2] * lms_root[2]};
    const Vec3 xyz = oklab_m1_inverse * lms;
    return {xyz[0], xyz[1], xyz[2]};
}

Oklch oklab_to_oklch(const Oklab& c) noexcept {
    return {c.L, std::hypot(c.a, c.b), hue_degrees(c.a, c.b)};
}

Oklab oklch_to_oklab(const Oklch& c) noexcept {
    const double h = c.h / degrees_per_radian;
    return {c.L, c.C * std::cos(h), c.C * std::sin(h)};
}

}  // namespace irid
