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
/// ACES 2.0's forward limit (1024 at 100 cd/m², 4096 at 1000) down to 2^-8 and 2^-6, linear
/// below; of 14 to 28 stops, 18 measured best (docs/DISPLAY.md, "LUTs and OpenColorIO 2.1").
inline constexpr int display_lut_stops = 18;

/// The options of a forward display transform from `source` to `target` for a LUT; an empty
/// target is the display's default encoding (aces2_display.h). Throws irid::Error naming the
/// target when the display has no default encoding (CIE XYZ, other primaries), and as
/// DisplayTransform for unknown names.
[[nodiscard]] DisplayTransformOptions display_lut_options(std::string_view view,
                                                          std::string_view display,
                                                          std::string_view source,
                                                          std::string_view target);

/// The domain a LUT of the transform covers unless one is named: for .clf over a linear source,
/// the log2 shaper over [0, the rendering's forward limit] with display_lut_stops stops; over an
/// encoded source (acescct), its code values [0, 1] uniformly. .cube and .spi3d carry no shaper,
/// so they take acescct (whose [0, 1] decodes to [-0.0069, 222.86]); throws irid::Error saying
/// so for another source.
[[nodiscard]] LutDomain display_lut_domain(const DisplayTransform& transform, LutFormat format);

/// The forward transform sampled at every node (its float path, on up to `threads` threads, 0:
/// all): source = the transform's source space, destination its target. The title names irid's
/// version, the view, the display, both spaces, the size and the domain. Throws irid::Error for
/// an inverse transform, a size or domain bake_lut refuses, or a non-finite result.
[[nodiscard]] Lut3D bake_display_lut(const DisplayTransform& transform, int size,
                                     const LutDomain& domain, int threads = 0);

}  // namespace irid
