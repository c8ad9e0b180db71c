#pragma once

// Colour spaces by name, and the conversion of triples between any two of them: what
// `irid convert`, `irid clip --from` and the Python module's convert() share.
//
// XYZ is relative to a reference white (Y = 1 for it); CIELUV and CIELAB use that white. RGB
// spaces and Oklab have whites of their own (Oklab: D65); where one differs from the reference
// white the XYZ is chromatically adapted between the two.
//
// Names: xyz, xyy, luv, lab, lchuv, lchab, oklab, oklch, then for each built-in RGB space NAME
// (encoded with its transfer function) and NAME-linear (builtin_rgb_spaces(); a linear space
// such as acescg takes both names for the same values). They are found in any case ("sRGB",
// "XYZ", "ACEScg-Linear": same_name, irid/color/rgb.h); color_space_name() and the lists of
// names in messages give the canonical lower-case ones.

#include <irid/color/adaptation.h>
#include <irid/color/matrix.h>
#include <irid/color/rgb.h>
#include <irid/color/types.h>

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace irid {

/// What a colour space's triples are.
enum class SpaceFamily { xyz, xyy, luv, lab, lchuv, lchab, oklab, oklch, rgb_linear, rgb_encoded };

/// A named colour space: a family, and for the RGB families the RGB space (a built-in one or
/// any other that outlives the ColorSpace).
struct ColorSpace {
    SpaceFamily family = SpaceFamily::xyz;
    const RgbSpace* rgb = nullptr;

    [[nodiscard]] bool is_rgb() const noexcept {
        return family == SpaceFamily::rgb_linear || family == SpaceFamily::rgb_encoded;
    }
    /// The same space's linear form (itself for every family but encoded RGB).
    [[nodiscard]] ColorSpace linear() const noexcept {
        return family == SpaceFamily::rgb_encoded ? ColorSpace{SpaceFamily::rgb_linear, rgb} : *this;
    }
    friend bool operator==(const ColorSpace&, const ColorSpace&) = default;
};

/// Every space name, in the order of messages: xyz, xyy, ..., oklch, then NAME and NAME-linear
/// of each built-in RGB space.
[[nodiscard]] std::vector<std::string> color_space_names();
/// Only the RGB names (NAME and NAME-linear of each built-in RGB space).
[[nodiscard]] std::vector<std::string> rgb_color_space_names();

/// The space with this name, or nothing.
[[nodiscard]] std::optional<ColorSpace> find_color_space(std::string_view name);
/// The space with this name; throws UnknownNameError listing the names otherwise.
[[nodiscard]] ColorSpace color_space(std::string_view name);
/// A space's name ("srgb", "srgb-linear", "lab", ...).
[[nodiscard]] std::string color_space_name(const ColorSpace& s);
/// The names of a space's three channels ("X,Y,Z", "L,a,b", "R,G,B", ...), as a CSV header.
[[nodiscard]] const char* channel_names(const ColorSpace& s) noexcept;

/// The conversion of triples from one space to another through XYZ relative to the reference
/// white. Built once; the calls are const and may run on many threads at once.
class Converter {
public:
    /// `white`: the reference white of XYZ, CIELUV and CIELAB; `cat`: the adaptation where a
    /// space's own white differs from it.
    Converter(const ColorSpace& from, const ColorSpace& to, const Xy& white = d65_xy,
              ChromaticAdaptation cat = ChromaticAdaptation::bradford);

    [[nodiscard]] const ColorSpace& from() const noexcept { return m_from; }
    [[nodiscard]] const ColorSpace& to() const noexcept { return m_to; }
    [[nodiscard]] const Xy& white() const noexcept { return m_white_xy; }

    /// A triple of the source space → the destination space. Between two forms of one space
    /// (srgb → srgb, srgb → srgb-linear, lab → lab) nothing goes through XYZ: only the transfer
    /// function is applied where the forms differ, so a colour comes back bit for bit. Throws
    /// irid::Error for an xyY chromaticity y = 0 with Y ≠ 0 (which has no XYZ).
    [[nodiscard]] Vec3 operator()(const Vec3& in) const;

    /// `in` and `out` hold whole triples (size a multiple of 3, the same for both; they may be
    /// the same memory, or disjoint). Throws irid::Error naming the triple's index for an xyY
    /// y = 0 with Y ≠ 0, for sizes that do not fit or for a partial overlap, before anything is
    /// written.
    void convert(std::span<const double> in, std::span<double> out) const;
    /// The same on floats, computed in double.
    void convert(std::span<const float> in, std::span<float> out) const;

    /// A triple of the source space → XYZ relative to the reference white. Throws irid::Error
    /// for an xyY chromaticity y = 0 with Y ≠ 0.
    [[nodiscard]] Xyz to_xyz(const Vec3& v) const;
    /// XYZ relative to the reference white → a triple of the destination space.
    [[nodiscard]] Vec3 from_xyz(const Xyz& c) const;
    /// XYZ relative to the reference white → XYZ relative to the destination's own white (the
    /// identity when the destination has none or it is the reference white).
    [[nodiscard]] Xyz to_destination_white(const Xyz& c) const { return apply(m_to_native, c); }

    /// When both spaces are linear (XYZ, linear RGB, or an RGB space whose curve is the identity)
    /// the whole conversion is one matrix,
    /// which this returns (in · columns); otherwise nothing.
    [[nodiscard]] std::optional<Mat3> linear_matrix() const;

private:
    static std::optional<Xy> native_white(const ColorSpace& s);
    bool is_reference(const Xy& w) const { return w.x == m_white_xy.x && w.y == m_white_xy.y; }
    Mat3 adaptation_from(const std::optional<Xy>& native, ChromaticAdaptation cat) const;
    Mat3 adaptation_to(const std::optional<Xy>& native, ChromaticAdaptation cat) const;
    static Xyz apply(const Mat3& m, const Xyz& c) {
        const Vec3 v = m * Vec3{c.X, c.Y, c.Z};
        return {v[0], v[1], v[2]};
    }
    template <class T>
    void convert_span(std::span<const T> in, std::span<T> out) const;

    /// Oklab is defined on XYZ relative to D65 (Ottosson 2020, "A perceptual color space for
    /// image processing": M1 takes XYZ under D65).
    static constexpr Xy oklab_white = d65_xy;

    ColorSpace m_from;
    ColorSpace m_to;
    Xy m_white_xy;
    Xyz m_white;
    Mat3 m_from_native;
    Mat3 m_to_native;
};

}  // namespace irid
