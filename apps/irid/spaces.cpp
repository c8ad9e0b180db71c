#include "spaces.h"

#include "cli_common.h"

#include <string_view>
#include <utility>

namespace irid::cli {

std::vector<std::string> space_names() {
    std::vector<std::string> names{"xyz", "xyy", "luv", "lab", "lchuv", "lchab", "oklab", "oklch"};
    for (const std::string& n : rgb_space_names()) names.push_back(n);
    return names;
}

std::vector<std::string> rgb_space_names() {
    std::vector<std::string> names;
    for (const RgbSpace* s : builtin_rgb_spaces()) {
        names.push_back(s->name());
        names.push_back(s->name() + "-linear");
    }
    return names;
}

Space parse_space(const std::string& name, const char* option) {
    static const std::pair<const char*, Family> fixed[] = {
        {"xyz", Family::xyz},     {"xyy", Family::xyy},     {"luv", Family::luv},
        {"lab", Family::lab},     {"lchuv", Family::lchuv}, {"lchab", Family::lchab},
        {"oklab", Family::oklab}, {"oklch", Family::oklch}};
    for (const auto& [n, f] : fixed) {
        if (name == n) return {f};
    }
    if (const RgbSpace* s = find_rgb_space(name)) return {Family::rgb_encoded, s};
    constexpr std::string_view suffix = "-linear";
    if (name.size() > suffix.size() && name.ends_with(suffix)) {
        if (const RgbSpace* s = find_rgb_space(name.substr(0, name.size() - suffix.size()))) {
            return {Family::rgb_linear, s};
        }
    }
    throw UsageError("unknown space '" + name + "' for " + option +
                     "; valid names: " + join(space_names()));
}

std::string space_name(const Space& s) {
    switch (s.family) {
        case Family::xyz: return "xyz";
        case Family::xyy: return "xyy";
        case Family::luv: return "luv";
        case Family::lab: return "lab";
        case Family::lchuv: return "lchuv";
        case Family::lchab: return "lchab";
        case Family::oklab: return "oklab";
        case Family::oklch: return "oklch";
        case Family::rgb_linear: return s.rgb->name() + "-linear";
        case Family::rgb_encoded: return s.rgb->name();
    }
    return "";
}

const char* header_of(const Space& s) {
    switch (s.family) {
        case Family::xyz: return "X,Y,Z";
        case Family::xyy: return "x,y,Y";
        case Family::luv: return "L,u,v";
        case Family::lab: return "L,a,b";
        case Family::lchuv: return "L,C,h";
        case Family::lchab: return "L,C,h";
        case Family::oklab: return "L,a,b";
        case Family::oklch: return "L,C,h";
        case Family::rgb_linear:
        case Family::rgb_encoded: return "R,G,B";
    }
    return "";
}

Xy parse_white(const std::string& name) {
    try {
        return white_point_xy(name);
    } catch (const Error& e) {
        throw UsageError(e.what());
    }
}

ChromaticAdaptation parse_adaptation(const std::string& name) {
    try {
        return parse_chromatic_adaptation(name);
    } catch (const Error& e) {
        throw UsageError(e.what());
    }
}

// --- Converter -------------------------------------------------------------------------------

Converter::Converter(const Space& from, const Space& to, const Xy& white, ChromaticAdaptation cat)
    : m_from(from),
      m_to(to),
      m_white_xy(white),
      m_white(xy_to_xyz(white)),
      m_from_native(adaptation_from(native_white(from), cat)),
      m_to_native(adaptation_to(native_white(to), cat)) {}

std::optional<Xy> Converter::native_white(const Space& s) {
    if (s.family == Family::oklab || s.family == Family::oklch) return oklab_white;
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
    if (is_rgb(m_from) && is_rgb(m_to) && m_from.rgb == m_to.rgb) {
        if (m_from.family == m_to.family) return in;
        const Rgb c{in[0], in[1], in[2]};
        const Rgb r = m_from.family == Family::rgb_encoded ? m_from.rgb->decode(c) : m_from.rgb->encode(c);
        return {r.r, r.g, r.b};
    }
    // The other families are relative to the reference white (or, for Oklab, to D65), which is
    // the same on both sides.
    if (!is_rgb(m_from) && m_from.family == m_to.family && m_from.family != Family::xyy) return in;
    return from_xyz(to_xyz(in));
}

Xyz Converter::to_xyz(const Vec3& v) const {
    switch (m_from.family) {
        case Family::xyz: return {v[0], v[1], v[2]};
        case Family::xyy:
            if (v[1] == 0.0 && v[2] != 0.0) {
                throw Error("chromaticity y = 0 with luminance Y = " + format_shortest(v[2]) +
                            " has no XYZ (only black may have y = 0)");
            }
            return xyy_to_xyz({v[0], v[1], v[2]});
        case Family::luv: return luv_to_xyz({v[0], v[1], v[2]}, m_white);
        case Family::lab: return lab_to_xyz({v[0], v[1], v[2]}, m_white);
        case Family::lchuv: return luv_to_xyz(lch_to_luv({v[0], v[1], v[2]}), m_white);
        case Family::lchab: return lab_to_xyz(lch_to_lab({v[0], v[1], v[2]}), m_white);
        case Family::oklab: return apply(m_from_native, oklab_to_xyz({v[0], v[1], v[2]}));
        case Family::oklch:
            return apply(m_from_native, oklab_to_xyz(oklch_to_oklab({v[0], v[1], v[2]})));
        case Family::rgb_linear:
            return apply(m_from_native, m_from.rgb->to_xyz({v[0], v[1], v[2]}));
        case Family::rgb_encoded:
            return apply(m_from_native, m_from.rgb->to_xyz(m_from.rgb->decode({v[0], v[1], v[2]})));
    }
    return {};
}

Vec3 Converter::from_xyz(const Xyz& c) const {
    switch (m_to.family) {
        case Family::xyz: return {c.X, c.Y, c.Z};
        case Family::xyy: {
            const Xyy r = xyz_to_xyy(c, m_white_xy);
            return {r.x, r.y, r.Y};
        }
        case Family::luv: {
            const Luv r = xyz_to_luv(c, m_white);
            return {r.L, r.u, r.v};
        }
        case Family::lab: {
            const Lab r = xyz_to_lab(c, m_white);
            return {r.L, r.a, r.b};
        }
        case Family::lchuv: {
            const LchUv r = luv_to_lch(xyz_to_luv(c, m_white));
            return {r.L, r.C, r.h};
        }
        case Family::lchab: {
            const LchAb r = lab_to_lch(xyz_to_lab(c, m_white));
            return {r.L, r.C, r.h};
        }
        case Family::oklab: {
            const Oklab r = xyz_to_oklab(apply(m_to_native, c));
            return {r.L, r.a, r.b};
        }
        case Family::oklch: {
            const Oklch r = oklab_to_oklch(xyz_to_oklab(apply(m_to_native, c)));
            return {r.L, r.C, r.h};
        }
        case Family::rgb_linear: {
            const Rgb r = m_to.rgb->from_xyz(apply(m_to_native, c));
            return {r.r, r.g, r.b};
        }
        case Family::rgb_encoded: {
            const Rgb r = m_to.rgb->encode(m_to.rgb->from_xyz(apply(m_to_native, c)));
            return {r.r, r.g, r.b};
        }
    }
    return {};
}

}  // namespace irid::cli
