#include <irid/color/difference.h>
#include <irid/color/spaces.h>
#include <irid/error.h>
#include <irid/text_input.h>

#include <string>

#include <cmath>
#include <numbers>

namespace irid {
namespace {

constexpr double pi = std::numbers::pi;
constexpr double radians(double degrees) noexcept { return degrees * pi / 180.0; }
constexpr double pow7(double x) noexcept {
    const double x2 = x * x;
    return x2 * x2 * x2 * x;
}
/// √(a² + b²) without std::hypot's overflow guard, which Lab-sized values never need and which
/// costs more than the rest of the formula's square roots.
double chroma(double a, double b) noexcept { return std::sqrt(a * a + b * b); }

}  // namespace

double delta_e_76(const Lab& a, const Lab& b) noexcept {
    return std::sqrt((a.L - b.L) * (a.L - b.L) + (a.a - b.a) * (a.a - b.a) +
                     (a.b - b.b) * (a.b - b.b));
}

double delta_e_2000(const Lab& c1, const Lab& c2, double k_l, double k_c, double k_h) noexcept {
    // Sharma, Wu & Dalal 2005, eq. 2-21.
    const double c_ab1 = chroma(c1.a, c1.b);
    const double c_ab2 = chroma(c2.a, c2.b);
    const double c_mean = 0.5 * (c_ab1 + c_ab2);
    const double c_mean7 = pow7(c_mean);
    constexpr double twenty_five_7 = 6103515625.0;  // 25^7
    const double g = 0.5 * (1.0 - std::sqrt(c_mean7 / (c_mean7 + twenty_five_7)));
    const double a1p = (1.0 + g) * c1.a;
    const double a2p = (1.0 + g) * c2.a;
    const double c1p = chroma(a1p, c1.b);
    const double c2p = chroma(a2p, c2.b);
    const double h1p = hue_degrees(a1p, c1.b);
    const double h2p = hue_degrees(a2p, c2.b);

    const double dl = c2.L - c1.L;
    const double dc = c2p - c1p;
    double dh_angle = 0.0;
    if (c1p * c2p != 0.0) {
        dh_angle = h2p - h1p;
        if (dh_angle > 180.0) dh_angle -= 360.0;
        else if (dh_angle < -180.0) dh_angle += 360.0;
    }
    const double dh = 2.0 * std::sqrt(c1p * c2p) * std::sin(radians(dh_angle) / 2.0);

    const double l_mean = 0.5 * (c1.L + c2.L);
    const double cp_mean = 0.5 * (c1p + c2p);
    double hp_mean = h1p + h2p;
    if (c1p * c2p != 0.0) {
        if (std::abs(h1p - h2p) <= 180.0) hp_mean = 0.5 * (h1p + h2p);
        else if (h1p + h2p < 360.0) hp_mean = 0.5 * (h1p + h2p + 360.0);
        else hp_mean = 0.5 * (h1p + h2p - 360.0);
    }
    const double t = 1.0 - 0.17 * std::cos(radians(hp_mean - 30.0)) +
                     0.24 * std::cos(radians(2.0 * hp_mean)) +
                     0.32 * std::cos(radians(3.0 * hp_mean + 6.0)) -
                     0.20 * std::cos(radians(4.0 * hp_mean - 63.0));
    const double d_theta = 30.0 * std::exp(-((hp_mean - 275.0) / 25.0) * ((hp_mean - 275.0) / 25.0));
    const double cp_mean7 = pow7(cp_mean);
    const double r_c = 2.0 * std::sqrt(cp_mean7 / (cp_mean7 + twenty_five_7));
    const double l50 = (l_mean - 50.0) * (l_mean - 50.0);
    const double s_l = 1.0 + 0.015 * l50 / std::sqrt(20.0 + l50);
    const double s_c = 1.0 + 0.045 * cp_mean;
    const double s_h = 1.0 + 0.015 * cp_mean * t;
    const double r_t = -std::sin(radians(2.0 * d_theta)) * r_c;

    const double tl = dl / (k_l * s_l);
    const double tc = dc / (k_c * s_c);
    const double th = dh / (k_h * s_h);
    return std::sqrt(tl * tl + tc * tc + th * th + r_t * tc * th);
}

double delta_e_uv(const Luv& a, const Luv& b) noexcept {
    return std::sqrt((a.L - b.L) * (a.L - b.L) + (a.u - b.u) * (a.u - b.u) +
                     (a.v - b.v) * (a.v - b.v));
}

double delta_c_uv(const Luv& a, const Luv& b) noexcept {
    return std::hypot(b.u, b.v) - std::hypot(a.u, a.v);
}

double delta_h_uv(const Luv& a, const Luv& b) noexcept {
    // Eq. 13's [(ΔE)² − (ΔL)² − (ΔC)²]^½ loses every digit to cancellation for small hue
    // differences; the identical quantity 2 (C1 C2)^½ |sin(Δh/2)| does not.
    const double c1 = std::hypot(a.u, a.v);
    const double c2 = std::hypot(b.u, b.v);
    const double dh = std::atan2(a.u * b.v - a.v * b.u, a.u * b.u + a.v * b.v);
    return 2.0 * std::sqrt(c1 * c2) * std::abs(std::sin(0.5 * dh));
}

double delta_s_uv(const Luv& a, const Luv& b) noexcept {
    const auto saturation = [](const Luv& c) {
        return c.L > 0.0 ? std::hypot(c.u, c.v) / c.L : 0.0;
    };
    return saturation(b) - saturation(a);
}

double delta_e_ok(const Oklab& a, const Oklab& b) noexcept {
    return std::sqrt((a.L - b.L) * (a.L - b.L) + (a.a - b.a) * (a.a - b.a) +
                     (a.b - b.b) * (a.b - b.b));
}

DeltaEMetric parse_delta_e_metric(std::string_view name) {
    for (const DeltaEMetric m :
         {DeltaEMetric::ciede2000, DeltaEMetric::cie76, DeltaEMetric::cieuv, DeltaEMetric::oklab}) {
        if (name == delta_e_metric_name(m)) return m;
    }
    throw UnknownNameError("unknown metric " + quote_untrusted(name) +
                               "; valid names: ciede2000, cie76, cieuv, oklab",
                           {"ciede2000", "cie76", "cieuv", "oklab"});
}

std::string_view delta_e_metric_name(DeltaEMetric metric) noexcept {
    switch (metric) {
        case DeltaEMetric::ciede2000: return "ciede2000";
        case DeltaEMetric::cie76: return "cie76";
        case DeltaEMetric::cieuv: return "cieuv";
        case DeltaEMetric::oklab: return "oklab";
    }
    return "";
}

double delta_e(DeltaEMetric metric, const Vec3& a, const Vec3& b) noexcept {
    switch (metric) {
        case DeltaEMetric::ciede2000: return delta_e_2000({a[0], a[1], a[2]}, {b[0], b[1], b[2]});
        case DeltaEMetric::cie76: return delta_e_76({a[0], a[1], a[2]}, {b[0], b[1], b[2]});
        case DeltaEMetric::cieuv: return delta_e_uv({a[0], a[1], a[2]}, {b[0], b[1], b[2]});
        case DeltaEMetric::oklab: return delta_e_ok({a[0], a[1], a[2]}, {b[0], b[1], b[2]});
    }
    return 0.0;
}

}  // namespace irid
