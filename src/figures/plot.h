#pragma once

// The drawing toolkit of irid_figures (private to the module and its tests): a Canvas over a
// Cairo SVG or PNG surface and a Plot with linear axes, nice ticks, line series, filled
// polygons, markers, text, colour strips, cell grids (heat maps), colour bars and a legend.
//
// Coordinates: Canvas functions take canvas coordinates (points for SVG, pixels for PNG;
// origin top left, y down). Plot functions take data coordinates (the axes' units, y up) and
// clip what they draw to the plot's frame. Colours are encoded sRGB in [0, 1]: figures clip
// with irid_gamut and encode with irid::srgb() before they make a Color (display_color()).

#include <irid/color/types.h>
#include <irid/gamut/clip.h>

#include <cstddef>
#include <filesystem>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

// Cairo's own declarations of its opaque types (cairo.h), so that this header does not need
// Cairo's include path; Canvas::cairo() hands out the context for drawing the toolkit lacks.
typedef struct _cairo cairo_t;                  // NOLINT(modernize-use-using)
typedef struct _cairo_surface cairo_surface_t;  // NOLINT(modernize-use-using)

namespace irid::figures {

// --- colours -------------------------------------------------------------------------------

/// A display colour: encoded sRGB components r, g, b in [0, 1] and opacity a in [0, 1].
struct Color {
    double r = 0.0, g = 0.0, b = 0.0, a = 1.0;
};

namespace palette {
inline constexpr Color black{0.0, 0.0, 0.0, 1.0};
inline constexpr Color white{1.0, 1.0, 1.0, 1.0};
/// Text and axis lines that should recede a little.
inline constexpr Color dark_grey{0.25, 0.25, 0.25, 1.0};
/// Zero lines, guides.
inline constexpr Color grey{0.5, 0.5, 0.5, 1.0};
/// Grid lines.
inline constexpr Color light_grey{0.88, 0.88, 0.88, 1.0};
}  // namespace palette

/// The i-th colour of a categorical palette for series (cycles after 8): the colour-blind safe
/// set of Okabe & Ito 2008, "Color Universal Design", in the order blue, vermillion, bluish
/// green, orange, reddish purple, sky blue, yellow, black.
[[nodiscard]] Color series_color(std::size_t index) noexcept;

/// A sequential colour map for heat maps, t in [0, 1] (clamped) from dark blue through
/// teal and green to light yellow: straight segments in Oklab between five anchors, so
/// lightness rises monotonically with t.
[[nodiscard]] Color sequential_color(double t) noexcept;

/// `c` with its opacity replaced by `alpha`.
[[nodiscard]] constexpr Color with_alpha(Color c, double alpha) noexcept {
    c.a = alpha;
    return c;
}

/// The display colour of a linear sRGB colour that is already inside the gamut (clipped by the
/// caller): encoded with the sRGB transfer function; components are clamped to [0, 1] only to
/// remove the rounding a clip leaves (|excess| ~1e-12).
[[nodiscard]] Color display_color(const Rgb& linear_srgb) noexcept;

/// The display colour of any XYZ (relative to D65, white Y = 1): converted to linear sRGB,
/// clipped by `srgb_clipper` (a GamutClipper on irid::srgb(); name its method in the caption),
/// encoded.
[[nodiscard]] Color clipped_display_color(const Xyz& xyz, const GamutClipper& srgb_clipper) noexcept;

// --- geometry and styles -------------------------------------------------------------------

struct Point {
    double x = 0.0, y = 0.0;
};

struct Rect {
    double x = 0.0, y = 0.0, width = 0.0, height = 0.0;
    [[nodiscard]] constexpr double right() const noexcept { return x + width; }
    [[nodiscard]] constexpr double bottom() const noexcept { return y + height; }
};

enum class Dash { solid, dashed, dotted, dash_dot };

struct LineStyle {
    Color color = palette::black;
    /// Line width in points (pixels for PNG).
    double width = 1.5;
    Dash dash = Dash::solid;
};

enum class MarkerShape { circle, square, diamond, triangle, cross, plus };

struct MarkerStyle {
    MarkerShape shape = MarkerShape::circle;
    /// Outer size (diameter) in points.
    double size = 8.0;
    Color fill = palette::black;
    Color stroke = palette::black;
    /// Outline width in points; 0 draws no outline.
    double stroke_width = 1.0;
};

enum class HAlign { left, center, right };
enum class VAlign { top, middle, baseline, bottom };

struct TextStyle {
    /// Font size in points.
    double size = 12.0;
    Color color = palette::black;
    bool bold = false;
    bool italic = false;
    /// Where the anchor point lies on the text's box.
    HAlign halign = HAlign::left;
    VAlign valign = VAlign::baseline;
    /// Rotation about the anchor, degrees counter-clockwise (90 reads bottom to top).
    double angle_deg = 0.0;
    /// A white outline behind the glyphs, to keep labels readable over data.
    bool halo = false;
};

/// The size of a text as set: advance width, and ascent/descent of the font, in points.
struct TextExtent {
    double width = 0.0, ascent = 0.0, descent = 0.0;
};

// --- the canvas ----------------------------------------------------------------------------

enum class ImageFormat { svg, png };

/// ".svg" → svg, ".png" → png (case-insensitive); anything else throws irid::Error naming the
/// path and listing the allowed extensions.
[[nodiscard]] ImageFormat image_format_for(const std::filesystem::path& path);

/// A drawing surface in memory: an SVG document (units: points) or an ARGB image (pixels) of
/// exactly width × height. Draw on it, then save() it (atomically) or take finish()'s bytes.
/// The background starts white and opaque.
class Canvas {
public:
    /// Throws irid::Error when width or height is outside [64, 8192] or Cairo cannot create
    /// the surface.
    Canvas(ImageFormat format, int width, int height);
    ~Canvas();
    Canvas(const Canvas&) = delete;
    Canvas& operator=(const Canvas&) = delete;
    Canvas(Canvas&&) noexcept;
    Canvas& operator=(Canvas&&) noexcept;

    [[nodiscard]] ImageFormat format() const noexcept;
    [[nodiscard]] int width() const noexcept;
    [[nodiscard]] int height() const noexcept;
    /// A scale for sizes (fonts, margins, line widths) relative to the 960 × 600 design size:
    /// min(width / 960, height / 600), limited to [0.5, 3].
    [[nodiscard]] double scale() const noexcept;
    /// The Cairo context, for drawing the toolkit does not offer. Wrap use in
    /// cairo_save()/cairo_restore().
    [[nodiscard]] cairo_t* cairo() noexcept;

    void fill_rect(const Rect& r, const Color& c);
    void stroke_rect(const Rect& r, const LineStyle& style);
    void line(Point a, Point b, const LineStyle& style);
    void polyline(std::span<const Point> points, const LineStyle& style, bool closed = false);
    void fill_polygon(std::span<const Point> points, const Color& c);
    void marker(Point at, const MarkerStyle& style);
    void text(Point anchor, std::string_view utf8, const TextStyle& style);
    [[nodiscard]] TextExtent measure_text(std::string_view utf8, const TextStyle& style);

    /// Ends drawing and returns the file's bytes (SVG text or PNG). Idempotent; drawing after
    /// it is a programming error.
    const std::string& finish();
    /// finish(), then writes the bytes to `path` (irid::io::OutputFile: whole or not at all). Throws
    /// irid::Error naming the path when writing fails.
    void save(const std::filesystem::path& path);

private:
    struct Impl;
    std::unique_ptr<Impl> m_impl;
};

/// The canvas minus a margin of 8 × canvas.scale() on every side: the area for a plot that
/// fills the image.
[[nodiscard]] Rect page_area(const Canvas& canvas) noexcept;

// --- ticks ---------------------------------------------------------------------------------

struct Tick {
    double value = 0.0;
    std::string label{};
};

/// The "nice" step (1, 2 or 5 × 10^k) for ticks over a span: the smallest such step that
/// gives at most `max_ticks` intervals over `span`. span > 0, max_ticks ≥ 1; else throws
/// irid::Error.
[[nodiscard]] double nice_step(double span, int max_ticks);

/// Ticks at the integer multiples of nice_step(hi − lo, max_ticks) that lie in [lo, hi]
/// (with a tolerance of 1e-9 steps), labelled by format_tick. Needs lo < hi, both finite.
[[nodiscard]] std::vector<Tick> nice_ticks(double lo, double hi, int max_ticks = 8);

/// [lo, hi] widened outwards to multiples of nice_step(hi − lo, max_ticks), for automatic
/// ranges. lo == hi is widened to lo ± 1 (or ± |lo|/10) first.
[[nodiscard]] std::pair<double, double> nice_range(double lo, double hi, int max_ticks = 8);

/// `value` with as many decimals as `step` needs (0.25 → 2, 5 → 0, 1e-3 → 3), a true minus
/// sign (U+2212) for negatives and never "−0".
[[nodiscard]] std::string format_tick(double value, double step);

// --- plots ---------------------------------------------------------------------------------

struct Axis {
    double min = 0.0, max = 1.0;
    /// The title with its unit: "wavelength λ (nm)".
    std::string title{};
    /// Explicit ticks (value, label); empty → nice_ticks(min, max, max_ticks).
    std::vector<Tick> ticks{};
    int max_ticks = 8;
    /// Grid lines at the ticks.
    bool grid = true;
};

struct PlotOptions {
    /// Font size of tick labels and legend in points; 0 → 12 × canvas.scale().
    double font_size = 0.0;
    /// One data unit on x as long as one on y (chromaticity diagrams): the frame shrinks and is
    /// centred in the available area.
    bool equal_aspect = false;
    /// Space in points reserved right of the frame for a colour bar (draw_color_bar) or an
    /// outside legend; 0 → none.
    double right_reserve = 0.0;
};

enum class LegendPosition { top_right, top_left, bottom_right, bottom_left, outside_right, none };

/// A 2-D plot inside a rectangle of a canvas: title on top, axes with ticks, labels and titles,
/// the data frame. The constructor lays it out and draws the background and grid; then draw
/// the data; finish() draws the frame, ticks, labels and legend on top.
class Plot {
public:
    /// Throws irid::Error when an axis has min ≥ max or a non-finite limit, or the area
    /// leaves no room for the frame.
    Plot(Canvas& canvas, const Rect& area, Axis x, Axis y, std::string title = {},
         PlotOptions options = {});

    [[nodiscard]] Canvas& canvas() noexcept { return *m_canvas; }
    /// The data frame in canvas coordinates.
    [[nodiscard]] const Rect& frame() const noexcept { return m_frame; }
    [[nodiscard]] const Axis& x_axis() const noexcept { return m_x; }
    [[nodiscard]] const Axis& y_axis() const noexcept { return m_y; }
    /// The ticks drawn on each axis (explicit or generated).
    [[nodiscard]] const std::vector<Tick>& x_ticks() const noexcept { return m_x.ticks; }
    [[nodiscard]] const std::vector<Tick>& y_ticks() const noexcept { return m_y.ticks; }
    [[nodiscard]] double font_size() const noexcept { return m_font_size; }
    /// Data → canvas coordinates.
    [[nodiscard]] Point to_canvas(Point data) const noexcept;
    [[nodiscard]] Point to_canvas(double x, double y) const noexcept { return to_canvas({x, y}); }

    /// A line through (xs[i], ys[i]); non-finite points break the line. Sizes must match.
    void line(std::span<const double> xs, std::span<const double> ys, const LineStyle& style,
              std::string legend = {});
    void line(std::span<const Point> points, const LineStyle& style, std::string legend = {});
    /// A filled polygon (closed automatically), optionally outlined.
    void polygon(std::span<const Point> points, const Color& fill, std::string legend = {});
    void polygon(std::span<const Point> points, const Color& fill, const LineStyle& outline,
                 std::string legend = {});
    void marker(Point at, const MarkerStyle& style, std::string legend = {});
    void markers(std::span<const Point> at, const MarkerStyle& style, std::string legend = {});
    /// Text anchored at a data point (not clipped to the frame).
    void text(Point at, std::string_view utf8, const TextStyle& style);
    /// Horizontal / vertical line across the whole frame.
    void hline(double y, const LineStyle& style, std::string legend = {});
    void vline(double x, const LineStyle& style, std::string legend = {});
    /// A row of colors.size() equal rectangles side by side from x0 to x1, between y0 and y1
    /// (data coordinates), drawn as a one-row raster (below) so that no seams show.
    void color_strip(double x0, double x1, double y0, double y1, std::span<const Color> colors);
    /// A heat map: nx × ny equal cells over [x0, x1] × [y0, y1]; colors row-major, row 0 at
    /// y0 (the bottom when y increases upward). colors.size() must be nx·ny.
    void cell_grid(double x0, double x1, double y0, double y1, int nx, int ny,
                   std::span<const Color> colors);
    /// The same as one image (a raster of nx × ny pixels scaled onto the rectangle, nearest
    /// neighbour when `smooth` is false, bilinear when true): compact in SVG (embedded PNG) for
    /// large grids. Colours with a < 1 are blended; a = 0 leaves the cell empty.
    void raster(double x0, double x1, double y0, double y1, int nx, int ny,
                std::span<const Color> colors, bool smooth = false);
    /// A legend entry without drawing anything (a swatch for a filled area, a line, a marker).
    void add_legend_line(std::string label, const LineStyle& style);
    void add_legend_swatch(std::string label, const Color& fill);
    void add_legend_marker(std::string label, const MarkerStyle& style);

    /// Draws frame, ticks, tick labels, axis titles, title and legend. Call once, last.
    void finish(LegendPosition legend = LegendPosition::top_right);
    /// The room (points) an outside_right legend with these labels needs right of the frame:
    /// for PlotOptions::right_reserve. font_size 0 → 12 × canvas.scale(), as Plot's default.
    [[nodiscard]] static double outside_legend_width(Canvas& canvas,
                                                     const std::vector<std::string>& labels,
                                                     double font_size = 0.0);
    /// Where finish() drew the legend (canvas coordinates); empty (0 × 0) when it drew none.
    [[nodiscard]] const Rect& legend_box() const noexcept { return m_legend_box; }

private:
    struct LegendEntry {
        enum class Kind { line, swatch, marker } kind;
        std::string label;
        LineStyle line;
        Color fill;
        MarkerStyle marker;
    };
    void clip_to_frame();
    void unclip();
    void draw_legend(LegendPosition position);

    Canvas* m_canvas;
    Rect m_area;
    Rect m_frame;
    Axis m_x, m_y;
    std::string m_title;
    PlotOptions m_options;
    double m_font_size;
    std::vector<LegendEntry> m_legend;
    Rect m_legend_box;
    bool m_finished = false;
};

/// A vertical colour bar in `bar` (canvas coordinates; the tick labels and title go right of
/// it, about 60 points × canvas.scale()): value `lo` at the bottom, `hi` at the top, colours
/// from `map(t)` with t = (value − lo)/(hi − lo), nice ticks. Throws irid::Error for lo ≥ hi.
void draw_color_bar(Canvas& canvas, const Rect& bar, double lo, double hi,
                    const std::string& title, const std::function<Color(double)>& map,
                    int max_ticks = 6);

}  // namespace irid::figures
