// film-error: how far the thesis' single-film model (Smits 1990, eq. 21/22 with the effective
// thickness of eq. 23–24) is from the exact Airy film, as a heat map of CIEDE2000 over thickness
// and angle of incidence (what irid film-error summarises).

#include <irid/color/difference.h>
#include <irid/color/measure.h>
#include <irid/color/numeric_table.h>
#include <irid/error.h>
#include <irid/optics/film.h>
#include <irid/optics/film_error_study.h>
#include <irid/optics/material.h>

#include "figure_support.h"
#include "film_clip_data.h"
#include "plot.h"

#include <algorithm>
#include <memory>
#include <cmath>
#include <numbers>
#include <string>

namespace irid::figures::detail {

SingleFilm film_by_name(std::string_view name) {
    const Material air = *find_material("air");
    const Material water = *find_material("water");
    if (name == "soap") return {air, water, air};
    if (name == "oil") return {air, *find_material("mineral-oil"), water};
    throw Error("film '" + std::string(name) + "' is unknown; valid: soap, oil");
}

FilmErrorGrid film_error_grid(const SingleFilm& film, const Colorimeter& colorimeter, double k,
                              double max_thickness_nm, double thickness_step_nm, double max_angle_deg,
                              double angle_step_deg) {
    if (!(thickness_step_nm > 0.0 && max_thickness_nm >= 0.0 && angle_step_deg > 0.0 && max_angle_deg >= 0.0 &&
          max_angle_deg < 90.0 && std::isfinite(max_thickness_nm) && std::isfinite(k) && k >= 0.0)) {
        throw Error("film error grid: steps must be > 0, thickness >= 0, angles in [0, 90) and K >= 0");
    }
    FilmErrorGrid g;
    g.k = k;
    // The nodes as thesis_error_study places them (thickness i · step, angle by repeated steps).
    const auto thickness_count =
        static_cast<std::size_t>(std::floor(max_thickness_nm / thickness_step_nm + 1e-9)) + 1;
    for (std::size_t i = 0; i < thickness_count; ++i) g.thickness_nm.push_back(thickness_step_nm * static_cast<double>(i));
    for (double angle = 0.0; angle <= max_angle_deg + 1e-9; angle += angle_step_deg) g.angle_deg.push_back(angle);

    g.delta_e.reserve(g.thickness_nm.size() * g.angle_deg.size());
    const ExactFilm exact_model(film.ambient, {{film.film, 0.0}}, film.substrate);
    const ThesisFilm thesis_model(film, 0.0, k);
    for (const double angle : g.angle_deg) {
        const double theta = angle * std::numbers::pi / 180.0;
        // Both models through irid/optics/film.h, each prepared once per angle.
        const std::unique_ptr<FilmAtAngle> exact_row = exact_model.at_angle(theta);
        const std::unique_ptr<FilmAtAngle> thesis_row = thesis_model.at_angle(theta);
        for (const double t : g.thickness_nm) {
            const Xyz exact = exact_row->color(t, colorimeter).xyz;
            const Xyz thesis = thesis_row->color(t, colorimeter).xyz;
            const double d = delta_e_2000_of(colorimeter, thesis, exact);
            if (d > g.max) {
                g.max = d;
                g.worst_thickness_nm = t;
                g.worst_angle_deg = angle;
            }
            g.delta_e.push_back(d);
        }
    }
    double sum = 0.0;
    for (const double d : g.delta_e) sum += d;
    g.mean = sum / static_cast<double>(g.delta_e.size());
    g.median = percentile(g.delta_e, 0.5);
    return g;
}

FigureResult draw_film_error(const FigureRequest& request) {
    const Options options(request, {"film", "k"});
    const std::string film_name = options.choice("film", {"soap", "oil"}, "soap");
    const std::string k_name = options.choice("k", {"matched", "1"}, "matched");
    const SingleFilm film = film_by_name(film_name);
    const Colorimeter colorimeter;  // D65, CIE 1931 2°, sRGB
    const double k = k_name == "matched" ? thesis_matched_k(film) : 1.0;

    constexpr double max_thickness = 1000.0, thickness_step = 5.0;
    constexpr double max_angle = 80.0, angle_step = 1.0;
    const FilmErrorGrid g = film_error_grid(film, colorimeter, k, max_thickness, thickness_step, max_angle, angle_step);

    // The colour scale runs from 0 to a nice value at or above the maximum.
    const double top = nice_range(0.0, std::max(g.max, 1.0), 6).second;
    const auto nx = static_cast<int>(g.thickness_nm.size());
    const auto ny = static_cast<int>(g.angle_deg.size());
    std::vector<Color> cells;
    cells.reserve(g.delta_e.size());
    for (const double d : g.delta_e) cells.push_back(sequential_color(d / top));

    Canvas canvas(image_format_for(request.output), request.width_px, request.height_px);
    const double s = canvas.scale();
    PlotOptions plot_options;
    plot_options.right_reserve = 110.0 * s;
    Axis x{.min = 0.0, .max = max_thickness, .title = "film thickness t (nm)"};
    Axis y{.min = 0.0, .max = max_angle, .title = "angle of incidence θ (degrees, in air)"};
    x.grid = false;
    y.grid = false;
    const std::string film_text = film_name == "soap" ? "soap film in air (air | water | air)"
                                                      : "mineral oil on water (air | mineral oil | water)";
    Plot plot(canvas, page_area(canvas), x, y,
              "ΔE2000 of the thesis' single-film model against the exact film: " + film_text, plot_options);
    // Each cell is centred on its grid node; the frame clips the half cells at the edges.
    plot.cell_grid(-0.5 * thickness_step, max_thickness + 0.5 * thickness_step, -0.5 * angle_step,
                   max_angle + 0.5 * angle_step, nx, ny, cells);
    plot.marker({g.worst_thickness_nm, g.worst_angle_deg},
                {MarkerShape::cross, 10.0 * s, palette::white, palette::white, 2.0 * s}, "");
    plot.finish(LegendPosition::none);
    const Rect& frame = plot.frame();
    draw_color_bar(canvas, {frame.right() + 18.0 * s, frame.y, 16.0 * s, frame.height}, 0.0, top, "ΔE2000",
                   [](double t) { return sequential_color(t); });
    canvas.save(request.output);

    FigureResult result;
    result.measurements = {
        {"K", fixed(k, 4) + (k_name == "matched" ? " (matched: |r01| + |r12| at normal incidence, 555 nm)" : " (as the thesis writes)")},
        {"samples", std::to_string(g.delta_e.size()) + " (" + std::to_string(nx) + " thicknesses × " + std::to_string(ny) + " angles)"},
        {"mean ΔE2000", fixed(g.mean, 3)},
        {"median ΔE2000", fixed(g.median, 3)},
        {"max ΔE2000", fixed(g.max, 3) + " at " + shortest(g.worst_thickness_nm) + " nm, " + shortest(g.worst_angle_deg) + "°"},
    };
    result.caption =
        "CIEDE2000 between the thesis' single-film reflectance (Smits 1990, eq. 21/22 with the effective "
        "thickness t n cos θ of eq. 23–24, K = " + fixed(k, 4) +
        (k_name == "matched" ? ", matched to the exact film's peak" : "") +
        ") and the exact Airy film (Fresnel amplitudes of both faces, all internal reflections, "
        "dispersion, unpolarised), for a " + film_text + ", at thickness 0–1000 nm every 5 nm and angle "
        "of incidence 0–80° every 1°; D65, CIE 1931 2°, CIELAB relative to D65's white. The cross marks the "
        "largest difference. Options: film=" + film_name + ", k=" + k_name + ".";
    return result;
}

}  // namespace irid::figures::detail
