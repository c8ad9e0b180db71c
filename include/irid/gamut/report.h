#pragma once

// The clip report: what every gamut-clipping method does to sets of colours a display cannot
// show, measured against the input colour, and how fast it does it (`irid clip-report`; the
// results and their reading are in docs/GAMUT.md).
//
// Sets. Each is a list of XYZ colours relative to the destination's white (white Y = 1); some
// are out of the destination's gamut, some not:
// - spectrum: the monochromatic stimuli 380, 381, ..., 780 nm (CIE 1931 2°, monochromatic_xyz),
//   401 colours, each scaled to Y = 0.3. The thesis (Smits 1990, §4.3.4) clips the spectrum
//   scaled to a constant luminance; 0.3 is a mid luminance whose grey lies inside every gamut
//   (the grey of Y = 0.3 is RGB (0.3, 0.3, 0.3) in any space whose white has Y = 1), so no
//   method is forced to white or black and the luminance-keeping methods can keep it.
// - interference: thin-film colours from the exact optics (exact_film_color, unpolarised, D65,
//   CIE 1931 2°): a soap film air | water | air and mineral oil on water (air | mineral-oil |
//   water), thickness 0, 5, ..., 1500 nm at 0°, 30° and 60°, 1806 colours, XYZ multiplied by a
//   fixed exposure of 5 (interference_set_exposure). Films reflect at most about 19 % (Y), so
//   unexposed they sit in the dark third of the gamut and leave it only through its lower faces
//   (a channel below 0: 119 colours on sRGB at any exposure up to 4). × 5 is the largest round
//   exposure that keeps every colour below the white's luminance (max Y = 0.96), so every colour
//   still has a grey of its luminance inside the gamut, while the brightest also cross the upper
//   faces (158 out of sRGB).
// - rec2020: linear Rec.2020 on a 9 × 9 × 9 grid over [0, 1]³ (surface and interior, 729
//   colours), to XYZ: the everyday Rec.2020 → sRGB case.
// - all: the union (2936 colours), reported per set and over the whole.
// XYZ from a space with another white is adapted to the destination's white by Bradford.
//
// Measurements, per method (every one of clip_methods()), on a Gamut (a destination space's
// linear cube [0, max]³): each colour becomes linear RGB of the destination (the input colour;
// its XYZ is recomputed from that RGB, so that an untouched colour measures exactly 0) and is
// clipped by GamutClipper::clip, or for smits-xyz by GamutClipper::clip_xyz on its XYZ. Then,
// with XYZ divided by max (white Y = 1), against the input:
// - ΔE2000: CIEDE2000 of CIELAB relative to the destination's white; mean, 95th percentile
//   (nearest rank: the ⌈0.95 n⌉-th smallest) and maximum over the whole set.
// - Hue shift |Δh| in degrees (0..180) of CIELAB h_ab and of Oklab (XYZ adapted to D65 by
//   Bradford when the destination's white is not D65), over the colours whose input has a hue:
//   C*ab > 1 (CIELAB), C > 0.005 (Oklab). An output that is a grey of the destination (its
//   linear RGB channels equal within 1e-9 max: a colour sent to black or white) has no hue; it is
//   left out of the hue figures and counted in hue_undefined (its loss shows in ΔE2000, |ΔY| and
//   chroma kept). Oklab's white is not exactly achromatic (the D65 white has Oklab C ≈ 1.3e-4 with
//   the published matrices), so a chroma threshold would not recognise it. The CIELUV hue h_uv
//   (C*uv > 1) is measured the same way but not printed.
// - |ΔY|: |Y_out − Y_in| of the relative luminance (white Y = 1), mean and maximum.
// - Chroma kept: the mean of C*ab_out / C*ab_in over the colours with C*ab_in > 1.
// - Colours per second: the whole set clipped again and again (single thread, the scalar
//   GamutClipper API, inputs prepared beforehand, outputs into an array) for at least
//   min_seconds (0.2 s) of std::chrono::steady_clock, in this run, as 10 rounds of at least
//   min_seconds / 10 each; the figure is the median of the rounds' rates, so that another
//   process taking the CPU for a moment does not move it. The only figure that is not
//   deterministic.
// - Out of gamut: the colours of the set with a channel below −1e-9 max or above (1 + 1e-9) max
//   (so rounding in the conversions does not count).

#include <irid/color/rgb.h>
#include <irid/color/types.h>
#include <irid/gamut/clip.h>

#include <cstddef>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace irid {

/// The sets of colours of the report.
enum class ClipReportSet { spectrum, interference, rec2020 };

/// Every set, in the order of the report.
[[nodiscard]] std::span<const ClipReportSet> clip_report_sets() noexcept;
/// "spectrum", "interference", "rec2020".
[[nodiscard]] std::string_view clip_report_set_name(ClipReportSet set) noexcept;
/// One set by name, or every set for "all". Throws irid::Error listing the valid names.
[[nodiscard]] std::vector<ClipReportSet> parse_clip_report_sets(std::string_view name);

/// The luminance every colour of the spectrum set is scaled to.
inline constexpr double spectrum_set_luminance = 0.3;
/// The factor every interference colour's XYZ is multiplied by.
inline constexpr double interference_set_exposure = 5.0;
/// Grid points per axis of the rec2020 set.
inline constexpr int rec2020_set_steps = 9;
/// Rounds of the speed measurement (the median is reported).
inline constexpr int clip_report_timing_rounds = 10;
/// Hue thresholds: the input chroma above which a colour has a hue to shift.
inline constexpr double clip_report_min_chroma_ab = 1.0;
inline constexpr double clip_report_min_chroma_oklab = 0.005;
inline constexpr double clip_report_min_chroma_uv = 1.0;

/// A named list of colours, XYZ relative to the destination's white (Y = 1 for the white).
struct ColorSet {
    std::string name;
    /// One sentence: what the colours are.
    std::string description;
    std::vector<Xyz> colors;
};

/// The spectrum set (it does not depend on the destination: monochromatic light has no white).
[[nodiscard]] ColorSet spectrum_color_set();
/// The interference set, relative to the destination's white.
[[nodiscard]] ColorSet interference_color_set(const RgbSpace& destination);
/// The rec2020 set on a steps³ grid (steps >= 2), relative to the destination's white.
[[nodiscard]] ColorSet rec2020_color_set(const RgbSpace& destination, int steps = rec2020_set_steps);
/// One of the above by its enumerator.
[[nodiscard]] ColorSet clip_report_color_set(ClipReportSet set, const RgbSpace& destination);
/// The concatenation of sets, in order.
[[nodiscard]] ColorSet union_color_set(std::span<const ColorSet> sets, std::string name = "all");

/// Mean, 95th percentile (nearest rank) and maximum of `count` values; all 0 when count is 0.
struct ClipStatistics {
    double mean = 0.0, p95 = 0.0, max = 0.0;
    std::size_t count = 0;
};

/// What one method did to one set.
struct MethodClipReport {
    ClipMethod method = ClipMethod::clamp;
    ClipStatistics delta_e2000;
    /// |Δh| in degrees, over the colours with a hue (see above).
    ClipStatistics hue_lab, hue_oklab, hue_luv;
    /// Colours with an input hue (C*ab > 1) whose output is a grey of the destination.
    std::size_t hue_undefined = 0;
    ClipStatistics delta_y;
    /// Mean C*ab_out / C*ab_in over chroma_kept_count colours (1 when there are none).
    double chroma_kept = 1.0;
    std::size_t chroma_kept_count = 0;
    /// Speed: the median rate of the rounds; timed_colors were clipped in timed_seconds in all
    /// (whole passes over the set).
    double colors_per_second = 0.0;
    std::size_t timed_colors = 0;
    double timed_seconds = 0.0;
};

/// The report of one set on one gamut.
struct ClipReport {
    std::string set_name;
    std::string set_description;
    /// The destination space's name and the gamut's maximum.
    std::string destination;
    double max = 1.0;
    std::size_t size = 0;
    std::size_t out_of_gamut = 0;
    /// One entry per method, in the order of clip_methods().
    std::vector<MethodClipReport> methods;
};

struct ClipReportOptions {
    /// Each method's timing runs passes over the set for at least this long in all (10 rounds;
    /// 0: a single pass). Throws irid::Error unless finite and in [0, 60].
    double min_seconds = 0.2;
};

/// Measures every method on a set (see the top of this file). Throws irid::Error for an empty
/// set or a bad option.
[[nodiscard]] ClipReport measure_clip_report(const ColorSet& set, const Gamut& gamut,
                                             const ClipReportOptions& options = {});

/// The report as Markdown: a first line naming the set, its size, how many colours are out of
/// the gamut and what they are, a blank line, then a table with one row per method: method,
/// ΔE00 mean, ΔE00 p95, ΔE00 max, hue° Lab mean / max, hue° OKLab mean / max, |ΔY| mean / max,
/// chroma kept, colours/s; a note follows when some outputs had no hue.
[[nodiscard]] std::string clip_report_markdown(const ClipReport& report);

}  // namespace irid
