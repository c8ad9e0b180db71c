// Figure 11 of Smits 1990: the visible spectrum at one luminance, clipped into the display's
// gamut by each method, as horizontal strips.

#include <irid/color/measure.h>
#include <irid/color/spaces.h>
#include <irid/error.h>
#include <irid/gamut/batch.h>
#include <irid/gamut/report.h>

#include "figure_data.h"
#include "figure_support.h"
#include "plot.h"

#include <algorithm>
#include <cmath>

namespace irid::figures::detail {

std::vector<Rgb> equal_luminance_spectrum(const RgbSpace& space, double lo_nm, double hi_nm,
                                          double step_nm, double Y) {
    std::vector<Rgb> out;
    const int n = static_cast<int>(std::floor((hi_nm - lo_nm) / step_nm + 1e-9));
    for (int i = 0; i <= n; ++i) {
        const Xyz m = monochromatic_xyz(lo_nm + i * step_nm);
        const double scale = m.Y > 0.0 ? Y / m.Y : 0.0;
        out.push_back(space.from_xyz({m.X * scale, m.Y * scale, m.Z * scale}));
    }
    return out;
}

std::vector<Rgb> clip_colors_batch(const GamutClipper& clipper, std::span<const Rgb> colors) {
    std::vector<float> buffer;
    buffer.reserve(colors.size() * 3);
    for (const Rgb& c : colors) {
        buffer.push_back(static_cast<float>(c.r));
        buffer.push_back(static_cast<float>(c.g));
        buffer.push_back(static_cast<float>(c.b));
    }
    clip_batch(clipper, buffer, BatchOptions{.threads = 1, .simd = true});
    std::vector<Rgb> out;
    out.reserve(colors.size());
    for (std::size_t i = 0; i < colors.size(); ++i) {
        out.push_back({buffer[3 * i], buffer[3 * i + 1], buffer[3 * i + 2]});
    }
    return out;
}

std::vector<ClipMethod> spectrum_clip_default_methods() {
    std::vector<ClipMethod> out{ClipMethod::clamp, ClipMethod::smits, ClipMethod::luv_hue};
    for (const ClipMethod m : clip_methods()) {
        if (std::find(out.begin(), out.end(), m) == out.end()) out.push_back(m);
    }
    return out;
}

FigureResult draw_spectrum_clip(const FigureRequest& request) {
    const Options options(request, {"methods", "luminance"});
    std::vector<std::string> default_names;
    for (const ClipMethod m : spectrum_clip_default_methods()) {
        default_names.emplace_back(clip_method_name(m));
    }
    std::vector<ClipMethod> methods;
    for (const std::string& name : options.list("methods", join(default_names, ","))) {
        ClipMethod m{};
        try {
            m = parse_clip_method(name);
        } catch (const Error&) {
            options.fail("methods", options.text("methods", ""), "unknown method \"" + name + "\"",
                         "a comma-separated list of " + join(default_names, ", "));
        }
        if (std::find(methods.begin(), methods.end(), m) != methods.end()) {
            options.fail("methods", options.text("methods", ""), "method \"" + name + "\" twice",
                         "each method at most once");
        }
        methods.push_back(m);
    }
    /// The default luminance: bright enough to see every hue, low enough that the blues (the
    /// sRGB blue primary alone has Y = 0.0722) keep some chroma. Relative to the white, Y = 1.
    const double luminance = options.number("luminance", 0.2, 0.01, 0.99);
    constexpr double lo_nm = 380.0, hi_nm = 700.0, step_nm = 1.0;

    const Gamut gamut(srgb());
    const std::vector<Rgb> spectrum = equal_luminance_spectrum(srgb(), lo_nm, hi_nm, step_nm,
                                                               luminance);
    const Xyz white = srgb().white_xyz();

    Canvas canvas(image_format_for(request.output), request.width_px, request.height_px);
    const double n = static_cast<double>(methods.size());
    std::vector<Tick> labels;
    for (std::size_t k = 0; k < methods.size(); ++k) {
        // The first method on top.
        labels.push_back({n - 1.0 - static_cast<double>(k) + 0.5,
                          std::string(clip_method_name(methods[k]))});
    }
    Plot plot(canvas, page_area(canvas), {.min = lo_nm, .max = hi_nm, .title = "wavelength λ (nm)"},
              {.min = 0.0, .max = n, .ticks = labels, .grid = false},
              "The spectrum at luminance Y = " + shortest(luminance) +
                  ", clipped into sRGB by each method");
    FigureResult result;
    for (std::size_t k = 0; k < methods.size(); ++k) {
        // What a display gets: aces-rgc with clip=true, as in the clip report and for images.
        const GamutClipper clipper = report_clipper(methods[k], gamut);
        const std::vector<Rgb> clipped = clip_colors_batch(clipper, spectrum);
        std::vector<Color> colors;
        colors.reserve(clipped.size());
        double luminance_error = 0.0, hue_error = 0.0, worst_hue = 0.0;
        for (std::size_t i = 0; i < clipped.size(); ++i) {
            colors.push_back(display_color(clipped[i]));
            const Xyz before = srgb().to_xyz(spectrum[i]);
            const Xyz after = srgb().to_xyz(clipped[i]);
            luminance_error += std::abs(after.Y - before.Y) / before.Y;
            const double dh = hue_difference(luv_to_lch(xyz_to_luv(before, white)).h,
                                             luv_to_lch(xyz_to_luv(after, white)).h);
            hue_error += std::abs(dh);
            worst_hue = std::max(worst_hue, std::abs(dh));
        }
        const double row = n - 1.0 - static_cast<double>(k);
        // Half a step beyond the ends, so each wavelength's cell is centred on it.
        plot.color_strip(lo_nm - step_nm / 2.0, hi_nm + step_nm / 2.0, row + 0.08, row + 0.92,
                         colors);
        const double count = static_cast<double>(clipped.size());
        result.measurements.emplace_back(
            std::string(clip_method_name(methods[k])),
            "mean |ΔY|/Y " + fixed(100.0 * luminance_error / count, 2) + " %, mean |Δh_uv| " +
                fixed(hue_error / count, 2) + "°, max |Δh_uv| " + fixed(worst_hue, 1) + "°");
    }
    plot.finish(LegendPosition::none);
    canvas.save(request.output);

    std::vector<std::string> names;
    for (const ClipMethod m : methods) names.emplace_back(clip_method_name(m));
    result.caption =
        "The visible spectrum, 380–700 nm every 1 nm, as monochromatic colours of equal "
        "luminance Y = " + shortest(luminance) +
        " (relative to the D65 white, CIE 1931 observer), none of which sRGB can show, "
        "brought into the sRGB gamut by each clip method (one strip per method, through the "
        "batch API on float RGB; aces-rgc with clip=true) and encoded as sRGB, after Smits 1990 Figure 11 (discarding "
        "negative values = clamp; constant hue and lightness = smits; constant hue = "
        "luv-hue). The measurements give each method's mean relative luminance change and its "
        "CIELUV hue change over the spectrum. Options: methods=" + join(names, ",") +
        ", luminance=" + shortest(luminance) + ".";
    return result;
}

}  // namespace irid::figures::detail
