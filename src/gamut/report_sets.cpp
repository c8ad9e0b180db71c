// The clip report's colour sets: the spectrum, the Rec.2020 grid, the ramps from a grey out to
// the Rec.2020 cube or the spectral locus, and unions of sets (docs/GAMUT.md, "The clip
// report").

#include <irid/color/adaptation.h>
#include <irid/color/difference.h>
#include <irid/color/numeric_table.h>
#include <irid/color/observer.h>
#include <irid/color/spaces.h>
#include <irid/error.h>
#include <irid/gamut/report.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace irid {
namespace {

/// Pieces of the line on which a ramp's CIEDE2000 arc length is summed (color_ramp).
constexpr int ramp_arc_samples = 4096;

bool same_white(const Xy& a, const Xy& b) noexcept { return a.x == b.x && a.y == b.y; }

Vec3 v3(const Xyz& c) noexcept { return {c.X, c.Y, c.Z}; }
Xyz xyz(const Vec3& v) noexcept { return {v[0], v[1], v[2]}; }

/// XYZ relative to `from` white → relative to the destination's white (Bradford).
Mat3 adaptation_to(const Xy& from, const RgbSpace& destination) {
    if (same_white(from, destination.white())) return Mat3::identity();
    return adaptation_matrix(xy_to_xyz(from), destination.white_xyz(), ChromaticAdaptation::bradford);
}

/// The monochromatic stimulus of an integer wavelength, as a vector.
Vec3 monochromatic(int nm) noexcept { return v3(monochromatic_xyz(nm)); }

/// The end of the ramp from `grey` along `d` on the Rec.2020 cube: the smallest s > 0 at which
/// a channel of linear Rec.2020 (adapted to the destination's white) reaches 0 or 1.
double rec2020_exit(const RgbSpace& destination, const Vec3& grey, const Vec3& d) {
    const RgbSpace& source = rec2020();
    const Mat3 to_rec2020 =
        inverse(adaptation_to(source.white(), destination) * source.to_xyz_matrix(), "Rec.2020 to XYZ");
    const Vec3 c0 = to_rec2020 * grey;
    const Vec3 dc = to_rec2020 * d;
    double end = std::numeric_limits<double>::infinity();
    for (int k = 0; k < 3; ++k) {
        if (dc[k] > 0.0) end = std::min(end, (1.0 - c0[k]) / dc[k]);
        if (dc[k] < 0.0) end = std::min(end, -c0[k] / dc[k]);
    }
    return end;
}

/// The end of the ramp on the spectral locus: the largest s > 0 with grey + s d = α m(λ) +
/// β m(λ + 1), α, β >= 0, over the 1 nm segments 380–780 nm and the purple line (780, 380).
double locus_exit(const Vec3& grey, const Vec3& d) {
    double end = -1.0;
    const Vec3 rhs{-grey[0], -grey[1], -grey[2]};
    for (int nm = 380; nm <= 780; ++nm) {
        const Vec3 a = monochromatic(nm);
        const Vec3 b = monochromatic(nm < 780 ? nm + 1 : 380);
        const Mat3 m = Mat3::from_columns(d, {-a[0], -a[1], -a[2]}, {-b[0], -b[1], -b[2]});
        const double det = m.determinant();
        // Parallel stimuli (the same chromaticity, at the table's long-wavelength end): no
        // segment to cross.
        const double scale = std::hypot(a[0], a[1], a[2]) * std::hypot(b[0], b[1], b[2]) *
                             std::hypot(d[0], d[1], d[2]);
        if (!(std::abs(det) > 1e-14 * scale)) continue;
        const Vec3 sol = inverse_unchecked(m) * rhs;
        // Through a vertex the weights are 0 to rounding on both of its segments.
        const double tol = -1e-12 * (std::abs(sol[1]) + std::abs(sol[2]));
        if (sol[0] > 0.0 && sol[1] >= tol && sol[2] >= tol) end = std::max(end, sol[0]);
    }
    return end;
}

}  // namespace

std::string_view ramp_end_name(RampEnd end) noexcept {
    switch (end) {
        case RampEnd::rec2020: return "rec2020";
        case RampEnd::locus: return "locus";
    }
    return "";
}

RampGeometry ramp_geometry(const RgbSpace& destination, double luminance, double hue_deg, RampEnd end) {
    if (!(luminance > 0.0 && luminance < 1.0)) {
        throw Error("ramp: luminance " + format_shortest(luminance) +
                    " must be in (0, 1), below the white's");
    }
    if (!std::isfinite(hue_deg)) throw Error("ramp: hue " + format_shortest(hue_deg) + " is not finite");
    const Xyz& white = destination.white_xyz();
    RampGeometry g;
    g.grey = {white.X * luminance, white.Y * luminance, white.Z * luminance};
    // Oklab at the grey (Ottosson 2020: Lab = M2 cbrt(M1 XYZ_D65)): its Jacobian with respect
    // to the destination's XYZ is M2 diag(1 / (3 lms^(2/3))) M1 A, A the adaptation to D65.
    const Mat3 to_d65 = same_white(destination.white(), d65_xy)
                            ? Mat3::identity()
                            : adaptation_matrix(white, xy_to_xyz(d65_xy), ChromaticAdaptation::bradford);
    const Mat3 to_lms = oklab_m1 * to_d65;
    const Vec3 lms = to_lms * v3(g.grey);
    Vec3 slope{};
    for (int k = 0; k < 3; ++k) {
        const double c = std::cbrt(lms[k]);
        slope[k] = 1.0 / (3.0 * c * c);
    }
    const Mat3 jacobian = oklab_m2 * Mat3::diagonal(slope) * to_lms;
    // (a, b) against (X, Z) at constant Y; solve for the direction of (cos h, sin h).
    const double j00 = jacobian[1][0], j01 = jacobian[1][2], j10 = jacobian[2][0], j11 = jacobian[2][2];
    const double det = j00 * j11 - j01 * j10;
    const double h = hue_deg * std::numbers::pi / 180.0;
    const double ca = std::cos(h), sb = std::sin(h);
    const double dx = (j11 * ca - j01 * sb) / det, dz = (j00 * sb - j10 * ca) / det;
    const double length = std::hypot(dx, dz);
    g.direction = {dx / length, 0.0, dz / length};
    g.end = end == RampEnd::rec2020 ? rec2020_exit(destination, v3(g.grey), g.direction)
                                    : locus_exit(v3(g.grey), g.direction);
    if (!(std::isfinite(g.end) && g.end > 0.0)) {
        throw Error("ramp: no end point at Y = " + format_shortest(luminance) + ", h = " +
                    format_shortest(hue_deg) + "°");  // not reached: the grey is inside both
    }
    return g;
}

std::vector<Xyz> color_ramp(const RgbSpace& destination, double luminance, double hue_deg, RampEnd end,
                            int steps) {
    if (steps < 2 || steps > 65536) {
        throw Error("ramp: " + std::to_string(steps) + " steps; valid: 2 to 65536");
    }
    const RampGeometry g = ramp_geometry(destination, luminance, hue_deg, end);
    // d has no Y component: every point of the line keeps the grey's Y exactly.
    const auto at = [&](double s) -> Xyz {
        return {g.grey.X + s * g.direction[0], g.grey.Y, g.grey.Z + s * g.direction[2]};
    };
    // CIEDE2000 arc length along the line (CIELAB relative to the destination's white), on
    // ramp_arc_samples equal pieces of s; the steps are placed at equal arc length by linear
    // interpolation of s within a piece.
    const Xyz white = destination.white_xyz();
    const auto lab = [&](double s) { return xyz_to_lab(at(s), white); };
    std::vector<double> length(ramp_arc_samples + 1, 0.0);
    Lab previous = lab(0.0);
    for (int j = 1; j <= ramp_arc_samples; ++j) {
        const Lab here = lab(g.end * j / ramp_arc_samples);
        length[static_cast<std::size_t>(j)] = length[static_cast<std::size_t>(j - 1)] + delta_e_2000(previous, here);
        previous = here;
    }
    const double total = length.back();
    std::vector<Xyz> out;
    out.reserve(static_cast<std::size_t>(steps));
    std::size_t piece = 0;
    for (int i = 0; i < steps; ++i) {
        if (i == 0 || i + 1 == steps) {
            out.push_back(at(i == 0 ? 0.0 : g.end));  // the grey and the end point, exactly
            continue;
        }
        const double target = total * i / (steps - 1);
        while (piece + 1 < static_cast<std::size_t>(ramp_arc_samples) && length[piece + 1] < target) ++piece;
        const double l0 = length[piece], l1 = length[piece + 1];
        const double f = l1 > l0 ? std::clamp((target - l0) / (l1 - l0), 0.0, 1.0) : 0.0;
        out.push_back(at(g.end * (static_cast<double>(piece) + f) / ramp_arc_samples));
    }
    return out;
}

ColorSet ramps_color_set(const RgbSpace& destination) {
    ColorSet set;
    set.name = "ramps";
    set.description = std::to_string(ramp_set_hues) + " Oklab hues × ends (Rec.2020 boundary, "
                      "spectral locus) × Y = 0.1, 0.3, 0.6: ramps of " + std::to_string(ramp_set_steps) +
                      " steps at constant Y from the grey";
    for (const double y : ramp_set_luminances) {
        for (const RampEnd end : {RampEnd::rec2020, RampEnd::locus}) {
            for (int k = 0; k < ramp_set_hues; ++k) {
                const double hue = 360.0 * k / ramp_set_hues;
                const std::vector<Xyz> ramp = color_ramp(destination, y, hue, end, ramp_set_steps);
                set.ramps.push_back({set.colors.size(), ramp.size(),
                                     "Y " + format_shortest(y) + ", h " + format_shortest(hue) + "°, to " +
                                         (end == RampEnd::rec2020 ? "rec2020" : "the locus")});
                set.colors.insert(set.colors.end(), ramp.begin(), ramp.end());
            }
        }
    }
    return set;
}

ColorSet spectrum_color_set() {
    ColorSet set;
    set.name = "spectrum";
    set.description = "Monochromatic stimuli 380-780 nm at 1 nm (CIE 1931 2°), each scaled to Y = " +
                      format_shortest(spectrum_set_luminance);
    for (int nm = 380; nm <= 780; ++nm) {
        const Xyz m = monochromatic_xyz(nm);
        const double k = spectrum_set_luminance / m.Y;
        set.colors.push_back({m.X * k, spectrum_set_luminance, m.Z * k});
    }
    return set;
}

ColorSet rec2020_color_set(const RgbSpace& destination, int steps) {
    if (steps < 2 || steps > 1000) {
        throw Error("rec2020 set: " + std::to_string(steps) + " steps per axis; valid: 2 to 1000");
    }
    ColorSet set;
    set.name = "rec2020";
    set.description = "Linear Rec.2020 on a " + std::to_string(steps) + "×" + std::to_string(steps) +
                      "×" + std::to_string(steps) + " grid over [0, 1]³ (surface and interior)";
    const RgbSpace& source = rec2020();
    const Mat3 m = adaptation_to(source.white(), destination) * source.to_xyz_matrix();
    const double step = 1.0 / (steps - 1);
    for (int r = 0; r < steps; ++r) {
        for (int g = 0; g < steps; ++g) {
            for (int b = 0; b < steps; ++b) set.colors.push_back(xyz(m * Vec3{r * step, g * step, b * step}));
        }
    }
    return set;
}

ColorSet union_color_set(std::span<const ColorSet> sets, std::string name) {
    ColorSet all;
    all.name = std::move(name);
    all.description = "The union of ";
    for (std::size_t i = 0; i < sets.size(); ++i) {
        all.description += (i == 0 ? "" : i + 1 == sets.size() ? " and " : ", ") + sets[i].name;
        for (ColorRamp ramp : sets[i].ramps) {
            ramp.first += all.colors.size();
            all.ramps.push_back(std::move(ramp));
        }
        all.colors.insert(all.colors.end(), sets[i].colors.begin(), sets[i].colors.end());
    }
    return all;
}

}  // namespace irid
