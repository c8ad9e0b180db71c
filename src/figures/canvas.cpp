// Colours for figures and the Cairo canvas (PNG and SVG) that figures draw on.

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

// --- colours -------------------------------------------------------------------------------

Color series_color(std::size_t index) noexcept {
    /// Okabe & Ito 2008, "Color Universal Design (CUD): how to make figures and presentations
    /// that are friendly to colorblind people", the eight colours as 8-bit sRGB.
    static constexpr std::array<std::array<int, 3>, 8> okabe_ito{{{0, 114, 178},
                                                                  {213, 94, 0},
                                                                  {0, 158, 115},
                                                                  {230, 159, 0},
                                                                  {204, 121, 167},
                                                                  {86, 180, 233},
                                                                  {240, 228, 66},
                                                                  {0, 0, 0}}};
    const auto& c = okabe_ito[index % okabe_ito.size()];
    return {c[0] / 255.0, c[1] / 255.0, c[2] / 255.0, 1.0};
}

namespace {

Oklab oklab_of_encoded(double r, double g, double b) {
    const Rgb linear = srgb().decode({r, g, b});
    return xyz_to_oklab(srgb().to_xyz(linear));
}

}  // namespace

Color sequential_color(double t) noexcept {
    // Five anchors (encoded sRGB) chosen by eye for a dark-to-light ramp; in Oklab their
    // lightness rises monotonically (tests/figures/plot_test.cpp checks it along the map).
    static const std::array<Oklab, 5> anchors{
        oklab_of_encoded(0.08, 0.06, 0.28), oklab_of_encoded(0.13, 0.33, 0.58),
        oklab_of_encoded(0.07, 0.58, 0.56), oklab_of_encoded(0.46, 0.78, 0.33),
        oklab_of_encoded(0.99, 0.94, 0.58)};
    if (!(t > 0.0)) t = 0.0;  // NaN → 0
    if (t > 1.0) t = 1.0;
    const double position = t * static_cast<double>(anchors.size() - 1);
    const std::size_t i = std::min<std::size_t>(static_cast<std::size_t>(position),
                                                anchors.size() - 2);
    const double f = position - static_cast<double>(i);
    const Oklab& a = anchors[i];
    const Oklab& b = anchors[i + 1];
    const Oklab mixed{a.L + f * (b.L - a.L), a.a + f * (b.a - a.a), a.b + f * (b.b - a.b)};
    // Straight Oklab segments between in-gamut anchors stay inside sRGB up to rounding.
    return display_color(srgb().from_xyz(oklab_to_xyz(mixed)));
}

Color display_color(const Rgb& linear_srgb) noexcept {
    const Rgb e = srgb().encode(linear_srgb);
    const auto unit = [](double v) { return v > 0.0 ? (v < 1.0 ? v : 1.0) : 0.0; };
    return {unit(e.r), unit(e.g), unit(e.b), 1.0};
}

Color clipped_display_color(const Xyz& xyz, const GamutClipper& srgb_clipper) noexcept {
    return display_color(srgb_clipper.clip(srgb().from_xyz(xyz)));
}

// --- the canvas ----------------------------------------------------------------------------

ImageFormat image_format_for(const std::filesystem::path& path) {
    std::string ext = path.extension().string();
    for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (ext == ".svg") return ImageFormat::svg;
    if (ext == ".png") return ImageFormat::png;
    throw Error(path.string() + ": unsupported image extension \"" + ext +
                "\"; allowed: .svg, .png");
}

struct Canvas::Impl {
    ImageFormat format;
    int width;
    int height;
    cairo_surface_t* surface = nullptr;
    cairo_t* cr = nullptr;
    std::string bytes;
    bool finished = false;

    ~Impl() {
        if (cr != nullptr) cairo_destroy(cr);
        if (surface != nullptr) cairo_surface_destroy(surface);
    }
};

namespace {

cairo_status_t append_bytes(void* closure, const unsigned char* data, unsigned int length) {
    auto* out = static_cast<std::string*>(closure);
    out->append(reinterpret_cast<const char*>(data), length);
    return CAIRO_STATUS_SUCCESS;
}

void set_color(cairo_t* cr, const Color& c) {
    cairo_set_source_rgba(cr, c.r, c.g, c.b, c.a);
}

void set_line(cairo_t* cr, const LineStyle& style) {
    set_color(cr, style.color);
    cairo_set_line_width(cr, style.width);
    cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
    const double w = std::max(style.width, 0.5);
    switch (style.dash) {
        case Dash::solid:
            cairo_set_dash(cr, nullptr, 0, 0.0);
            cairo_set_line_cap(cr, CAIRO_LINE_CAP_BUTT);
            break;
        case Dash::dashed: {
            const std::array<double, 2> d{5.0 * w, 3.0 * w};
            cairo_set_dash(cr, d.data(), 2, 0.0);
            cairo_set_line_cap(cr, CAIRO_LINE_CAP_BUTT);
            break;
        }
        case Dash::dotted: {
            const std::array<double, 2> d{0.0, 2.5 * w};
            cairo_set_dash(cr, d.data(), 2, 0.0);
            cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
            break;
        }
        case Dash::dash_dot: {
            const std::array<double, 4> d{6.0 * w, 2.5 * w, 0.0, 2.5 * w};
            cairo_set_dash(cr, d.data(), 4, 0.0);
            cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
            break;
        }
    }
}

void select_font(cairo_t* cr, const TextStyle& style) {
    cairo_select_font_face(cr, "sans-serif",
                           style.italic ? CAIRO_FONT_SLANT_ITALIC : CAIRO_FONT_SLANT_NORMAL,
                           style.bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
    cairo_set_font_size(cr, style.size);
}

}  // namespace

Canvas::Canvas(ImageFormat format, int width, int height) {
    if (width < min_size_px || width > max_size_px || height < min_size_px ||
        height > max_size_px) {
        throw Error("image size " + std::to_string(width) + "x" + std::to_string(height) +
                    " is outside the allowed " + std::to_string(min_size_px) + ".." +
                    std::to_string(max_size_px) + " pixels per side");
    }
    m_impl = std::make_unique<Impl>();
    m_impl->format = format;
    m_impl->width = width;
    m_impl->height = height;
    if (format == ImageFormat::svg) {
        m_impl->surface = cairo_svg_surface_create_for_stream(append_bytes, &m_impl->bytes,
                                                              width, height);
    } else {
        m_impl->surface = cairo_image_surface_create(CAIRO_FORMAT_RGB24, width, height);
    }
    if (cairo_surface_status(m_impl->surface) != CAIRO_STATUS_SUCCESS) {
        throw Error(std::string("cannot create the drawing surface: ") +
                    cairo_status_to_string(cairo_surface_status(m_impl->surface)));
    }
    m_impl->cr = cairo_create(m_impl->surface);
    if (cairo_status(m_impl->cr) != CAIRO_STATUS_SUCCESS) {
        throw Error(std::string("cannot create the drawing context: ") +
                    cairo_status_to_string(cairo_status(m_impl->cr)));
    }
    fill_rect({0.0, 0.0, static_cast<double>(width), static_cast<double>(height)},
              palette::white);
}

Canvas::~Canvas() = default;
Canvas::Canvas(Canvas&&) noexcept = default;
Canvas& Canvas::operator=(Canvas&&) noexcept = default;

ImageFormat Canvas::format() const noexcept {
    return m_impl->format;
}
int Canvas::width() const noexcept {
    return m_impl->width;
}
int Canvas::height() const noexcept {
    return m_impl->height;
}
double Canvas::scale() const noexcept {
    const double s = std::min(m_impl->width / 960.0, m_impl->height / 600.0);
    return std::clamp(s, 0.5, 3.0);
}
cairo_t* Canvas::cairo() noexcept {
    return m_impl->cr;
}

void Canvas::fill_rect(const Rect& r, const Color& c) {
    cairo_t* cr = m_impl->cr;
    cairo_save(cr);
    set_color(cr, c);
    cairo_rectangle(cr, r.x, r.y, r.width, r.height);
    cairo_fill(cr);
    cairo_restore(cr);
}

void Canvas::stroke_rect(const Rect& r, const LineStyle& style) {
    cairo_t* cr = m_impl->cr;
    cairo_save(cr);
    set_line(cr, style);
    cairo_rectangle(cr, r.x, r.y, r.width, r.height);
    cairo_stroke(cr);
    cairo_restore(cr);
}

void Canvas::line(Point a, Point b, const LineStyle& style) {
    const std::array<Point, 2> points{a, b};
    polyline(points, style);
}

void Canvas::polyline(std::span<const Point> points, const LineStyle& style, bool closed) {
    cairo_t* cr = m_impl->cr;
    cairo_save(cr);
    set_line(cr, style);
    bool pen_down = false;
    for (const Point& p : points) {
        if (!std::isfinite(p.x) || !std::isfinite(p.y)) {
            pen_down = false;
            continue;
        }
        if (pen_down) {
            cairo_line_to(cr, p.x, p.y);
        } else {
            cairo_move_to(cr, p.x, p.y);
            pen_down = true;
        }
    }
    if (closed && pen_down) cairo_close_path(cr);
    cairo_stroke(cr);
    cairo_restore(cr);
}

void Canvas::fill_polygon(std::span<const Point> points, const Color& c) {
    if (points.size() < 3) return;
    cairo_t* cr = m_impl->cr;
    cairo_save(cr);
    set_color(cr, c);
    cairo_move_to(cr, points[0].x, points[0].y);
    for (std::size_t i = 1; i < points.size(); ++i) cairo_line_to(cr, points[i].x, points[i].y);
    cairo_close_path(cr);
    cairo_fill(cr);
    cairo_restore(cr);
}

void Canvas::marker(Point at, const MarkerStyle& style) {
    cairo_t* cr = m_impl->cr;
    const double r = style.size / 2.0;
    cairo_save(cr);
    cairo_new_path(cr);
    bool fillable = true;
    switch (style.shape) {
        case MarkerShape::circle:
            cairo_arc(cr, at.x, at.y, r, 0.0, 2.0 * std::numbers::pi);
            break;
        case MarkerShape::square:
            cairo_rectangle(cr, at.x - r * 0.85, at.y - r * 0.85, 1.7 * r, 1.7 * r);
            break;
        case MarkerShape::diamond:
            cairo_move_to(cr, at.x, at.y - r);
            cairo_line_to(cr, at.x + r, at.y);
            cairo_line_to(cr, at.x, at.y + r);
            cairo_line_to(cr, at.x - r, at.y);
            cairo_close_path(cr);
            break;
        case MarkerShape::triangle:
            cairo_move_to(cr, at.x, at.y - r);
            cairo_line_to(cr, at.x + r * 0.866, at.y + r * 0.5);
            cairo_line_to(cr, at.x - r * 0.866, at.y + r * 0.5);
            cairo_close_path(cr);
            break;
        case MarkerShape::cross:
            fillable = false;
            cairo_move_to(cr, at.x - r * 0.75, at.y - r * 0.75);
            cairo_line_to(cr, at.x + r * 0.75, at.y + r * 0.75);
            cairo_move_to(cr, at.x - r * 0.75, at.y + r * 0.75);
            cairo_line_to(cr, at.x + r * 0.75, at.y - r * 0.75);
            break;
        case MarkerShape::plus:
            fillable = false;
            cairo_move_to(cr, at.x - r, at.y);
            cairo_line_to(cr, at.x + r, at.y);
            cairo_move_to(cr, at.x, at.y - r);
            cairo_line_to(cr, at.x, at.y + r);
            break;
    }
    if (fillable) {
        set_color(cr, style.fill);
        cairo_fill_preserve(cr);
    }
    if (style.stroke_width > 0.0 || !fillable) {
        set_line(cr, {fillable ? style.stroke : style.fill,
                      style.stroke_width > 0.0 ? style.stroke_width : 1.5, Dash::solid});
        cairo_stroke(cr);
    }
    cairo_new_path(cr);
    cairo_restore(cr);
}

TextExtent Canvas::measure_text(std::string_view utf8, const TextStyle& style) {
    cairo_t* cr = m_impl->cr;
    cairo_save(cr);
    select_font(cr, style);
    const std::string text(utf8);
    cairo_text_extents_t te;
    cairo_text_extents(cr, text.c_str(), &te);
    cairo_font_extents_t fe;
    cairo_font_extents(cr, &fe);
    cairo_restore(cr);
    return {te.x_advance, fe.ascent, fe.descent};
}

void Canvas::text(Point anchor, std::string_view utf8, const TextStyle& style) {
    if (utf8.empty()) return;
    const TextExtent extent = measure_text(utf8, style);
    double dx = 0.0;
    if (style.halign == HAlign::center) dx = -extent.width / 2.0;
    if (style.halign == HAlign::right) dx = -extent.width;
    // Cap-height-ish box: ascent of the font overstates lowercase text; 0.72 em is the
    // height of DejaVu's capitals, close enough for centring labels on ticks.
    const double cap = 0.72 * style.size;
    double dy = 0.0;
    switch (style.valign) {
        case VAlign::top:
            dy = cap;
            break;
        case VAlign::middle:
            dy = cap / 2.0;
            break;
        case VAlign::baseline:
            dy = 0.0;
            break;
        case VAlign::bottom:
            dy = -extent.descent;
            break;
    }
    const std::string text(utf8);
    cairo_t* cr = m_impl->cr;
    cairo_save(cr);
    select_font(cr, style);
    cairo_translate(cr, anchor.x, anchor.y);
    cairo_rotate(cr, -style.angle_deg * std::numbers::pi / 180.0);
    cairo_move_to(cr, dx, dy);
    if (style.halo) {
        cairo_text_path(cr, text.c_str());
        set_line(cr, {with_alpha(palette::white, 0.85), style.size * 0.25, Dash::solid});
        cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
        cairo_stroke_preserve(cr);
        set_color(cr, style.color);
        cairo_fill(cr);
    } else {
        set_color(cr, style.color);
        cairo_show_text(cr, text.c_str());
    }
    cairo_restore(cr);
}

const std::string& Canvas::finish() {
    if (m_impl->finished) return m_impl->bytes;
    cairo_surface_flush(m_impl->surface);
    if (m_impl->format == ImageFormat::png) {
        m_impl->bytes.clear();
        const cairo_status_t status =
            cairo_surface_write_to_png_stream(m_impl->surface, append_bytes, &m_impl->bytes);
        if (status != CAIRO_STATUS_SUCCESS) {
            throw Error(std::string("cannot encode the PNG image: ") +
                        cairo_status_to_string(status));
        }
    }
    cairo_destroy(m_impl->cr);
    m_impl->cr = nullptr;
    cairo_surface_finish(m_impl->surface);  // the SVG surface writes its document now
    const cairo_status_t status = cairo_surface_status(m_impl->surface);
    if (status != CAIRO_STATUS_SUCCESS) {
        throw Error(std::string("cannot finish the image: ") + cairo_status_to_string(status));
    }
    m_impl->finished = true;
    return m_impl->bytes;
}

void Canvas::save(const std::filesystem::path& path) {
    io::write_output_file(path, finish());
}

Rect page_area(const Canvas& canvas) noexcept {
    const double m = 8.0 * canvas.scale();
    return {m, m, canvas.width() - 2.0 * m, canvas.height() - 2.0 * m};
}

}  // namespace irid::figures
