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
#include <string>

namespace irid {
namespace {

constexpr Xy d65_xy{0.3127, 0.3290};

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

}  // namespace

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
    for (std::size_t i = 0; i < n; ++i) {
        rgb_in[i] = space.from_xyz(set.colors[i]);
        xyz_in[i] = space.to_xyz(rgb_in[i]);
        in[i] = meter(xyz_in[i]);
        const Rgb& c = rgb_in[i];
        const bool inside = c.r >= lo && c.g >= lo && c.b >= lo && c.r <= hi && c.g <= hi && c.b <= hi;
        if (!inside) ++report.out_of_gamut;
    }

    std::vector<Rgb> rgb_out(n);
    std::vector<Xyz> xyz_out(n);
    for (const ClipMethod method : clip_methods()) {
        const GamutClipper clipper(method, gamut);
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
        Collector delta_e, hue_lab, hue_ok, hue_uv, delta_y;
        double kept = 0.0;
        const double grey_tolerance = 1e-9 * max;
        for (std::size_t i = 0; i < n; ++i) {
            const Xyz out_xyz = xyz_form ? xyz_out[i] : space.to_xyz(rgb_out[i]);
            const Appearance out = meter(out_xyz);
            const Appearance& src = in[i];
            delta_e.add(delta_e_2000(src.lab, out.lab));
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
    return s;
}

}  // namespace irid
