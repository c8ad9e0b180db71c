#pragma once

// The numbers behind figures-A's figures (cmf-primaries, cmf-xyz, chromaticity, clip-geometry,
// spectrum-clip, film-spectra, table1), computed from the library and kept apart from the
// drawing so that tests/figures/ can check them.

#include <irid/color/observer.h>
#include <irid/color/primaries.h>
#include <irid/color/rgb.h>
#include <irid/color/types.h>
#include <irid/gamut/clip.h>
#include <irid/optics/film.h>
#include <irid/optics/film_color.h>

#include "plot.h"

#include <span>

#include <string>
#include <string_view>
#include <vector>

namespace irid::figures::detail {

/// A named curve: y over x.
struct Series {
    std::string label;
    std::vector<double> x, y;
};

/// The largest y of a series and the x where it occurs (the first, on ties).
struct Peak {
    double x = 0.0, y = 0.0;
};
[[nodiscard]] Peak series_peak(const Series& s);
/// The smallest y and its x.
[[nodiscard]] Peak series_minimum(const Series& s);

/// x̄, ȳ, z̄ of `observer` at every tabulated nanometre, 360–830 nm (labels "x̄", "ȳ", "z̄").
[[nodiscard]] std::vector<Series> cmf_xyz_series(Observer observer);

/// r̄, ḡ, b̄ of three monochromatic primaries at every tabulated nanometre, 360–830 nm (labels
/// "r̄ (645 nm)", ...), in the order red, green, blue.
[[nodiscard]] std::vector<Series> primary_cmf_series(const PrimaryMatchingFunctions& p);

// --- chromaticity ---------------------------------------------------------------------------

/// The chromaticity diagram's plane: CIE 1931 xy or CIE 1976 u′v′.
enum class Diagram { xy, uv };

/// A chromaticity in the diagram's coordinates (x, y) or (u′, v′).
[[nodiscard]] Point diagram_point(const Xy& xy, Diagram diagram) noexcept;

/// The CIE 1931 spectral locus from lo_nm to hi_nm every step_nm (both ends included).
[[nodiscard]] std::vector<Point> spectral_locus(Diagram diagram, double lo_nm = 360.0,
                                                double hi_nm = 830.0, double step_nm = 1.0);

/// Area of a simple polygon (shoelace formula), positive whatever the orientation.
[[nodiscard]] double polygon_area(std::span<const Point> polygon) noexcept;

/// True when p lies inside the polygon (even-odd rule).
[[nodiscard]] bool inside_polygon(std::span<const Point> polygon, Point p) noexcept;

/// The triangle of a space's primaries, red, green, blue.
[[nodiscard]] std::vector<Point> gamut_triangle(const RgbSpace& space, Diagram diagram);

/// The fill colour of the diagram at chromaticity xy: the colour of that chromaticity at the
/// luminance where its largest linear sRGB channel is 1, brought into sRGB by `clipper` (which
/// moves colours outside the sRGB triangle toward the grey), encoded.
[[nodiscard]] Color chromaticity_fill_color(const Xy& xy, const GamutClipper& clipper) noexcept;

// --- clip geometry --------------------------------------------------------------------------

/// The slice of a gamut's cube [0, max]³ at luminance Y: the polygon where the plane
/// A r + B g + C b = Y (A, B, C: Gamut::luminance_row) cuts the cube, as its vertices in linear
/// RGB, in order around the polygon (by angle about their mean in xy). Empty unless
/// 0 < Y < the white's luminance.
[[nodiscard]] std::vector<Rgb> luminance_slice(const Gamut& gamut, double Y);

/// Where one clip method puts a colour.
struct ClipLanding {
    ClipMethod method;
    Rgb rgb;      ///< clipped linear RGB
    Xyy xyy;      ///< its chromaticity and luminance
    double hue_shift_deg = 0.0;  ///< CIELUV hue h_uv after minus before, in (−180, 180]
};
/// Clips `xyz` (relative to the gamut's white) by each method.
[[nodiscard]] std::vector<ClipLanding> clip_landings(const Gamut& gamut, const Xyz& xyz,
                                                     std::span<const ClipMethod> methods);

// --- spectrum clip ----------------------------------------------------------------------------

/// Linear RGB of `space` of the monochromatic colours at lo_nm, lo_nm + step_nm, ..., hi_nm,
/// each scaled to luminance Y (relative to the space's white), unclipped.
[[nodiscard]] std::vector<Rgb> equal_luminance_spectrum(const RgbSpace& space, double lo_nm,
                                                        double hi_nm, double step_nm, double Y);

/// `colors` clipped by `clipper` through the batch API (clip_batch on float RGB, as an image
/// would be), back in double.
[[nodiscard]] std::vector<Rgb> clip_colors_batch(const GamutClipper& clipper,
                                                 std::span<const Rgb> colors);

/// The default order of the spectrum-clip strips: clamp, smits, luv-hue (the thesis' Figure
/// 11), then every other method in clip_methods() order.
[[nodiscard]] std::vector<ClipMethod> spectrum_clip_default_methods();

// --- film spectra -----------------------------------------------------------------------------

/// One film of the film-spectra figure: "thickness_nm[@material]".
struct FilmSpec {
    double thickness_nm = 0.0;
    /// The film's material as given ("" → the figure's film= option).
    std::string material;
};
/// Parses "100", "250@mineral-oil", "300@1.5". Throws irid::Error naming the item unless the
/// thickness is a finite number in [0, 10000] nm; the material is checked by the caller.
[[nodiscard]] FilmSpec parse_film_spec(std::string_view item);

/// A single film's reflectance on the 1 nm grid through the film models (irid/optics/film.h):
/// the thesis' eq. 21/22 with K = k, or the exact Airy film.
[[nodiscard]] DenseValues film_reflectance(const SingleFilm& film, double thickness_nm, double angle_rad,
                                           bool thesis, double k);

/// The reflectance of a single film at every whole nanometre in [lo_nm, hi_nm], as
/// film_reflectance gives it. angle_rad in the ambient.
[[nodiscard]] Series film_reflectance_series(const SingleFilm& film, double thickness_nm,
                                             double angle_rad, bool thesis, double k,
                                             double lo_nm = 380.0, double hi_nm = 780.0);

// --- Table 1 ----------------------------------------------------------------------------------

/// A range of operation counts as the thesis gives them ("5–7"; lo == hi for one number).
struct CountRange {
    long lo = 0, hi = 0;
    [[nodiscard]] bool contains(long v) const noexcept { return v >= lo && v <= hi; }
};
/// Smits 1990, Table 1: operations per clipped colour of the RGB clip.
inline constexpr CountRange thesis_comparisons{5, 7};
inline constexpr CountRange thesis_additions{9, 11};
inline constexpr CountRange thesis_multiplications{7, 7};
inline constexpr CountRange thesis_divisions{1, 3};

/// Table 1 as Markdown: a heading, one row per case of count_smits_operations() and the
/// thesis' row, then notes on the differences.
[[nodiscard]] std::string table1_markdown(const Table1& counts);
/// The same as HTML: a whole page when `page`, else a fragment (<section>...</section>) for
/// embedding.
[[nodiscard]] std::string table1_html(const Table1& counts, bool page);

}  // namespace irid::figures::detail
