#include <irid/color/convert.h>

#include "convert_simd.h"

#include <irid/color/illuminant.h>
#include <irid/color/numeric_table.h>
#include <irid/color/observer.h>
#include <irid/color/spaces.h>
#include <irid/error.h>
#include <irid/text_input.h>

#include <cmath>
#include <functional>
#include <string>
#include <utility>

namespace irid {
namespace {

constexpr std::pair<const char*, SpaceFamily> fixed_spaces[] = {
    {"xyz", SpaceFamily::xyz},     {"xyy", SpaceFamily::xyy},     {"luv", SpaceFamily::luv},
    {"lab", SpaceFamily::lab},     {"lchuv", SpaceFamily::lchuv}, {"lchab", SpaceFamily::lchab},
    {"oklab", SpaceFamily::oklab}, {"oklch", SpaceFamily::oklch}};

std::string join_names(const std::vector<std::string>& names) {
    std::string out;
    for (const std::string& n : names) out += (out.empty() ? "" : ", ") + n;
    return out;
}

}  // namespace

std::vector<std::string> color_space_names() {
    std::vector<std::string> names;
    for (const auto& [n, f] : fixed_spaces) names.emplace_back(n);
    for (const std::string& n : rgb_color_space_names()) names.push_back(n);
    return names;
}

std::vector<std::string> rgb_color_space_names() {
    std::vector<std::string> names;
    for (const std::string& n : rgb_space_names()) {
        names.push_back(n);
        names.push_back(n + "-linear");
    }
    return names;
}

std::optional<ColorSpace> find_color_space(std::string_view name) {
    for (const auto& [n, f] : fixed_spaces) {
        if (same_name(name, n)) return ColorSpace{f};
    }
    if (const RgbSpace* s = find_rgb_space(name)) return ColorSpace{SpaceFamily::rgb_encoded, s};
    constexpr std::string_view suffix = "-linear";
    if (name.size() > suffix.size() && same_name(name.substr(name.size() - suffix.size()), suffix)) {
        if (const RgbSpace* s = find_rgb_space(name.substr(0, name.size() - suffix.size()))) {
            return ColorSpace{SpaceFamily::rgb_linear, s};
        }
    }
    return std::nullopt;
}

ColorSpace color_space(std::string_view name) {
    if (const std::optional<ColorSpace> s = find_color_space(name)) return *s;
    std::vector<std::string> valid = color_space_names();
    const std::string message =
        "unknown space " + quote_untrusted(name) + "; valid names: " + join_names(valid);
    throw UnknownNameError(message, std::move(valid));
}

std::string color_space_name(const ColorSpace& s) {
    switch (s.family) {
        case SpaceFamily::xyz: return "xyz";
        case SpaceFamily::xyy: return "xyy";
        case SpaceFamily::luv: return "luv";
        case SpaceFamily::lab: return "lab";
        case SpaceFamily::lchuv: return "lchuv";
        case SpaceFamily::lchab: return "lchab";
        case SpaceFamily::oklab: return "oklab";
        case SpaceFamily::oklch: return "oklch";
        case SpaceFamily::rgb_linear: return s.rgb->name() + "-linear";
        case SpaceFamily::rgb_encoded: return s.rgb->name();
    }
    return "";
}

const char* channel_names(const ColorSpace& s) noexcept {
    switch (s.family) {
        case SpaceFamily::xyz: return "X,Y,Z";
        case SpaceFamily::xyy: return "x,y,Y";
        case SpaceFamily::luv: return "L,u,v";
        case SpaceFamily::lab: return "L,a,b";
        case SpaceFamily::lchuv: return "L,C,h";
        case SpaceFamily::lchab: return "L,C,h";
        case SpaceFamily::oklab: return "L,a,b";
        case SpaceFamily::oklch: return "L,C,h";
        case SpaceFamily::rgb_linear:
        case SpaceFamily::rgb_encoded: return "R,G,B";
    }
    return "";
}

// --- Converter -------------------------------------------------------------------------------

Converter::Converter(const ColorSpace& from, const ColorSpace& to, const Xy& white,
                     ChromaticAdaptation cat)
    : m_from(from),
      m_to(to),
      m_white_xy(white),
      m_white(xy_to_xyz(white)),
      m_from_native(adaptation_from(native_white(from), cat)),
      m_to_native(adaptation_to(native_white(to), cat)) {
    if ((from.is_rgb() && from.rgb == nullptr) || (to.is_rgb() && to.rgb == nullptr)) {
        throw Error("converter: an RGB family needs its RGB space");
    }
    check_white_chromaticity(white, "reference white");
}

std::optional<Xy> Converter::native_white(const ColorSpace& s) {
    if (s.family == SpaceFamily::oklab || s.family == SpaceFamily::oklch) return oklab_white;
    if (s.rgb != nullptr) return s.rgb->white();
    return std::nullopt;
}

Mat3 Converter::adaptation_from(const std::optional<Xy>& native, ChromaticAdaptation cat) const {
    if (!native || is_reference(*native)) return Mat3::identity();
    return adaptation_matrix(xy_to_xyz(*native), m_white, cat);
}

Mat3 Converter::adaptation_to(const std::optional<Xy>& native, ChromaticAdaptation cat) const {
    if (!native || is_reference(*native)) return Mat3::identity();
    return adaptation_matrix(m_white, xy_to_xyz(*native), cat);
}

Vec3 Converter::operator()(const Vec3& in) const {
    if (m_from.is_rgb() && m_to.is_rgb() && m_from.rgb == m_to.rgb) {
        if (m_from.family == m_to.family) return in;
        const Rgb c{in[0], in[1], in[2]};
        const Rgb r = m_from.family == SpaceFamily::rgb_encoded ? m_from.rgb->decode(c)
                                                                : m_from.rgb->encode(c);
        return {r.r, r.g, r.b};
    }
    // The other families are relative to the reference white (or, for Oklab, to D65), which is
    // the same on both sides.
    if (!m_from.is_rgb() && m_from.family == m_to.family && m_from.family != SpaceFamily::xyy) {
        return in;
    }
    return from_xyz(to_xyz(in));
}

template <class T>
void Converter::convert_span(std::span<const T> in, std::span<T> out) const {
    if (in.size() % 3 != 0 || out.size() != in.size()) {
        throw Error("convert: " + std::to_string(in.size()) + " values in, " +
                    std::to_string(out.size()) + " out; both must be the same multiple of 3");
    }
    // The same memory, or none in common (std::less: a total order on unrelated pointers).
    const std::less<const T*> less;
    if (in.data() != out.data() && less(in.data(), out.data() + out.size()) &&
        less(out.data(), in.data() + in.size())) {
        throw Error("convert: input and output overlap; they must be the same array or disjoint");
    }
    const std::size_t n = in.size() / 3;
    // An xyY y = 0 with Y ≠ 0 is refused before anything is written (out may be in).
    if (m_from.family == SpaceFamily::xyy) {
        for (std::size_t i = 0; i < n; ++i) {
            if (in[3 * i + 1] == T(0) && in[3 * i + 2] != T(0)) {
                throw Error("colour " + std::to_string(i) + ": chromaticity y = 0 with luminance Y = " +
                            format_shortest(static_cast<double>(in[3 * i + 2])) +
                            " has no XYZ (only black may have y = 0)");
            }
        }
    }
    // Linear source → Oklab: one matrix to LMS (M1 after the adaptation to D65, after the
    // source's matrix to XYZ), the cube roots, M2.
    const bool linear_source =
        m_from.family == SpaceFamily::xyz || m_from.family == SpaceFamily::rgb_linear;
    if (linear_source && m_to.family == SpaceFamily::oklab) {
        const Mat3 source_to_xyz = m_from.family == SpaceFamily::xyz
                                       ? Mat3::identity()
                                       : m_from_native * m_from.rgb->to_xyz_matrix();
        const Mat3 to_lms = oklab_m1 * (m_to_native * source_to_xyz);
        double m1[9], m2[9];
        for (int r = 0; r < 3; ++r) {
            for (int c = 0; c < 3; ++c) {
                m1[3 * r + c] = to_lms.m[r][c];
                m2[3 * r + c] = oklab_m2.m[r][c];
            }
        }
        // In place (out == in) is safe: each block is read whole before it is written.
        detail::linear_to_oklab_simd(in.data(), out.data(), n, m1, m2);
        return;
    }
    const std::optional<Mat3> m = m_from == m_to ? std::nullopt : linear_matrix();
    if (m) {
        for (std::size_t i = 0; i < n; ++i) {
            const Vec3 v = *m * Vec3{static_cast<double>(in[3 * i]), static_cast<double>(in[3 * i + 1]),
                                     static_cast<double>(in[3 * i + 2])};
            out[3 * i] = static_cast<T>(v[0]);
            out[3 * i + 1] = static_cast<T>(v[1]);
            out[3 * i + 2] = static_cast<T>(v[2]);
        }
        return;
    }
    for (std::size_t i = 0; i < n; ++i) {
        const Vec3 v = (*this)({static_cast<double>(in[3 * i]), static_cast<double>(in[3 * i + 1]),
                                static_cast<double>(in[3 * i + 2])});
        out[3 * i] = static_cast<T>(v[0]);
        out[3 * i + 1] = static_cast<T>(v[1]);
        out[3 * i + 2] = static_cast<T>(v[2]);
    }
}

void Converter::convert(std::span<const double> in, std::span<double> out) const {
    convert_span<double>(in, out);
}

void Converter::convert(std::span<const float> in, std::span<float> out) const {
    convert_span<float>(in, out);
}

std::optional<Mat3> Converter::linear_matrix() const {
    // An encoded space whose curve is the identity (aces2065-1, acescg) is linear too.
    const auto linear = [](const ColorSpace& s) {
        return s.family == SpaceFamily::xyz || s.family == SpaceFamily::rgb_linear ||
               (s.family == SpaceFamily::rgb_encoded && s.rgb->transfer().kind() == TransferFunction::Kind::linear);
    };
    if (!linear(m_from) || !linear(m_to)) return std::nullopt;
    // The map is linear: its columns are the images of the unit vectors.
    return Mat3::from_columns((*this)({1.0, 0.0, 0.0}), (*this)({0.0, 1.0, 0.0}),
                              (*this)({0.0, 0.0, 1.0}));
}

Xyz Converter::to_xyz(const Vec3& v) const {
    switch (m_from.family) {
        case SpaceFamily::xyz: return {v[0], v[1], v[2]};
        case SpaceFamily::xyy:
            if (v[1] == 0.0 && v[2] != 0.0) {
                throw Error("chromaticity y = 0 with luminance Y = " + format_shortest(v[2]) +
                            " has no XYZ (only black may have y = 0)");
            }
            return xyy_to_xyz({v[0], v[1], v[2]});
        case SpaceFamily::luv: return luv_to_xyz({v[0], v[1], v[2]}, m_white);
        case SpaceFamily::lab: return lab_to_xyz({v[0], v[1], v[2]}, m_white);
        case SpaceFamily::lchuv: return luv_to_xyz(lch_to_luv({v[0], v[1], v[2]}), m_white);
        case SpaceFamily::lchab: return lab_to_xyz(lch_to_lab({v[0], v[1], v[2]}), m_white);
        case SpaceFamily::oklab: return apply(m_from_native, oklab_to_xyz({v[0], v[1], v[2]}));
        case SpaceFamily::oklch:
            return apply(m_from_native, oklab_to_xyz(oklch_to_oklab({v[0], v[1], v[2]})));
        case SpaceFamily::rgb_linear:
            return apply(m_from_native, m_from.rgb->to_xyz({v[0], v[1], v[2]}));
        case SpaceFamily::rgb_encoded:
            return apply(m_from_native, m_from.rgb->to_xyz(m_from.rgb->decode({v[0], v[1], v[2]})));
    }
    return {};
}

Vec3 Converter::from_xyz(const Xyz& c) const {
    switch (m_to.family) {
        case SpaceFamily::xyz: return {c.X, c.Y, c.Z};
        case SpaceFamily::xyy: {
            const Xyy r = xyz_to_xyy(c, m_white_xy);
            return {r.x, r.y, r.Y};
        }
        case SpaceFamily::luv: {
            const Luv r = xyz_to_luv(c, m_white);
            return {r.L, r.u, r.v};
        }
        case SpaceFamily::lab: {
            const Lab r = xyz_to_lab(c, m_white);
            return {r.L, r.a, r.b};
        }
        case SpaceFamily::lchuv: {
            const LchUv r = luv_to_lch(xyz_to_luv(c, m_white));
            return {r.L, r.C, r.h};
        }
        case SpaceFamily::lchab: {
            const LchAb r = lab_to_lch(xyz_to_lab(c, m_white));
            return {r.L, r.C, r.h};
        }
        case SpaceFamily::oklab: {
            const Oklab r = xyz_to_oklab(apply(m_to_native, c));
            return {r.L, r.a, r.b};
        }
        case SpaceFamily::oklch: {
            const Oklch r = oklab_to_oklch(xyz_to_oklab(apply(m_to_native, c)));
            return {r.L, r.C, r.h};
        }
        case SpaceFamily::rgb_linear: {
            const Rgb r = m_to.rgb->from_xyz(apply(m_to_native, c));
            return {r.r, r.g, r.b};
        }
        case SpaceFamily::rgb_encoded: {
            const Rgb r = m_to.rgb->encode(m_to.rgb->from_xyz(apply(m_to_native, c)));
            return {r.r, r.g, r.b};
        }
    }
    return {};
}

}  // namespace irid
