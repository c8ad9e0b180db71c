#include <irid/color/adaptation.h>
#include <irid/color/measure.h>
#include <irid/color/spaces.h>
#include <irid/error.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace irid {

double percentile_of_sorted(std::span<const double> sorted, double p) {
    if (!(p >= 0.0 && p <= 1.0))
        throw Error("percentile: p is " + std::to_string(p) + "; allowed: [0, 1]");
    if (sorted.empty()) return 0.0;
    // ⌈p n⌉ in doubles, then the 1-based rank clamped to [1, n].
    const double rank = std::ceil(p * static_cast<double>(sorted.size()));
    const auto k = static_cast<std::size_t>(std::clamp(rank, 1.0, static_cast<double>(sorted.size())));
    return sorted[k - 1];
}

double percentile(std::vector<double> values, double p) {
    std::sort(values.begin(), values.end());
    return percentile_of_sorted(values, p);
}

Statistics summarize(std::vector<double> values) {
    Statistics s;
    s.count = values.size();
    if (values.empty()) return s;
    if (std::any_of(values.begin(), values.end(), [](double v) { return std::isnan(v); })) {
        const double nan = std::numeric_limits<double>::quiet_NaN();
        s.mean = s.median = s.p95 = s.p99 = s.max = nan;
        return s;
    }
    std::sort(values.begin(), values.end());
    double sum = 0.0;
    for (const double v : values) sum += v;
    s.mean = sum / static_cast<double>(s.count);
    s.median = percentile_of_sorted(values, 0.5);
    s.p95 = percentile_of_sorted(values, 0.95);
    s.p99 = percentile_of_sorted(values, 0.99);
    s.max = values.back();
    return s;
}

double hue_difference(double from_deg, double to_deg) noexcept {
    double d = std::fmod(to_deg - from_deg, 360.0);
    if (d > 180.0) d -= 360.0;
    if (d <= -180.0) d += 360.0;
    return d;
}

AppearanceMeter::AppearanceMeter(const Xy& white, double scale)
    : m_scale(scale),
      m_white(xy_to_xyz(white)),
      m_to_d65(white.x == d65_xy.x && white.y == d65_xy.y
                   ? Mat3::identity()
                   : adaptation_matrix(m_white, xy_to_xyz(d65_xy), ChromaticAdaptation::bradford)) {}

Appearance AppearanceMeter::operator()(const Xyz& c) const noexcept {
    const Xyz n{c.X * m_scale, c.Y * m_scale, c.Z * m_scale};
    Appearance a;
    a.lab = xyz_to_lab(n, m_white);
    const LchAb ab = lab_to_lch(a.lab);
    a.c_ab = ab.C;
    a.h_ab = ab.h;
    const LchUv uv = luv_to_lch(xyz_to_luv(n, m_white));
    a.l_uv = uv.L;
    a.c_uv = uv.C;
    a.h_uv = uv.h;
    const Vec3 d65 = m_to_d65 * Vec3{n.X, n.Y, n.Z};
    const Oklch ok = oklab_to_oklch(xyz_to_oklab({d65[0], d65[1], d65[2]}));
    a.c_ok = ok.C;
    a.h_ok = ok.h;
    a.saturation_uv = saturation_uv(n, m_white);
    a.y = n.Y;
    return a;
}

}  // namespace irid
