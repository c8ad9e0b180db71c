#pragma once

// The thesis' claims for its clip, measured (Smits 1990, §4.3.4). For the constant-lightness
// clip (ClipMethod::smits) the thesis claims that
//   1. lightness is constant for every clipped colour,
//   2. saturation is lower, and
//   3. the hue change is small, except where a face of the gamut is nearly parallel to the plane
//      of constant lightness.
// analyse_clip() measures what any clip method does to every colour of a set on these three
// counts, and summarises the set.
//
// Conventions (those of the clip report, defined in docs/GAMUT.md, so the two agree):
// - Each colour of the set (XYZ relative to the destination's white) becomes linear RGB of the
//   destination; its XYZ is recomputed from that RGB (the input); it is clipped by
//   GamutClipper::clip, or for smits-xyz by GamutClipper::clip_xyz on its XYZ (the output).
//   Measurements use XYZ divided by the gamut's max (white Y = 1).
// - Out of gamut (clipped): a channel of the input below −1e-9 max or above (1 + 1e-9) max. The
//   summary is over these colours only; the others are in the gamut, and every method returns
//   them unchanged.
// - Lightness: L* of CIELAB and of CIELUV relative to the destination's white (they are the same
//   function of Y, CIE 015:2018 §8.2, computed through each space independently).
// - Saturation: s_uv = 13 [(u' − u'n)² + (v' − v'n)²]^½ = C*uv / L* (CIE 015:2018 §8.2.2).
//   Lower means s_out < s_in (1 − 1e-9); higher means s_out > s_in (1 + 1e-9); anything between
//   is equal (rounding).
// - Hue: the signed change h_out − h_in in degrees, wrapped to (−180, 180], of CIELUV h_uv,
//   CIELAB h_ab and Oklab h (XYZ adapted to D65 by Bradford when the destination's white is not
//   D65). A hue change is defined when the input has a hue (C*uv > 1, C*ab > 1, Oklab C > 0.005:
//   the clip report's thresholds) and the output is not a grey of the destination (its linear RGB
//   channels equal within 1e-9 max: black or white); otherwise it is NaN.
// - The face: every output of a clip that changed the colour lies on the cube's surface, with one
//   channel at 0 or at max (within 1e-9 max); two such channels put it on an edge. The face
//   reported is the one among those whose bound the input crossed farthest (the largest distance
//   of the input's channel beyond the bound, negative when inside).
// - The face angle: each face of the cube [0, max]³ lies in a plane row_i · XYZ = 0 or = max,
//   row_i the i-th row of the space's XYZ → RGB matrix, so row_i is the face's normal (both
//   faces of a channel are parallel). The plane of constant luminance Y = const has the normal
//   (0, 1, 0). The angle between the planes is the angle between the normals,
//   acos(|row_i,Y| / |row_i|), in degrees: 0° means the face is parallel to the plane of
//   constant Y (and so of constant L*). It is measured in CIE XYZ, which the thesis' argument
//   uses; a linear map of XYZ would change it.

#include <irid/color/rgb.h>
#include <irid/color/types.h>
#include <irid/gamut/clip.h>
#include <irid/gamut/report.h>

#include <array>
#include <cstddef>
#include <span>
#include <string>
#include <vector>

namespace irid {

/// A face of the RGB cube [0, max]³: a channel (0 r, 1 g, 2 b) at 0 or at max.
struct GamutFace {
    int channel = 0;
    bool upper = false;

    /// 0..5: 2 channel + upper (r=0, r=max, g=0, g=max, b=0, b=max).
    [[nodiscard]] int index() const noexcept { return 2 * channel + (upper ? 1 : 0); }
    [[nodiscard]] static GamutFace from_index(int index) noexcept { return {index / 2, index % 2 == 1}; }
    [[nodiscard]] friend bool operator==(const GamutFace&, const GamutFace&) = default;
};

inline constexpr int gamut_face_count = 6;

/// "r=0", "r=max", "g=0", ...
[[nodiscard]] std::string gamut_face_name(GamutFace face);

/// The angle in degrees (0..90) between the faces of a channel (0 r, 1 g, 2 b) of the space's
/// cube and the plane of constant Y in XYZ (see the top of this file). Throws irid::Error for a
/// channel outside 0..2.
[[nodiscard]] double face_angle_to_constant_y_deg(const RgbSpace& space, int channel);
/// The three angles, r, g, b.
[[nodiscard]] std::array<double, 3> face_angles_to_constant_y_deg(const RgbSpace& space);

/// What a clip did to one colour.
struct ClipColorAnalysis {
    /// XYZ relative to the destination's white, divided by max (white Y = 1).
    Xyz xyz_in, xyz_out;
    /// Linear RGB of the destination (in the cube [0, max]³ for the output).
    Rgb rgb_in, rgb_out;
    bool out_of_gamut = false;
    /// L*_out − L*_in of CIELAB and of CIELUV.
    double delta_l_ab = 0.0, delta_l_uv = 0.0;
    /// s_uv = C*uv / L* of input and output.
    double saturation_in = 0.0, saturation_out = 0.0;
    /// Signed hue changes in degrees, (−180, 180]; NaN when undefined (see the top of the file).
    double hue_shift_uv = 0.0, hue_shift_ab = 0.0, hue_shift_oklab = 0.0;
    /// The face the output lies on, when it lies on one; faces_touched counts the channels at a
    /// bound (2 or 3: an edge or a corner).
    bool on_face = false;
    GamutFace face;
    int faces_touched = 0;
    /// The face's angle to the plane of constant Y [degrees]; NaN when not on a face.
    double face_angle_deg = 0.0;
};

/// |Δh| statistics of the three hue measures over a group of clipped colours.
struct HueShiftStatistics {
    ClipStatistics uv, ab, oklab;
};

/// The clipped colours that ended on one face.
struct FaceHueStatistics {
    GamutFace face;
    double angle_deg = 0.0;
    std::size_t count = 0;
    HueShiftStatistics hue;
};

/// The clipped colours whose face angle is in [min_deg, max_deg) (the last bin includes 90°).
struct AngleBinHueStatistics {
    double min_deg = 0.0, max_deg = 0.0;
    std::size_t count = 0;
    HueShiftStatistics hue;
};

/// Width of the face-angle bins of the summary [degrees].
inline constexpr double clip_analysis_angle_bin_deg = 15.0;

/// The set's summary, over the clipped (out-of-gamut) colours.
struct ClipClaimsSummary {
    std::size_t size = 0;
    std::size_t clipped = 0;
    /// Claim 1: max |ΔL*| of CIELAB and CIELUV (0 when nothing is clipped).
    double max_abs_delta_l_ab = 0.0, max_abs_delta_l_uv = 0.0;
    /// Claim 2: clipped colours whose saturation fell, stayed and rose; the indices (into the set)
    /// of those whose saturation did not fall.
    std::size_t saturation_lower = 0, saturation_equal = 0, saturation_higher = 0;
    std::vector<std::size_t> saturation_exceptions;
    /// Claim 3: |Δh| over the clipped colours with a defined hue change, and how many clipped
    /// colours had none (uv, ab, oklab).
    HueShiftStatistics hue;
    std::array<std::size_t, 3> hue_undefined{};
    /// By the face reached (gamut_face_count entries, in GamutFace::index order).
    std::array<FaceHueStatistics, gamut_face_count> faces{};
    /// By face angle, bins of clip_analysis_angle_bin_deg from 0° to 90°.
    std::vector<AngleBinHueStatistics> angle_bins;
    /// Pearson's correlation between the face angle and |Δh| over the clipped colours on a face
    /// with a defined hue change (uv, ab, oklab); NaN when fewer than two such colours or either
    /// variable is constant. Negative: the hue changes more on faces nearer parallel.
    double correlation_uv = 0.0, correlation_ab = 0.0, correlation_oklab = 0.0;
    /// Clipped colours whose output lies on an edge or a corner (two or three channels at a bound).
    std::size_t on_edge = 0;
};

/// One method on one set.
struct ClipAnalysis {
    ClipMethod method = ClipMethod::smits;
    std::string set_name;
    /// The destination space's name and the gamut's max.
    std::string destination;
    double max = 1.0;
    /// One entry per colour of the set, in order.
    std::vector<ClipColorAnalysis> colors;
    ClipClaimsSummary summary;
};

/// Measures one method on a set (see the top of this file). Throws irid::Error for an empty set.
[[nodiscard]] ClipAnalysis analyse_clip(const ColorSet& set, const Gamut& gamut, ClipMethod method);

/// The monochromatic stimuli min_nm, min_nm + step_nm, ..., max_nm (CIE 1931 2°,
/// monochromatic_xyz), each scaled to Y = luminance: spectrum_color_set() at another luminance
/// or spacing. Throws irid::Error unless 0 < luminance ≤ 1e6, 360 ≤ min_nm ≤ max_nm ≤ 830 and
/// step_nm > 0 (all finite).
[[nodiscard]] ColorSet monochromatic_color_set(double luminance, double min_nm = 380.0,
                                               double max_nm = 780.0, double step_nm = 1.0);

/// Hue change against wavelength: one method's analysis of the monochromatic set, with the
/// wavelength of every colour.
struct SpectrumHueSeries {
    std::vector<double> wavelength_nm;
    ClipAnalysis analysis;
};
/// The series of every method given, on monochromatic_color_set(luminance) (380-780 nm at 1 nm).
[[nodiscard]] std::vector<SpectrumHueSeries> spectrum_hue_series(
    const Gamut& gamut, std::span<const ClipMethod> methods,
    double luminance = spectrum_set_luminance);

}  // namespace irid
