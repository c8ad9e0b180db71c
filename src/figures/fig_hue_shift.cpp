// hue-shift: the hue change of the spectrum's colours, clipped into sRGB at one luminance, against
// wavelength, one line per clip method (Smits 1990, §4.3.4 clips the spectrum at a constant
// luminance; Figure 11 compares three of the methods on it).

#include <irid/color/rgb.h>
#include <irid/error.h>

#include "figure_support.h"
#include "film_clip_data.h"
#include "plot.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace irid::figures::detail {

HueMeasure parse_hue_measure(std::string_view name) {
    if (name == "oklab") return HueMeasure::oklab;
    if (name == "luv") return HueMeasure::luv;
    if (name == "lab") return HueMeasure::lab;
    throw Error("hue measure '" + std::string(name) + "' is unknown; valid: oklab, luv, lab");
}

std::string hue_measure_label(HueMeasure hue) {
    switch (hue) {
        case HueMeasure::oklab: return "Oklab h";
        case HueMeasure::luv: return "CIELUV h_uv";
        case HueMeasure::lab: return "CIELAB h_ab";
    }
    return "";
}

double hue_shift_of(const ClipColorAnalysis& c, HueMeasure hue) noexcept {
    switch (hue) {
        case HueMeasure::oklab: return c.hue_shift_oklab;
        case HueMeasure::luv: return c.hue_shift_uv;
        case HueMeasure::lab: return c.hue_shift_ab;
    }
    return c.hue_shift_oklab;
}

const ClipStatistics& hue_statistics_of(const HueShiftStatistics& s, HueMeasure hue) noexcept {
    switch (hue) {
        case HueMeasure::oklab: return s.oklab;
        case HueMeasure::luv: return s.uv;
        case HueMeasure::lab: return s.ab;
    }
    return s.oklab;
}

HueShiftData hue_shift_data(std::span<const ClipMethod> methods, HueMeasure hue, double luminance) {
    HueShiftData data;
    data.luminance = luminance;
    data.hue = hue;
    const std::vector<SpectrumHueSeries> series = spectrum_hue_series(Gamut(srgb()), methods, luminance);
    for (const SpectrumHueSeries& s : series) {
        if (data.wavelength_nm.empty()) data.wavelength_nm = s.wavelength_nm;
        HueShiftCurve curve;
        curve.method = s.analysis.method;
        for (const ClipColorAnalysis& c : s.analysis.colors) curve.shift_deg.push_back(hue_shift_of(c, hue));
        // Every colour of the spectrum is out of sRGB, so the summary covers the whole curve.
        curve.abs_shift = hue_statistics_of(s.analysis.summary.hue, hue);
        data.curves.push_back(std::move(curve));
    }
    return data;
}

namespace {

/// The default curves: every method but smits-xyz and luv-lightness-hue, which give smits'
/// colours (to 3e-15, docs/GAMUT.md) and so draw the same curve; methods=all adds them.
std::string default_methods() {
    std::vector<std::string> names;
    for (const ClipMethod m : clip_methods()) {
        if (m != ClipMethod::smits_xyz && m != ClipMethod::luv_lightness_hue) names.emplace_back(clip_method_name(m));
    }
    return join(names, ",");
}

/// The methods of an option value ("all" or names), in the order given, without repeats.
std::vector<ClipMethod> parse_methods(const Options& options) {
    std::vector<ClipMethod> methods;
    for (const std::string& name : options.list("methods", default_methods())) {
        if (name == "all") {
            for (const ClipMethod m : clip_methods()) {
                if (std::find(methods.begin(), methods.end(), m) == methods.end()) methods.push_back(m);
            }
            continue;
        }
        ClipMethod m{};
        try {
            m = parse_clip_method(name);
        } catch (const Error&) {
            std::vector<std::string> names{"all"};
            for (const ClipMethod c : clip_methods()) names.emplace_back(clip_method_name(c));
            options.fail("methods", name, "unknown clip method", join(names, ", "));
        }
        if (std::find(methods.begin(), methods.end(), m) == methods.end()) methods.push_back(m);
    }
    return methods;
}

}  // namespace

FigureResult draw_hue_shift(const FigureRequest& request) {
    const Options options(request, {"hue", "methods", "luminance"});
    const std::string hue_name = options.choice("hue", {"oklab", "luv", "lab"}, "oklab");
    const HueMeasure hue = parse_hue_measure(hue_name);
    const std::vector<ClipMethod> methods = parse_methods(options);
    // Y in (0, 1): at 0 and 1 every method returns black or white.
    const double luminance = options.number("luminance", spectrum_set_luminance, 0.01, 0.99);

    const HueShiftData data = hue_shift_data(methods, hue, luminance);

    double extreme = 0.0;
    for (const HueShiftCurve& c : data.curves) extreme = std::max(extreme, c.abs_shift.max);
    const double limit = nice_range(-std::max(extreme, 1.0) * 1.05, std::max(extreme, 1.0) * 1.05, 8).second;

    Canvas canvas(image_format_for(request.output), request.width_px, request.height_px);
    const double fs = 12.0 * canvas.scale();
    std::vector<std::string> labels;
    double widest = 0.0;
    for (const HueShiftCurve& c : data.curves) {
        labels.emplace_back(clip_method_name(c.method));
        widest = std::max(widest, canvas.measure_text(labels.back(), TextStyle{.size = fs}).width);
    }
    PlotOptions plot_options;
    plot_options.right_reserve = widest + 4.6 * fs;
    Axis x{.min = 380.0, .max = 780.0, .title = "wavelength λ (nm)"};
    const std::string y_title = hue == HueMeasure::oklab ? "Oklab hue change Δh (degrees)"
                                : hue == HueMeasure::luv ? "CIELUV hue change Δh_uv (degrees)"
                                                         : "CIELAB hue change Δh_ab (degrees)";
    Axis y{.min = -limit, .max = limit, .title = y_title};
    Plot plot(canvas, page_area(canvas), x, y,
              "Hue change of the spectrum clipped into sRGB at Y = " + shortest(luminance) + " (" +
                  hue_measure_label(hue) + ")",
              plot_options);
    plot.hline(0.0, {palette::grey, std::max(0.6, canvas.scale()), Dash::solid});

    // Methods that give the same colours (smits, smits-xyz and luv-lightness-hue) overlap: the
    // later ones are drawn thinner and dashed so that the earlier stay visible. The palette has 8
    // colours; from the ninth curve on the dash moves on by one more, so that no two of the first
    // 32 curves share both colour and dash.
    static constexpr Dash dashes[] = {Dash::solid, Dash::dashed, Dash::dotted, Dash::dash_dot};
    FigureResult result;
    for (std::size_t k = 0; k < data.curves.size(); ++k) {
        const HueShiftCurve& c = data.curves[k];
        const LineStyle style{series_color(k), (k < 4 ? 2.6 - 0.4 * static_cast<double>(k) : 1.6) * canvas.scale(),
                              dashes[(k + k / 8) % 4]};
        plot.line(data.wavelength_nm, c.shift_deg, style, labels[k]);
        std::size_t undefined = 0;
        for (const double v : c.shift_deg) undefined += std::isnan(v) ? 1 : 0;
        std::string value = "mean " + fixed(c.abs_shift.mean, 2) + "°, p95 " + fixed(c.abs_shift.p95, 2) +
                            "°, max " + fixed(c.abs_shift.max, 2) + "°";
        if (undefined > 0) value += " (" + std::to_string(undefined) + " sent to white or black: no hue)";
        result.measurements.emplace_back(labels[k] + " |Δh|", value);
    }
    plot.finish(LegendPosition::outside_right);
    canvas.save(request.output);

    result.caption =
        "Signed change of the " + hue_measure_label(hue) +
        " hue, output minus input in degrees (wrapped to ±180°), of the monochromatic stimuli "
        "380–780 nm (CIE 1931 2°, every 1 nm) scaled to luminance Y = " + shortest(luminance) +
        " (white Y = 1) and clipped into linear sRGB [0, 1]³ by each method, as the thesis clips the "
        "spectrum at constant luminance (Smits 1990, §4.3.4). Gaps are wavelengths a method sends to "
        "white or black, which have no hue. smits, smits-xyz and luv-lightness-hue give the same "
        "colours (the last two are left out by default; methods=all shows them overlapping); in "
        "CIELUV they keep the hue exactly. aces-rgc is measured with clip=true, as a display gets "
        "it. Options: hue=" + hue_name +
        ", methods=" + join(labels, ",") + ", luminance=" + shortest(luminance) + ".";
    return result;
}

}  // namespace irid::figures::detail
