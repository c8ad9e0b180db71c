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
// - ramps: gradients from a grey out of the gamut (ramps_color_set, below), 36 864 colours in
//   144 ramps of 256 steps.
// - a union of sets (`irid clip-report --set all`: spectrum, interference, rec2020 and ramps,
//   39 800 colours), reported per set and over the whole; the union keeps every set's ramps.
// XYZ from a space with another white is adapted to the destination's white by Bradford.
//
// Ramps (ramps_color_set, color_ramp). A ramp at luminance Y and Oklab hue h starts at the grey
// of luminance Y, G = Y × the destination's white (XYZ, white Y = 1, so G.Y = Y exactly), and
// runs in a straight line at constant Y, G + s d with d = (dX, 0, dZ), out to an end point:
// - the direction d is the Oklab hue h at the grey: the direction of constant Y along which
//   Oklab (a, b) starts out as (cos h, sin h), i.e. [dX, dZ] = J⁻¹ (cos h, sin h) with J the
//   2 × 2 Jacobian of Oklab (a, b) with respect to (X, Z) at G (Oklab after Bradford adaptation
//   to D65 when the destination's white is not D65, as the hue is measured below);
// - end rec2020: the smallest s > 0 at which a channel of linear Rec.2020 (adapted to the
//   destination's white) reaches 0 or 1: the point where the line leaves the Rec.2020 cube;
// - end locus: the largest s > 0 at which the chromaticity of G + s d lies on the spectral
//   locus: the polygon of the chromaticities of monochromatic_xyz(λ), λ = 380, 381, ..., 780 nm
//   (the CIE table is linear between its 1 nm entries, so its chromaticities between two entries
//   are the straight segment between theirs), closed by the purple line 780–380 nm; each
//   segment is solved exactly as G + s d = α m(λ) + β m(λ + 1), α, β ≥ 0 (the largest s: the
//   outer boundary where the table's long-wavelength end folds back on itself). XYZ of
//   monochromatic light is taken as it is (not adapted), as in the spectrum set.
// The ramp's 256 steps are evenly spaced in CIEDE2000, the measure of banding below: at equal
// ΔE2000 arc length along the line (CIELAB relative to the destination's white, ΔE2000 summed
// over 4096 equal pieces of s, each step placed by linear interpolation within its piece), the
// first exactly the grey and the last exactly the end point; so the input ramps themselves
// score a banding of about 1. Evenly spaced in s (XYZ) or in Oklab they would not be: CIEDE2000
// weighs a chroma step beside the neutral axis up to 1.5 times more (its G term) and one at
// chroma C far less (S_C = 1 + 0.045 C), and far out on a long ramp (toward violet the locus at
// Y = 0.6 has Z ≈ 59) a step in XYZ is a far smaller step to the eye than one beside the grey.
// Why constant Y rather than constant Oklab L: every step then has exactly the ramp's
// luminance (the ramps are at Y = 0.1, 0.3 and 0.6, as stated), the line is straight in XYZ and
// in every linear RGB (a gradient as a renderer or a saturation control in linear light makes
// it), the end points are exact (linear conditions), and it is the line along which the thesis'
// methods move a colour toward its grey: a hard clip of that family sends the whole tail beyond
// the boundary onto one point, which is what the ramps are to show. The price: Oklab hue lines
// curve in the chromaticity diagram, so the Oklab hue drifts along the ramp from h at the grey
// (most toward blue); the report prints the input ramps' own banding, the score of a method
// that changed nothing, as the reference.
// Order: Y = 0.1, 0.3, 0.6; for each, the rec2020 ends, then the locus ends; for each, the hues
// h = 0°, 15°, ..., 345°; for each, the 256 steps from the grey outward (ColorSet::ramps names
// them). Luminance beyond the gamut's white: a gamut whose white is below a ramp's luminance
// (Gamut max < Y) has no grey of it; that ramp is then out of gamut from its first step, and
// the methods that keep luminance send it all to the white (its banding is then 1 and its
// collapse 1, below). At Y = 0.6 the locus ends of the blue and violet hues lie far outside
// every display cube (channels of tens), as the spectrum at high luminance does; every method
// returns a finite colour for them and they are measured like any other.
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
// - In-gamut moved: ΔE2000 between output and input over the set's colours that are not out of
//   gamut (mean and max; 0 for every method that leaves in-gamut colours alone, which the soft
//   methods, moves_in_gamut_colours(), do not).
// - Banding, over the set's ramps (ColorSet::ramps): per ramp, ramp_banding of its outputs:
//   the largest ΔE2000 between neighbouring outputs divided by the mean of those ΔE2000 over
//   the ramp (1: every step alike; a hard clip that stops the tail on the boundary has its
//   steps inside and then nothing, and its knee shows as a large ratio). The mean, p95 and max
//   over the ramps. The same of the input ramps is ClipReport::input_banding.
// - Collapse, over the set's ramps: per ramp, ramp_collapse: of its steps 0..254 whose input is
//   out of gamut (the last step has no next), the share whose output is within ΔE2000 0.5
//   (clip_report_collapse_delta_e) of the next step's output; the mean over the ramps that have
//   such a step (a ramp inside the gamut has none and is not counted). With 256 steps the
//   input ramps' own steps are 0.08 to 0.34 ΔE2000 (their lengths are 19 to 87), below 0.5,
//   so this share is near 1 for every method, soft or hard; the report therefore also gives
//   collapse ½ step: the same share with the threshold half the ramp's mean input step
//   (clip_report_relative_collapse), which a method reaches only by compressing the tail to
//   less than half its length (a hard clip: to nothing).
// - Clippers: each method at its parameters' defaults, except aces-rgc with clip = true
//   (report_clipper): the report measures what a display gets, and aces-rgc alone does not
//   confine its output to the cube.

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

/// Where a ramp ends (see the top of this file).
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

/// The parameter s_end of a ramp's end point G + s_end d and its direction d (dY = 0, see the
/// top of this file), for the grey of `luminance` on `destination`.
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

/// Banding of one ramp (see the top of this file): max over i of ΔE2000(lab[i], lab[i + 1])
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

/// Measures every method on a set (see the top of this file). Throws irid::Error for an empty
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
