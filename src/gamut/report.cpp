#include <irid/color/adaptation.h>
#include <irid/color/difference.h>
#include <irid/color/numeric_table.h>
#include <irid/color/observer.h>
#include <irid/color/spaces.h>
#include <irid/error.h>
#include <irid/gamut/report.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <numbers>
#include <string>

namespace irid {
namespace {

constexpr Xy d65_xy{0.3127, 0.3290};

/// Pieces of the line on which a ramp's CIEDE2000 arc length is summed (color_ramp).
constexpr int ramp_arc_samples = 4096;

bool same_white(const Xy& a, const Xy& b) noexcept { return a.x == b.x && a.y == b.y; }

Vec3 v3(const Xyz& c) noexcept { return {c.X, c.Y, c.Z}; }
Xyz xyz(const Vec3& v) noexcept { return {v[0], v[1], v[2]}; }

/// |b − a| of two hue angles in degrees, in [0, 180].
double hue_shift(double a, double b) noexcept {
    double d = std::fmod(std::abs(b - a), 360.0);
    if (d > 180.0) d = 360.0 - d;
    return d;
}

/// Accumulates values for ClipStatistics.
class Collector {
public:
    void add(double v) { m_values.push_back(v); }
    [[nodiscard]] ClipStatistics statistics() {
        ClipStatistics s;
        s.count = m_values.size();
        if (m_values.empty()) return s;
        std::sort(m_values.begin(), m_values.end());
        double sum = 0.0;
        for (const double v : m_values) sum += v;
        s.mean = sum / static_cast<double>(s.count);
        s.max = m_values.back();
        // Nearest rank: the ⌈0.95 n⌉-th smallest (1-based).
        const auto rank = static_cast<std::size_t>(std::ceil(0.95 * static_cast<double>(s.count)));
        s.p95 = m_values[std::max<std::size_t>(rank, 1) - 1];
        return s;
    }

private:
    std::vector<double> m_values;
};

/// Everything measured about one colour, input or output.
struct Appearance {
    Lab lab;
    double c_ab = 0.0, h_ab = 0.0;
    double c_ok = 0.0, h_ok = 0.0;
    double c_uv = 0.0, h_uv = 0.0;
    double y = 0.0;
};

class Meter {
public:
    explicit Meter(const Gamut& gamut)
        : m_scale(1.0 / gamut.max()),
          m_white(gamut.space().white_xyz()),
          m_to_d65(same_white(gamut.space().white(), d65_xy)
                       ? Mat3::identity()
                       : adaptation_matrix(m_white, xy_to_xyz(d65_xy), ChromaticAdaptation::bradford)) {}

    [[nodiscard]] Appearance operator()(const Xyz& c) const noexcept {
        const Xyz n{c.X * m_scale, c.Y * m_scale, c.Z * m_scale};
        Appearance a;
        a.lab = xyz_to_lab(n, m_white);
        const LchAb lch = lab_to_lch(a.lab);
        a.c_ab = lch.C;
        a.h_ab = lch.h;
        const Oklch ok = oklab_to_oklch(xyz_to_oklab(xyz(m_to_d65 * v3(n))));
        a.c_ok = ok.C;
        a.h_ok = ok.h;
        const LchUv uv = luv_to_lch(xyz_to_luv(n, m_white));
        a.c_uv = uv.C;
        a.h_uv = uv.h;
        a.y = n.Y;
        return a;
    }

private:
    double m_scale;
    Xyz m_white;
    Mat3 m_to_d65;
};

/// XYZ relative to `from` white → relative to the destination's white (Bradford).
Mat3 adaptation_to(const Xy& from, const RgbSpace& destination) {
    if (same_white(from, destination.white())) return Mat3::identity();
    return adaptation_matrix(xy_to_xyz(from), destination.white_xyz(), ChromaticAdaptation::bradford);
}

std::string format(const char* pattern, double a) {
    std::array<char, 64> buffer{};
    std::snprintf(buffer.data(), buffer.size(), pattern, a);
    return buffer.data();
}

std::string format(const char* pattern, double a, double b) {
    std::array<char, 96> buffer{};
    std::snprintf(buffer.data(), buffer.size(), pattern, a, b);
    return buffer.data();
}

std::string format_rate(double per_second) {
    if (per_second >= 1e6) return format("%.3g M", per_second / 1e6);
    if (per_second >= 1e3) return format("%.3g k", per_second / 1e3);
    return format("%.3g", per_second);
}

/// "–" for a statistic over nothing, else the pattern applied to mean and max.
std::string format_or_dash(const char* pattern, const ClipStatistics& s) {
    return s.count == 0 ? std::string("–") : format(pattern, s.mean, s.max);
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

double ramp_banding(std::span<const Lab> lab) {
    if (lab.size() < 2) return 1.0;
    double sum = 0.0, largest = 0.0;
    for (std::size_t i = 0; i + 1 < lab.size(); ++i) {
        const double d = delta_e_2000(lab[i], lab[i + 1]);
        sum += d;
        largest = std::max(largest, d);
    }
    if (!(sum > 0.0)) return 1.0;
    return largest / (sum / static_cast<double>(lab.size() - 1));
}

std::optional<double> ramp_collapse(std::span<const Lab> lab, std::span<const bool> out_of_gamut,
                                    double threshold) {
    if (lab.size() != out_of_gamut.size()) throw Error("ramp collapse: the spans differ in size");
    std::size_t counted = 0, collapsed = 0;
    for (std::size_t i = 0; i + 1 < lab.size(); ++i) {
        if (!out_of_gamut[i]) continue;
        ++counted;
        if (delta_e_2000(lab[i], lab[i + 1]) <= threshold) ++collapsed;
    }
    if (counted == 0) return std::nullopt;
    return static_cast<double>(collapsed) / static_cast<double>(counted);
}

GamutClipper report_clipper(ClipMethod method, const Gamut& gamut) {
    return GamutClipper(method, gamut, display_clip_settings(method));
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

ClipReport measure_clip_report(const ColorSet& set, const Gamut& gamut, const ClipReportOptions& options) {
    if (set.colors.empty()) throw Error("clip report: the set '" + set.name + "' is empty");
    if (!(options.min_seconds >= 0.0 && options.min_seconds <= 60.0)) {
        throw Error("clip report: min_seconds " + format_shortest(options.min_seconds) +
                    " must be in [0, 60]");
    }
    const RgbSpace& space = gamut.space();
    const double max = gamut.max();
    const std::size_t n = set.colors.size();

    ClipReport report;
    report.set_name = set.name;
    report.set_description = set.description;
    report.destination = space.name();
    report.max = max;
    report.size = n;

    // The input colours: linear RGB of the destination, and XYZ recomputed from it.
    std::vector<Rgb> rgb_in(n);
    std::vector<Xyz> xyz_in(n);
    std::vector<Appearance> in(n);
    const Meter meter(gamut);
    const double lo = -1e-9 * max, hi = (1.0 + 1e-9) * max;
    const auto outside = std::make_unique<bool[]>(n);
    for (std::size_t i = 0; i < n; ++i) {
        rgb_in[i] = space.from_xyz(set.colors[i]);
        xyz_in[i] = space.to_xyz(rgb_in[i]);
        in[i] = meter(xyz_in[i]);
        const Rgb& c = rgb_in[i];
        const bool inside = c.r >= lo && c.g >= lo && c.b >= lo && c.r <= hi && c.g <= hi && c.b <= hi;
        outside[i] = !inside;
        if (!inside) ++report.out_of_gamut;
    }
    for (const ColorRamp& ramp : set.ramps) {
        if (ramp.size == 0 || ramp.first > n || ramp.size > n - ramp.first) {
            throw Error("clip report: a ramp of the set '" + set.name + "' (" + ramp.label +
                        ") lies outside its colours");
        }
    }
    report.ramps = set.ramps.size();
    std::vector<double> input_step;  // per ramp, the mean ΔE2000 between neighbouring inputs
    // The input ramps' own banding: what a method that changed nothing would score.
    {
        std::vector<Lab> lab(n);
        for (std::size_t i = 0; i < n; ++i) lab[i] = in[i].lab;
        Collector banding;
        for (const ColorRamp& ramp : set.ramps) {
            banding.add(ramp_banding(std::span<const Lab>(lab).subspan(ramp.first, ramp.size)));
        }
        report.input_banding = banding.statistics();
        for (const ColorRamp& ramp : set.ramps) {
            const auto steps = std::span<const Lab>(lab).subspan(ramp.first, ramp.size);
            double sum = 0.0;
            for (std::size_t i = 0; i + 1 < steps.size(); ++i) sum += delta_e_2000(steps[i], steps[i + 1]);
            input_step.push_back(steps.size() > 1 ? sum / static_cast<double>(steps.size() - 1) : 0.0);
        }
    }

    std::vector<Rgb> rgb_out(n);
    std::vector<Xyz> xyz_out(n);
    std::vector<Lab> lab_out(n);
    for (const ClipMethod method : clip_methods()) {
        const GamutClipper clipper = report_clipper(method, gamut);
        const bool xyz_form = method == ClipMethod::smits_xyz;
        const auto clip_all = [&] {
            if (xyz_form) {
                for (std::size_t i = 0; i < n; ++i) xyz_out[i] = clipper.clip_xyz(xyz_in[i]);
            } else {
                for (std::size_t i = 0; i < n; ++i) rgb_out[i] = clipper.clip(rgb_in[i]);
            }
        };

        // Accuracy.
        clip_all();
        MethodClipReport m;
        m.method = method;
        Collector delta_e, hue_lab, hue_ok, hue_uv, delta_y, in_gamut_moved;
        double kept = 0.0;
        const double grey_tolerance = 1e-9 * max;
        for (std::size_t i = 0; i < n; ++i) {
            const Xyz out_xyz = xyz_form ? xyz_out[i] : space.to_xyz(rgb_out[i]);
            const Appearance out = meter(out_xyz);
            const Appearance& src = in[i];
            const double de = delta_e_2000(src.lab, out.lab);
            delta_e.add(de);
            if (!outside[i]) in_gamut_moved.add(de);
            lab_out[i] = out.lab;
            delta_y.add(std::abs(out.y - src.y));
            // A grey of the destination (black and white included) has no hue to compare.
            const Rgb o = xyz_form ? space.from_xyz(out_xyz) : rgb_out[i];
            const bool grey = std::abs(o.r - o.g) <= grey_tolerance && std::abs(o.g - o.b) <= grey_tolerance &&
                              std::abs(o.b - o.r) <= grey_tolerance;
            if (src.c_ab > clip_report_min_chroma_ab) {
                if (grey) {
                    ++m.hue_undefined;
                } else {
                    hue_lab.add(hue_shift(src.h_ab, out.h_ab));
                }
                kept += out.c_ab / src.c_ab;
                ++m.chroma_kept_count;
            }
            if (src.c_ok > clip_report_min_chroma_oklab && !grey) hue_ok.add(hue_shift(src.h_ok, out.h_ok));
            if (src.c_uv > clip_report_min_chroma_uv && !grey) hue_uv.add(hue_shift(src.h_uv, out.h_uv));
        }
        m.delta_e2000 = delta_e.statistics();
        m.hue_lab = hue_lab.statistics();
        m.hue_oklab = hue_ok.statistics();
        m.hue_luv = hue_uv.statistics();
        m.delta_y = delta_y.statistics();
        if (m.chroma_kept_count > 0) m.chroma_kept = kept / static_cast<double>(m.chroma_kept_count);
        m.in_gamut_moved = in_gamut_moved.statistics();
        Collector banding, collapse, collapse_relative;
        for (std::size_t r = 0; r < set.ramps.size(); ++r) {
            const ColorRamp& ramp = set.ramps[r];
            const auto lab = std::span<const Lab>(lab_out).subspan(ramp.first, ramp.size);
            const auto out_of_gamut = std::span<const bool>(outside.get() + ramp.first, ramp.size);
            banding.add(ramp_banding(lab));
            if (const auto c = ramp_collapse(lab, out_of_gamut)) collapse.add(*c);
            const double relative = clip_report_relative_collapse * input_step[r];
            if (const auto c = ramp_collapse(lab, out_of_gamut, relative)) collapse_relative.add(*c);
        }
        m.banding = banding.statistics();
        m.collapse = collapse.statistics();
        m.collapse_relative = collapse_relative.statistics();

        // Speed: rounds of whole passes over the set, each round at least min_seconds / rounds
        // long; the median of the rounds' rates (robust to another process taking the CPU for a
        // moment on a shared machine).
        using clock = std::chrono::steady_clock;
        const int rounds = options.min_seconds > 0.0 ? clip_report_timing_rounds : 1;
        const double round_seconds = options.min_seconds / rounds;
        std::vector<double> rates;
        for (int round = 0; round < rounds; ++round) {
            const auto start = clock::now();
            std::size_t passes = 0;
            double elapsed = 0.0;
            do {
                clip_all();
                ++passes;
                elapsed = std::chrono::duration<double>(clock::now() - start).count();
            } while (elapsed < round_seconds);
            m.timed_colors += passes * n;
            m.timed_seconds += elapsed;
            // A pass too short for the clock's resolution: at least 1 ns per pass.
            rates.push_back(static_cast<double>(passes * n) / std::max(elapsed, 1e-9));
        }
        // Read the outputs so the timed work has an observable result.
        volatile double sink = xyz_form ? xyz_out[n - 1].Y : rgb_out[n - 1].g;
        (void)sink;
        std::sort(rates.begin(), rates.end());
        const std::size_t half = rates.size() / 2;
        m.colors_per_second = rates.size() % 2 == 1 ? rates[half] : 0.5 * (rates[half - 1] + rates[half]);
        report.methods.push_back(m);
    }
    return report;
}

std::string clip_report_markdown(const ClipReport& r) {
    std::string s = "Set " + r.set_name + ": " + std::to_string(r.size) + " colours, " +
                    std::to_string(r.out_of_gamut) + " out of the " + r.destination + " gamut" +
                    (r.max != 1.0 ? " [0, " + format_shortest(r.max) + "]³" : std::string()) + ". " +
                    r.set_description + ".\n\n";
    s += "| method | ΔE00 mean | ΔE00 p95 | ΔE00 max | hue° Lab mean / max | hue° OKLab mean / max "
         "| \\|ΔY\\| mean / max | chroma kept | colours/s |\n";
    s += "|---|---:|---:|---:|---:|---:|---:|---:|---:|\n";
    std::string undefined;
    for (const MethodClipReport& m : r.methods) {
        const std::string name(clip_method_name(m.method));
        s += "| " + name + " | " + format("%.2f", m.delta_e2000.mean) + " | " +
             format("%.2f", m.delta_e2000.p95) + " | " + format("%.2f", m.delta_e2000.max) + " | " +
             format("%.2f / %.2f", m.hue_lab.mean, m.hue_lab.max) + " | " +
             format("%.2f / %.2f", m.hue_oklab.mean, m.hue_oklab.max) + " | " +
             format("%.4f / %.4f", m.delta_y.mean, m.delta_y.max) + " | " +
             format("%.3f", m.chroma_kept) + " | " + format_rate(m.colors_per_second) + " |\n";
        if (m.hue_undefined > 0) {
            undefined += (undefined.empty() ? "" : ", ") + name + " " + std::to_string(m.hue_undefined);
        }
    }
    if (!undefined.empty()) {
        s += "\nColours with a hue clipped to a grey (white or black; no hue, so left out of the hue "
             "columns): " + undefined + ".\n";
    }
    const std::size_t inside = r.size - r.out_of_gamut;
    s += "\nGradients and in-gamut colours: ΔE00 of the " + std::to_string(inside) +
         " colours inside the gamut; banding (max / mean ΔE00 of neighbouring steps, 1 = even) and "
         "collapse (share of out-of-gamut steps within ΔE00 " + format_shortest(clip_report_collapse_delta_e) +
         " of the next; collapse ½ step: within half the ramp's mean input step instead) over " +
         std::to_string(r.ramps) + " ramps";
    s += r.ramps == 0 ? std::string(".\n\n")
                      : "; the input ramps' own banding is " +
                            format("%.2f / %.2f", r.input_banding.mean, r.input_banding.max) + ".\n\n";
    s += "| method | in-gamut ΔE00 mean / max | banding mean / max | collapse | collapse ½ step |\n";
    s += "|---|---:|---:|---:|---:|\n";
    for (const MethodClipReport& m : r.methods) {
        s += "| " + std::string(clip_method_name(m.method)) + " | " +
             format_or_dash("%.2f / %.2f", m.in_gamut_moved) + " | " +
             format_or_dash("%.2f / %.2f", m.banding) + " | " +
             (m.collapse.count == 0 ? std::string("–") : format("%.3f", m.collapse.mean)) + " | " +
             (m.collapse_relative.count == 0 ? std::string("–") : format("%.3f", m.collapse_relative.mean)) +
             " |\n";
    }
    return s;
}

}  // namespace irid
