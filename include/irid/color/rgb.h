#pragma once

#include <irid/color/matrix.h>
#include <irid/color/types.h>

#include <array>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace irid {

/// A transfer function (opto-electronic encoding) of an RGB space. Encoding maps linear light
/// to the encoded signal, decoding is its exact inverse. Negative values are encoded with the
/// sign mirrored, f(−v) = −f(v), so out-of-gamut values survive a round trip (as extended
/// sRGB and CSS Color 4 do); PQ, an absolute display signal, and ACEScct, whose standard
/// defines it on all reals by its own pieces, are the exceptions (see Kind::pq, Kind::acescct).
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
        /// SMPTE ST 2084 (PQ, ITU-R BT.2100-2 Table 4) with irid's display-light scale, linear
        /// 1.0 = 100 cd/m²: encode(v) = pq_encode(100 v) (irid/color/hdr_transfer.h). PQ's signal
        /// holds 0 to 10000 cd/m² and nothing else, so linear values are clamped to [0, 100]
        /// (a negative one encodes as 0 cd/m², whose signal is 7.3e-7, not 0) and signals to
        /// [0, 1]; NaN encodes as 0 cd/m². The round trip is exact within [0, 100] only.
        pq,
        /// ITU-R BT.2100-2 HLG (Table 5) as a display encoding with irid's display-light scale,
        /// linear 1.0 = 100 cd/m², for a display of nominal peak hlg_nominal_peak_nits (1000
        /// cd/m², system gamma 1.2): display light → scene light through the inverse of the
        /// reference OOTF, then the OETF. The OOTF acts on the luminance Y_S of all three
        /// channels (F_D = L_W Y_S^(γ−1) E), so RgbSpace::encode and decode apply it to whole
        /// colours (hlg_encode, hlg_decode of irid/color/hdr_transfer.h); encode() and decode()
        /// of one value are the curve on the neutral axis (R = G = B), where Y_S = E: signal 1 is
        /// linear 10 (1000 cd/m²), 0.75 is 2.03 (BT.2408's reference white, 203 cd/m²). As PQ,
        /// it is not mirrored: a negative channel is 0 cd/m², display light beyond what the
        /// signal holds (scene light above 1) is clamped, signals to [0, 1], NaN to 0.
        hlg,
        /// ACEScct (Academy S-2016-001 §4.4): 10.5402377416545 v + 0.0729055341958355 for
        /// v <= 0.0078125 (2^-7), else (log2 v + 9.72) / 17.52; decoded as its exact inverse
        /// (the standard's clamp of decoded values at 65504, half float's largest, is left out).
        /// Not mirrored: negatives take the linear toe, as the standard defines them, so
        /// encode(0) = 0.0729055341958355 and decode(1) = 2^7.8 = 222.86.
        acescct,
        /// ICC.1:2022 §10.18 parametricCurveType in its general form (function type 4): the
        /// decoding is (a e + b)^g + ec for e >= d, else c e + f. Types 0-3 are special cases
        /// of it (see parametric()).
        parametric,
        /// A sampled decoding (ICC curveType with more than one entry): linear values at n
        /// evenly spaced encoded values 0, 1/(n-1), ..., 1, interpolated linearly between them
        /// and extended beyond 1 along the last segment.
        sampled,
    };

    /// The parameters (g, a, b, c, d, e, f) of a parametric curve, in ICC.1's order.
    using Parameters = std::array<double, 7>;
    /// How many parameters ICC.1:2022 Table 68 gives function types 0 to 4.
    static constexpr std::array<std::size_t, 5> parametric_counts{1, 3, 4, 5, 7};

    /// Throws irid::Error for a gamma kind with γ not in (0, 10], and for the parametric and
    /// sampled kinds (which need parametric() or sampled()).
    explicit TransferFunction(Kind kind, double gamma = 1.0);

    /// An ICC parametric curve of function type 0-4 (ICC.1:2022 Table 68) with its 1, 3, 4, 5
    /// or 7 parameters, brought to the general form: type 0 Y = X^g; 1 Y = (aX + b)^g for
    /// X >= -b/a, else 0; 2 the same + c; 3 (aX + b)^g for X >= d, else cX; 4 (aX + b)^g + e
    /// for X >= d, else cX + f. Throws irid::Error for another type or count, a parameter that is
    /// not finite, g not in (0, 10], a <= 0 or c < 0 (a decoding that does not rise).
    [[nodiscard]] static TransferFunction parametric(int function_type, std::span<const double> params);
    /// A sampled decoding: `linear[i]` is the linear value of the encoded value i/(n-1). Throws
    /// irid::Error for fewer than 2 or more than 65536 samples, a sample that is not finite, or
    /// samples that fall anywhere (a decoding must not; flat runs are allowed) or do not rise
    /// at all.
    [[nodiscard]] static TransferFunction sampled(std::vector<double> linear);

    [[nodiscard]] double encode(double linear) const noexcept;
    [[nodiscard]] double decode(double encoded) const noexcept;
    [[nodiscard]] Kind kind() const noexcept { return m_kind; }
    [[nodiscard]] double gamma() const noexcept { return m_gamma; }
    /// The curve as an ICC parametric curve of type 4, (g, a, b, c, d, e, f): exact for every
    /// kind but sampled and pq (for which it is empty). sRGB: g 2.4, a 1/1.055, b 0.055/1.055,
    /// c 1/12.92, d 12.92 × 0.0031308; BT.709/BT.2020: g 1/0.45, a 1/α, b (α−1)/α, c 1/4.5,
    /// d 4.5 β; gamma γ: g γ, a 1; linear: g 1, a 1.
    [[nodiscard]] std::optional<Parameters> parameters() const noexcept;
    /// The samples of a sampled curve (empty for any other kind).
    [[nodiscard]] std::span<const double> samples() const noexcept;
    /// The largest |decode(e) − other.decode(e)| over 1024 evenly spaced e in [0, 1].
    [[nodiscard]] double max_difference(const TransferFunction& other) const noexcept;

private:
    TransferFunction(Kind kind, const Parameters& params, std::shared_ptr<const std::vector<double>> samples);
    [[nodiscard]] double decode_magnitude(double e) const noexcept;
    [[nodiscard]] double encode_magnitude(double v) const noexcept;

    Kind m_kind;
    double m_gamma;
    Parameters m_params{};
    /// The sampled kind's table, shared by copies.
    std::shared_ptr<const std::vector<double>> m_samples;
};

/// The nominal peak of the HLG display encoding (TransferFunction::Kind::hlg) [cd/m²]: the
/// reference display of ITU-R BT.2100-2 Table 5 (note 5b: system gamma 1.2 at 1000 cd/m²) and of
/// ITU-R BT.2408.
inline constexpr double hlg_nominal_peak_nits = 1000.0;

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
    /// The transfer function on each channel; for HLG on the colour's luminance (Kind::hlg).
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

/// ACEScct: AP1 primaries, the ACES white, the ACEScct log curve (Academy S-2016-001;
/// TransferFunction::Kind::acescct). Named "acescct": a grading (log) space, not a working
/// space: builtin_rgb_spaces() leaves it out, as its code value 1 decodes to 222.86, which a
/// working space's cube [0, 1]³, its ICC profile and the figures of the built-in spaces do not
/// take; rgb_space_names() and find_rgb_space() know it (log_rgb_spaces()).
[[nodiscard]] const RgbSpace& acescct();

// The display encodings: how a display's signal is written to a file, for the display
// transforms (irid/gamut/display_transform.h). Their linear values are display light with
// 1.0 = 100 cd/m². They are named spaces like the ones above (convert, clip and Python take
// them) but not working spaces: builtin_rgb_spaces() leaves them out.

/// ITU-R BT.1886: BT.709 primaries, D65, the reference EOTF with a black of 0, L = V^2.4
/// (BT.1886 Annex 1 with L_B = 0). Named "rec1886".
[[nodiscard]] const RgbSpace& rec1886();
/// ITU-R BT.1886 on the BT.2020 primaries (OpenColorIO's "Rec.1886 Rec.2020 - Display"): D65,
/// γ = 2.4. Named "rec1886-rec2020".
[[nodiscard]] const RgbSpace& rec1886_rec2020();
/// SMPTE RP 431-2 / EG 432-1 "P3-D65" for projection: P3 primaries, D65, γ = 2.6 (RP 431-2
/// §7.1's decoding gamma). Named "p3-d65".
[[nodiscard]] const RgbSpace& p3_d65();
/// ITU-R BT.2100-2 PQ: BT.2020 primaries, D65, ST 2084 (TransferFunction::Kind::pq). Named
/// "rec2100-pq".
[[nodiscard]] const RgbSpace& rec2100_pq();
/// P3 primaries, D65, ST 2084: the HDR mastering display of SMPTE ST 2084 with P3-D65 (as
/// OpenColorIO's "ST2084-P3-D65 - Display"). Named "p3-d65-pq".
[[nodiscard]] const RgbSpace& p3_d65_pq();
/// ITU-R BT.2100-2 HLG: BT.2020 primaries, D65, the HLG OETF with the reference OOTF of a 1000
/// cd/m² display (TransferFunction::Kind::hlg), display light to signal. Named "rec2100-hlg".
[[nodiscard]] const RgbSpace& rec2100_hlg();

/// Every built-in working space, in a stable order (the order of the names in messages).
[[nodiscard]] std::span<const RgbSpace* const> builtin_rgb_spaces();
/// The display encodings, in a stable order: rec1886, rec1886-rec2020, p3-d65, rec2100-pq,
/// p3-d65-pq, rec2100-hlg.
[[nodiscard]] std::span<const RgbSpace* const> display_rgb_spaces();
/// The log (grading) encodings: acescct.
[[nodiscard]] std::span<const RgbSpace* const> log_rgb_spaces();
/// The names of the working spaces, then of the log encodings and of the display encodings (the
/// names find_rgb_space knows), in that stable order.
[[nodiscard]] std::vector<std::string> rgb_space_names();
/// The built-in space with this name ("srgb", "display-p3", "rec2020", "adobe-rgb",
/// "smpte-c", "ntsc1953", "aces2065-1", "acescg", "acescct", or a display encoding), in any case
/// ("sRGB", "ACEScg"; same_name), or nullptr. The space keeps its canonical lower-case name().
[[nodiscard]] const RgbSpace* find_rgb_space(std::string_view name) noexcept;
/// Whether `given` names the lower-case `canonical`: equal but for the case of ASCII letters
/// (UTF-8 and every other byte compared as they are). How every space is looked up by name, as
/// displays are (irid/gamut/aces2_display.h).
[[nodiscard]] bool same_name(std::string_view given, std::string_view canonical) noexcept;

}  // namespace irid
