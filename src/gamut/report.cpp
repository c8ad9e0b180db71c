// The clip report's measurements: every method over a set, against the input colour
// (docs/GAMUT.md, "The clip report").

#include "report_timing.h"

#include <irid/color/difference.h>
#include <irid/color/measure.h>
#include <irid/color/numeric_table.h>
#include <irid/error.h>
#include <irid/gamut/report.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>

namespace irid {

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
    const AppearanceMeter meter(gamut.space().white(), 1.0 / gamut.max());
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
        StatisticsCollector banding;
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
        StatisticsCollector delta_e, hue_lab, hue_ok, hue_uv, delta_y, in_gamut_moved;
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
                    hue_lab.add(std::abs(hue_difference(src.h_ab, out.h_ab)));
                }
                kept += out.c_ab / src.c_ab;
                ++m.chroma_kept_count;
            }
            if (src.c_ok > clip_report_min_chroma_oklab && !grey) hue_ok.add(std::abs(hue_difference(src.h_ok, out.h_ok)));
            if (src.c_uv > clip_report_min_chroma_uv && !grey) hue_uv.add(std::abs(hue_difference(src.h_uv, out.h_uv)));
        }
        m.delta_e2000 = delta_e.statistics();
        m.hue_lab = hue_lab.statistics();
        m.hue_oklab = hue_ok.statistics();
        m.hue_luv = hue_uv.statistics();
        m.delta_y = delta_y.statistics();
        if (m.chroma_kept_count > 0) m.chroma_kept = kept / static_cast<double>(m.chroma_kept_count);
        m.in_gamut_moved = in_gamut_moved.statistics();
        StatisticsCollector banding, collapse, collapse_relative;
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

        // Speed: rounds of whole passes over the set (report_timing.h).
        const ClipTiming timing = time_passes(clip_all, n, options.min_seconds);
        m.timed_colors = timing.colors;
        m.timed_seconds = timing.seconds;
        m.colors_per_second = timing.colors_per_second;
        // Read the outputs so the timed work has an observable result.
        volatile double sink = xyz_form ? xyz_out[n - 1].Y : rgb_out[n - 1].g;
        (void)sink;
        report.methods.push_back(m);
    }
    return report;
}

}  // namespace irid
