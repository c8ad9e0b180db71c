#include <irid/color/measure.h>
#include <irid/color/numeric_table.h>
#include <irid/color/observer.h>
#include <irid/color/spaces.h>
#include <irid/error.h>
#include <irid/gamut/analysis.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

namespace irid {
namespace {

constexpr double degrees_per_radian = 180.0 / std::numbers::pi;
constexpr double nan = std::numeric_limits<double>::quiet_NaN();

/// Relative tolerances of the definitions at the top of analysis.h.
constexpr double gamut_tolerance = 1e-9;       // out of gamut, on a face, grey (× max)
constexpr double saturation_tolerance = 1e-9;  // lower / higher (× s_in)


/// |Δh| of the three measures of a group of colours, collected then summarised.
struct HueCollector {
    std::vector<double> uv, ab, oklab;

    void add(const ClipColorAnalysis& c) {
        if (!std::isnan(c.hue_shift_uv)) uv.push_back(std::abs(c.hue_shift_uv));
        if (!std::isnan(c.hue_shift_ab)) ab.push_back(std::abs(c.hue_shift_ab));
        if (!std::isnan(c.hue_shift_oklab)) oklab.push_back(std::abs(c.hue_shift_oklab));
    }
    [[nodiscard]] HueShiftStatistics statistics() const {
        return {summarize(uv), summarize(ab), summarize(oklab)};
    }
};

/// Pearson's r of the pairs (x, y); NaN for fewer than two pairs or a constant variable.
double correlation(const std::vector<double>& x, const std::vector<double>& y) noexcept {
    const std::size_t n = x.size();
    if (n < 2) return nan;
    double mx = 0.0, my = 0.0;
    for (std::size_t i = 0; i < n; ++i) mx += x[i], my += y[i];
    mx /= static_cast<double>(n);
    my /= static_cast<double>(n);
    double sxx = 0.0, syy = 0.0, sxy = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        const double dx = x[i] - mx, dy = y[i] - my;
        sxx += dx * dx;
        syy += dy * dy;
        sxy += dx * dy;
    }
    // A variable constant to rounding has no direction to correlate.
    const double scale_x = std::max(std::abs(mx), 1.0), scale_y = std::max(std::abs(my), 1.0);
    if (sxx <= 1e-24 * scale_x * scale_x * static_cast<double>(n) ||
        syy <= 1e-24 * scale_y * scale_y * static_cast<double>(n)) {
        return nan;
    }
    return sxy / std::sqrt(sxx * syy);
}

bool outside(const Rgb& c, double max) noexcept {
    const double lo = -gamut_tolerance * max, hi = (1.0 + gamut_tolerance) * max;
    return !(c.r >= lo && c.g >= lo && c.b >= lo && c.r <= hi && c.g <= hi && c.b <= hi);
}

double channel(const Rgb& c, int i) noexcept { return i == 0 ? c.r : i == 1 ? c.g : c.b; }

}  // namespace

std::string gamut_face_name(GamutFace face) {
    static constexpr const char* names[] = {"r", "g", "b"};
    const int ch = std::clamp(face.channel, 0, 2);
    return std::string(names[ch]) + (face.upper ? "=max" : "=0");
}

double face_angle_to_constant_y_deg(const RgbSpace& space, int channel) {
    if (channel < 0 || channel > 2) {
        throw Error("face angle: channel " + std::to_string(channel) + " must be 0 (r), 1 (g) or 2 (b)");
    }
    // The face's normal is the channel's row of XYZ → RGB; Y = const has the normal (0, 1, 0).
    const Vec3& n = space.from_xyz_matrix()[channel];
    const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    const double cosine = std::min(1.0, std::abs(n[1]) / length);
    return std::acos(cosine) * degrees_per_radian;
}

std::array<double, 3> face_angles_to_constant_y_deg(const RgbSpace& space) {
    return {face_angle_to_constant_y_deg(space, 0), face_angle_to_constant_y_deg(space, 1),
            face_angle_to_constant_y_deg(space, 2)};
}

ClipAnalysis analyse_clip(const ColorSet& set, const Gamut& gamut, ClipMethod method) {
    if (set.colors.empty()) throw Error("clip analysis: the set '" + set.name + "' is empty");
    const RgbSpace& space = gamut.space();
    const double max = gamut.max();
    const double scale = 1.0 / max;
    const std::size_t n = set.colors.size();
    const GamutClipper clipper = report_clipper(method, gamut);  // as the clip report: aces-rgc clipped
    const AppearanceMeter meter(space.white());
    const std::array<double, 3> angles = face_angles_to_constant_y_deg(space);

    ClipAnalysis result;
    result.method = method;
    result.set_name = set.name;
    result.destination = space.name();
    result.max = max;
    result.colors.resize(n);

    const auto relative = [scale](const Xyz& c) { return Xyz{c.X * scale, c.Y * scale, c.Z * scale}; };
    const double tolerance = gamut_tolerance * max;
    for (std::size_t i = 0; i < n; ++i) {
        ClipColorAnalysis& a = result.colors[i];
        a.rgb_in = space.from_xyz(set.colors[i]);
        const Xyz xyz_in = space.to_xyz(a.rgb_in);
        Xyz xyz_out;
        if (method == ClipMethod::smits_xyz) {
            xyz_out = clipper.clip_xyz(xyz_in);
            a.rgb_out = space.from_xyz(xyz_out);
        } else {
            a.rgb_out = clipper.clip(a.rgb_in);
            xyz_out = space.to_xyz(a.rgb_out);
        }
        a.xyz_in = relative(xyz_in);
        a.xyz_out = relative(xyz_out);
        a.out_of_gamut = outside(a.rgb_in, max);

        const Appearance in = meter(a.xyz_in), out = meter(a.xyz_out);
        a.delta_l_ab = out.lab.L - in.lab.L;
        a.delta_l_uv = out.l_uv - in.l_uv;
        a.saturation_in = in.saturation_uv;
        a.saturation_out = out.saturation_uv;
        const Rgb& o = a.rgb_out;
        const bool grey = std::abs(o.r - o.g) <= tolerance && std::abs(o.g - o.b) <= tolerance &&
                          std::abs(o.b - o.r) <= tolerance;
        a.hue_shift_uv = in.c_uv > clip_report_min_chroma_uv && !grey ? hue_difference(in.h_uv, out.h_uv) : nan;
        a.hue_shift_ab = in.c_ab > clip_report_min_chroma_ab && !grey ? hue_difference(in.h_ab, out.h_ab) : nan;
        a.hue_shift_oklab =
            in.c_ok > clip_report_min_chroma_oklab && !grey ? hue_difference(in.h_ok, out.h_ok) : nan;

        // The face: among the output's channels at a bound, the one whose bound the input crossed
        // farthest.
        double farthest = -std::numeric_limits<double>::infinity();
        a.face_angle_deg = nan;
        for (int ch = 0; ch < 3; ++ch) {
            const double v_out = channel(o, ch), v_in = channel(a.rgb_in, ch);
            for (const bool upper : {false, true}) {
                const double bound = upper ? max : 0.0;
                if (std::abs(v_out - bound) > tolerance) continue;
                ++a.faces_touched;
                const double beyond = upper ? v_in - max : -v_in;
                if (beyond > farthest) {
                    farthest = beyond;
                    a.on_face = true;
                    a.face = {ch, upper};
                }
            }
        }
        if (a.on_face) a.face_angle_deg = angles[static_cast<std::size_t>(a.face.channel)];
    }

    // The summary over the clipped colours.
    ClipClaimsSummary& s = result.summary;
    s.size = n;
    HueCollector all;
    std::array<HueCollector, gamut_face_count> by_face;
    const auto bin_count = static_cast<std::size_t>(std::ceil(90.0 / clip_analysis_angle_bin_deg - 1e-9));
    std::vector<HueCollector> by_bin(bin_count);
    std::vector<std::size_t> bin_colors(bin_count, 0);
    std::array<std::vector<double>, 3> corr_angle, corr_shift;
    for (std::size_t i = 0; i < n; ++i) {
        const ClipColorAnalysis& a = result.colors[i];
        if (!a.out_of_gamut) continue;
        ++s.clipped;
        s.max_abs_delta_l_ab = std::max(s.max_abs_delta_l_ab, std::abs(a.delta_l_ab));
        s.max_abs_delta_l_uv = std::max(s.max_abs_delta_l_uv, std::abs(a.delta_l_uv));
        if (a.saturation_out < a.saturation_in * (1.0 - saturation_tolerance)) {
            ++s.saturation_lower;
        } else {
            if (a.saturation_out > a.saturation_in * (1.0 + saturation_tolerance)) {
                ++s.saturation_higher;
            } else {
                ++s.saturation_equal;
            }
            s.saturation_exceptions.push_back(i);
        }
        all.add(a);
        const double shifts[3] = {a.hue_shift_uv, a.hue_shift_ab, a.hue_shift_oklab};
        for (int k = 0; k < 3; ++k) {
            if (std::isnan(shifts[k])) ++s.hue_undefined[static_cast<std::size_t>(k)];
        }
        if (a.faces_touched >= 2) ++s.on_edge;
        if (!a.on_face) continue;
        by_face[static_cast<std::size_t>(a.face.index())].add(a);
        ++s.faces[static_cast<std::size_t>(a.face.index())].count;
        const auto bin = std::min(static_cast<std::size_t>(a.face_angle_deg / clip_analysis_angle_bin_deg),
                                  bin_count - 1);
        by_bin[bin].add(a);
        ++bin_colors[bin];
        for (std::size_t k = 0; k < 3; ++k) {
            if (std::isnan(shifts[k])) continue;
            corr_angle[k].push_back(a.face_angle_deg);
            corr_shift[k].push_back(std::abs(shifts[k]));
        }
    }
    s.hue = all.statistics();
    for (int f = 0; f < gamut_face_count; ++f) {
        FaceHueStatistics& face = s.faces[static_cast<std::size_t>(f)];
        face.face = GamutFace::from_index(f);
        face.angle_deg = angles[static_cast<std::size_t>(face.face.channel)];
        face.hue = by_face[static_cast<std::size_t>(f)].statistics();
    }
    for (std::size_t b = 0; b < bin_count; ++b) {
        AngleBinHueStatistics bin;
        bin.min_deg = clip_analysis_angle_bin_deg * static_cast<double>(b);
        bin.max_deg = std::min(90.0, bin.min_deg + clip_analysis_angle_bin_deg);
        bin.hue = by_bin[b].statistics();
        bin.count = bin_colors[b];
        s.angle_bins.push_back(bin);
    }
    s.correlation_uv = correlation(corr_angle[0], corr_shift[0]);
    s.correlation_ab = correlation(corr_angle[1], corr_shift[1]);
    s.correlation_oklab = correlation(corr_angle[2], corr_shift[2]);
    return result;
}

ColorSet monochromatic_color_set(double luminance, double min_nm, double max_nm, double step_nm) {
    if (!(std::isfinite(luminance) && luminance > 0.0 && luminance <= 1e6)) {
        throw Error("monochromatic set: luminance " + format_shortest(luminance) + " must be in (0, 1e6]");
    }
    if (!(std::isfinite(min_nm) && std::isfinite(max_nm) && min_nm >= 360.0 && min_nm <= max_nm &&
          max_nm <= 830.0)) {
        throw Error("monochromatic set: wavelengths " + format_shortest(min_nm) + " to " +
                    format_shortest(max_nm) + " nm must satisfy 360 <= min <= max <= 830");
    }
    if (!(std::isfinite(step_nm) && step_nm > 0.0)) {
        throw Error("monochromatic set: step " + format_shortest(step_nm) + " nm must be > 0");
    }
    ColorSet set;
    set.name = "spectrum";
    set.description = "Monochromatic stimuli " + format_shortest(min_nm) + "-" + format_shortest(max_nm) +
                      " nm at " + format_shortest(step_nm) + " nm (CIE 1931 2°), each scaled to Y = " +
                      format_shortest(luminance);
    const auto count = static_cast<std::size_t>(std::floor((max_nm - min_nm) / step_nm + 1e-9)) + 1;
    for (std::size_t i = 0; i < count; ++i) {
        const double nm = min_nm + step_nm * static_cast<double>(i);
        const Xyz m = monochromatic_xyz(nm);
        const double k = luminance / m.Y;
        set.colors.push_back({m.X * k, luminance, m.Z * k});
    }
    return set;
}

std::vector<SpectrumHueSeries> spectrum_hue_series(const Gamut& gamut, std::span<const ClipMethod> methods,
                                                   double luminance) {
    const ColorSet set = monochromatic_color_set(luminance);
    std::vector<double> wavelengths;
    for (std::size_t i = 0; i < set.colors.size(); ++i) wavelengths.push_back(380.0 + static_cast<double>(i));
    std::vector<SpectrumHueSeries> series;
    for (const ClipMethod method : methods) series.push_back({wavelengths, analyse_clip(set, gamut, method)});
    return series;
}

}  // namespace irid
