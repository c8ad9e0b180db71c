#pragma once

// The colour sets of the clip report, made where films are known (irid_figures).
//
// The clip report (include/irid/gamut/report.h) measures the sets its caller gives it:
// clipping knows no physics (docs/DESIGN.md: the arrows point down), so irid_gamut builds only
// the sets that need nothing but colour science (spectrum_color_set, rec2020_color_set,
// ramps_color_set, union_color_set). The interference set needs the film optics (irid_optics);
// it is made here, in the layer that needs colour, optics and gamut, together with the report's catalogue of
// sets by name. `irid clip-report`, the clip-claims table and the gallery take their sets from
// here and pass them to measure_clip_report / analyse_clip.
//
// - interference: thin-film colours from the exact optics (exact_film_color, unpolarised, D65,
//   CIE 1931 2°): a soap film air | water | air and mineral oil on water (air | mineral-oil |
//   water), thickness 0, 5, ..., 1500 nm at 0°, 30° and 60°, 1806 colours, XYZ multiplied by a
//   fixed exposure of 5 (interference_set_exposure). Films reflect at most about 19 % (Y), so
//   unexposed they sit in the dark third of the gamut and leave it only through its lower faces
//   (a channel below 0: 119 colours on sRGB at any exposure up to 4). × 5 is the largest round
//   exposure that keeps every colour below the white's luminance (max Y = 0.96), so every colour
//   still has a grey of its luminance inside the gamut, while the brightest also cross the upper
//   faces (158 out of sRGB).
// - spectrum, rec2020, ramps: irid_gamut's (docs/GAMUT.md, "The sets").

#include <irid/color/rgb.h>
#include <irid/gamut/report.h>

#include <span>
#include <string_view>
#include <vector>

namespace irid::figures {

/// The factor every interference colour's XYZ is multiplied by.
inline constexpr double interference_set_exposure = 5.0;

/// The interference set, XYZ relative to the destination's white (Y = 1 for the white).
[[nodiscard]] ColorSet interference_color_set(const RgbSpace& destination);

/// The sets of the clip report.
enum class ClipReportSet { spectrum, interference, rec2020, ramps };

/// Every set, in the order of the report.
[[nodiscard]] std::span<const ClipReportSet> clip_report_sets() noexcept;
/// "spectrum", "interference", "rec2020", "ramps".
[[nodiscard]] std::string_view clip_report_set_name(ClipReportSet set) noexcept;
/// One set by name, or every set for "all". Throws irid::Error listing the valid names.
[[nodiscard]] std::vector<ClipReportSet> parse_clip_report_sets(std::string_view name);
/// One set by its enumerator, relative to the destination's white: spectrum_color_set(),
/// interference_color_set(destination), rec2020_color_set(destination) or
/// ramps_color_set(destination).
[[nodiscard]] ColorSet clip_report_color_set(ClipReportSet set, const RgbSpace& destination);

}  // namespace irid::figures
