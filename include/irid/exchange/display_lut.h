#pragma once

// A display transform (irid/gamut/display_transform.h) baked as a 3D LUT, for the tools that
// cannot run it: OpenColorIO 2.1 (which has no ACES 2.0), Resolve, Nuke. docs/DISPLAY.md
// ("LUTs and OpenColorIO 2.1") measures how closely the LUT stands for the transform.

#include <irid/exchange/lut.h>
#include <irid/gamut/display_transform.h>

#include <string>
#include <string_view>

namespace irid {

/// The stops below the domain's top that the default log2 shaper of a display LUT spans: from
/// ACES 2.0's forward limit (1024 at 100 cd/m², 4096 at 1000) down to its offset e = limit ·
/// 2^-16 (2^-6 and 2^-4); log2(x + e) steps almost evenly in x below e (irid/exchange/lut.h).
/// Of 14 to 24 stops, 16 gave the smallest p95 and p99 ΔE2000 at 33³ and 65³ on both displays
/// measured, over random colours of the 18-stop and of the 24-stop domain alike
/// (scripts/display-lut-stops; docs/DISPLAY.md, "How closely the LUT stands for the transform").
inline constexpr int display_lut_stops = 16;

/// The space in which a display LUT over light lays out its cube: AP1 (ACEScg), where the ACES
/// 2.0 display chain clamps its input to [0, the forward limit] (aces2_display.h, step 1).
inline constexpr std::string_view display_lut_cube_space = "acescg-linear";

/// Throws irid::Error unless `source` (a name of irid/color/convert.h) can be a display LUT's
/// input, which every channel of is one range: light (xyz, or an RGB space's linear light, which
/// a matrix takes to AP1, where it is clamped as the chain clamps and laid out through a log2
/// shaper) or an RGB space's code values ([0, 1]). xyY, CIELUV, CIELAB, their LCh forms, Oklab and Oklch
/// are refused: their axes are lightness, chromaticity, opponent chroma or hue, which a
/// per-channel shaper over [0, a limit] in light cannot lay out. Throws UnknownNameError for an
/// unknown name.
void check_display_lut_source(std::string_view source);

/// The options of a forward display transform from `source` to `target` for a LUT; an empty
/// target is the display's default encoding (aces2_display.h). Throws irid::Error as
/// check_display_lut_source, naming the target when the display has no default encoding (CIE
/// XYZ, other primaries), and as DisplayTransform for unknown names.
[[nodiscard]] DisplayTransformOptions display_lut_options(std::string_view view,
                                                          std::string_view display,
                                                          std::string_view source,
                                                          std::string_view target);

/// The domain a LUT of the transform covers unless one is named:
/// - for .clf over light (xyz, linear RGB): a matrix from the source to AP1
///   (display_lut_cube_space; none when the source is AP1), then the log2 shaper over
///   [0, the rendering's forward limit] with display_lut_stops stops. The domain's faces are
///   then the chain's own clamp, which the LUT reproduces exactly.
/// - over an encoded source: its code values [0, 1], uniformly (acescct is AP1 already).
/// .cube and .spi3d carry no shaper and no matrix, so they take acescct (whose [0, 1] decodes to
/// [-0.0069, 222.86]); throws irid::Error saying so for another source, and as
/// check_display_lut_source.
[[nodiscard]] LutDomain display_lut_domain(const DisplayTransform& transform, LutFormat format);

/// The forward transform sampled at every node (its float path, on up to `threads` threads, 0:
/// all): source = the transform's source space, destination its target. The title names irid's
/// version, the view, the display, both spaces, the size and the domain. With a matrix in the
/// domain the nodes lie in the matrix's space, and the transform takes each through the matrix's
/// inverse. Throws irid::Error for an inverse transform, a source check_display_lut_source
/// refuses, a size or domain bake_lut refuses, or a non-finite result.
[[nodiscard]] Lut3D bake_display_lut(const DisplayTransform& transform, int size,
                                     const LutDomain& domain, int threads = 0);

}  // namespace irid
