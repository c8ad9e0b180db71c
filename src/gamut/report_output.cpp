// The clip report's timing (rounds of whole passes, the median rate) and its Markdown tables.

#include "report_timing.h"

#include <irid/color/measure.h>
#include <irid/color/numeric_table.h>
#include <irid/gamut/report.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <string>

namespace irid {
namespace {

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

}  // namespace

ClipTiming time_passes(const std::function<void()>& pass, std::size_t colors, double min_seconds) {
    // Rounds of whole passes, each at least min_seconds / rounds long; the median of the
    // rounds' rates, robust to another process taking the CPU for a moment.
    using clock = std::chrono::steady_clock;
    const int rounds = min_seconds > 0.0 ? clip_report_timing_rounds : 1;
    const double round_seconds = min_seconds / rounds;
    ClipTiming t;
    std::vector<double> rates;
    for (int round = 0; round < rounds; ++round) {
        const auto start = clock::now();
        std::size_t passes = 0;
        double elapsed = 0.0;
        do {
            pass();
            ++passes;
            elapsed = std::chrono::duration<double>(clock::now() - start).count();
        } while (elapsed < round_seconds);
        t.colors += passes * colors;
        t.seconds += elapsed;
        // A pass too short for the clock's resolution: at least 1 ns per pass.
        rates.push_back(static_cast<double>(passes * colors) / std::max(elapsed, 1e-9));
    }
    t.colors_per_second = percentile(std::move(rates), 0.5);
    return t;
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
