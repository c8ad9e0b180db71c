// ramps: the clip report's ramps (include/irid/gamut/report.h) at one luminance and one end,
// clipped into sRGB by each method and drawn as colour swatches: one panel per method, a row
// per Oklab hue, the steps from the grey (left) to the end (right). Banding shows as a step of
// colour where the ramp meets the boundary, collapse as a flat run to the right of it.

#include <irid/color/spaces.h>
#include <irid/error.h>
#include <irid/gamut/report.h>

#include "figure_data.h"
#include "figure_support.h"
#include "plot.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

namespace irid::figures::detail {
namespace {

/// The methods of the option value ("all" or names), in the order given, without repeats.
std::vector<ClipMethod> ramp_methods(const Options& options) {
    std::vector<ClipMethod> methods;
    for (const std::string& name : options.list("methods", "all")) {
        if (name == "all") {
            for (const ClipMethod m : clip_methods()) {
                if (std::find(methods.begin(), methods.end(), m) == methods.end())
                    methods.push_back(m);
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

/// Panel columns for n panels on the canvas: as many as keep a panel about 1.3 times as wide as
/// high.
int panel_columns(std::size_t n, double width, double height) {
    int best = 1;
    double best_error = 1e300;
    for (int cols = 1; cols <= static_cast<int>(n); ++cols) {
        const int rows = static_cast<int>((n + static_cast<std::size_t>(cols) - 1) /
                                          static_cast<std::size_t>(cols));
        const double aspect = (width / cols) / (height / rows);
        const double error = std::abs(std::log(aspect / 1.3));
        if (error < best_error) best = cols, best_error = error;
    }
    return best;
}

}  // namespace

FigureResult draw_ramps(const FigureRequest& request) {
    const Options options(request, {"luminance", "end", "methods", "boundary"});
    const double luminance = options.number("luminance", 0.3, 0.01, 0.99);
    const std::string end_name = options.choice("end", {"locus", "rec2020"}, "locus");
    const RampEnd end = end_name == "locus" ? RampEnd::locus : RampEnd::rec2020;
    const bool boundary = options.choice("boundary", {"on", "off"}, "on") == "on";
    const std::vector<ClipMethod> methods = ramp_methods(options);

    const RgbSpace& space = srgb();
    const Gamut gamut(space);
    const Xyz white = space.white_xyz();
    constexpr int hues = ramp_set_hues, steps = ramp_set_steps;

    // The input: one ramp per hue, as linear sRGB; where each leaves the gamut.
    std::vector<Rgb> input;
    std::vector<int> exit_step(hues, steps);
    const auto outside = std::make_unique<bool[]>(static_cast<std::size_t>(hues) * steps);
    for (int k = 0; k < hues; ++k) {
        const std::vector<Xyz> ramp = color_ramp(space, luminance, 360.0 * k / hues, end, steps);
        for (int i = 0; i < steps; ++i) {
            const Rgb c = space.from_xyz(ramp[static_cast<std::size_t>(i)]);
            const double lo = -1e-9, hi = 1.0 + 1e-9;  // the report's rule
            const bool out = c.r < lo || c.g < lo || c.b < lo || c.r > hi || c.g > hi || c.b > hi;
            outside[static_cast<std::size_t>(k * steps + i)] = out;
            if (out && exit_step[static_cast<std::size_t>(k)] == steps)
                exit_step[static_cast<std::size_t>(k)] = i;
            input.push_back(c);
        }
    }

    Canvas canvas(image_format_for(request.output), request.width_px, request.height_px);
    const double fs = 12.0 * canvas.scale();
    const Rect page = page_area(canvas);
    const std::string title =
        "Ramps at Y = " + shortest(luminance) + " from the grey to " +
        (end == RampEnd::locus ? "the spectral locus" : "the Rec.2020 boundary") +
        ", clipped into sRGB by each method (rows: Oklab hue)";
    canvas.text(
        {page.x + page.width / 2.0, page.y + fs}, title,
        TextStyle{
            .size = fs * 1.1, .bold = true, .halign = HAlign::center, .valign = VAlign::middle});
    const double top = page.y + 2.2 * fs;
    const int cols = panel_columns(methods.size(), page.width, page.bottom() - top);
    const int rows = static_cast<int>((methods.size() + static_cast<std::size_t>(cols) - 1) /
                                      static_cast<std::size_t>(cols));
    const double panel_w = page.width / cols, panel_h = (page.bottom() - top) / rows;
    const double small =
        std::max(7.0 * canvas.scale(), std::min(10.0 * canvas.scale(), panel_h / 12.0));

    FigureResult result;
    for (std::size_t p = 0; p < methods.size(); ++p) {
        const ClipMethod method = methods[p];
        const GamutClipper clipper = report_clipper(method, gamut);
        const std::vector<Rgb> clipped = clip_colors_batch(clipper, input);

        // The numbers of the clip report on these ramps (CIELAB relative to sRGB's white).
        std::vector<Lab> lab;
        lab.reserve(clipped.size());
        for (const Rgb& c : clipped) lab.push_back(xyz_to_lab(space.to_xyz(c), white));
        double banding_sum = 0.0, banding_max = 0.0, collapse_sum = 0.0;
        int collapse_count = 0;
        for (int k = 0; k < hues; ++k) {
            const std::size_t first = static_cast<std::size_t>(k) * steps;
            const auto ramp = std::span<const Lab>(lab).subspan(first, steps);
            const double b = ramp_banding(ramp);
            banding_sum += b;
            banding_max = std::max(banding_max, b);
            if (const auto c =
                    ramp_collapse(ramp, std::span<const bool>(outside.get() + first, steps))) {
                collapse_sum += *c;
                ++collapse_count;
            }
        }
        const std::string name(clip_method_name(method));
        const double banding_mean = banding_sum / hues;
        result.measurements.emplace_back(
            name, "banding mean " + fixed(banding_mean, 2) + ", max " + fixed(banding_max, 2) +
                      (collapse_count > 0 ? ", collapse " + fixed(collapse_sum / collapse_count, 3)
                                          : std::string()));

        // Row k of the raster is hue k (0° at the bottom); column i is step i.
        std::vector<Color> colors;
        colors.reserve(clipped.size());
        for (const Rgb& c : clipped) colors.push_back(display_color(c));
        const int col = static_cast<int>(p) % cols, row = static_cast<int>(p) / cols;
        const Rect area{page.x + col * panel_w, top + row * panel_h, panel_w, panel_h};
        Axis x{.min = 0.0,
               .max = static_cast<double>(steps),
               .ticks = {{0.0, "grey"}, {static_cast<double>(steps), "end"}},
               .grid = false};
        Axis y{.min = 0.0,
               .max = 360.0,
               .ticks = {{7.5, "0°"}, {97.5, "90°"}, {187.5, "180°"}, {277.5, "270°"}},
               .grid = false};
        Plot plot(canvas, area, x, y, name, PlotOptions{.font_size = small});
        plot.raster(0.0, steps, 0.0, 360.0, steps, hues, colors);
        if (boundary) {
            // Where each hue's input leaves sRGB: a thin mark at the left edge of that step.
            const LineStyle mark{with_alpha(palette::black, 0.75), std::max(0.8, canvas.scale()),
                                 Dash::solid};
            for (int k = 0; k < hues; ++k) {
                const int e = exit_step[static_cast<std::size_t>(k)];
                if (e >= steps) continue;
                const double y0 = 15.0 * k + 3.0, y1 = 15.0 * k + 12.0;
                plot.line(
                    std::vector<Point>{{static_cast<double>(e), y0}, {static_cast<double>(e), y1}},
                    mark);
            }
        }
        plot.finish(LegendPosition::none);
    }
    canvas.save(request.output);

    std::vector<std::string> names;
    for (const ClipMethod m : methods) names.emplace_back(clip_method_name(m));
    result.caption =
        "The clip report's ramps (irid clip-report --set ramps; include/irid/gamut/report.h) at "
        "luminance Y = " +
        shortest(luminance) +
        ": for each of 24 Oklab hues (rows, 0° at the "
        "bottom, every 15°), 256 steps at constant Y in a straight line from the grey of that "
        "luminance (left) to " +
        (end == RampEnd::locus ? std::string("the spectral locus")
                               : std::string("the Rec.2020 boundary")) +
        " (right), evenly spaced in CIEDE2000, clipped into sRGB by each method through the batch "
        "API (aces-rgc with clip=true) and encoded as sRGB. " +
        (boundary ? "The dark marks are where each ramp leaves sRGB. " : "") +
        "A hard clip shows a sharp knee there and a flat run after it (collapse: distinct inputs, "
        "one output); a soft one starts bending before it. The measurements give each method's "
        "banding (per ramp the largest ΔE2000 between neighbouring outputs over their mean, 1 = "
        "even; mean and max over the 24 ramps) and collapse (the share of out-of-gamut steps "
        "within ΔE2000 0.5 of the next). Options: luminance=" +
        shortest(luminance) + ", end=" + end_name + ", methods=" + join(names, ",") +
        ", boundary=" + (boundary ? "on" : "off") + ".";
    return result;
}

}  // namespace irid::figures::detail
