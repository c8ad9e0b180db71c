#pragma once

#include <irid/color/matrix.h>
#include <irid/color/types.h>

#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace irid {

/// A transfer function (opto-electronic encoding) of an RGB space. Encoding maps linear light
/// to the encoded signal, decoding is its exact inverse. Negative values are encoded with the
/// sign mirrored, f(−v) = −f(v), so out-of-gamut values survive a round trip (as extended
/// sRGB and CSS Color 4 do).
class TransferFunction {
public:
    enum class Kind {
        /// Identity.
        linear,
        /// IEC 61966-2-1 (sRGB, also Display P3): 12.92 v below 0.0031308, else
        /// 1.055 v^(1/2.4) − 0.055; decoded as its exact inverse.
        srgb,
        /// ITU-R BT.709 / BT.601 / SMPTE 170M: 4.5 v below 0.018, else 1.099 v^0.45 − 0.099.
        rec709,
        /// ITU-R BT.2020-2: 4.5 v below β = 0.018053968510807, else α v^0.45 − (α − 1) with
        /// α = 1.09929682680944.
        rec2020,
        /// A pure power law v^(1/γ).
        gamma,
    };

    /// Throws irid::Error for a gamma kind with γ not in (0, 10].
    explicit TransferFunction(Kind kind, double gamma = 1.0);

    [[nodiscard]] double encode(double linear) const noexcept;
    [[nodiscard]] double decode(double encoded) const noexcept;
    [[nodiscard]] Kind kind() const noexcept { return m_kind; }
    [[nodiscard]] double gamma() const noexcept { return m_gamma; }

private:
    Kind m_kind;
    double m_gamma;
};

/// Chromaticities of the three primaries.
struct RgbPrimaries {
    Xy red, green, blue;
};

/// The normalised primary matrix (RGB → XYZ, white at Y = 1) derived from the primaries and the
/// white point, SMPTE RP 177-1993 §3.3: the columns are the primaries' XYZ (at Y = 1), scaled so
/// that RGB = (1, 1, 1) maps to the white. Throws irid::Error if a chromaticity is not finite, a
/// primary has y = 0, the white has y ≤ 0 or lies outside the primaries' triangle, or the
/// primaries are collinear. Imaginary primaries (y < 0, as ACES AP0's blue) are allowed.
[[nodiscard]] Mat3 rgb_to_xyz_matrix(const RgbPrimaries& primaries, const Xy& white);

/// An RGB colour space: primaries, white point and transfer function. Validated when built.
class RgbSpace {
public:
    RgbSpace(std::string name, const RgbPrimaries& primaries, const Xy& white,
             TransferFunction transfer);

    [[nodiscard]] const std::string& name() const noexcept { return m_name; }
    [[nodiscard]] const RgbPrimaries& primaries() const noexcept { return m_primaries; }
    [[nodiscard]] const Xy& white() const noexcept { return m_white; }
    /// XYZ of the white (RGB = 1, 1, 1), Y = 1.
    [[nodiscard]] const Xyz& white_xyz() const noexcept { return m_white_xyz; }
    [[nodiscard]] const TransferFunction& transfer() const noexcept { return m_transfer; }
    [[nodiscard]] const Mat3& to_xyz_matrix() const noexcept { return m_to_xyz; }
    [[nodiscard]] const Mat3& from_xyz_matrix() const noexcept { return m_from_xyz; }

    /// Linear RGB → XYZ (relative to this space's white).
    [[nodiscard]] Xyz to_xyz(const Rgb& linear) const noexcept;
    /// XYZ (relative to this space's white) → linear RGB, unclipped.
    [[nodiscard]] Rgb from_xyz(const Xyz& c) const noexcept;
    [[nodiscard]] Rgb encode(const Rgb& linear) const noexcept;
    [[nodiscard]] Rgb decode(const Rgb& encoded) const noexcept;

private:
    std::string m_name;
    RgbPrimaries m_primaries;
    Xy m_white;
    Xyz m_white_xyz;
    TransferFunction m_transfer;
    Mat3 m_to_xyz;
    Mat3 m_from_xyz;
};

/// sRGB / Rec.709 primaries, D65, sRGB transfer (IEC 61966-2-1:1999; ITU-R BT.709-6).
[[nodiscard]] const RgbSpace& srgb();
/// Display P3: DCI-P3 primaries, D65, sRGB transfer (SMPTE EG 432-1:2010; Apple).
[[nodiscard]] const RgbSpace& display_p3();
/// ITU-R BT.2020-2 primaries, D65, BT.2020 transfer.
[[nodiscard]] const RgbSpace& rec2020();
/// Adobe RGB (1998), D65, γ = 563/256 (Adobe RGB (1998) Color Image Encoding, 2005, §4.3).
[[nodiscard]] const RgbSpace& adobe_rgb();
/// SMPTE-C: SMPTE RP 145 primaries, D65, SMPTE 170M transfer (the studio monitors of 1990).
[[nodiscard]] const RgbSpace& smpte_c();
/// NTSC 1953: FCC 1953 primaries, illuminant C, γ = 2.2 (the FCC's assumed display gamma).
[[nodiscard]] const RgbSpace& ntsc1953();

/// ACES2065-1: AP0 primaries (blue imaginary, y < 0), the ACES white (0.32168, 0.33767), linear
/// (SMPTE ST 2065-1:2012). Named "aces2065-1".
[[nodiscard]] const RgbSpace& aces2065_1();
/// ACEScg: AP1 primaries, the ACES white, linear (Academy S-2014-004). Named "acescg".
[[nodiscard]] const RgbSpace& acescg();

/// Every built-in space, in a stable order (the order of the names in messages).
[[nodiscard]] std::span<const RgbSpace* const> builtin_rgb_spaces();
/// The built-in space with this name ("srgb", "display-p3", "rec2020", "adobe-rgb",
/// "smpte-c", "ntsc1953", "aces2065-1", "acescg"), or nullptr.
[[nodiscard]] const RgbSpace* find_rgb_space(std::string_view name) noexcept;

}  // namespace irid
