#pragma once

// The clip report (`irid clip-report`): what every gamut-clipping method does to sets of
// colours, measured against the input colour, and how fast. The sets, the ramps' geometry and
// the definition of every measurement are in docs/GAMUT.md ("The clip report" and "Gradients:
// the ramps"); percentiles are nearest rank (irid/color/measure.h).
//
// This library builds the sets that need colour science alone (spectrum, rec2020, ramps and
// their unions). The interference set needs film physics and is made in irid_figures
// (irid/figures/clip_sets.h); callers pass every set in as a ColorSet, XYZ relative to the
// destination's white at Y = 1.

#include <irid/color/measure.h>
#include <irid/color/rgb.h>
#include <irid/color/types.h>
#include <irid/gamut/clip.h>

#include <array>
#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <string_view>
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

/// The ramps set: luminances, hues and steps per ramp.
inline constexpr std::array<double, 3> ramp_set_luminances{0.1, 0.3, 0.6};
inline constexpr int ramp_set_hues = 24;
inline constexpr int ramp_set_steps = 256;
/// Collapse: neighbouring outputs within this ΔE2000 are "the same output" (a difference of
/// 0.5 ΔE00 is below what a viewer sees between two adjacent patches).
inline constexpr double clip_report_collapse_delta_e = 0.5;
/// Collapse ½ step: the threshold as a fraction of the ramp's mean input step.
inline constexpr double clip_report_relative_collapse = 0.5;

/// Where a ramp ends: where its line leaves the Rec.2020 cube, or meets the spectral locus.
enum class RampEnd { rec2020, locus };
/// "rec2020", "locus".
[[nodiscard]] std::string_view ramp_end_name(RampEnd end) noexcept;

/// Consecutive colours of a set that form one ramp, grey first.
struct ColorRamp {
    std::size_t first = 0;
    std::size_t size = 0;
    /// "Y 0.3, h 45°, to the locus".
    std::string label;
};

/// A named list of colours, XYZ relative to the destination's white (Y = 1 for the white).
struct ColorSet {
    std::string name;
    /// One sentence: what the colours are.
    std::string description;
    std::vector<Xyz> colors;
    /// The ramps among the colours (empty for sets that have none); each lies inside colors.
    std::vector<ColorRamp> ramps{};
};

/// The spectrum set (it does not depend on the destination: monochromatic light has no white).
[[nodiscard]] ColorSet spectrum_color_set();
/// The rec2020 set on a steps³ grid (steps >= 2), relative to the destination's white.
[[nodiscard]] ColorSet rec2020_color_set(const RgbSpace& destination, int steps = rec2020_set_steps);
/// The concatenation of sets, in order, with their ramps (moved to their new places).
[[nodiscard]] ColorSet union_color_set(std::span<const ColorSet> sets, std::string name = "all");

/// The parameter s_end of a ramp's end point G + s_end d and its direction d (dY = 0, see
/// docs/GAMUT.md), for the grey of `luminance` on `destination`.
struct RampGeometry {
    Xyz grey;
    Vec3 direction;
    double end = 0.0;
};
/// Throws irid::Error unless 0 < luminance < 1 (below the destination's white, whose Y is 1)
/// and hue_deg is finite.
[[nodiscard]] RampGeometry ramp_geometry(const RgbSpace& destination, double luminance,
                                         double hue_deg, RampEnd end);
/// The `steps` colours G + s_i d at equal CIEDE2000 arc length from s_0 = 0 (the grey, exactly) to
/// s_end (the end point, exactly). Throws irid::Error as ramp_geometry, or unless
/// 2 <= steps <= 65536.
[[nodiscard]] std::vector<Xyz> color_ramp(const RgbSpace& destination, double luminance,
                                          double hue_deg, RampEnd end, int steps = ramp_set_steps);
/// The ramps set: every luminance of ramp_set_luminances, both ends, ramp_set_hues hues
/// h = 360° k / ramp_set_hues, ramp_set_steps steps each, in that order (outermost first), with
/// one ColorRamp per ramp.
[[nodiscard]] ColorSet ramps_color_set(const RgbSpace& destination);

/// Banding of one ramp (docs/GAMUT.md): max over i of ΔE2000(lab[i], lab[i + 1])
/// over their mean; 1 for fewer than two colours or when every step is 0 (a ramp made one
/// colour: no step to see, its collapse shows it).
[[nodiscard]] double ramp_banding(std::span<const Lab> lab);
/// Collapse of one ramp: of the i < size − 1 with out_of_gamut[i], the share with
/// ΔE2000(lab[i], lab[i + 1]) <= threshold; nothing when there is no such i. The spans must
/// have the same size.
[[nodiscard]] std::optional<double> ramp_collapse(std::span<const Lab> lab,
                                                  std::span<const bool> out_of_gamut,
                                                  double threshold = clip_report_collapse_delta_e);

/// The clipper the report measures for a method: its parameters' defaults, with clip = true
/// for a method that has that parameter (aces-rgc), so that every output is inside the cube.
[[nodiscard]] GamutClipper report_clipper(ClipMethod method, const Gamut& gamut);

/// Mean, percentiles (nearest rank, irid/color/measure.h) and maximum of `count` values; all 0
/// when count is 0. The report prints mean, p95 and max.
using ClipStatistics = Statistics;

/// What one method did to one set.
struct MethodClipReport {
    ClipMethod method = ClipMethod::clamp;
    ClipStatistics delta_e2000;
    /// |Δh| in degrees, over the colours with a hue (C above the thresholds, output not a grey).
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
    /// ΔE2000 output against input over the colours inside the gamut (count: how many).
    ClipStatistics in_gamut_moved;
    /// Banding per ramp, over the ramps (count: the set's ramps; all 0 without ramps).
    ClipStatistics banding;
    /// Collapse per ramp, over the ramps with an out-of-gamut step (count: those ramps).
    ClipStatistics collapse;
    /// The same with half the ramp's mean input step as the threshold.
    ClipStatistics collapse_relative;
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
    /// The set's ramps, and the banding of the input ramps themselves (the reference).
    std::size_t ramps = 0;
    ClipStatistics input_banding;
    /// One entry per method, in the order of clip_methods().
    std::vector<MethodClipReport> methods;
};

struct ClipReportOptions {
    /// Each method's timing runs passes over the set for at least this long in all (10 rounds;
    /// 0: a single pass). Throws irid::Error unless finite and in [0, 60].
    double min_seconds = 0.2;
};

/// Measures every method on a set (docs/GAMUT.md). Throws irid::Error for an empty
/// set or a bad option.
[[nodiscard]] ClipReport measure_clip_report(const ColorSet& set, const Gamut& gamut,
                                             const ClipReportOptions& options = {});

/// The report as Markdown: a first line naming the set, its size, how many colours are out of
/// the gamut and what they are, a blank line, then a table with one row per method: method,
/// ΔE00 mean, ΔE00 p95, ΔE00 max, hue° Lab mean / max, hue° OKLab mean / max, |ΔY| mean / max,
/// chroma kept, colours/s; a note follows when some outputs had no hue. Then a second table
/// after a line naming its measures: method, in-gamut ΔE00 mean / max, banding mean / max,
/// collapse, collapse ½ step (means); "–" where the set has no such colours or ramps.
[[nodiscard]] std::string clip_report_markdown(const ClipReport& report);

}  // namespace irid
