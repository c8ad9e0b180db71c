#pragma once

// The colour spaces of the command line, shared by every command that takes a SPACE (convert,
// clip): their names, parsing, CSV headers, and the conversion of a triple through XYZ relative
// to a reference white.
//
// XYZ is relative to the reference white (--white, Y = 1); CIELUV and CIELAB use that white. RGB
// spaces and Oklab have whites of their own (Oklab: D65); where it differs from the reference
// white the XYZ is chromatically adapted between the two (--adaptation).

#include <irid/color.h>

#include <optional>
#include <string>
#include <vector>

namespace irid::cli {

enum class Family { xyz, xyy, luv, lab, lchuv, lchab, oklab, oklch, rgb_linear, rgb_encoded };

/// A space named on the command line: a family, and for the RGB families the RGB space.
struct Space {
    Family family;
    const RgbSpace* rgb = nullptr;
};

/// True for NAME and NAME-linear of an RGB space.
[[nodiscard]] inline bool is_rgb(const Space& s) noexcept {
    return s.family == Family::rgb_linear || s.family == Family::rgb_encoded;
}

/// Every space name, in the order of messages: xyz, xyy, ..., then NAME and NAME-linear of each
/// built-in RGB space.
[[nodiscard]] std::vector<std::string> space_names();
/// Only the RGB names (NAME and NAME-linear of each built-in RGB space).
[[nodiscard]] std::vector<std::string> rgb_space_names();

/// The space with this name; throws UsageError naming `option` and listing the names otherwise.
[[nodiscard]] Space parse_space(const std::string& name, const char* option);
/// The command-line name of a space ("srgb", "srgb-linear", "lab", ...).
[[nodiscard]] std::string space_name(const Space& s);
/// The CSV header of a space's triples ("X,Y,Z", "L,a,b", "R,G,B", ...).
[[nodiscard]] const char* header_of(const Space& s);

/// --white: a named white or "x,y"; throws UsageError listing the names otherwise.
[[nodiscard]] Xy parse_white(const std::string& name);
/// --adaptation; throws UsageError listing the methods otherwise.
[[nodiscard]] ChromaticAdaptation parse_adaptation(const std::string& name);

/// The conversion of one triple through XYZ relative to the reference white.
class Converter {
public:
    Converter(const Space& from, const Space& to, const Xy& white, ChromaticAdaptation cat);

    /// A triple of the source space → the destination space. Between two forms of one space
    /// (srgb → srgb, srgb → srgb-linear, lab → lab) nothing goes through XYZ: only the transfer
    /// function is applied where the forms differ, so a colour comes back bit for bit.
    [[nodiscard]] Vec3 operator()(const Vec3& in) const;

    /// A triple of the source space → XYZ relative to the reference white. Throws irid::Error
    /// for an xyY chromaticity y = 0 with Y ≠ 0.
    [[nodiscard]] Xyz to_xyz(const Vec3& v) const;
    /// XYZ relative to the reference white → a triple of the destination space.
    [[nodiscard]] Vec3 from_xyz(const Xyz& c) const;
    /// XYZ relative to the reference white → XYZ relative to the destination's own white (the
    /// identity when the destination has none or it is the reference white).
    [[nodiscard]] Xyz to_destination_white(const Xyz& c) const { return apply(m_to_native, c); }

private:
    /// The white a space's XYZ is relative to, when it has one of its own.
    static std::optional<Xy> native_white(const Space& s);
    bool is_reference(const Xy& w) const { return w.x == m_white_xy.x && w.y == m_white_xy.y; }
    /// XYZ under a space's native white → XYZ under the reference white (identity when equal).
    Mat3 adaptation_from(const std::optional<Xy>& native, ChromaticAdaptation cat) const;
    Mat3 adaptation_to(const std::optional<Xy>& native, ChromaticAdaptation cat) const;
    /// XYZ → XYZ by an adaptation matrix.
    static Xyz apply(const Mat3& m, const Xyz& c) {
        const Vec3 v = m * Vec3{c.X, c.Y, c.Z};
        return {v[0], v[1], v[2]};
    }

    /// Oklab is defined on XYZ relative to D65 (Ottosson 2020).
    static constexpr Xy oklab_white{0.3127, 0.3290};

    Space m_from;
    Space m_to;
    Xy m_white_xy;
    Xyz m_white;
    Mat3 m_from_native;
    Mat3 m_to_native;
};

}  // namespace irid::cli
