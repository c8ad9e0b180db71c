// Figure 3 of Smits 1990: the CIE colour-matching functions x̄, ȳ, z̄.

#include <irid/color/spectrum.h>

#include "figure_data.h"
#include "figure_support.h"
#include "plot.h"

#include <algorithm>
#include <array>

namespace irid::figures::detail {

Peak series_peak(const Series& s) {
    Peak best{s.x.empty() ? 0.0 : s.x[0], s.y.empty() ? 0.0 : s.y[0]};
    for (std::size_t i = 1; i < s.y.size(); ++i) {
        if (s.y[i] > best.y) best = {s.x[i], s.y[i]};
    }
    return best;
}

Peak series_minimum(const Series& s) {
    Peak best{s.x.empty() ? 0.0 : s.x[0], s.y.empty() ? 0.0 : s.y[0]};
    for (std::size_t i = 1; i < s.y.size(); ++i) {
        if (s.y[i] < best.y) best = {s.x[i], s.y[i]};
    }
    return best;
}

std::vector<Series> cmf_xyz_series(Observer observer) {
    const ColorMatchingFunctions& cmf = color_matching_functions(observer);
    std::vector<Series> out{{"x̄", {}, {}}, {"ȳ", {}, {}}, {"z̄", {}, {}}};
    const std::array<const DenseSpectrum*, 3> functions{&cmf.x, &cmf.y, &cmf.z};
    for (std::size_t k = 0; k < 3; ++k) {
        out[k].x.reserve(dense_sample_count);
        out[k].y.reserve(dense_sample_count);
        for (int i = 0; i < dense_sample_count; ++i) {
            out[k].x.push_back(DenseSpectrum::wavelength_nm(i));
            out[k].y.push_back((*functions[k])[i]);
        }
    }
    return out;
}

FigureResult draw_cmf_xyz(const FigureRequest& request) {
    const Options options(request, {"observer"});
    const std::string which = options.choice("observer", {"cie1931", "cie1964", "both"}, "cie1931");
    std::vector<Observer> observers;
    if (which != "cie1964") observers.push_back(Observer::cie1931_2deg);
    if (which != "cie1931") observers.push_back(Observer::cie1964_10deg);

    std::vector<std::vector<Series>> curves;
    double top = 0.0;
    for (const Observer o : observers) {
        curves.push_back(cmf_xyz_series(o));
        for (const Series& s : curves.back()) top = std::max(top, series_peak(s).y);
    }

    Canvas canvas(image_format_for(request.output), request.width_px, request.height_px);
    Axis x{.min = lambda_min_nm, .max = lambda_max_nm, .title = "wavelength λ (nm)"};
    Axis y{.min = 0.0, .max = nice_range(0.0, top * 1.04, 8).second,
           .title = "tristimulus value (relative)"};
    Plot plot(canvas, page_area(canvas), x, y,
              which == "both" ? "CIE colour-matching functions: 1931 2° and 1964 10° observers"
              : which == "cie1931" ? "CIE 1931 2° colour-matching functions"
                                   : "CIE 1964 10° colour-matching functions");
    // Red, green and blue-ish members of the Okabe–Ito palette for x̄, ȳ, z̄.
    const std::array<Color, 3> colors{series_color(1), series_color(2), series_color(0)};
    FigureResult result;
    for (std::size_t o = 0; o < observers.size(); ++o) {
        const std::string suffix =
            observers.size() > 1 ? (observers[o] == Observer::cie1931_2deg ? " 1931 2°" : " 1964 10°")
                                 : "";
        for (std::size_t k = 0; k < 3; ++k) {
            const Series& s = curves[o][k];
            plot.line(s.x, s.y,
                      {colors[k], 2.0 * canvas.scale(), o == 0 ? Dash::solid : Dash::dashed},
                      s.label + suffix);
            const Peak p = series_peak(s);
            result.measurements.emplace_back(
                s.label + suffix + " peak",
                fixed(p.y, 4) + " at " + fixed(p.x, 0) + " nm");
        }
        const ColorMatchingFunctions& cmf = color_matching_functions(observers[o]);
        result.measurements.emplace_back(
            "Σ x̄, Σ ȳ, Σ z̄" + suffix + " (1 nm)",
            fixed(cmf.x.sum(), 3) + ", " + fixed(cmf.y.sum(), 3) + ", " + fixed(cmf.z.sum(), 3));
    }
    plot.finish(LegendPosition::top_right);
    canvas.save(request.output);

    result.caption =
        std::string("The colour-matching functions x̄(λ), ȳ(λ), z̄(λ) of the ") +
        (which == "both" ? "CIE 1931 2° (solid) and CIE 1964 10° (dashed) standard observers"
         : which == "cie1931" ? "CIE 1931 2° standard observer"
                              : "CIE 1964 10° supplementary standard observer") +
        " (CIE 015:2018 tables, 1 nm, 360–830 nm), as in Smits 1990 Figure 3: the tristimulus "
        "values of a unit monochromatic stimulus. All three are non-negative; ȳ is the "
        "luminous efficiency V(λ). Options: observer=" + which + ".";
    return result;
}

}  // namespace irid::figures::detail
