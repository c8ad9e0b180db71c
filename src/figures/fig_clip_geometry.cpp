// Figure 10 of Smits 1990: the geometry of the clip. A slice of the RGB gamut at constant
// luminance, an out-of-gamut colour of that luminance, its neutral point (the grey of the same
// luminance), the line between them, and where the clip methods put the colour.

#include <irid/color/measure.h>
#include <irid/color/spaces.h>
#include <irid/error.h>
#include <irid/gamut/report.h>

#include "figure_data.h"
#include "figure_support.h"
#include "plot.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace irid::figures::detail {

std::vector<Rgb> luminance_slice(const Gamut& gamut, double Y) {
    const Vec3& lum = gamut.luminance_row();
    const double m = gamut.max();
    const double white = (lum[0] + lum[1] + lum[2]) * m;
    if (!(Y > 0.0 && Y < white)) return {};
    const auto luminance = [&](const Rgb& c) { return lum[0] * c.r + lum[1] * c.g + lum[2] * c.b; };
    // The 12 edges of the cube: pairs of corners that differ in one channel.
    std::vector<Rgb> points;
    for (int corner = 0; corner < 8; ++corner) {
        const Rgb a{(corner & 4) ? m : 0.0, (corner & 2) ? m : 0.0, (corner & 1) ? m : 0.0};
        for (const int bit : {4, 2, 1}) {
            if (corner & bit) continue;
            const int other = corner | bit;
            const Rgb b{(other & 4) ? m : 0.0, (other & 2) ? m : 0.0, (other & 1) ? m : 0.0};
            const double la = luminance(a);
            const double lb = luminance(b);
            // Half-open on one side, so that a plane through a corner gives that corner once.
            if (!((la <= Y && Y < lb) || (lb <= Y && Y < la))) continue;
            const double t = (Y - la) / (lb - la);
            points.push_back({a.r + t * (b.r - a.r), a.g + t * (b.g - a.g), a.b + t * (b.b - a.b)});
        }
    }
    // Duplicates (a plane through a corner meets its three edges at the corner itself).
    std::vector<Rgb> unique;
    for (const Rgb& p : points) {
        const bool seen = std::any_of(unique.begin(), unique.end(), [&](const Rgb& q) {
            return std::abs(p.r - q.r) + std::abs(p.g - q.g) + std::abs(p.b - q.b) < 1e-12 * m;
        });
        if (!seen) unique.push_back(p);
    }
    // Order around the polygon: by angle about the mean, in xy (a projective image of the
    // plane, so the order is the plane's).
    Xy centre{};
    std::vector<Xy> xy;
    for (const Rgb& p : unique) {
        xy.push_back(xyz_to_xy(gamut.space().to_xyz(p)));
        centre.x += xy.back().x / static_cast<double>(unique.size());
        centre.y += xy.back().y / static_cast<double>(unique.size());
    }
    std::vector<std::size_t> order(unique.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::sort(order.begin(), order.end(), [&](std::size_t i, std::size_t j) {
        return std::atan2(xy[i].y - centre.y, xy[i].x - centre.x) <
               std::atan2(xy[j].y - centre.y, xy[j].x - centre.x);
    });
    std::vector<Rgb> out;
    for (const std::size_t i : order) out.push_back(unique[i]);
    return out;
}

std::vector<ClipLanding> clip_landings(const Gamut& gamut, const Xyz& xyz,
                                       std::span<const ClipMethod> methods) {
    const RgbSpace& space = gamut.space();
    const Rgb input = space.from_xyz(xyz);
    const Xyz white = space.white_xyz();
    const double hue_in = luv_to_lch(xyz_to_luv(xyz, white)).h;
    std::vector<ClipLanding> out;
    for (const ClipMethod method : methods) {
        // aces-rgc with its final clip, as the report measures it: where a display lands it.
        const GamutClipper clipper = report_clipper(method, gamut);
        ClipLanding landing{method, clipper.clip(input), {}, 0.0};
        const Xyz clipped = space.to_xyz(landing.rgb);
        landing.xyy = xyz_to_xyy(clipped);
        landing.hue_shift_deg = hue_difference(hue_in, luv_to_lch(xyz_to_luv(clipped, white)).h);
        out.push_back(landing);
    }
    return out;
}

namespace {

std::vector<std::string> method_names() {
    std::vector<std::string> names;
    for (const ClipMethod m : clip_methods()) names.emplace_back(clip_method_name(m));
    return names;
}

}  // namespace

FigureResult draw_clip_geometry(const FigureRequest& request) {
    const Options options(request, {"method", "color", "space"});
    std::vector<std::string> method_choices = method_names();
    method_choices.emplace_back("all");
    const std::string method_name = options.choice("method", method_choices, "smits");
    std::vector<ClipMethod> methods;
    if (method_name == "all") {
        methods.assign(clip_methods().begin(), clip_methods().end());
    } else {
        methods.push_back(parse_clip_method(method_name));
    }
    std::vector<std::string> space_names;
    for (const RgbSpace* sp : builtin_rgb_spaces()) space_names.push_back(sp->name());
    const RgbSpace& space = *find_rgb_space(options.choice("space", space_names, "srgb"));

    /// The default colour: the spectral colour at 520 nm (outside every built-in gamut) at a
    /// luminance of 0.25, where the sRGB slice is a pentagon.
    constexpr double default_nm = 520.0;
    constexpr double default_luminance = 0.25;
    const Xy locus_520 = spectral_locus_xy(default_nm);
    const std::string color_allowed =
        "x,y,Y: chromaticity x, y in [0, 1] with x + y <= 1 and y > 0, luminance Y in "
        "[0.001, 0.999] (relative to the white)";
    Xyy input{locus_520.x, locus_520.y, default_luminance};
    const bool default_color = !options.has("color");
    if (!default_color) {
        const std::vector<double> v = options.numbers("color", "", 0.0, 1.0, 3);
        if (!(v[1] > 0.0) || v[0] + v[1] > 1.0 || v[2] < 0.001 || v[2] > 0.999) {
            options.fail("color", options.text("color", ""), "not a valid xyY colour",
                         color_allowed);
        }
        input = {v[0], v[1], v[2]};
    }
    const Gamut gamut(space);
    const Xyz input_xyz = xyy_to_xyz(input);
    const Rgb input_rgb = space.from_xyz(input_xyz);
    const bool in_gamut = gamut.contains(input_rgb);
    const std::vector<Rgb> slice = luminance_slice(gamut, input.Y);
    const std::vector<ClipLanding> landings = clip_landings(gamut, input_xyz, methods);

    std::vector<Point> polygon;
    for (const Rgb& c : slice) {
        const Xy xy = xyz_to_xy(space.to_xyz(c));
        polygon.push_back({xy.x, xy.y});
    }
    const Xy neutral = xyz_to_xy(space.white_xyz());
    const std::vector<Point> locus = spectral_locus(Diagram::xy);

    Canvas canvas(image_format_for(request.output), request.width_px, request.height_px);
    const double s = canvas.scale();
    const Rect page = page_area(canvas);

    static constexpr std::array<MarkerShape, 4> shapes{MarkerShape::diamond, MarkerShape::triangle,
                                                       MarkerShape::square, MarkerShape::circle};
    const auto landing_style = [&](std::size_t k) {
        return MarkerStyle{
            .shape = landings.size() == 1 ? MarkerShape::diamond : shapes[k % shapes.size()],
            // Decreasing sizes: methods that land on the same point show as nested markers.
            .size = (landings.size() == 1 ? 10.0 : 16.0 - 1.2 * static_cast<double>(k)) * s,
            .fill = landings.size() == 1 ? series_color(1) : series_color(k),
            .stroke = palette::black,
            .stroke_width = 1.0 * s};
    };
    const MarkerStyle input_marker{.shape = MarkerShape::circle, .size = 11.0 * s,
                                   .fill = palette::white, .stroke = palette::black,
                                   .stroke_width = 2.0 * s};
    const MarkerStyle neutral_marker{.shape = MarkerShape::square, .size = 10.0 * s,
                                     .fill = palette::grey, .stroke = palette::black,
                                     .stroke_width = 1.5 * s};

    // One scene, drawn twice: the whole diagram (with the legend) and a zoom on the landings.
    const auto draw_scene = [&](Plot& plot, bool legend) {
        const Rect frame = plot.frame();
        const Axis& xa = plot.x_axis();
        const Axis& ya = plot.y_axis();
        plot.line(locus, {palette::grey, 1.0 * s, Dash::solid});
        const std::array<Point, 2> purple{locus.back(), locus.front()};
        plot.line(purple, {palette::grey, 1.0 * s, Dash::dashed});
        const std::string slice_label = legend ? "gamut slice at Y = " + shortest(input.Y) : "";
        if (&space == &srgb()) {
            // Every colour of the slice is inside the gamut: shown exactly, no clip needed.
            const int nx = std::clamp(static_cast<int>(frame.width / 1.5), 16, 700);
            const int ny = std::clamp(static_cast<int>(frame.height / 1.5), 16, 700);
            std::vector<Color> cells(static_cast<std::size_t>(nx) * ny, Color{0.0, 0.0, 0.0, 0.0});
            for (int j = 0; j < ny; ++j) {
                for (int i = 0; i < nx; ++i) {
                    const Xy xy{xa.min + (i + 0.5) / nx * (xa.max - xa.min),
                                ya.min + (j + 0.5) / ny * (ya.max - ya.min)};
                    if (!(xy.y > 0.0)) continue;
                    const Rgb c = space.from_xyz(xy_to_xyz(xy, input.Y));
                    if (gamut.contains(c)) {
                        cells[static_cast<std::size_t>(j) * nx + i] = display_color(c);
                    }
                }
            }
            plot.raster(xa.min, xa.max, ya.min, ya.max, nx, ny, cells, false);
            plot.polygon(polygon, with_alpha(palette::white, 0.0),
                         {palette::black, 1.5 * s, Dash::solid}, slice_label);
        } else {
            plot.polygon(polygon, palette::light_grey, {palette::black, 1.5 * s, Dash::solid},
                         slice_label);
        }
        const std::array<Point, 2> segment{Point{input.x, input.y}, Point{neutral.x, neutral.y}};
        plot.line(segment, {palette::dark_grey, 1.3 * s, Dash::dashed},
                  legend ? "line to the neutral point (constant Y)" : "");
        plot.marker({input.x, input.y}, input_marker,
                    !legend         ? ""
                    : default_color ? "input: 520 nm at Y = " + shortest(input.Y)
                                    : "input colour" + std::string(in_gamut ? " (in gamut)" : ""));
        plot.marker({neutral.x, neutral.y}, neutral_marker,
                    legend ? "neutral point (grey, same Y)" : "");
        for (std::size_t k = 0; k < landings.size(); ++k) {
            const ClipLanding& l = landings[k];
            const std::string name(clip_method_name(l.method));
            const bool off_slice = std::abs(l.xyy.Y - input.Y) > 1e-6 * input.Y;
            plot.marker({l.xyy.x, l.xyy.y}, landing_style(k),
                        legend ? name + (off_slice ? " (Y = " + fixed(l.xyy.Y, 3) + ")" : "")
                               : "");
        }
    };

    Plot main(canvas, page, {.min = -0.06, .max = 0.8, .title = "chromaticity x"},
              {.min = 0.0, .max = 0.9, .title = "chromaticity y"},
              "The " + space.name() + " gamut at luminance Y = " + shortest(input.Y) +
                  ": where the clip puts a colour",
              {.equal_aspect = true, .right_reserve = 0.44 * page.width});
    draw_scene(main, true);
    // The zoom's extent: the landings, widened by 30 % (at least ±0.012 in x and y), centred
    // on them.
    double x_lo = landings.front().xyy.x, x_hi = x_lo;
    double y_lo = landings.front().xyy.y, y_hi = y_lo;
    for (const ClipLanding& l : landings) {
        x_lo = std::min(x_lo, l.xyy.x);
        x_hi = std::max(x_hi, l.xyy.x);
        y_lo = std::min(y_lo, l.xyy.y);
        y_hi = std::max(y_hi, l.xyy.y);
    }
    const double half = std::max({(x_hi - x_lo) * 0.65, (y_hi - y_lo) * 0.65, 0.012});
    const Point mid{(x_lo + x_hi) / 2.0, (y_lo + y_hi) / 2.0};
    const Rect frame = main.frame();
    main.finish(LegendPosition::outside_right);
    const Rect legend_box = main.legend_box();
    const Rect zoom_area{legend_box.x, legend_box.bottom() + 6.0 * s,
                         page.right() - legend_box.x,
                         frame.bottom() + 3.0 * main.font_size() - legend_box.bottom() - 6.0 * s};
    if (zoom_area.height > 120.0 * s && zoom_area.width > 120.0 * s) {
        Plot zoom(canvas, zoom_area, {.min = mid.x - half, .max = mid.x + half, .max_ticks = 4},
                  {.min = mid.y - half, .max = mid.y + half, .max_ticks = 4}, "zoom",
                  {.font_size = 0.85 * main.font_size(), .equal_aspect = true});
        draw_scene(zoom, false);
        zoom.finish(LegendPosition::none);
    }
    canvas.save(request.output);

    FigureResult result;
    for (const ClipLanding& l : landings) {
        result.measurements.emplace_back(
            std::string(clip_method_name(l.method)) + ": x, y, Y",
            fixed(l.xyy.x, 4) + ", " + fixed(l.xyy.y, 4) + ", " + fixed(l.xyy.Y, 4) +
                " (CIELUV hue shift " + fixed(l.hue_shift_deg, 1) + "°)");
    }
    result.measurements.insert(
        result.measurements.begin(),
        {"slice vertices", std::to_string(slice.size()) + " (a " +
                               (slice.size() == 3   ? std::string("triangle")
                                : slice.size() == 4 ? std::string("quadrilateral")
                                : slice.size() == 5 ? std::string("pentagon")
                                                    : std::to_string(slice.size()) + "-gon") +
                               ")"});
    std::vector<std::string> names;
    for (const ClipMethod m : methods) names.emplace_back(clip_method_name(m));
    result.caption =
        "The geometry of gamut clipping, after Smits 1990 Figure 10, drawn in the CIE 1931 xy "
        "plane: the slice of the " + space.name() + " RGB cube at luminance Y = " +
        shortest(input.Y) + " (a plane of constant luminance meets the cube in a polygon, and a "
        "constant-Y plane maps to xy projectively, so its edges stay straight), " +
        (&space == &srgb() ? std::string("filled with its own colours (all inside sRGB, shown "
                                         "exactly, no clip)")
                           : std::string("filled grey")) +
        "; the colour x, y = " + fixed(input.x, 4) + ", " + fixed(input.y, 4) +
        (default_color ? " (the spectral colour at 520 nm)" : "") +
        (in_gamut ? ", which is inside the gamut (every method leaves it unchanged)"
                  : ", outside the gamut") +
        "; its neutral point, the grey of the same luminance (at the white's chromaticity); "
        "the line between them, along which the thesis' clip moves the colour to the slice's "
        "edge; and where the method" + (methods.size() > 1 ? "s " : " ") + join(names, ", ") +
        (methods.size() > 1 ? " put" : " puts") +
        " it. Methods that change the luminance land off this slice (their Y is given). "
        "Options: method=" + method_name + ", color=" + fixed(input.x, 4) + "," +
        fixed(input.y, 4) + "," + shortest(input.Y) + ", space=" + space.name() + ".";
    return result;
}

}  // namespace irid::figures::detail
