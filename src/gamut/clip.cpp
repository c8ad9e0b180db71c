#include <irid/color/adaptation.h>
#include <irid/color/difference.h>
#include <irid/color/numeric_table.h>
#include <irid/color/spaces.h>
#include <irid/error.h>
#include <irid/text_input.h>
#include <irid/gamut/clip.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <charconv>
#include <limits>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

namespace irid {
namespace {

constexpr std::array<ClipMethod, 12> all_methods{
    ClipMethod::clamp,          ClipMethod::smits,        ClipMethod::smits_xyz,
    ClipMethod::luv_lightness_hue, ClipMethod::luv_hue,   ClipMethod::css,
    ClipMethod::oklab,          ClipMethod::css_raytrace, ClipMethod::oklab_adaptive,
    ClipMethod::oklab_cusp,     ClipMethod::smits_soft,   ClipMethod::aces_rgc};

/// Methods irid had and retired, with the reason (GAMUT.md), so that an old script or scene
/// learns why its method is gone rather than only that it is unknown.
constexpr std::array<std::pair<std::string_view, std::string_view>, 1> retired_methods{{
    {"smits-corrected",
     "smits-corrected was retired: its hue correction along one face of the cube jumped (by up "
     "to ΔE2000 37) where smits' landing point moves from a face to an edge; use oklab (keeps "
     "Oklab lightness and hue exactly) or smits"},
}};

// The parameters of each method. Ranges are closed; consistency between parameters is checked
// by GamutClipper::check_parameters.
//
// aces-rgc: the published defaults of LMT.Academy.ReferenceGamutCompress.ctl (ACES 1.3), in
// ACEScg; ranges as OpenColorIO 2.1 validates FixedFunction ACES_GamutComp13's parameters.
constexpr std::array<ClipParameterInfo, 8> aces_rgc_parameters{{
    {"limit-cyan", 1.147, 1.001, 65504.0, false, "distance limit of the red channel (toward cyan): it maps to 1"},
    {"limit-magenta", 1.264, 1.001, 65504.0, false, "distance limit of the green channel (toward magenta)"},
    {"limit-yellow", 1.312, 1.001, 65504.0, false, "distance limit of the blue channel (toward yellow)"},
    {"threshold-cyan", 0.815, 0.0, 0.9995, false, "distance of the red channel below which nothing moves"},
    {"threshold-magenta", 0.803, 0.0, 0.9995, false, "distance of the green channel below which nothing moves"},
    {"threshold-yellow", 0.880, 0.0, 0.9995, false, "distance of the blue channel below which nothing moves"},
    {"power", 1.2, 1.0, 65504.0, false, "power of the compression curve (higher: sharper knee)"},
    {"clip", 0.0, 0.0, 1.0, true, "clamp the result into the cube [0, max]^3 (images: default true)"},
}};
// Ottosson 2021 ("gamut_clip_adaptive_L0_0_5", "..._L_cusp"): alpha = 0.05 is his default.
constexpr std::array<ClipParameterInfo, 1> oklab_adaptive_parameters{{
    {"alpha", 0.05, 0.0, 100.0, false, "how far L0 stays from 0.5 (or the cusp's L) toward the colour's L as chroma grows"},
}};
// smits-soft (smits_soft.cpp): defaults chosen on ramps from the grey out to the Rec.2020 cube's
// surface (206 ramps, 512 steps) and to the spectral locus (62) in an sRGB destination. The
// Rec.2020 surface lies up to r = 2.23 from the grey in sRGB (mean 1.66), so limit 2.3 leaves no
// Rec.2020 colour frozen on the boundary (0.1 % of ramp steps moving less than 1 % of their
// input step, against 12 % at limit 1.5 and 37 % for smits), with no kink in the ramp (largest
// jump of the output/input step ratio 0.02, smits 1.0); threshold 0.8 moves in-gamut colours by
// a mean ΔEOK of 0.0010 (0.0021 at 0.7); power 1.2 (ACES') freezes fewer steps than 2 (0.1 %
// against 6.8 %).
constexpr std::array<ClipParameterInfo, 3> smits_soft_parameters{{
    {"threshold", 0.8, 0.0, 0.9999, false, "distance from the grey, as a fraction of the boundary's, below which nothing moves"},
    {"limit", 2.3, 1.0001, 1000.0, false, "distance (same unit) that maps onto the boundary; farther colours stop on it"},
    {"power", 1.2, 1.0, 100.0, false, "power of the compression curve (ACES' form)"},
}};

Vec3 v3(const Rgb& c) noexcept { return {c.r, c.g, c.b}; }
Rgb rgb(const Vec3& v) noexcept { return {v[0], v[1], v[2]}; }

/// CSS Color 4 §13.2.2: the just noticeable difference and the search's resolution, in Oklab.
constexpr double css_jnd = 0.02;
constexpr double css_epsilon = 0.0001;

}  // namespace

std::span<const ClipMethod> clip_methods() noexcept { return all_methods; }

std::string_view clip_method_name(ClipMethod method) noexcept {
    switch (method) {
        case ClipMethod::clamp: return "clamp";
        case ClipMethod::smits: return "smits";
        case ClipMethod::smits_xyz: return "smits-xyz";
        case ClipMethod::luv_lightness_hue: return "luv-lightness-hue";
        case ClipMethod::luv_hue: return "luv-hue";
        case ClipMethod::css: return "css";
        case ClipMethod::oklab: return "oklab";
        case ClipMethod::css_raytrace: return "css-raytrace";
        case ClipMethod::oklab_adaptive: return "oklab-adaptive";
        case ClipMethod::oklab_cusp: return "oklab-cusp";
        case ClipMethod::smits_soft: return "smits-soft";
        case ClipMethod::aces_rgc: return "aces-rgc";
    }
    return "";
}

std::span<const ClipParameterInfo> clip_parameters(ClipMethod method) noexcept {
    switch (method) {
        case ClipMethod::aces_rgc: return aces_rgc_parameters;
        case ClipMethod::oklab_adaptive:
        case ClipMethod::oklab_cusp: return oklab_adaptive_parameters;
        case ClipMethod::smits_soft: return smits_soft_parameters;
        default: return {};
    }
}

bool has_inverse(ClipMethod method) noexcept {
    return method == ClipMethod::aces_rgc || method == ClipMethod::smits_soft;
}

bool moves_in_gamut_colours(ClipMethod method) noexcept {
    return method == ClipMethod::aces_rgc || method == ClipMethod::smits_soft;
}

ClipSettings& ClipSettings::set(std::string_view name, double value) {
    for (auto& [n, v] : values) {
        if (n == name) {
            v = value;
            return *this;
        }
    }
    values.emplace_back(std::string(name), value);
    return *this;
}

ClipSettings& ClipSettings::set(std::string_view name_equals_value) {
    const std::size_t eq = name_equals_value.find('=');
    if (eq == std::string_view::npos || eq == 0) {
        throw Error("parameter '" + std::string(name_equals_value) +
                    "' is not of the form name=value");
    }
    const std::string_view name = name_equals_value.substr(0, eq);
    const std::string_view text = name_equals_value.substr(eq + 1);
    for (const auto& [word, v] : {std::pair{"true", 1.0}, {"yes", 1.0}, {"on", 1.0},
                                  {"false", 0.0}, {"no", 0.0}, {"off", 0.0}}) {
        if (text == word) return set(name, v);
    }
    double v = 0.0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
    if (text.empty() || ec != std::errc() || end != text.data() + text.size()) {
        throw Error("parameter " + std::string(name) + ": value '" + std::string(text) +
                    "' is not a number nor true/false");
    }
    return set(name, v);
}

ClipSettings display_clip_settings(ClipMethod method, ClipSettings given) {
    if (method != ClipMethod::aces_rgc) return given;
    for (const auto& [name, value] : given.values) {
        if (name == "clip") return given;
    }
    return std::move(given.set("clip", 1.0));
}

ClipMethod parse_clip_method(std::string_view name) {
    std::string names;
    std::vector<std::string> valid;
    for (const ClipMethod m : all_methods) {
        if (clip_method_name(m) == name) return m;
        names += (names.empty() ? "" : ", ") + std::string(clip_method_name(m));
        valid.emplace_back(clip_method_name(m));
    }
    for (const auto& [retired, why] : retired_methods) {
        if (name == retired) throw UnknownNameError(std::string(why) + "; valid: " + names, std::move(valid));
    }
    throw UnknownNameError("unknown clip method " + quote_untrusted(name) + "; valid: " + names,
                           std::move(valid));
}

Gamut::Gamut(const RgbSpace& space, double max) : m_space(space), m_max(max) {
    if (!(std::isfinite(max) && max > 0.0 && max <= 1e6)) {
        throw Error("gamut: maximum " + format_shortest(max) + " must be in (0, 1e6]");
    }
    m_luminance = space.to_xyz_matrix()[1];
}

namespace {

std::string describe_parameters(ClipMethod method) {
    std::string out;
    for (const ClipParameterInfo& p : clip_parameters(method)) {
        out += (out.empty() ? "" : ", ") + std::string(p.name) +
               (p.boolean ? std::string(" (true or false)")
                          : " in [" + format_shortest(p.min) + ", " + format_shortest(p.max) + "]");
    }
    return out;
}

}  // namespace

GamutClipper::GamutClipper(ClipMethod method, const Gamut& gamut, const ClipSettings& settings)
    : m_method(method),
      m_gamut(gamut),
      m_rgb_to_xyz(gamut.space().to_xyz_matrix()),
      m_xyz_to_rgb(gamut.space().from_xyz_matrix()),
      m_inverse(settings.inverse) {
    const std::string name(clip_method_name(method));
    const std::span<const ClipParameterInfo> known = clip_parameters(method);
    for (const ClipParameterInfo& p : known) m_parameters.emplace_back(p.name, p.default_value);
    for (const auto& setting : settings.values) {
        // (Not a structured binding: clang 14 cannot capture one in a lambda.)
        const std::string& key = setting.first;
        const double value = setting.second;
        const auto it = std::find_if(known.begin(), known.end(),
                                     [&](const ClipParameterInfo& p) { return p.name == key; });
        if (it == known.end()) {
            std::vector<std::string> valid;
            for (const ClipParameterInfo& p : known) valid.emplace_back(p.name);
            throw UnknownNameError(
                "method " + name + " has no parameter " + quote_untrusted(key) +
                    (known.empty() ? "; it takes none"
                                   : "; its parameters: " + describe_parameters(method)),
                std::move(valid));
        }
        const bool ok = it->boolean ? (value == 0.0 || value == 1.0)
                                    : (std::isfinite(value) && value >= it->min && value <= it->max);
        if (!ok) {
            throw Error("method " + name + ": parameter " + key + " = " + format_shortest(value) +
                        (it->boolean ? " must be true or false"
                                     : " must be in [" + format_shortest(it->min) + ", " +
                                           format_shortest(it->max) + "]"));
        }
        m_parameters[static_cast<std::size_t>(it - known.begin())].second = value;
    }
    if (m_inverse && !has_inverse(method)) {
        std::string with;
        for (const ClipMethod m : all_methods) {
            if (has_inverse(m)) with += (with.empty() ? "" : ", ") + std::string(clip_method_name(m));
        }
        throw Error("method " + name + " has no inverse; methods with one: " + with);
    }
    // Oklab is defined on XYZ relative to D65 (Ottosson 2020): adapt from the space's white.
    const Xy d65 = d65_xy;
    const Xy w = gamut.space().white();
    const Mat3 to_d65 = (w.x == d65.x && w.y == d65.y)
                            ? Mat3::identity()
                            : adaptation_matrix(xy_to_xyz(w), xy_to_xyz(d65), ChromaticAdaptation::bradford);
    m_rgb_to_lms = oklab_m1 * to_d65 * m_rgb_to_xyz;
    m_lms_to_rgb = irid::inverse(m_rgb_to_lms, "RGB to LMS matrix");
    const double max = gamut.max();
    const Vec3 white = m_rgb_to_xyz * Vec3{max, max, max};
    m_white = {white[0], white[1], white[2]};
    m_white_oklab_l = to_oklab({max, max, max}).L;
    m_white_uv = xyz_to_uv_prime(m_white);
    prepare();
    m_confined = (method != ClipMethod::aces_rgc || parameter("clip") != 0.0) &&
                 !(method == ClipMethod::smits_soft && m_inverse);
}

void GamutClipper::prepare() {
    switch (m_method) {
        case ClipMethod::aces_rgc: prepare_aces_rgc(); return;
        case ClipMethod::smits_soft: prepare_smits_soft(); return;
        case ClipMethod::oklab_adaptive:
        case ClipMethod::oklab_cusp: prepare_oklab_projection(); return;
        default: return;
    }
}

double GamutClipper::parameter(std::string_view name) const {
    for (const auto& [n, v] : m_parameters) {
        if (n == name) return v;
    }
    std::vector<std::string> valid;
    for (const auto& [n, v] : m_parameters) valid.push_back(n);
    throw UnknownNameError("method " + std::string(clip_method_name(m_method)) +
                               " has no parameter " + quote_untrusted(name),
                           std::move(valid));
}

Oklab GamutClipper::to_oklab(const Rgb& c) const noexcept {
    const Vec3 lms = m_rgb_to_lms * v3(c);
    const Vec3 lab = oklab_m2 * Vec3{std::cbrt(lms[0]), std::cbrt(lms[1]), std::cbrt(lms[2])};
    return {lab[0], lab[1], lab[2]};
}

Rgb GamutClipper::from_oklab(const Oklab& c) const noexcept {
    const Vec3 r = oklab_m2_inverse * Vec3{c.L, c.a, c.b};
    return rgb(m_lms_to_rgb * Vec3{r[0] * r[0] * r[0], r[1] * r[1] * r[1], r[2] * r[2] * r[2]});
}

Rgb GamutClipper::clip(const Rgb& linear) const noexcept {
    const Rgb c{finite_or_default(linear.r), finite_or_default(linear.g), finite_or_default(linear.b)};
    if (m_method == ClipMethod::clamp) return clamp(c);
    if (m_method == ClipMethod::aces_rgc) {
        const Rgb out = aces_rgc(c);
        return confines_to_cube() ? clamp(out) : out;
    }
    if (m_method == ClipMethod::smits_soft) {
        const Rgb out = smits_soft(c);
        return confines_to_cube() ? clamp(out) : out;  // the inverse expands beyond the cube
    }
    if (m_gamut.contains(c)) return c;
    Rgb out = clip_finite(c);
    // Rounding may leave a result a few ulps outside a face; the contract is [0, max]³.
    out = clamp(out);
    return out;
}

Xyz GamutClipper::clip_xyz(const Xyz& xyz) const noexcept {
    const Xyz c{finite_or_default(xyz.X), finite_or_default(xyz.Y), finite_or_default(xyz.Z)};
    if (m_method == ClipMethod::smits_xyz) return smits_xyz(c);
    const Rgb out = clip(rgb(m_xyz_to_rgb * Vec3{c.X, c.Y, c.Z}));
    const Vec3 v = m_rgb_to_xyz * v3(out);
    return {v[0], v[1], v[2]};
}

std::uint64_t GamutClipper::branch_signature(const Rgb& linear) const noexcept {
    const Rgb c{finite_or_default(linear.r), finite_or_default(linear.g), finite_or_default(linear.b)};
    if (m_gamut.contains(c)) return 0;
    Branches b;
    switch (m_method) {
        case ClipMethod::luv_hue: (void)luv_hue(c, &b); break;
        case ClipMethod::css: (void)css(c, &b); break;
        case ClipMethod::oklab: (void)oklab(c, &b); break;
        case ClipMethod::css_raytrace: (void)css_raytrace(c, &b); break;
        case ClipMethod::oklab_adaptive: (void)oklab_projection(c, false, &b); break;
        case ClipMethod::oklab_cusp: (void)oklab_projection(c, true, &b); break;
        default: break;
    }
    return b.value;
}

Rgb GamutClipper::clip_finite(const Rgb& c) const noexcept {
    switch (m_method) {
        case ClipMethod::clamp: return clamp(c);
        case ClipMethod::smits: return smits(c);
        case ClipMethod::smits_xyz: {
            const Vec3 x = m_rgb_to_xyz * v3(c);
            const Xyz clipped = smits_xyz({x[0], x[1], x[2]});
            return rgb(m_xyz_to_rgb * Vec3{clipped.X, clipped.Y, clipped.Z});
        }
        case ClipMethod::luv_lightness_hue: return luv_lightness_hue(c);
        case ClipMethod::luv_hue: return luv_hue(c);
        case ClipMethod::css: return css(c);
        case ClipMethod::oklab: return oklab(c);
        case ClipMethod::css_raytrace: return css_raytrace(c);
        case ClipMethod::oklab_adaptive: return oklab_projection(c, false);
        case ClipMethod::oklab_cusp: return oklab_projection(c, true);
        case ClipMethod::smits_soft: return smits_soft(c);
        case ClipMethod::aces_rgc: return aces_rgc(c);
    }
    return c;
}

Rgb GamutClipper::clamp(const Rgb& c) const noexcept {
    const double m = m_gamut.max();
    return {std::clamp(c.r, 0.0, m), std::clamp(c.g, 0.0, m), std::clamp(c.b, 0.0, m)};
}

// --- Smits 1990, §4.3 ------------------------------------------------------------------------

Rgb GamutClipper::smits(const Rgb& c) const noexcept {
    const Vec3& lum = m_gamut.luminance_row();
    const auto out = smits_clip_rgb<double>({c.r, c.g, c.b}, {lum[0], lum[1], lum[2]},
                                            1.0 / (lum[0] + lum[1] + lum[2]), m_gamut.max());
    return {out[0], out[1], out[2]};
}

Xyz GamutClipper::smits_xyz(const Xyz& c) const noexcept {
    // The parallelepiped's three pairs of planes row_i · XYZ = 0 and = max, row_i the rows of
    // the XYZ → RGB matrix; the neutral point is the white's direction at the colour's Y.
    const double max = m_gamut.max();
    const Vec3 p{c.X, c.Y, c.Z};
    std::array<double, 3> value{};
    bool outside = false;
    for (int i = 0; i < 3; ++i) {
        const Vec3& row = m_xyz_to_rgb[i];
        value[i] = row[0] * p[0] + row[1] * p[1] + row[2] * p[2];
        outside = outside || value[i] < 0.0 || value[i] > max;
    }
    if (!outside) return c;
    if (!(c.Y > 0.0)) return {0.0, 0.0, 0.0};
    // The white (max, max, max) has luminance m_white.Y; the grey of luminance Y is W Y / W_Y.
    const double k = c.Y / m_white.Y;
    if (!(k < 1.0)) return m_white;
    const Vec3 n{m_white.X * k, m_white.Y * k, m_white.Z * k};
    // Each plane's value at the neutral point is max · k (the grey's RGB channels).
    const double neutral = max * k;
    double t = 0.0;
    for (int i = 0; i < 3; ++i) {
        if (value[i] < 0.0) t = std::max(t, value[i] / (value[i] - neutral));
        else if (value[i] > max) t = std::max(t, (value[i] - max) / (value[i] - neutral));
    }
    return {p[0] + t * (n[0] - p[0]), p[1] + t * (n[1] - p[1]), p[2] + t * (n[2] - p[2])};
}

// --- CIELUV methods --------------------------------------------------------------------------

double GamutClipper::luv_chroma_limit(double y, double du, double dv) const noexcept {
    // At luminance y and chromaticity (u', v'): X = 9 y u' / (4 v'), Z = y (12 − 3u' − 20v')/(4v'),
    // so channel i = y N_i / (4 v') with N_i = 9 m_i0 u' + 4 m_i1 v' + m_i2 (12 − 3u' − 20v'),
    // linear in s; channel >= 0 ⇔ N_i >= 0 and channel <= max ⇔ y N_i − 4 max v' <= 0 (v' > 0).
    const UvPrime& n = m_white_uv;
    const double max = m_gamut.max();
    double limit = 1.0;
    for (int i = 0; i < 3; ++i) {
        const Vec3& m = m_xyz_to_rgb[i];
        const auto numerator = [&](double u, double v) {
            return 9.0 * m[0] * u + 4.0 * m[1] * v + m[2] * (12.0 - 3.0 * u - 20.0 * v);
        };
        const double n0 = numerator(n.u, n.v);
        const double n1 = numerator(n.u + du, n.v + dv);
        // Lower face: n0 + s (n1 − n0) >= 0.
        if (n1 < 0.0 && n0 > 0.0) limit = std::min(limit, n0 / (n0 - n1));
        // Upper face: g(s) = y N(s) − 4 max v'(s) <= 0.
        const double g0 = y * n0 - 4.0 * max * n.v;
        const double g1 = y * n1 - 4.0 * max * (n.v + dv);
        if (g1 > 0.0 && g0 < 0.0) limit = std::min(limit, g0 / (g0 - g1));
    }
    return std::max(limit, 0.0);
}

Rgb GamutClipper::luv_lightness_hue(const Rgb& c) const noexcept {
    const Vec3 x = m_rgb_to_xyz * v3(c);
    const double y = x[1];
    if (!(y > 0.0)) return {0.0, 0.0, 0.0};
    if (!(y < m_white.Y)) return {m_gamut.max(), m_gamut.max(), m_gamut.max()};
    const double d = x[0] + 15.0 * x[1] + 3.0 * x[2];
    if (!(d > 0.0)) return smits(c);  // no chromaticity: fall back to the thesis' clip
    const UvPrime& n = m_white_uv;
    const UvPrime uv{4.0 * x[0] / d, 9.0 * x[1] / d};
    const double s = luv_chroma_limit(y, uv.u - n.u, uv.v - n.v);
    const double u = n.u + s * (uv.u - n.u), v = n.v + s * (uv.v - n.v);
    const Vec3 out{9.0 * y * u / (4.0 * v), y, y * (12.0 - 3.0 * u - 20.0 * v) / (4.0 * v)};
    return rgb(m_xyz_to_rgb * out);
}

Rgb GamutClipper::luv_hue(const Rgb& c, Branches* branches) const noexcept {
    // The nearest in-gamut colour in ΔE*uv within the colour's CIELUV hue plane, at every
    // lightness: no black or white rule (the method moves lightness, so a colour brighter than
    // the white lands on the hue's upper boundary, and one of negative luminance, whose L* and
    // (u*, v*) are negative, near black).
    const Vec3 x = m_rgb_to_xyz * v3(c);
    // X + 15Y + 3Z <= 0 (far outside the spectral locus) has no chromaticity and so no hue:
    // the method is undefined there and falls back to luv-lightness-hue (GAMUT.md: the one place
    // where luv-hue jumps, since u' and v' go to infinity as the plane is approached).
    if (!(x[0] + 15.0 * x[1] + 3.0 * x[2] > 0.0)) {
        take(branches, 1);
        return luv_lightness_hue(c);
    }
    const Luv luv = xyz_to_luv({x[0], x[1], x[2]}, m_white);
    const double c0 = std::hypot(luv.u, luv.v);
    const double l_max = 100.0;  // L* of the white (max, max, max), the reference
    if (!(c0 > 1e-12)) {
        take(branches, 2);
        // No hue: a grey (or nearly), whose nearest in-gamut colour is the grey of its L* clamped
        // to [0, 100].
        const double L = std::clamp(luv.L, 0.0, l_max);
        const double g = m_gamut.max() * cie_lightness_to_relative_luminance(L);
        return {g, g, g};
    }
    // The hue's unit direction in (u*, v*). For L* > 0 the chromaticity offset (u' − u'n,
    // v' − v'n) points the same way; (u*, v*) = 13 L* times it.
    const double du = luv.u / c0, dv = luv.v / c0;
    // The largest in-gamut chroma at lightness L along this hue: luv_chroma_limit gives the
    // largest fraction of a chromaticity offset inside the gamut at luminance y; the offset of
    // chroma c0 at lightness L is (du, dv) c0 / (13 L).
    const auto c_max = [&](double L) {
        if (!(L > 0.0) || !(L < l_max)) return 0.0;
        const double y = m_white.Y * cie_lightness_to_relative_luminance(L);
        const double scale = c0 / (13.0 * L);
        return c0 * luv_chroma_limit(y, du * scale, dv * scale);
    };
    const auto distance2 = [&](double L) {
        const double cm = std::min(c0, c_max(L));
        return (L - luv.L) * (L - luv.L) + (c0 - cm) * (c0 - cm);
    };
    // A 1-D minimisation over L in [0, 100]: the distance is continuous but need not be
    // unimodal (the slice of the cube is not convex), so every local minimum of a grid of
    // 256 intervals is refined by golden section within its two neighbouring intervals, and the
    // best of them is kept (tests/gamut/luv_hue_test.cpp checks it against a dense search).
    constexpr int samples = 256;
    std::array<double, samples + 1> f{};
    for (int k = 0; k <= samples; ++k) f[static_cast<std::size_t>(k)] = distance2(l_max * k / samples);
    double best_l = 0.0, best = std::numeric_limits<double>::infinity();
    int best_k = 0;
    constexpr double golden = 0.6180339887498949;
    for (int k = 0; k <= samples; ++k) {
        const std::size_t i = static_cast<std::size_t>(k);
        if ((k > 0 && f[i - 1] < f[i]) || (k < samples && f[i + 1] < f[i])) continue;
        double lo = l_max * std::max(0, k - 1) / samples, hi = l_max * std::min(samples, k + 1) / samples;
        double a = hi - golden * (hi - lo), b = lo + golden * (hi - lo);
        double fa = distance2(a), fb = distance2(b);
        for (int it = 0; it < 80 && hi - lo > 1e-13 * l_max; ++it) {
            if (fa < fb) {
                hi = b;
                b = a;
                fb = fa;
                a = hi - golden * (hi - lo);
                fa = distance2(a);
            } else {
                lo = a;
                a = b;
                fa = fb;
                b = lo + golden * (hi - lo);
                fb = distance2(b);
            }
        }
        for (const auto& [L, value] : {std::pair{l_max * k / samples, f[i]}, {0.5 * (lo + hi), distance2(0.5 * (lo + hi))}}) {
            if (value < best) {
                best = value;
                best_l = L;
                best_k = k;
            }
        }
    }
    take(branches, 3 + static_cast<std::uint64_t>(best_k));  // which local minimum
    const double L = best_l;
    const double C = std::min(c0, c_max(L));
    if (!(L > 0.0)) return {0.0, 0.0, 0.0};
    if (!(L < l_max)) return {m_gamut.max(), m_gamut.max(), m_gamut.max()};
    return rgb(m_xyz_to_rgb * [&] {
        const Xyz out = luv_to_xyz({L, C * du, C * dv}, m_white);
        return Vec3{out.X, out.Y, out.Z};
    }());
}

// --- Oklab methods ---------------------------------------------------------------------------

Rgb GamutClipper::css(const Rgb& origin, Branches* branches) const noexcept {
    // CSS Color Module Level 4, §13.2.2 "Binary Search Gamut Mapping with Local MINDE", steps
    // as the specification writes them; "white" and "black" are the gamut's extremes.
    const double max = m_gamut.max();
    const Oklab lab = to_oklab(origin);
    if (lab.L >= m_white_oklab_l) { take(branches, 1); return Rgb{max, max, max}; }
    if (lab.L <= 0.0) { take(branches, 2); return Rgb{0.0, 0.0, 0.0}; }
    if (m_gamut.contains(origin)) return origin;
    const Oklch origin_lch = oklab_to_oklch(lab);
    Oklch current = origin_lch;
    const auto delta = [&](const Rgb& clipped, const Oklch& cur) {
        return delta_e_ok(to_oklab(clipped), oklch_to_oklab(cur));
    };
    Rgb clipped = clamp(from_oklab(oklch_to_oklab(current)));
    double e = delta(clipped, current);
    if (e < css_jnd) { take(branches, 3); return clipped; }
    double lo = 0.0, hi = origin_lch.C;
    bool lo_in_gamut = true;
    while (hi - lo > css_epsilon) {
        const double chroma = 0.5 * (lo + hi);
        current.C = chroma;
        const Rgb candidate = from_oklab(oklch_to_oklab(current));
        if (lo_in_gamut && m_gamut.contains(candidate)) {
            take(branches, 4);
            lo = chroma;
            continue;
        }
        clipped = clamp(candidate);
        e = delta(clipped, current);
        if (e < css_jnd) {
            if (css_jnd - e < css_epsilon) { take(branches, 5); return clipped; }
            take(branches, 6);
            lo_in_gamut = false;
            lo = chroma;
        } else {
            take(branches, 7);
            hi = chroma;
        }
    }
    return clipped;
}

Rgb GamutClipper::oklab(const Rgb& c, Branches* branches) const noexcept {
    const double max = m_gamut.max();
    // Within rounding of the cube, the colour is on it (clip.h): the line of its lightness and
    // hue may meet the cube only at the colour itself (sRGB blue's leaves through r = 0 at 85 %
    // of its chroma and comes back only at the vertex), so no search along it could stay close.
    // Tested before the lightness rule: inside ACES2065-1's cube some colours are lighter than
    // its white (its imaginary blue has a negative Oklab L), and one a hair outside must not
    // become white.
    const double tol = oklab_rounding_tolerance * max;
    if (c.r >= -tol && c.g >= -tol && c.b >= -tol && c.r <= max + tol && c.g <= max + tol &&
        c.b <= max + tol) {
        take(branches, 1);
        return clamp(c);
    }
    const Oklab lab = to_oklab(c);
    if (!(lab.L > 0.0)) { take(branches, 2); return Rgb{0.0, 0.0, 0.0}; }
    if (!(lab.L < m_white_oklab_l)) { take(branches, 3); return Rgb{max, max, max}; }
    // The chroma line (L, s a, s b), s in [0, 1], is the segment of Ottosson's projections with
    // L0 = L: its exit, the upper end of the last piece inside the cube (oklab_projection.cpp).
    const double s = oklab_segment_exit(lab.L, lab, branches);
    return from_oklab({lab.L, s * lab.a, s * lab.b});
}

// --- Table 1 ---------------------------------------------------------------------------------

namespace {

/// A double that counts the operations done on it (Table 1's comparisons, additions and
/// subtractions, multiplications, divisions).
struct Counted {
    double v = 0.0;
    static OperationCounts& counts() {
        thread_local OperationCounts c;
        return c;
    }
    Counted() = default;
    explicit Counted(double x) : v(x) {}
    friend Counted operator+(Counted a, Counted b) { ++counts().additions; return Counted(a.v + b.v); }
    friend Counted operator-(Counted a, Counted b) { ++counts().additions; return Counted(a.v - b.v); }
    friend Counted operator*(Counted a, Counted b) { ++counts().multiplications; return Counted(a.v * b.v); }
    friend Counted operator/(Counted a, Counted b) { ++counts().divisions; return Counted(a.v / b.v); }
    friend bool operator<(Counted a, Counted b) { ++counts().comparisons; return a.v < b.v; }
    friend bool operator>(Counted a, Counted b) { ++counts().comparisons; return a.v > b.v; }
};

OperationCounts count_one(const Rgb& c) {
    const Vec3& lum = srgb().to_xyz_matrix()[1];
    const std::array<Counted, 3> l{Counted(lum[0]), Counted(lum[1]), Counted(lum[2])};
    const Counted inv(1.0 / (lum[0] + lum[1] + lum[2]));  // precomputed once per gamut
    Counted::counts() = {};
    (void)smits_clip_rgb<Counted>({Counted(c.r), Counted(c.g), Counted(c.b)}, l, inv, Counted(1.0));
    return Counted::counts();
}

}  // namespace

Table1 count_smits_operations() {
    // Representative sRGB colours: inside; above 1 in red only; red above 1 and green below 0;
    // all three channels out of range (their grey lies inside, so every plane is tested).
    return {count_one({0.5, 0.4, 0.3}), count_one({1.3, 0.5, 0.4}), count_one({1.3, -0.2, 0.4}),
            count_one({1.3, -0.2, -0.1})};
}

}  // namespace irid
