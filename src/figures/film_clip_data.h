#pragma once

// The numbers behind the figures hue-shift, clip-claims, film-error, newton and morpho-angle,
// computed from the library (irid_gamut's clip analysis, irid_optics' film models) and kept apart
// from the drawing so that tests/figures/ can check them. Private to irid_figures and its tests.

#include <irid/color/types.h>
#include <irid/gamut/analysis.h>
#include <irid/gamut/clip.h>
#include <irid/gamut/report.h>
#include <irid/optics/film_color.h>
#include <irid/optics/film_error_study.h>
#include <irid/optics/thesis_models.h>

#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace irid::figures::detail {

// --- hue-shift: hue change against wavelength, per clip method ------------------------------

/// The hue whose change a figure shows.
enum class HueMeasure { oklab, luv, lab };

/// "oklab" / "luv" / "lab" → the measure; anything else throws irid::Error listing them.
[[nodiscard]] HueMeasure parse_hue_measure(std::string_view name);
/// "Oklab h", "CIELUV h_uv", "CIELAB h_ab".
[[nodiscard]] std::string hue_measure_label(HueMeasure hue);
/// The signed change of that hue in a colour's analysis (NaN when undefined).
[[nodiscard]] double hue_shift_of(const ClipColorAnalysis& c, HueMeasure hue) noexcept;
/// The |Δh| statistics of that hue in a set of statistics.
[[nodiscard]] const ClipStatistics& hue_statistics_of(const HueShiftStatistics& s, HueMeasure hue) noexcept;

/// One method's curve: the signed hue change at every wavelength (NaN where undefined: the
/// output is black or white).
struct HueShiftCurve {
    ClipMethod method = ClipMethod::smits;
    std::vector<double> shift_deg;
    /// |Δh| over the defined points.
    ClipStatistics abs_shift;
};

struct HueShiftData {
    double luminance = spectrum_set_luminance;
    HueMeasure hue = HueMeasure::oklab;
    std::vector<double> wavelength_nm;
    std::vector<HueShiftCurve> curves;
};

/// The monochromatic stimuli 380–780 nm (1 nm) at Y = luminance, clipped into sRGB by every
/// method given (spectrum_hue_series).
[[nodiscard]] HueShiftData hue_shift_data(std::span<const ClipMethod> methods, HueMeasure hue,
                                          double luminance);

// --- clip-claims: the §4.3.4 summary per method ----------------------------------------------

/// The sets the table accepts: spectrum, interference, rec2020, all (their union).
[[nodiscard]] ColorSet clip_claims_set(std::string_view name);

/// The verdict on one claim of Smits 1990 §4.3.4 for one method.
struct ClaimVerdict {
    std::string claim;
    bool holds = false;
    /// One line: what was measured and what it means.
    std::string verdict;
};

/// The claims, judged on a method's summary:
/// 1. "lightness is constant": holds when max |ΔL*| (CIELAB and CIELUV) ≤ 1e-9 (rounding);
/// 2. "saturation is lower": holds when every clipped colour's s_uv fell;
/// 3. "the hue change is small" in the thesis' own hue, CIELUV h_uv: holds when max |Δh_uv| ≤ 1°;
/// 4. "... except where a face is nearly parallel to constant lightness": holds, for the hue
///    `hue`, when |Δh| correlates negatively with the face angle (r < −0.1) and the clipped
///    colours on the occupied faces nearest parallel have the largest mean |Δh| of all faces.
[[nodiscard]] std::vector<ClaimVerdict> clip_claim_verdicts(const ClipClaimsSummary& summary, HueMeasure hue);

/// The table: one row per method, a face table, and the verdicts for `verdict_method`.
[[nodiscard]] std::string clip_claims_markdown(const std::vector<ClipAnalysis>& analyses,
                                               const ColorSet& set, HueMeasure hue,
                                               ClipMethod verdict_method);
[[nodiscard]] std::string clip_claims_html(const std::vector<ClipAnalysis>& analyses, const ColorSet& set,
                                           HueMeasure hue, ClipMethod verdict_method);

// --- film-error: ΔE2000 of the thesis' single film against the exact one ---------------------

/// "soap" (air | water | air) or "oil" (air | mineral-oil | water), as irid film-error; anything
/// else throws irid::Error listing the names.
[[nodiscard]] SingleFilm film_by_name(std::string_view name);

/// ΔE2000 over thickness 0, step, ..., max and angle 0, step, ..., max (degrees), computed as
/// thesis_error_study computes each sample.
struct FilmErrorGrid {
    double k = 1.0;
    std::vector<double> thickness_nm, angle_deg;
    /// Row-major: delta_e[j * thickness_nm.size() + i] at angle j, thickness i.
    std::vector<double> delta_e;
    double mean = 0.0, median = 0.0, max = 0.0;
    double worst_thickness_nm = 0.0, worst_angle_deg = 0.0;
};
/// Throws irid::Error unless steps > 0, max thickness ≥ 0 and 0 ≤ max angle < 90.
[[nodiscard]] FilmErrorGrid film_error_grid(const SingleFilm& film, const Colorimeter& colorimeter,
                                            double k, double max_thickness_nm, double thickness_step_nm,
                                            double max_angle_deg, double angle_step_deg);

// --- newton: Newton's colour scale --------------------------------------------------------

/// How the strips' brightness is set before the sRGB clip.
enum class Brightness {
    /// The reflected colour as it is (a perfect white reflector has Y = 1).
    off,
    /// One factor per strip, so that its brightest colour has Y = strip_peak_luminance.
    strip,
    /// Every colour scaled to Y = each_luminance (only hue and saturation remain); colours with
    /// Y < 1e-6 stay black.
    each,
};
inline constexpr double strip_peak_luminance = 0.5;
inline constexpr double each_luminance = 0.3;

[[nodiscard]] Brightness parse_brightness(std::string_view name);
/// Applies the brightness rule to a strip of XYZ colours, in place.
void normalise_brightness(std::vector<Xyz>& colors, Brightness brightness) noexcept;

/// The thicknesses in (0, max] where the reference wavelength is extinguished by a film of
/// index n: with the phase change (eq. 21) 2nt = m λ, t = m λ/(2n); without (eq. 22)
/// 2nt = (m − ½) λ. These are the order boundaries of Newton's scale: the path-difference phase
/// 2π · 2nt/λ passes a multiple of 2π (phase change) or an odd multiple of π (none).
[[nodiscard]] std::vector<double> order_boundaries_nm(double n, bool phase_change, double reference_nm,
                                                      double max_thickness_nm);

/// One strip of the scale.
struct NewtonStrip {
    std::string label;
    bool exact = false;
    bool phase_change = true;
    /// The film's index at the reference wavelength, and the order boundaries it gives.
    double n_at_reference = 1.0;
    std::vector<double> boundaries_nm;
    /// XYZ (D65, white Y = 1) at each thickness, before and after the brightness rule.
    std::vector<Xyz> raw, shown;
};

struct NewtonData {
    double reference_nm = 550.0;
    double k = 1.0;
    Brightness brightness = Brightness::strip;
    std::vector<double> thickness_nm;
    /// Thesis eq. 21, exact soap film, thesis eq. 22, exact film without a phase change.
    std::vector<NewtonStrip> strips;
};

/// The film of the "no phase change" strips: water on a substrate of index newton_substrate_n
/// (n between the ambient's 1 and the substrate's, so neither or both reflections shift).
inline constexpr double newton_substrate_n = 1.77;

/// The strips' films: the soap film air | water | air (phase_change) or water on a substrate of
/// index newton_substrate_n (not).
[[nodiscard]] SingleFilm newton_film(bool phase_change);

/// Thickness 0..max every step nm, D65 and CIE 1931 2° (the colorimeter's), K for the thesis
/// strips (thesis_matched_k of each film when k_matched, else 1).
[[nodiscard]] NewtonData newton_data(double max_thickness_nm, double step_nm, double reference_nm,
                                     bool k_matched, Brightness brightness, const Colorimeter& colorimeter);

// --- morpho-angle: the Morpho wing against viewing angle ------------------------------------

struct MorphoRowData {
    std::string label;
    /// XYZ (white Y = 1) at each angle, before and after the brightness rule.
    std::vector<Xyz> raw, shown;
    /// dominant_peak_nm of the spectrum at each angle [nm] (NaN: outside the visible range).
    std::vector<double> peak_nm;
};

struct MorphoAngleData {
    MorphoParameters wing;
    MorphoBlend blend;
    Brightness brightness = Brightness::strip;
    std::vector<double> angle_deg;
    /// Thesis eq. 29 (one wing), thesis eq. 29 blended, exact stack, exact stack blended.
    std::vector<MorphoRowData> rows;
};

/// The exact counterpart of the thesis' wing for the transfer-matrix method: `periods` layers of
/// chitin d₂ (constant index wing.n) separated by air gaps d₁, in air; air has n = 1 as eq. 29
/// assumes. Throws irid::Error as validate_morpho.
[[nodiscard]] FilmStack morpho_exact_stack(const MorphoParameters& wing);

/// The angles are the centres of equal cells over [0°, 90°]: (j + ½) step, j = 0 .. 90/step − 1
/// (step must divide 90; grazing incidence, 90°, carries no power into the stack). K of the
/// thesis' rows is 2/(l + 1)², so eq. 25 peaks at 1. The exact blend averages the exact stack's
/// spectra over exact_blend_samples values of the thickness the thesis' blend varies. Throws
/// irid::Error unless 0 < step ≤ 45 divides 90 and 2 ≤ exact_blend_samples ≤ 1001.
[[nodiscard]] MorphoAngleData morpho_angle_data(double step_deg, Brightness brightness,
                                                const Colorimeter& colorimeter, int exact_blend_samples);

/// The wavelength of a spectrum's largest value on the 1 nm grid 360–830 nm (the first on
/// ties); NaN when it lies outside 380–780 nm (its peak has left the visible range; a maximum at
/// an end of the grid is such a case).
[[nodiscard]] double dominant_peak_nm(const DenseSpectrum& spectrum) noexcept;

}  // namespace irid::figures::detail
