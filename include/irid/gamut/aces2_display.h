#pragma once

// The ACES 2.0 Output Transform as OpenColorIO's built-in display transforms apply it
// ("ACES-OUTPUT - ACES2065-1_to_CIE-XYZ-D65 - <display>_2.0"): ACES2065-1 to CIE XYZ of a D65
// display, 1.0 = 100 cd/m², and back. The chain around the rendering (aces2.h):
// 1. ACES2065-1 to AP1, clamped to [0, forward_limit], and back;
// 2. the rendering, to RGB of the limiting primaries;
// 3. a clamp to [0, peak/100];
// 4. the white scaling: a limiting white other than the encoding's (a D60 white shown on a D65
//    display) is scaled so that it fits the encoding gamut;
// 5. a linear scale (the cinema presets of 108 and 300 cd/m² render for 225 and 625 and scale
//    by 0.48);
// 6. limiting RGB to XYZ (no adaptation: the limiting white is the white shown).

#include <irid/color/matrix.h>
#include <irid/color/rgb.h>
#include <irid/color/types.h>
#include <irid/gamut/aces2.h>

#include <cmath>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace irid {

/// What the display chain takes a non-finite input channel as (forward and inverse, the double
/// chain, Aces2Kernel and DisplayTransform alike, before any matrix): +Inf as 65504, the largest
/// finite IEEE 754 binary16 value (a half float's +Inf is an overflow beyond it), which lies
/// beyond every display's forward limit (at most 7168 in AP1, at 10000 cd/m²), so a blown-out
/// highlight is shown as the brightest the display shows of it, not as black; -Inf and NaN as 0.
inline constexpr double aces2_positive_infinity_as = 65504.0;
[[nodiscard]] inline double aces2_finite_input(double v) noexcept {
    return std::isfinite(v) ? v : (v > 0.0 ? aces2_positive_infinity_as : 0.0);
}

/// One display of the ACES 2.0 Output Transform.
struct Aces2DisplaySpec {
    /// The short name, lower case ("sdr-100nit-rec709"); the OCIO style is
    /// "ACES-OUTPUT - ACES2065-1_to_CIE-XYZ-D65 - " + the name in OCIO's case + "_2.0".
    std::string name;
    /// The peak the rendering targets [cd/m²] (225 and 625 for the 108 and 300 cinema presets).
    double peak_nits = 100.0;
    RgbPrimaries limiting{};
    Xy limiting_white{};
    /// The encoding's primaries and white; ignored when encoding_xyz (CIE XYZ itself, white E).
    RgbPrimaries encoding{};
    Xy encoding_white{};
    bool encoding_xyz = false;
    /// The linear scale after the rendering (0.48 for the cinema presets, else 1).
    double linear_scale = 1.0;
    /// Whether the limiting white is scaled into the encoding gamut (OpenColorIO's
    /// SDR-100nit-P3-D60-in-XYZ-E does not scale).
    bool scale_white = true;
};

/// The 31 built-in displays of OpenColorIO 2.4+, in its order.
[[nodiscard]] std::span<const Aces2DisplaySpec> aces2_displays();

/// A display of one's own: the rendering for `peak_nits` (100 to 10000) within the limiting
/// primaries and white, shown in the encoding's primaries and white (CIE XYZ when `encoding` is
/// nullptr), scaled by `linear_scale` (in (0, 1]; the cinema presets' 0.48) and, when
/// `scale_white`, the white scaled into the encoding gamut as the built-in displays do
/// (OpenColorIO's SDR-100nit-P3-D60-in-XYZ-E alone does not). Named in the form aces2_display()
/// reads. Throws irid::Error for a peak or linear scale out of range.
[[nodiscard]] Aces2DisplaySpec custom_aces2_display(double peak_nits, const RgbSpace& limiting,
                                                    const Xy& limiting_white, const RgbSpace* encoding,
                                                    double linear_scale = 1.0, bool scale_white = true);

/// The form of a custom display's name (aces2_display), for messages and help.
inline constexpr std::string_view aces2_custom_form =
    "custom:peak=NITS,limiting=SPACE[,white=W][,encoding=SPACE|xyz][,linear-scale=S][,scale-white=yes|no]";

/// The display of a name: a built-in one by its short name or the full OCIO style, in any case;
/// or a custom one, aces2_custom_form (the keys in any order) with the spaces named as
/// irid/color/rgb.h names them, the limiting white W (default the limiting space's) a name of
/// white_point_xy, "aces" (the ACES white), or its chromaticity "x,y" or "x:y", the encoding
/// defaulting to the limiting space, the linear scale to 1 and scale-white to yes. A custom
/// display of a built-in one's parts (`irid display --list`) is that display bit for bit.
/// Throws irid::UnknownNameError listing the names for an unknown display or space, irid::Error
/// for a malformed custom form or a value out of range.
[[nodiscard]] Aces2DisplaySpec aces2_display(std::string_view name);

/// The display encoding (irid/color/rgb.h) a file of the display's signal is written in unless
/// one is named: above 100 cd/m² (nominal) PQ, p3-d65-pq for P3-D65 and else rec2100-pq for any
/// D65 encoding gamut inside BT.2020's; at 100 cd/m² srgb for BT.709, display-p3 for P3-D65,
/// rec1886-rec2020 for BT.2020, else the built-in space of the encoding's primaries and white.
/// nullptr when none fits (CIE XYZ, or other primaries).
[[nodiscard]] const RgbSpace* default_display_encoding(const Aces2DisplaySpec& spec) noexcept;

/// The whole chain for one display; its tables are built at construction.
class Aces2Output {
public:
    /// Throws irid::Error for a spec Aces2Rendering refuses.
    explicit Aces2Output(const Aces2DisplaySpec& spec);

    /// ACES2065-1 to CIE XYZ of the D65 display, 1.0 = 100 cd/m².
    [[nodiscard]] Xyz forward(const Vec3& aces) const noexcept;
    /// CIE XYZ (1.0 = 100 cd/m²) to ACES2065-1. XYZ outside what the display shows is clamped
    /// to its limiting cube first.
    [[nodiscard]] Vec3 inverse(const Xyz& xyz) const noexcept;
    /// Whether the display value has a scene value the chain shows as it, to `tolerance` of the
    /// peak in the limiting RGB. It has one exactly, forward(inverse(xyz)) = xyz to 1e-10 of the
    /// peak, where it lies inside the limiting cube, is a value the rendering reaches
    /// (Aces2Rendering::reaches) and has its source inside the AP1 clamp of step 1; elsewhere
    /// when the round trip misses by at most `tolerance` (the default takes the float rounding
    /// of a colour the display shows as shown). docs/DISPLAY.md, "The inverse".
    [[nodiscard]] bool has_scene_value(const Xyz& xyz, double tolerance = 1e-5) const noexcept;
    /// How far forward(inverse(xyz)) misses xyz: the largest channel of the difference in the
    /// limiting RGB, of the peak (both before the white and linear scales).
    [[nodiscard]] double inverse_miss(const Xyz& xyz) const noexcept;

    [[nodiscard]] const Aces2DisplaySpec& spec() const noexcept { return m_spec; }
    [[nodiscard]] const Aces2Rendering& rendering() const noexcept { return m_rendering; }
    /// The factor of steps 4 and 5 together.
    [[nodiscard]] double output_scale() const noexcept { return m_scale; }

private:
    friend class Aces2Kernel;  // folds the matrices into its own

    Aces2DisplaySpec m_spec;
    Aces2Rendering m_rendering;
    Mat3 m_ap0_to_ap1, m_ap1_to_ap0;
    Mat3 m_limiting_to_xyz, m_xyz_to_limiting;
    double m_scale = 1.0;
};

}  // namespace irid
