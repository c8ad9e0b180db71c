#pragma once

// The clip report: what every gamut-clipping method does to sets of colours a display cannot
// show, measured against the input colour, and how fast it does it (`irid clip-report`; the
// results and their reading are in docs/GAMUT.md).
//
// Sets. The report measures the sets its caller gives it (ColorSet: a name, a description and
// XYZ colours relative to the destination's white, white Y = 1; some out of the destination's
// gamut, some not). Clipping knows no physics: this library builds only the sets that need
// nothing but colour science. The interference set of `irid clip-report` (thin-film colours,
// which need the film physics) is made in irid_figures (include/irid/figures/clip_sets.h, with
// the report's catalogue of sets by name), and its callers pass it in. The sets built here:
// - spectrum: the monochromatic stimuli 380, 381, ..., 780 nm (CIE 1931 2°, monochromatic_xyz),
//   401 colours, each scaled to Y = 0.3. The thesis (Smits 1990, §4.3.4) clips the spectrum
//   scaled to a constant luminance; 0.3 is a mid luminance whose grey lies inside every gamut
//   (the grey of Y = 0.3 is RGB (0.3, 0.3, 0.3) in any space whose white has Y = 1), so no
//   method is forced to white or black and the luminance-keeping methods can keep it.
// - rec2020: linear Rec.2020 on a 9 × 9 × 9 grid over [0, 1]³ (surface and interior, 729
//   colours), to XYZ: the everyday Rec.2020 → sRGB case.
// - a union of sets (`irid clip-report --set all`: spectrum, interference and rec2020, 2936
//   colours), reported per set and over the whole.
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
#include <vector>

namespace irid {

/// The luminance every colour of the spectrum set is scaled to.
inline constexpr double spectrum_set_luminance = 0.3;
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
/// The rec2020 set on a steps³ grid (steps >= 2), relative to the destination's white.
[[nodiscard]] ColorSet rec2020_color_set(const RgbSpace& destination, int steps = rec2020_set_steps);
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
