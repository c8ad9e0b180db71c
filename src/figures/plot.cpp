// Axis ticks and the Plot: axes, series, rasters and legends on a Canvas.

#include "plot.h"

#include <irid/color/rgb.h>
#include <irid/color/spaces.h>
#include <irid/error.h>
#include <irid/figures/figures.h>
#include <irid/io/output_file.h>

#include <cairo-svg.h>
#include <cairo.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstddef>
#include <cstdio>
#include <limits>
#include <numbers>

namespace irid::figures {

// --- ticks ---------------------------------------------------------------------------------

double nice_step(double span, int max_ticks) {
    if (!(span > 0.0) || !std::isfinite(span)) {
        throw Error("nice_step: span must be finite and > 0, got " + std::to_string(span));
    }
    if (max_ticks < 1) {
        throw Error("nice_step: max_ticks must be >= 1, got " + std::to_string(max_ticks));
    }
    const double raw = span / max_ticks;
    const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
    // 1e-9 of slack: a span of exactly 8 × 0.1 must still take 0.1, not 0.2.
    for (const double m : {1.0, 2.0, 5.0, 10.0}) {
        if (m * magnitude >= raw * (1.0 - 1e-9)) return m * magnitude;
    }
    return 10.0 * magnitude;
}

std::string format_tick(double value, double step) {
    int decimals = 0;
    const double s = std::abs(step);
    if (s > 0.0 && std::isfinite(s)) {
        while (decimals < 12) {
            const double scaled = s * std::pow(10.0, decimals);
            if (std::abs(scaled - std::round(scaled)) <= 1e-6 * scaled) break;
            ++decimals;
        }
    }
    const double unit = std::pow(10.0, -decimals);
    if (std::abs(value) < unit / 2.0) value = 0.0;  // never "−0"
    std::array<char, 64> buffer{};
    std::snprintf(buffer.data(), buffer.size(), "%.*f", decimals, std::abs(value));
    std::string out = value < 0.0 ? "\u2212" : "";
    out += buffer.data();
    return out;
}

std::vector<Tick> nice_ticks(double lo, double hi, int max_ticks) {
    if (!std::isfinite(lo) || !std::isfinite(hi) || !(lo < hi)) {
        throw Error("nice_ticks: need finite lo < hi, got " + std::to_string(lo) + ", " +
                    std::to_string(hi));
    }
    const double step = nice_step(hi - lo, max_ticks);
    const double first = std::ceil(lo / step - 1e-9);
    const double last = std::floor(hi / step + 1e-9);
    std::vector<Tick> ticks;
    for (double k = first; k <= last; k += 1.0) {
        double v = k * step;
        if (std::abs(v) < step * 1e-9) v = 0.0;
        ticks.push_back({v, format_tick(v, step)});
    }
    return ticks;
}

std::pair<double, double> nice_range(double lo, double hi, int max_ticks) {
    if (!std::isfinite(lo) || !std::isfinite(hi)) {
        throw Error("nice_range: limits must be finite");
    }
    if (lo > hi) std::swap(lo, hi);
    if (lo == hi) {
        const double pad = lo == 0.0 ? 1.0 : std::abs(lo) / 10.0;
        lo -= pad;
        hi += pad;
    }
    const double step = nice_step(hi - lo, max_ticks);
    return {std::floor(lo / step + 1e-9) * step, std::ceil(hi / step - 1e-9) * step};
}

// --- plots ---------------------------------------------------------------------------------

namespace {

void check_axis(const Axis& axis, const char* which) {
    if (!std::isfinite(axis.min) || !std::isfinite(axis.max) || !(axis.min < axis.max)) {
        throw Error(std::string("plot: the ") + which + " axis needs finite min < max, got " +
                    std::to_string(axis.min) + ", " + std::to_string(axis.max));
    }
}

}  // namespace

Plot::Plot(Canvas& canvas, const Rect& area, Axis x, Axis y, std::string title,
           PlotOptions options)
    : m_canvas(&canvas),
      m_area(area),
      m_x(std::move(x)),
      m_y(std::move(y)),
      m_title(std::move(title)),
      m_options(options) {
    check_axis(m_x, "x");
    check_axis(m_y, "y");
    if (m_x.ticks.empty()) m_x.ticks = nice_ticks(m_x.min, m_x.max, m_x.max_ticks);
    if (m_y.ticks.empty()) m_y.ticks = nice_ticks(m_y.min, m_y.max, m_y.max_ticks);
    m_font_size = options.font_size > 0.0 ? options.font_size : 12.0 * canvas.scale();
    const double fs = m_font_size;
    const TextStyle label_style{.size = fs};
    const double tick_length = 0.45 * fs;

    double widest_y_label = 0.0;
    for (const Tick& t : m_y.ticks) {
        widest_y_label = std::max(widest_y_label, canvas.measure_text(t.label, label_style).width);
    }
    double last_x_label = 0.0;
    if (!m_x.ticks.empty()) {
        last_x_label = canvas.measure_text(m_x.ticks.back().label, label_style).width;
    }
    const double top = m_title.empty() ? 0.9 * fs : 2.6 * fs;
    const double bottom = tick_length + 1.4 * fs + (m_x.title.empty() ? 0.0 : 1.7 * fs);
    const double left =
        tick_length + 0.4 * fs + widest_y_label + (m_y.title.empty() ? 0.4 * fs : 1.9 * fs);
    const double right = std::max(fs, last_x_label / 2.0 + 0.3 * fs) + options.right_reserve;
    m_frame = {area.x + left, area.y + top, area.width - left - right,
               area.height - top - bottom};
    if (m_frame.width < 10.0 || m_frame.height < 10.0) {
        throw Error("plot: the area " + std::to_string(area.width) + "x" +
                    std::to_string(area.height) + " leaves no room for the plot");
    }
    if (m_options.equal_aspect) {
        const double sx = m_frame.width / (m_x.max - m_x.min);
        const double sy = m_frame.height / (m_y.max - m_y.min);
        const double s = std::min(sx, sy);
        const double w = s * (m_x.max - m_x.min);
        const double h = s * (m_y.max - m_y.min);
        // Kept at the top left; the plot's area shrinks with the frame, so the titles stay
        // next to it and the room freed is left to the right and below.
        m_area.width -= m_frame.width - w;
        m_area.height -= m_frame.height - h;
        m_frame.width = w;
        m_frame.height = h;
    }

    canvas.fill_rect(m_frame, palette::white);
    const LineStyle grid{palette::light_grey, std::max(0.5, 0.8 * canvas.scale()), Dash::solid};
    if (m_x.grid) {
        for (const Tick& t : m_x.ticks) {
            const double px = to_canvas(t.value, m_y.min).x;
            canvas.line({px, m_frame.y}, {px, m_frame.bottom()}, grid);
        }
    }
    if (m_y.grid) {
        for (const Tick& t : m_y.ticks) {
            const double py = to_canvas(m_x.min, t.value).y;
            canvas.line({m_frame.x, py}, {m_frame.right(), py}, grid);
        }
    }
}

Point Plot::to_canvas(Point data) const noexcept {
    return {m_frame.x + (data.x - m_x.min) / (m_x.max - m_x.min) * m_frame.width,
            m_frame.bottom() - (data.y - m_y.min) / (m_y.max - m_y.min) * m_frame.height};
}

void Plot::clip_to_frame() {
    cairo_t* cr = m_canvas->cairo();
    cairo_save(cr);
    cairo_rectangle(cr, m_frame.x, m_frame.y, m_frame.width, m_frame.height);
    cairo_clip(cr);
}

void Plot::unclip() {
    cairo_restore(m_canvas->cairo());
}

void Plot::line(std::span<const double> xs, std::span<const double> ys, const LineStyle& style,
                std::string legend) {
    if (xs.size() != ys.size()) {
        throw Error("plot: a line needs as many x values as y values, got " +
                    std::to_string(xs.size()) + " and " + std::to_string(ys.size()));
    }
    std::vector<Point> points(xs.size());
    for (std::size_t i = 0; i < xs.size(); ++i) points[i] = {xs[i], ys[i]};
    line(points, style, std::move(legend));
}

void Plot::line(std::span<const Point> points, const LineStyle& style, std::string legend) {
    std::vector<Point> mapped;
    mapped.reserve(points.size());
    constexpr double nan = std::numeric_limits<double>::quiet_NaN();
    for (const Point& p : points) {
        mapped.push_back(std::isfinite(p.x) && std::isfinite(p.y) ? to_canvas(p)
                                                                  : Point{nan, nan});
    }
    clip_to_frame();
    m_canvas->polyline(mapped, style);
    unclip();
    if (!legend.empty()) add_legend_line(std::move(legend), style);
}

void Plot::polygon(std::span<const Point> points, const Color& fill, std::string legend) {
    std::vector<Point> mapped;
    mapped.reserve(points.size());
    for (const Point& p : points) mapped.push_back(to_canvas(p));
    clip_to_frame();
    m_canvas->fill_polygon(mapped, fill);
    unclip();
    if (!legend.empty()) add_legend_swatch(std::move(legend), fill);
}

void Plot::polygon(std::span<const Point> points, const Color& fill, const LineStyle& outline,
                   std::string legend) {
    std::vector<Point> mapped;
    mapped.reserve(points.size());
    for (const Point& p : points) mapped.push_back(to_canvas(p));
    clip_to_frame();
    m_canvas->fill_polygon(mapped, fill);
    m_canvas->polyline(mapped, outline, true);
    unclip();
    if (!legend.empty()) {
        if (fill.a > 0.0) {
            add_legend_swatch(std::move(legend), fill);
        } else {
            add_legend_line(std::move(legend), outline);
        }
    }
}

void Plot::marker(Point at, const MarkerStyle& style, std::string legend) {
    const std::array<Point, 1> one{at};
    markers(one, style, std::move(legend));
}

void Plot::markers(std::span<const Point> at, const MarkerStyle& style, std::string legend) {
    clip_to_frame();
    for (const Point& p : at) {
        if (std::isfinite(p.x) && std::isfinite(p.y)) m_canvas->marker(to_canvas(p), style);
    }
    unclip();
    if (!legend.empty()) add_legend_marker(std::move(legend), style);
}

void Plot::text(Point at, std::string_view utf8, const TextStyle& style) {
    m_canvas->text(to_canvas(at), utf8, style);
}

void Plot::hline(double y, const LineStyle& style, std::string legend) {
    const std::array<Point, 2> points{Point{m_x.min, y}, Point{m_x.max, y}};
    line(points, style, std::move(legend));
}

void Plot::vline(double x, const LineStyle& style, std::string legend) {
    const std::array<Point, 2> points{Point{x, m_y.min}, Point{x, m_y.max}};
    line(points, style, std::move(legend));
}

void Plot::color_strip(double x0, double x1, double y0, double y1,
                       std::span<const Color> colors) {
    if (colors.empty()) return;
    // One raster row: no seams between cells, whatever the scale.
    raster(x0, x1, y0, y1, static_cast<int>(colors.size()), 1, colors, false);
}

void Plot::cell_grid(double x0, double x1, double y0, double y1, int nx, int ny,
                     std::span<const Color> colors) {
    if (nx < 1 || ny < 1 || colors.size() != static_cast<std::size_t>(nx) * ny) {
        throw Error("plot: a cell grid of " + std::to_string(nx) + "x" + std::to_string(ny) +
                    " needs " + std::to_string(std::max(nx, 0) * std::max(ny, 0)) +
                    " colours, got " + std::to_string(colors.size()));
    }
    const Point a = to_canvas(x0, y0);
    const Point b = to_canvas(x1, y1);
    const double cw = (b.x - a.x) / nx;
    const double ch = (b.y - a.y) / ny;  // negative when y grows upward
    // Adjacent antialiased edges leave hairline seams; each cell reaches a little into the next.
    const double overlap = 0.6;
    clip_to_frame();
    cairo_t* cr = m_canvas->cairo();
    cairo_save(cr);
    const Rect bounds{std::min(a.x, b.x), std::min(a.y, b.y), std::abs(b.x - a.x),
                      std::abs(b.y - a.y)};
    cairo_rectangle(cr, bounds.x, bounds.y, bounds.width, bounds.height);
    cairo_clip(cr);
    for (int j = 0; j < ny; ++j) {
        for (int i = 0; i < nx; ++i) {
            const Color& c = colors[static_cast<std::size_t>(j) * nx + i];
            double left = a.x + i * cw;
            double right = a.x + (i + 1) * cw;
            double top = a.y + (j + 1) * ch;
            double bottom = a.y + j * ch;
            if (left > right) std::swap(left, right);
            if (top > bottom) std::swap(top, bottom);
            cairo_set_source_rgba(cr, c.r, c.g, c.b, c.a);
            cairo_rectangle(cr, left, top, right - left + overlap, bottom - top + overlap);
            cairo_fill(cr);
        }
    }
    cairo_restore(cr);
    unclip();
}

void Plot::raster(double x0, double x1, double y0, double y1, int nx, int ny,
                  std::span<const Color> colors, bool smooth) {
    if (nx < 1 || ny < 1 || nx > 32768 || ny > 32768 ||
        colors.size() != static_cast<std::size_t>(nx) * ny) {
        throw Error("plot: a raster of " + std::to_string(nx) + "x" + std::to_string(ny) +
                    " (each side 1..32768) needs one colour per cell, got " +
                    std::to_string(colors.size()));
    }
    cairo_surface_t* image = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, nx, ny);
    if (cairo_surface_status(image) != CAIRO_STATUS_SUCCESS) {
        cairo_surface_destroy(image);
        throw Error("plot: cannot create a raster of " + std::to_string(nx) + "x" +
                    std::to_string(ny));
    }
    cairo_surface_flush(image);
    unsigned char* data = cairo_image_surface_get_data(image);
    const int stride = cairo_image_surface_get_stride(image);
    const auto byte = [](double v) {
        return static_cast<std::uint32_t>(std::lround(std::clamp(v, 0.0, 1.0) * 255.0));
    };
    for (int j = 0; j < ny; ++j) {
        // Image row 0 is the top: data row j (at y0 + ...) goes to image row ny − 1 − j when
        // y0 is at the bottom of the frame.
        auto* row = reinterpret_cast<std::uint32_t*>(data + static_cast<std::ptrdiff_t>(ny - 1 - j) * stride);
        for (int i = 0; i < nx; ++i) {
            const Color& c = colors[static_cast<std::size_t>(j) * nx + i];
            const double a = std::clamp(c.a, 0.0, 1.0);
            // CAIRO_FORMAT_ARGB32: native-endian 32-bit words, premultiplied alpha.
            row[i] = (byte(a) << 24) | (byte(c.r * a) << 16) | (byte(c.g * a) << 8) | byte(c.b * a);
        }
    }
    cairo_surface_mark_dirty(image);

    const Point a = to_canvas(x0, y0);
    const Point b = to_canvas(x1, y1);
    clip_to_frame();
    cairo_t* cr = m_canvas->cairo();
    cairo_save(cr);
    const double left = std::min(a.x, b.x);
    const double top = std::min(a.y, b.y);
    const double width = std::abs(b.x - a.x);
    const double height = std::abs(b.y - a.y);
    cairo_rectangle(cr, left, top, width, height);
    cairo_clip(cr);
    cairo_translate(cr, left, top);
    // Mirror when the data axes run against the canvas (x1 < x0 or y1 below y0).
    cairo_scale(cr, (b.x >= a.x ? 1.0 : -1.0) * width / nx, (b.y <= a.y ? 1.0 : -1.0) * height / ny);
    if (b.x < a.x) cairo_translate(cr, -nx, 0.0);
    if (b.y > a.y) cairo_translate(cr, 0.0, -ny);
    cairo_set_source_surface(cr, image, 0.0, 0.0);
    cairo_pattern_set_filter(cairo_get_source(cr),
                             smooth ? CAIRO_FILTER_BILINEAR : CAIRO_FILTER_NEAREST);
    cairo_pattern_set_extend(cairo_get_source(cr), CAIRO_EXTEND_PAD);
    cairo_paint(cr);
    cairo_restore(cr);
    unclip();
    cairo_surface_destroy(image);
}

void Plot::add_legend_line(std::string label, const LineStyle& style) {
    m_legend.push_back({LegendEntry::Kind::line, std::move(label), style, {}, {}});
}

void Plot::add_legend_swatch(std::string label, const Color& fill) {
    m_legend.push_back({LegendEntry::Kind::swatch, std::move(label), {}, fill, {}});
}

void Plot::add_legend_marker(std::string label, const MarkerStyle& style) {
    m_legend.push_back({LegendEntry::Kind::marker, std::move(label), {}, {}, style});
}

void Plot::finish(LegendPosition legend) {
    if (m_finished) return;
    m_finished = true;
    Canvas& canvas = *m_canvas;
    const double fs = m_font_size;
    const double tick_length = 0.45 * fs;
    const LineStyle axis_line{palette::dark_grey, std::max(0.6, 1.0 * canvas.scale()),
                              Dash::solid};
    canvas.stroke_rect(m_frame, axis_line);

    TextStyle label{.size = fs, .color = palette::dark_grey};
    label.halign = HAlign::center;
    label.valign = VAlign::top;
    for (const Tick& t : m_x.ticks) {
        const double px = to_canvas(t.value, m_y.min).x;
        canvas.line({px, m_frame.bottom()}, {px, m_frame.bottom() + tick_length}, axis_line);
        canvas.text({px, m_frame.bottom() + tick_length + 0.3 * fs}, t.label, label);
    }
    label.halign = HAlign::right;
    label.valign = VAlign::middle;
    for (const Tick& t : m_y.ticks) {
        const double py = to_canvas(m_x.min, t.value).y;
        canvas.line({m_frame.x - tick_length, py}, {m_frame.x, py}, axis_line);
        canvas.text({m_frame.x - tick_length - 0.3 * fs, py}, t.label, label);
    }

    TextStyle title_style{.size = 1.05 * fs};
    if (!m_x.title.empty()) {
        title_style.halign = HAlign::center;
        title_style.valign = VAlign::bottom;
        canvas.text({m_frame.x + m_frame.width / 2.0, m_area.bottom() - 0.15 * fs}, m_x.title,
                    title_style);
    }
    if (!m_y.title.empty()) {
        title_style.halign = HAlign::center;
        title_style.valign = VAlign::top;
        title_style.angle_deg = 90.0;
        canvas.text({m_area.x + 0.2 * fs, m_frame.y + m_frame.height / 2.0}, m_y.title,
                    title_style);
    }
    if (!m_title.empty()) {
        const TextStyle heading{.size = 1.3 * fs, .bold = true, .halign = HAlign::center,
                                .valign = VAlign::top};
        canvas.text({m_area.x + m_area.width / 2.0, m_area.y + 0.6 * fs}, m_title, heading);
    }
    draw_legend(legend);
}

namespace {

/// The legend box's width for labels at most `widest` wide: padding, key, gap, text, padding.
double legend_box_width(double widest, double fs) {
    return 0.6 * fs + 2.2 * fs + 0.5 * fs + widest + 0.6 * fs;
}

}  // namespace

double Plot::outside_legend_width(Canvas& canvas, const std::vector<std::string>& labels,
                                  double font_size) {
    const double fs = font_size > 0.0 ? font_size : 12.0 * canvas.scale();
    const TextStyle label{.size = fs, .valign = VAlign::middle};
    double widest = 0.0;
    for (const std::string& l : labels) widest = std::max(widest, canvas.measure_text(l, label).width);
    // The inset between frame and box, the box, and a margin after it.
    return 0.6 * fs + legend_box_width(widest, fs) + 0.3 * fs;
}

void Plot::draw_legend(LegendPosition position) {
    if (position == LegendPosition::none || m_legend.empty()) return;
    Canvas& canvas = *m_canvas;
    const double fs = m_font_size;
    const TextStyle label{.size = fs, .valign = VAlign::middle};
    double widest = 0.0;
    for (const LegendEntry& e : m_legend) {
        widest = std::max(widest, canvas.measure_text(e.label, label).width);
    }
    const double pad = 0.6 * fs;
    const double row = 1.5 * fs;
    const double key = 2.2 * fs;
    const double w = legend_box_width(widest, fs);
    const double h = pad + row * static_cast<double>(m_legend.size()) + pad - 0.5 * fs;
    const double inset = 0.6 * fs;
    Rect box{0.0, 0.0, w, h};
    switch (position) {
        case LegendPosition::top_right:
            box.x = m_frame.right() - inset - w;
            box.y = m_frame.y + inset;
            break;
        case LegendPosition::top_left:
            box.x = m_frame.x + inset;
            box.y = m_frame.y + inset;
            break;
        case LegendPosition::bottom_right:
            box.x = m_frame.right() - inset - w;
            box.y = m_frame.bottom() - inset - h;
            break;
        case LegendPosition::bottom_left:
            box.x = m_frame.x + inset;
            box.y = m_frame.bottom() - inset - h;
            break;
        case LegendPosition::outside_right:
            box.x = m_frame.right() + inset;
            box.y = m_frame.y;
            break;
        case LegendPosition::none:
            return;
    }
    m_legend_box = box;
    canvas.fill_rect(box, with_alpha(palette::white, 0.88));
    canvas.stroke_rect(box, {palette::light_grey, std::max(0.5, 0.8 * canvas.scale()),
                             Dash::solid});
    double y = box.y + pad + 0.5 * fs;
    for (const LegendEntry& e : m_legend) {
        const double kx = box.x + pad;
        switch (e.kind) {
            case LegendEntry::Kind::line:
                canvas.line({kx, y}, {kx + key, y}, e.line);
                break;
            case LegendEntry::Kind::swatch:
                canvas.fill_rect({kx, y - 0.45 * fs, key, 0.9 * fs}, e.fill);
                canvas.stroke_rect({kx, y - 0.45 * fs, key, 0.9 * fs},
                                   {palette::grey, 0.5, Dash::solid});
                break;
            case LegendEntry::Kind::marker:
                canvas.marker({kx + key / 2.0, y}, e.marker);
                break;
        }
        canvas.text({kx + key + 0.5 * fs, y}, e.label, label);
        y += row;
    }
}

void draw_color_bar(Canvas& canvas, const Rect& bar, double lo, double hi,
                    const std::string& title, const std::function<Color(double)>& map,
                    int max_ticks) {
    if (!std::isfinite(lo) || !std::isfinite(hi) || !(lo < hi)) {
        throw Error("colour bar: need finite lo < hi, got " + std::to_string(lo) + ", " +
                    std::to_string(hi));
    }
    constexpr int steps = 256;
    const double h = bar.height / steps;
    for (int i = 0; i < steps; ++i) {
        const double t = (i + 0.5) / steps;
        // Row i counts up from the bottom; each overlaps the next by half a unit (no seams).
        canvas.fill_rect({bar.x, bar.bottom() - (i + 1) * h, bar.width, h + 0.5}, map(t));
    }
    const double s = canvas.scale();
    const double fs = 12.0 * s;
    const LineStyle axis_line{palette::dark_grey, std::max(0.6, s), Dash::solid};
    canvas.stroke_rect(bar, axis_line);
    const TextStyle label{.size = fs, .color = palette::dark_grey, .valign = VAlign::middle};
    double widest = 0.0;
    for (const Tick& t : nice_ticks(lo, hi, max_ticks)) {
        const double y = bar.bottom() - (t.value - lo) / (hi - lo) * bar.height;
        canvas.line({bar.right(), y}, {bar.right() + 0.45 * fs, y}, axis_line);
        canvas.text({bar.right() + 0.7 * fs, y}, t.label, label);
        widest = std::max(widest, canvas.measure_text(t.label, label).width);
    }
    if (!title.empty()) {
        const TextStyle title_style{.size = 1.05 * fs, .halign = HAlign::center,
                                    .valign = VAlign::bottom, .angle_deg = -90.0};
        canvas.text({bar.right() + 0.9 * fs + widest + 0.4 * fs, bar.y + bar.height / 2.0},
                    title, title_style);
    }
}

}  // namespace irid::figures
