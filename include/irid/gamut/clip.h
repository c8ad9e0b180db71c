#pragma once

// Gamut clipping: bringing a colour a display cannot show back into its gamut.
//
// The thesis' method (Smits 1990, §4.3) moves an out-of-gamut colour along the line of constant
// luminance toward the grey of the same luminance and stops where the line enters the display's
// RGB cube, found Cohen–Sutherland style from the outcodes of the three channels. It is
// implemented in both of the thesis' forms (on linear RGB and on XYZ against the parallelepiped)
// and compared with the methods used today: the per-channel clamp, CIELUV and Oklab projections,
// CSS Color 4's binary search and ray trace, Ottosson's lightness-adaptive projections (2021),
// the ACES 1.3 Reference Gamut Compression, and a soft form of the thesis' own clip. Every
// method is behind one interface, GamutClipper, selected by name, with its parameters
// (ClipSettings) checked against clip_parameters().
//
// Hard and soft methods. The hard methods (all but aces-rgc and smits-soft) leave every colour
// inside the gamut as it is and put every other one on the gamut's boundary, so a smooth
// out-of-gamut gradient ends in a flat band where it meets the boundary. The soft ones compress
// what lies beyond a threshold: colours inside the gamut but near its edge move too, and the
// boundary is reached only at a limit (the clip report measures both: banding, collapse and
// in-gamut movement along the `ramps` set). aces-rgc works per channel in the destination's
// linear RGB and, like OpenColorIO, leaves a colour beyond its limits outside the cube unless
// its parameter clip is true (irid clip turns clip on for images).
//
// What the thesis leaves open, decided here for every method (and tested):
// - Non-finite input: NaN channels are taken as 0 and ±Inf as ±1e30 before clipping, so every
//   output is finite (an image never receives a NaN).
// - Lightness at the ends: the methods that keep a lightness send a colour whose lightness is
//   at or below black's to black and one at or above the white's (max, max, max) to that white,
//   since no other colour of that lightness is in the gamut: smits, smits-xyz,
//   luv-lightness-hue and smits-soft on luminance, oklab on Oklab L, and css and css-raytrace on
//   Oklab L because CSS Color 4 prescribes it. The methods that move lightness (luv-hue,
//   oklab-adaptive, oklab-cusp) have no such rule: their definitions apply at every lightness,
//   below 0 and above the white's. With an HDR peak, CIELUV's L* is relative to the peak's white.
// - Oklab is CSS Color 4's (color/spaces.h): the D65 white maps exactly onto Oklab's neutral
//   axis (L = cbrt(max) for the white (max, max, max) of any space, adapted to D65), as in
//   colorjs.io, so the grey of every lightness up to the white's is inside the cube. (With
//   Ottosson's published M1 the white has a chroma of 1.2e-4, and the neutral axis leaves the
//   cube 1.4e-4 below the white's L: css-raytrace's anchor fell outside the cube there.)
// - A colour exactly on a face (a channel equal to 0 or to max) is in the gamut and unchanged.
// - A colour within rounding outside the cube comes back within rounding of itself, whatever the
//   method (tests/gamut/boundary_test.cpp: moved by at most 100 times its distance d to the cube,
//   plus rounding). The methods that move toward a grey are continuous and need no rule (they
//   move it by up to d (1 − l)/l, l the smallest luminance weight over their sum: 13 d for
//   sRGB); two needed one:
//   oklab keeps lightness and hue exactly, and the line of a colour's lightness and hue can meet
//   the cube only at the colour: sRGB blue's leaves it through r = 0 at 85 % of blue's chroma and
//   comes back only at the vertex, and so do those of the blue–black edge, of the blue end of
//   the blue–cyan edge and of a strip of the face r = 0 beside them (Rec.2020 alike). A
//   colour a hair outside there has no colour of its lightness and hue near it, so a colour
//   within oklab_rounding_tolerance × max of the cube (every channel in [−tol, max + tol]) is
//   taken as on it and clamped (moved by at most that much); css-raytrace, oklab-adaptive and
//   oklab-cusp apply the same rule (their rays and segments meet the same trouble). The soft
//   methods are continuous and move such a colour by a bounded amount like any other near the
//   boundary.
// - The destination's maximum may differ from 1 (an HDR peak): the cube is [0, max]³.

#include <irid/color/matrix.h>
#include <irid/color/rgb.h>
#include <irid/color/types.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

namespace irid {

/// oklab: a colour no farther than this × max outside the cube is on it to within rounding and
/// is clamped (see above). Above float's rounding (an ulp of max is 2^-23 max ≈ 1.2e-7 max: an
/// image stored as float sits up to half of that off a face it was on), far below what shows
/// (a 16-bit code is 1.5e-5 of the range).
inline constexpr double oklab_rounding_tolerance = 1e-6;

/// The clipping methods, in the order of the reports.
enum class ClipMethod {
    /// Per-channel clamp to [0, max] ("discarding negative values", Smits 1990 Figure 11 top).
    clamp,
    /// Smits 1990 §4.3, RGB form.
    smits,
    /// Smits 1990 §4.3, XYZ form (the parallelepiped's planes in XYZ).
    smits_xyz,
    /// Constant L* and hue in CIELUV, chroma reduced exactly to the gamut boundary.
    luv_lightness_hue,
    /// Constant CIELUV hue: the nearest in-gamut colour in ΔE*uv within the hue plane
    /// (Figure 11 bottom).
    luv_hue,
    /// CSS Color Module Level 4 gamut mapping (binary search on OKLCh chroma, ΔEOK < JND 0.02).
    css,
    /// Constant Oklab lightness and hue, chroma reduced exactly to the boundary: to the nearest
    /// chroma at or below the colour's that is inside the cube (the upper end of the last piece
    /// of the chroma line inside it). It jumps where a piece appears or vanishes (GAMUT.md).
    oklab,
    /// CSS Color Module Level 4 "Ray Trace" gamut mapping (§13.2.3 of the current draft, with
    /// the corrections of csswg-drafts issue 14029): up to four slab intersections from the
    /// OkLCh(L, 0, h) anchor toward the colour, L and h restored after each, then a final clip.
    css_raytrace,
    /// Ottosson 2021, "gamut_clip_adaptive_L0_0_5": toward L0 = an adaptive point around 0.5
    /// in the colour's Oklab hue plane (parameter alpha), stopped exactly on the boundary.
    oklab_adaptive,
    /// Ottosson 2021, "gamut_clip_adaptive_L0_L_cusp": the same around the cusp's lightness.
    oklab_cusp,
    /// The thesis' direction (constant Y, toward the grey w of equal luminance) with a soft
    /// compression instead of the hard stop (smits_soft.cpp). The relative distance
    /// r = max_i of (c_i − w)/(max − w) for c_i > w and (w − c_i)/w for c_i < w (1 where the ray
    /// from w through c leaves the cube) becomes r' = r up to `threshold` (nothing inside it
    /// moves), ACES 1.3's power curve (`power`) above it, reaching 1 (the boundary) exactly at
    /// `limit`, and 1 (smits' own answer) beyond; the output is w + (r'/r)(c − w), so luminance
    /// is kept exactly. Y <= 0 → black, w >= max → white. The inverse undoes the curve for
    /// r' < 1 and maps the boundary, and every colour beyond it along its ray, to the limit.
    smits_soft,
    /// ACES 1.3 Reference Gamut Compression (Academy LMT.Academy.ReferenceGamutCompress.ctl;
    /// OpenColorIO 2.1 FixedFunction ACES_GamutComp13), per channel in the linear RGB of the
    /// destination. Its output is not confined to the cube unless its parameter clip is true.
    aces_rgc,
};

/// Every method, in order.
[[nodiscard]] std::span<const ClipMethod> clip_methods() noexcept;
/// The name used on the command line ("smits-xyz", "luv-lightness-hue", ...).
[[nodiscard]] std::string_view clip_method_name(ClipMethod method) noexcept;
/// Throws irid::Error listing the names when `name` is none of them (and, for a retired method,
/// why it was retired: smits-corrected, GAMUT.md).
[[nodiscard]] ClipMethod parse_clip_method(std::string_view name);

/// One parameter of a method: its name (as in `irid clip --param name=value`), default, allowed
/// closed range and meaning. A boolean parameter takes true/false (stored as 1/0).
struct ClipParameterInfo {
    std::string_view name;
    double default_value;
    double min, max;
    bool boolean;
    std::string_view description;
};
/// The parameters of a method, in the order of messages (empty for most methods).
[[nodiscard]] std::span<const ClipParameterInfo> clip_parameters(ClipMethod method) noexcept;
/// Whether `ClipSettings::inverse` is allowed for the method (aces-rgc, smits-soft).
[[nodiscard]] bool has_inverse(ClipMethod method) noexcept;
/// Whether the method moves colours that are inside the gamut (the soft ones: aces-rgc and
/// smits-soft compress what lies beyond their threshold).
[[nodiscard]] bool moves_in_gamut_colours(ClipMethod method) noexcept;

/// A method's parameter values, set by name, and the direction. Values not set take their
/// defaults. Checked by GamutClipper's constructor against the method.
struct ClipSettings {
    std::vector<std::pair<std::string, double>> values;
    bool inverse = false;

    /// Sets `name` to `value` (the last setting of a name wins).
    ClipSettings& set(std::string_view name, double value);
    /// Parses "name=value" (value a number, or true/false/yes/no/on/off/1/0 for any parameter)
    /// and sets it; throws irid::Error for a missing '=' or a value that is not a number or a
    /// boolean. Whether the name and the value suit the method is checked by GamutClipper.
    ClipSettings& set(std::string_view name_equals_value);
};

/// The settings of a method whose result goes to a display or an integer file, which hold the
/// cube and nothing beyond it: `given`, with aces-rgc's clip=true unless `given` sets clip
/// (ACES 1.3's compression alone leaves colours past the cube's faces). The one place this
/// policy lives: images (irid clip IN OUT, Python's clip_image), the renderer, the figures and
/// the clip report, and the looks of an OCIO config.
[[nodiscard]] ClipSettings display_clip_settings(ClipMethod method, ClipSettings given = {});

/// A display gamut: linear RGB of a space in [0, max]³.
class Gamut {
public:
    /// Throws irid::Error unless 0 < max <= 1e6 (finite).
    explicit Gamut(const RgbSpace& space, double max = 1.0);

    [[nodiscard]] const RgbSpace& space() const noexcept { return m_space; }
    [[nodiscard]] double max() const noexcept { return m_max; }
    /// The luminance row (A, B, C) of the RGB → XYZ matrix: Y = A r + B g + C b.
    [[nodiscard]] const Vec3& luminance_row() const noexcept { return m_luminance; }
    [[nodiscard]] bool contains(const Rgb& c) const noexcept {
        return c.r >= 0.0 && c.g >= 0.0 && c.b >= 0.0 && c.r <= m_max && c.g <= m_max && c.b <= m_max;
    }

private:
    RgbSpace m_space;
    double m_max;
    Vec3 m_luminance;
};

/// Replaces NaN by 0 and ±Inf by ±1e30 (the rule above), in double or in float (the batches'
/// scalar form; the SIMD form is simd::FiniteOrDefault in src/gamut/simd_common-inl.h).
/// T is never deduced: a float argument is taken as a double unless T = float is asked for.
template <class T = double>
[[nodiscard]] inline T finite_or_default(std::type_identity_t<T> v) noexcept {
    if (std::isnan(v)) return T(0);
    if (std::isinf(v)) return v > T(0) ? T(1e30) : T(-1e30);
    return v;
}

/// The thesis' clip in RGB form (Smits 1990, §4.3) on any arithmetic type T, so that the same
/// code runs in double, in float for batches, and on a counting type to reproduce Table 1.
/// `lum` is the luminance row (A, B, C), `inv_lum_sum` = 1/(A + B + C), `max` the cube's size.
/// Steps: outcodes (a channel below 0 or above max); none → unchanged (comparisons only).
/// Otherwise the grey of equal luminance w = (A r + B g + C b)/(A + B + C); Y <= 0 → black,
/// w >= max → white; else the colour moves along the segment w + s (c − w), s from 1 (the
/// colour) down to 0 (the grey): every channel out of range meets its face at
/// s_i = (0 − w)/(c_i − w) = w/(w − c_i) below 0 and s_i = (max − w)/(c_i − w) above max, and
/// the smallest s_i (the intersection farthest from the input, where the segment enters the
/// cube) gives the point w + s (c − w), whose channel on that face is set exactly to the face's
/// bound (0 or max) rather than to within rounding.
///
/// Each s_i is kept as a fraction n/d of two positive numbers (0 < w < max here): n = w,
/// d = w − c_i below 0; n = max − w (computed once), d = c_i − w (the interpolation's own
/// difference) above max. The first crossed channel is taken as it is; a later one replaces the
/// kept N/D when n D < N d (cross-multiplication), and the one division s = N/D comes last.
/// So a colour costs 1 division whatever the planes crossed, 2 multiplications and 1 comparison
/// per crossed plane after the first, and 9 to 11 additions (Table 1, count_smits_operations).
/// The products stay finite for every input below 3e32 (n <= max <= 1e6, d < 2 × 1.7e32), in
/// particular for 1e30, what ±Inf becomes.
template <class T>
[[nodiscard]] std::array<T, 3> smits_clip_rgb(const std::array<T, 3>& c, const std::array<T, 3>& lum,
                                              const T& inv_lum_sum, const T& max) noexcept {
    const T zero(0.0);
    const bool low[3] = {c[0] < zero, c[1] < zero, c[2] < zero};
    const bool high[3] = {c[0] > max, c[1] > max, c[2] > max};
    if (!(low[0] || low[1] || low[2] || high[0] || high[1] || high[2])) return c;
    const T y = lum[0] * c[0] + lum[1] * c[1] + lum[2] * c[2];
    if (!(y > zero)) return {zero, zero, zero};
    const T w = y * inv_lum_sum;
    if (!(w < max)) return {max, max, max};
    const std::array<T, 3> e{c[0] - w, c[1] - w, c[2] - w};
    const T room = (high[0] || high[1] || high[2]) ? max - w : zero;
    T num = zero, den = zero;  // the kept s = num/den
    int face = -1;             // the channel whose face gave it
    for (int i = 0; i < 3; ++i) {
        if (!(low[i] || high[i])) continue;
        const T n = low[i] ? w : room;
        const T d = low[i] ? w - c[i] : e[i];
        if (face < 0 || n * den < num * d) num = n, den = d, face = i;
    }
    const T s = num / den;
    std::array<T, 3> out{w + s * e[0], w + s * e[1], w + s * e[2]};
    // The point is on that face: say so exactly rather than to within rounding.
    out[face] = low[face] ? zero : max;
    return out;
}

/// What aces-rgc precomputes from its parameters (aces_rgc.cpp), for the double method and its
/// batch kernel. Channels in the order red, green, blue (the limits toward cyan, magenta,
/// yellow).
struct AcesRgcPrepared {
    std::array<double, 3> threshold{};  ///< distance below which nothing moves
    std::array<double, 3> scale{};      ///< s of the curve, so that the limit maps to 1
    std::array<double, 3> asymptote{};  ///< threshold + scale: the inverse's domain ends there
    double power = 1.0, inverse_power = 1.0;
};
/// What smits-soft precomputes (smits_soft.cpp).
struct SmitsSoftPrepared {
    double threshold = 0.0, limit = 0.0, power = 1.0, scale = 1.0, inverse_power = 1.0;
};
/// What oklab-adaptive and oklab-cusp precompute (oklab_projection.cpp) for their kernel.
struct OklabProjectionPrepared {
    /// [z]: S_max ≈ k0 + k1 a' + k2 b' over the hues whose rays from black first reach the face
    /// where channel z (r, g, b) is 0: a least-squares fit to the exact S_max, the kernel's
    /// starting guess.
    std::array<std::array<double, 3>, 3> s_max_fit{};
    /// The unit hue (a', b') of the red, green and blue primaries.
    std::array<std::array<double, 2>, 3> primary_hue{};
    /// Every hue from red to green (counter-clockwise) first reaches b = 0, from green to blue
    /// r = 0, from blue to red g = 0, each of these sectors under 180°, and the cusp lies at
    /// S_max, at 48 hues of each sector (false for ACES2065-1: its kernel runs the double
    /// reference).
    bool structured = false;
};

/// One clipping method on one gamut: built once (matrices, Oklab transforms), then clip() is
/// noexcept and allocates nothing.
class GamutClipper {
public:
    /// Throws irid::Error for a parameter the method does not have (listing its parameters and
    /// their ranges), a value outside its range or inconsistent with the others (naming both),
    /// or `inverse` for a method that has none (listing those that have).
    GamutClipper(ClipMethod method, const Gamut& gamut, const ClipSettings& settings = {});

    /// Clips linear RGB of the gamut's space. Every output is finite. In-gamut colours come back
    /// unchanged and every output is inside [0, max]³, except for the soft methods (which
    /// compress colours beyond their threshold, inside or not), for aces-rgc without clip=1
    /// (whose curve, forward or inverse, may leave colours outside the cube, as OCIO's does) and
    /// for the inverse of smits-soft (confines_to_cube()).
    [[nodiscard]] Rgb clip(const Rgb& linear) const noexcept;
    /// Which branches of its definition the method took for this colour, as one number: two
    /// colours with the same signature went through the same branches, and the method's output
    /// is continuous between them; where the signature changes, the definition itself may jump
    /// (GAMUT.md, "Where a method may jump"; tests/gamut/continuity_test.cpp). The branches
    /// recorded: css, the lightness rule and each step of its binary search; css-raytrace, the
    /// lightness rule and each pass (a ray found, the anchor moved, the face reached); oklab,
    /// oklab-adaptive and oklab-cusp, the lightness or rounding rule and the number of pieces of
    /// the colour's segment inside the cube (the result ends the last; oklab-cusp also records
    /// the kind of its cusp candidate); luv-hue,
    /// a colour without chromaticity (X + 15Y + 3Z <= 0) and the local minimum of its search.
    /// 0 for an in-gamut colour and for the methods without such branches.
    [[nodiscard]] std::uint64_t branch_signature(const Rgb& linear) const noexcept;
    /// The same on XYZ relative to the gamut's white (Y = max for the white), returning XYZ.
    /// For smits_xyz this is the thesis' XYZ form itself; the others go through RGB.
    [[nodiscard]] Xyz clip_xyz(const Xyz& xyz) const noexcept;

    [[nodiscard]] ClipMethod method() const noexcept { return m_method; }
    [[nodiscard]] const Gamut& gamut() const noexcept { return m_gamut; }
    /// The value of one of the method's parameters (set or default); throws irid::Error for a
    /// name the method does not have.
    [[nodiscard]] double parameter(std::string_view name) const;
    /// Every parameter of the method with its value, in clip_parameters() order.
    [[nodiscard]] const std::vector<std::pair<std::string, double>>& parameters() const noexcept {
        return m_parameters;
    }
    /// What a method precomputes (its batch kernel reads it); only the clipper's own method's is
    /// filled.
    [[nodiscard]] const AcesRgcPrepared& aces_rgc_prepared() const noexcept { return m_aces_rgc; }
    [[nodiscard]] const SmitsSoftPrepared& smits_soft_prepared() const noexcept { return m_smits_soft; }
    [[nodiscard]] const OklabProjectionPrepared& oklab_projection_prepared() const noexcept {
        return m_oklab_projection;
    }
    [[nodiscard]] bool inverse() const noexcept { return m_inverse; }
    /// Whether outputs are confined to [0, max]³ (false only for aces-rgc without clip and for
    /// the inverse of smits-soft, which expands toward the limit).
    [[nodiscard]] bool confines_to_cube() const noexcept { return m_confined; }

    // The transforms the batch kernels need (batch_*.cpp), built once here.
    [[nodiscard]] const Mat3& rgb_to_xyz() const noexcept { return m_rgb_to_xyz; }
    [[nodiscard]] const Mat3& xyz_to_rgb() const noexcept { return m_xyz_to_rgb; }
    /// Linear RGB → Oklab's LMS before the cube root (M1 after adapting to D65), and back.
    [[nodiscard]] const Mat3& rgb_to_lms() const noexcept { return m_rgb_to_lms; }
    [[nodiscard]] const Mat3& lms_to_rgb() const noexcept { return m_lms_to_rgb; }
    /// XYZ of (max, max, max), and its Oklab lightness.
    [[nodiscard]] const Xyz& white_xyz() const noexcept { return m_white; }
    [[nodiscard]] double white_oklab_lightness() const noexcept { return m_white_oklab_l; }
    /// Oklab of linear RGB of this gamut (adapted from the space's white to D65 when needed).
    [[nodiscard]] Oklab to_oklab(const Rgb& c) const noexcept;
    [[nodiscard]] Rgb from_oklab(const Oklab& c) const noexcept;

private:
    /// The branches taken, accumulated by the methods that branch (branch_signature).
    struct Branches {
        std::uint64_t value = 0;
        void take(std::uint64_t branch) noexcept { value = value * 1000003u + branch + 1u; }
    };
    static void take(Branches* b, std::uint64_t branch) noexcept {
        if (b != nullptr) b->take(branch);
    }
    [[nodiscard]] Rgb clip_finite(const Rgb& c) const noexcept;
    [[nodiscard]] Rgb smits(const Rgb& c) const noexcept;
    [[nodiscard]] Xyz smits_xyz(const Xyz& c) const noexcept;
    [[nodiscard]] Rgb luv_lightness_hue(const Rgb& c) const noexcept;
    [[nodiscard]] Rgb luv_hue(const Rgb& c, Branches* branches = nullptr) const noexcept;
    [[nodiscard]] Rgb css(const Rgb& c, Branches* branches = nullptr) const noexcept;
    [[nodiscard]] Rgb oklab(const Rgb& c, Branches* branches = nullptr) const noexcept;
    // css_raytrace.cpp
    [[nodiscard]] Rgb css_raytrace(const Rgb& c, Branches* branches = nullptr) const noexcept;
    [[nodiscard]] Rgb smits_soft(const Rgb& c) const noexcept;        // smits_soft.cpp
    [[nodiscard]] Rgb aces_rgc(const Rgb& c) const noexcept;          // aces_rgc.cpp
    [[nodiscard]] Rgb clamp(const Rgb& c) const noexcept;
    /// oklab-adaptive and oklab-cusp's exact geometry (oklab_projection.cpp). The cusp of the hue
    /// of unit direction (a', b'): its L and C, its saturation S = C / L, the saturation S_max
    /// where the hue's rays from black first leave the cube through a face at 0 (the cusp is
    /// there unless the chroma peaks before it), and that face's channel (-1 for none).
    struct OklabCusp {
        double L, C, S, s_max;
        int zero_channel;
    };
    [[nodiscard]] OklabCusp oklab_cusp_of_hue(double a_unit, double b_unit,
                                              Branches* branches = nullptr) const noexcept;
    /// The t in [0, 1] where the segment (L0 + t (L - L0), t a, t b) from (L0, 0, 0) to `lab`
    /// last leaves the cube (the upper end of its last piece inside); see oklab_projection.cpp.
    [[nodiscard]] double oklab_segment_exit(double l0, const Oklab& lab,
                                            Branches* branches = nullptr) const noexcept;
    /// oklab-adaptive (around_cusp false) and oklab-cusp (true) of an out-of-gamut colour
    /// (oklab_projection.cpp).
    [[nodiscard]] Rgb oklab_projection(const Rgb& c, bool around_cusp,
                                       Branches* branches = nullptr) const noexcept;
    /// Checks the values of m_parameters that depend on each other, throwing irid::Error naming
    /// them, and fills the method's prepared values (m_aces_rgc, ...); the per-method
    /// parts live beside each method (prepare_aces_rgc in aces_rgc.cpp, ...).
    void prepare();
    void prepare_aces_rgc();
    void prepare_smits_soft();
    void prepare_oklab_projection();
    /// The largest s in [0, 1] for which the chromaticity u' = u'n + s Δu', v' = v'n + s Δv' at
    /// luminance y is inside the gamut (exact: each face is a linear condition in s).
    [[nodiscard]] double luv_chroma_limit(double y, double du, double dv) const noexcept;

    ClipMethod m_method;
    Gamut m_gamut;
    Mat3 m_rgb_to_xyz, m_xyz_to_rgb;
    Mat3 m_rgb_to_lms, m_lms_to_rgb;  // Oklab's LMS (before the cube root)
    Xyz m_white;                      // XYZ of (max, max, max)
    UvPrime m_white_uv;               // its u'v', the neutral point of the CIELUV methods
    double m_white_oklab_l;           // Oklab L of (max, max, max)
    std::vector<std::pair<std::string, double>> m_parameters;  // every parameter, resolved
    bool m_inverse = false;
    bool m_confined = true;
    AcesRgcPrepared m_aces_rgc;
    SmitsSoftPrepared m_smits_soft;
    OklabProjectionPrepared m_oklab_projection;
};

/// Operation counts of the thesis' RGB clip on one colour (Table 1), from the same template run
/// on a counting number type.
struct OperationCounts {
    long comparisons = 0, additions = 0, multiplications = 0, divisions = 0;
};
/// Counts for an in-gamut colour and for colours crossing one, two and three planes (sRGB).
struct Table1 {
    OperationCounts in_gamut, one_plane, two_planes, three_planes;
};
[[nodiscard]] Table1 count_smits_operations();

}  // namespace irid
