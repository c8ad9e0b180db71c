// Figure 2 of Smits 1990: the colour-matching functions of three monochromatic primaries
// (645, 526, 444 nm), with the negative lobes no real primaries avoid.

#include <irid/color/spectrum.h>
#include <irid/error.h>

#include "figure_data.h"
#include "figure_support.h"
#include "plot.h"

#include <algorithm>
#include <array>

namespace irid::figures::detail {

std::vector<Series> primary_cmf_series(const PrimaryMatchingFunctions& p) {
    const std::array<const DenseSpectrum*, 3> functions{&p.r, &p.g, &p.b};
    const std::array<double, 3> nm{p.red_nm, p.green_nm, p.blue_nm};
    const std::array<const char*, 3> names{"r̄", "ḡ", "b̄"};
    std::vector<Series> out;
    for (std::size_t k = 0; k < 3; ++k) {
        Series s{std::string(names[k]) + " (" + shortest(nm[k]) + " nm)", {}, {}};
        s.x.reserve(dense_sample_count);
        s.y.reserve(dense_sample_count);
        for (int i = 0; i < dense_sample_count; ++i) {
            s.x.push_back(DenseSpectrum::wavelength_nm(i));
            s.y.push_back((*functions[k])[i]);
        }
        out.push_back(std::move(s));
    }
    return out;
}

FigureResult draw_cmf_primaries(const FigureRequest& request) {
    const Options options(request, {"primaries", "observer"});
    std::vector<double> nm = options.numbers("primaries", "444,526,645", lambda_min_nm,
                                             lambda_max_nm, 3);
    std::sort(nm.begin(), nm.end());
    const std::string allowed_primaries =
        "three distinct wavelengths in nm, each in [360, 830], e.g. 444,526,645 (sorted: the "
        "shortest is blue, the longest red)";
    if (nm[1] - nm[0] < 1.0 || nm[2] - nm[1] < 1.0) {
        options.fail("primaries", options.text("primaries", ""),
                     "the wavelengths must differ by at least 1 nm", allowed_primaries);
    }
    const std::string observer_name = options.choice("observer", {"cie1931", "cie1964"}, "cie1931");
    const Observer observer =
        observer_name == "cie1931" ? Observer::cie1931_2deg : Observer::cie1964_10deg;
    PrimaryMatchingFunctions primaries;
    try {
        primaries = monochromatic_primary_matching_functions(nm[2], nm[1], nm[0], observer);
    } catch (const Error& e) {
        options.fail("primaries", options.text("primaries", "444,526,645"), e.what(),
                     allowed_primaries);
    }
    const std::vector<Series> curves = primary_cmf_series(primaries);

    // The plotted range is the visible one; the tables' tails beyond it are < 1e-3 of the peaks.
    constexpr double lo_nm = 380.0, hi_nm = 780.0;
    double top = 0.0, bottom = 0.0;
    for (const Series& s : curves) {
        for (std::size_t i = 0; i < s.x.size(); ++i) {
            if (s.x[i] < lo_nm || s.x[i] > hi_nm) continue;
            top = std::max(top, s.y[i]);
            bottom = std::min(bottom, s.y[i]);
        }
    }
    const auto [y_lo, y_hi] = nice_range(bottom * 1.05, top * 1.05, 8);

    Canvas canvas(image_format_for(request.output), request.width_px, request.height_px);
    const double s = canvas.scale();
    Plot plot(canvas, page_area(canvas),
              {.min = lo_nm, .max = hi_nm, .title = "wavelength λ (nm)"},
              {.min = y_lo, .max = y_hi, .title = "amount of each primary (relative)"},
              "Colour-matching functions of monochromatic primaries at " + shortest(nm[2]) +
                  ", " + shortest(nm[1]) + " and " + shortest(nm[0]) + " nm");
    plot.hline(0.0, {palette::dark_grey, 1.0 * s, Dash::solid});
    // Red, green and blue members of the Okabe–Ito palette.
    const std::array<Color, 3> colors{series_color(1), series_color(2), series_color(0)};
    const std::array<double, 3> at{primaries.red_nm, primaries.green_nm, primaries.blue_nm};
    FigureResult result;
    for (std::size_t k = 0; k < 3; ++k) {
        plot.vline(at[k], {with_alpha(colors[k], 0.6), 1.0 * s, Dash::dotted});
        plot.text({at[k], y_hi}, shortest(at[k]) + " nm", {.size = 0.9 * plot.font_size(),
                                                           .color = colors[k],
                                                           .halign = HAlign::center,
                                                           .valign = VAlign::top,
                                                           .halo = true});
        plot.line(curves[k].x, curves[k].y, {colors[k], 2.0 * s, Dash::solid}, curves[k].label);
        const Peak peak = series_peak(curves[k]);
        const Peak low = series_minimum(curves[k]);
        result.measurements.emplace_back(curves[k].label + " peak",
                                         fixed(peak.y, 3) + " at " + fixed(peak.x, 0) + " nm");
        result.measurements.emplace_back(curves[k].label + " most negative",
                                         fixed(low.y, 3) + " at " + fixed(low.x, 0) + " nm");
    }
    plot.finish(LegendPosition::top_right);
    canvas.save(request.output);

    const Peak red_low = series_minimum(curves[0]);
    result.caption =
        "Colour-matching functions r̄(λ), ḡ(λ), b̄(λ) of monochromatic primaries at " +
        shortest(nm[2]) + " (red), " + shortest(nm[1]) + " (green) and " + shortest(nm[0]) +
        " nm (blue), as in Smits 1990 Figure 2: the amounts of each primary that match a unit "
        "monochromatic stimulus, a linear transform of the " +
        (observer == Observer::cie1931_2deg ? std::string("CIE 1931 2°") : std::string("CIE 1964 10°")) +
        " x̄ȳz̄ (each function scaled so that equal amounts match the equal-energy white, with "
        "the 1 nm sum of ȳ). Where a function is negative (below the zero line) the stimulus "
        "cannot be matched by adding the three primaries; the deepest lobe is r̄ = " +
        fixed(red_low.y, 3) + " at " + fixed(red_low.x, 0) +
        " nm. Options: primaries=" + shortest(nm[0]) + "," + shortest(nm[1]) + "," +
        shortest(nm[2]) + ", observer=" + observer_name + ".";
    return result;
}

}  // namespace irid::figures::detail
