// Figure 4 of Smits 1990: the CIE chromaticity diagram with the spectral locus, the purple
// line and the gamut triangles of RGB spaces (in CIE 1931 xy or CIE 1976 u′v′).

#include <irid/color/spaces.h>
#include <irid/error.h>

#include "figure_data.h"
#include "figure_support.h"
#include "plot.h"

#include <cairo.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace irid::figures::detail {

Point diagram_point(const Xy& xy, Diagram diagram) noexcept {
    if (diagram == Diagram::xy) return {xy.x, xy.y};
    const UvPrime uv = xy_to_uv_prime(xy);
    return {uv.u, uv.v};
}

std::vector<Point> spectral_locus(Diagram diagram, double lo_nm, double hi_nm, double step_nm) {
    std::vector<Point> out;
    const int n = static_cast<int>(std::floor((hi_nm - lo_nm) / step_nm + 1e-9));
    for (int i = 0; i <= n; ++i) {
        out.push_back(diagram_point(spectral_locus_xy(lo_nm + i * step_nm), diagram));
    }
    if (lo_nm + n * step_nm < hi_nm - 1e-9) {
        out.push_back(diagram_point(spectral_locus_xy(hi_nm), diagram));
    }
    return out;
}

double polygon_area(std::span<const Point> polygon) noexcept {
    double twice = 0.0;
    for (std::size_t i = 0; i < polygon.size(); ++i) {
        const Point& a = polygon[i];
        const Point& b = polygon[(i + 1) % polygon.size()];
        twice += a.x * b.y - b.x * a.y;
    }
    return std::abs(twice) / 2.0;
}

bool inside_polygon(std::span<const Point> polygon, Point p) noexcept {
    bool inside = false;
    for (std::size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
        const Point& a = polygon[i];
        const Point& b = polygon[j];
        if ((a.y > p.y) != (b.y > p.y) && p.x < (b.x - a.x) * (p.y - a.y) / (b.y - a.y) + a.x) {
            inside = !inside;
        }
    }
    return inside;
}

std::vector<Point> gamut_triangle(const RgbSpace& space, Diagram diagram) {
    const RgbPrimaries& p = space.primaries();
    return {diagram_point(p.red, diagram), diagram_point(p.green, diagram),
            diagram_point(p.blue, diagram)};
}

Color chromaticity_fill_color(const Xy& xy, const GamutClipper& clipper) noexcept {
    const Rgb rgb = srgb().from_xyz(xy_to_xyz(xy, 1.0));
    const double peak = std::max({rgb.r, rgb.g, rgb.b});
    if (!(peak > 0.0)) return palette::black;
    return display_color(clipper.clip({rgb.r / peak, rgb.g / peak, rgb.b / peak}));
}

namespace {

/// The name of a white point when it is a standard one (to 5e-4 in xy), else its xy.
std::string white_name(const Xy& w) {
    struct Named {
        const char* name;
        Xy xy;
    };
    /// CIE 015:2018 Table 11.3 (D65, D50, A) and Table 11.4 (C), 2° observer.
    static constexpr std::array<Named, 4> known{{{"D65", {0.31272, 0.32903}},
                                                 {"D50", {0.34567, 0.35851}},
                                                 {"C", {0.31006, 0.31616}},
                                                 {"A", {0.44757, 0.40745}}}};
    for (const Named& k : known) {
        if (std::hypot(w.x - k.xy.x, w.y - k.xy.y) < 5e-4) return k.name;
    }
    std::string out = "(";  // appended, not "(" + ...: g++ 12 warns falsely there (-Wrestrict)
    out += fixed(w.x, 4);
    out += ", ";
    out += fixed(w.y, 4);
    out += ")";
    return out;
}

std::vector<std::string> rgb_space_names() {
    std::vector<std::string> names;
    for (const RgbSpace* s : builtin_rgb_spaces()) names.push_back(s->name());
    return names;
}

}  // namespace

FigureResult draw_chromaticity(const FigureRequest& request) {
    const Options options(request, {"spaces", "diagram", "fill"});
    const std::vector<std::string> space_items =
        options.list("spaces", "srgb,display-p3,rec2020");
    std::vector<const RgbSpace*> spaces;
    for (const std::string& item : space_items) {
        std::string name = item;
        // The command line's NAME-linear names the same gamut as NAME.
        if (name.size() > 7 && name.ends_with("-linear")) name.resize(name.size() - 7);
        const RgbSpace* space = find_rgb_space(name);
        if (space == nullptr) {
            options.fail("spaces", options.text("spaces", ""), "unknown RGB space \"" + item + "\"",
                         "a comma-separated list of " + join(rgb_space_names(), ", ") +
                             " (NAME-linear is the same gamut)");
        }
        if (std::find(spaces.begin(), spaces.end(), space) == spaces.end()) spaces.push_back(space);
    }
    const Diagram diagram = options.choice("diagram", {"xy", "uv"}, "xy") == "xy" ? Diagram::xy
                                                                                : Diagram::uv;
    const bool fill = options.choice("fill", {"colors", "none"}, "colors") == "colors";
    const std::string u = diagram == Diagram::xy ? "x" : "u′";
    const std::string v = diagram == Diagram::xy ? "y" : "v′";

    const std::vector<Point> locus = spectral_locus(diagram);
    const double locus_area = polygon_area(locus);

    std::vector<std::string> legend_labels{"spectral locus 360–830 nm", "purple line",
                                           "white point"};
    for (const RgbSpace* sp : spaces) legend_labels.push_back(sp->name());
    Canvas canvas(image_format_for(request.output), request.width_px, request.height_px);
    const double s = canvas.scale();
    // x from below 0 so that the labels of the locus' left side (490–510 nm) stay inside.
    const Axis x_axis{.min = diagram == Diagram::xy ? -0.06 : -0.04, .max = diagram == Diagram::xy ? 0.8 : 0.65,
                      .title = "chromaticity " + u};
    const Axis y_axis{.min = 0.0, .max = diagram == Diagram::xy ? 0.9 : 0.6,
                      .title = "chromaticity " + v};
    Plot plot(canvas, page_area(canvas), x_axis, y_axis,
              diagram == Diagram::xy ? "CIE 1931 xy chromaticity diagram"
                                     : "CIE 1976 u′v′ chromaticity diagram",
              {.equal_aspect = true,
               .right_reserve = Plot::outside_legend_width(canvas, legend_labels)});
    const Rect frame = plot.frame();

    std::vector<Point> locus_canvas;
    locus_canvas.reserve(locus.size());
    for (const Point& p : locus) locus_canvas.push_back(plot.to_canvas(p));

    const GamutClipper clipper(ClipMethod::smits, Gamut(srgb()));
    if (fill) {
        const int nx = std::clamp(static_cast<int>(frame.width / 1.5), 16, 700);
        const int ny = std::clamp(static_cast<int>(frame.height / 1.5), 16, 700);
        std::vector<Color> cells(static_cast<std::size_t>(nx) * ny);
        for (int j = 0; j < ny; ++j) {
            for (int i = 0; i < nx; ++i) {
                const Point p{x_axis.min + (i + 0.5) / nx * (x_axis.max - x_axis.min),
                              y_axis.min + (j + 0.5) / ny * (y_axis.max - y_axis.min)};
                Color c{0.0, 0.0, 0.0, 0.0};
                if (inside_polygon(locus, p)) {
                    const Xy xy = diagram == Diagram::xy ? Xy{p.x, p.y}
                                                         : uv_prime_to_xy({p.x, p.y});
                    c = with_alpha(chromaticity_fill_color(xy, clipper), 0.85);
                }
                cells[static_cast<std::size_t>(j) * nx + i] = c;
            }
        }
        cairo_t* cr = canvas.cairo();
        cairo_save(cr);
        cairo_move_to(cr, locus_canvas[0].x, locus_canvas[0].y);
        for (const Point& p : locus_canvas) cairo_line_to(cr, p.x, p.y);
        cairo_close_path(cr);
        cairo_clip(cr);
        plot.raster(x_axis.min, x_axis.max, y_axis.min, y_axis.max, nx, ny, cells, true);
        cairo_restore(cr);
    }

    // The locus, and the purple line closing it between its ends.
    plot.line(locus, {palette::black, 1.6 * s, Dash::solid}, "spectral locus 360–830 nm");
    const std::array<Point, 2> purple{locus.back(), locus.front()};
    plot.line(purple, {palette::dark_grey, 1.6 * s, Dash::dashed}, "purple line");

    // Wavelength ticks normal to the locus, pointing away from the D65 white.
    const Point white = plot.to_canvas(diagram_point({0.31272, 0.32903}, diagram));
    std::vector<double> labelled;
    for (int nm = 460; nm <= 620; nm += 10) labelled.push_back(nm);
    labelled.push_back(700.0);
    const TextStyle tick_text{.size = 0.85 * plot.font_size(), .color = palette::dark_grey};
    for (const double nm : labelled) {
        const Point p = plot.to_canvas(diagram_point(spectral_locus_xy(nm), diagram));
        const Point a = plot.to_canvas(diagram_point(spectral_locus_xy(nm - 1.0), diagram));
        const Point b = plot.to_canvas(diagram_point(spectral_locus_xy(nm + 1.0), diagram));
        double nx = -(b.y - a.y);
        double ny = b.x - a.x;
        const double length = std::hypot(nx, ny);
        if (!(length > 0.0)) continue;
        nx /= length;
        ny /= length;
        if (nx * (p.x - white.x) + ny * (p.y - white.y) < 0.0) {
            nx = -nx;
            ny = -ny;
        }
        const double tick = 6.0 * s;
        canvas.line(p, {p.x + tick * nx, p.y + tick * ny}, {palette::black, 1.2 * s, Dash::solid});
        TextStyle t = tick_text;
        t.halign = nx > 0.35 ? HAlign::left : (nx < -0.35 ? HAlign::right : HAlign::center);
        t.valign = ny > 0.35 ? VAlign::top : (ny < -0.35 ? VAlign::baseline : VAlign::middle);
        const double gap = tick + 3.0 * s;
        canvas.text({p.x + gap * nx, p.y + gap * ny}, fixed(nm, 0), t);
    }

    FigureResult result;
    result.measurements.emplace_back("spectral locus area (" + u + v + ")", fixed(locus_area, 4));
    std::vector<std::string> whites_done;
    for (std::size_t k = 0; k < spaces.size(); ++k) {
        const RgbSpace& space = *spaces[k];
        const Color color = series_color(k == 0 ? 0 : k + 1);  // skip vermillion near the reds
        const std::vector<Point> triangle = gamut_triangle(space, diagram);
        plot.polygon(triangle, with_alpha(color, 0.0), {color, 2.0 * s, Dash::solid},
                     space.name());
        plot.markers(triangle, {.shape = MarkerShape::circle, .size = 6.0 * s, .fill = color,
                                .stroke = palette::white, .stroke_width = 1.0 * s});
        const double area = polygon_area(triangle);
        result.measurements.emplace_back(
            space.name() + " triangle area (" + u + v + ")",
            fixed(area, 4) + " = " + fixed(100.0 * area / locus_area, 1) + " % of the locus");
        const std::string w = white_name(space.white());
        if (std::find(whites_done.begin(), whites_done.end(), w) == whites_done.end()) {
            whites_done.push_back(w);
            const Point wp = diagram_point(space.white(), diagram);
            plot.marker(wp, {.shape = MarkerShape::plus, .size = 10.0 * s, .fill = palette::black,
                             .stroke = palette::black, .stroke_width = 1.5 * s});
            plot.text(wp, "  " + w,
                      {.size = 0.85 * plot.font_size(), .valign = VAlign::top, .halo = true});
        }
    }
    plot.add_legend_marker("white point", {.shape = MarkerShape::plus, .size = 10.0 * s,
                                           .fill = palette::black, .stroke = palette::black,
                                           .stroke_width = 1.5 * s});
    plot.finish(LegendPosition::outside_right);
    canvas.save(request.output);

    std::vector<std::string> names;
    for (const RgbSpace* sp : spaces) names.push_back(sp->name());
    result.caption =
        std::string("The ") + (diagram == Diagram::xy ? "CIE 1931 xy" : "CIE 1976 u′v′") +
        " chromaticity diagram, as in Smits 1990 Figure 4: the spectral locus of the CIE 1931 "
        "2° observer (360–830 nm, ticks normal to it at 460–620 nm every 10 nm and at 700 nm), "
        "the purple line joining its ends, and the gamut triangles of " + join(names, ", ") +
        " with their white points. " +
        (fill ? "The inside of the locus is filled with approximate colours: each chromaticity "
                "at the luminance where its largest linear sRGB channel is 1, clipped into sRGB "
                "by the smits method (constant luminance, toward the grey), so colours outside "
                "the sRGB triangle are shown desaturated. "
              : "") +
        "Options: spaces=" + join(names, ",") + ", diagram=" +
        (diagram == Diagram::xy ? "xy" : "uv") + ", fill=" + (fill ? "colors" : "none") + ".";
    return result;
}

}  // namespace irid::figures::detail
