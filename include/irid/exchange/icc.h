#pragma once

// ICC profiles and OpenEXR chromaticities: what an image file says about the space of its
// values, and what irid writes so that other programs know the space of its outputs.
//
// Reading (IccProfile::parse, through Little CMS 2):
// - A matrix/TRC RGB profile (ICC.1:2022 §F.3: rXYZ, gXYZ, bXYZ and one tone curve per channel)
//   whose three curves are the same is taken exactly as an RgbSpace: the colorants are brought
//   back from the profile connection space's D50 to the profile's own white, with the inverse of
//   its chromatic adaptation tag ("chad", ICC.1 Annex G) or, without one (version 2 profiles),
//   with the inverse of a Bradford adaptation from the media white point to D50 (the convention
//   of ICC.1:2001); the primaries and the white are their chromaticities, and the curve is the
//   profile's parametric curve or its table.
// - Any other RGB profile (LUT-based, or with three different curves) is used through an lcms2
//   transform to CIE XYZ (relative colorimetric, the PCS's D50 white), Bradford-adapted to the
//   reference white.
// - Refused, naming the file and the reason: a profile lcms2 cannot parse, one whose data are
//   not RGB (CMYK, grey, Lab, ...), a device link, an abstract or a named-colour profile.
//
// Writing (make_icc_profile): an ICC version 4.3 display profile built by lcms2 from the space's
// primaries, white and transfer function. Version 4 because its parametricCurveType stores the
// transfer functions irid uses (sRGB, BT.709, BT.2020, power laws) as their parameters, where a
// version 2 profile can only hold a power law or a sampled table, and because its "chad" tag
// records how the colorants were adapted to D50, so a reader can recover the primaries exactly.
// Every current reader (lcms2, and so PIL and GIMP; Apple ColorSync; Skia in Chromium; Firefox's
// qcms; exiftool) reads version 4 matrix/TRC profiles.

#include <irid/color/convert.h>
#include <irid/color/rgb.h>
#include <irid/color/types.h>
#include <irid/io/image.h>

#include <array>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace irid {

/// A parsed ICC profile of RGB data.
class IccProfile {
public:
    /// Parses `bytes`. Throws irid::Error "WHAT: ICC profile: REASON" for a profile that cannot be
    /// used: unreadable or corrupt (lcms2's reason), data not RGB (names the data colour space),
    /// a device link, abstract or named-colour profile, or an RGB profile that cannot turn its
    /// values into colours (neither matrix/TRC tags nor an A2B table).
    [[nodiscard]] static IccProfile parse(std::span<const unsigned char> bytes, const std::string& what);

    /// The profile's description (its English text, else the first it has); "" when none.
    [[nodiscard]] const std::string& description() const noexcept { return m_description; }
    /// The version in the header, "4.3", "2.1", ...
    [[nodiscard]] const std::string& version() const noexcept { return m_version; }
    /// The exact RGB space of a matrix/TRC profile with one curve for the three channels, with
    /// the profile's description as its name; empty for any other profile.
    [[nodiscard]] const std::optional<RgbSpace>& rgb_space() const noexcept { return m_space; }
    /// Why rgb_space() is empty ("a LUT-based profile", "three different tone curves"); "" when
    /// it is not.
    [[nodiscard]] const std::string& not_exact_reason() const noexcept { return m_not_exact; }

    /// The profile's RGB triples (encoded, as stored: integers scaled to [0, 1]) → CIE XYZ
    /// relative to `white` (Y = 1 for it), through lcms2's relative colorimetric transform to
    /// the PCS and a Bradford adaptation from its D50 to `white`. `in` may be `out`; sizes are
    /// whole triples, the same for both (irid::Error otherwise). Works for every profile, exact
    /// ones included (irid's own path for those is rgb_space()).
    void to_xyz(std::span<const float> in, std::span<float> out, const Xy& white, int threads = 0) const;

    /// A sentence for messages: "the ICC profile 'sRGB' (version 4.4, matrix/TRC)".
    [[nodiscard]] std::string summary() const;

private:
    struct Transform;
    std::string m_description;
    std::string m_version;
    std::optional<RgbSpace> m_space;
    std::string m_not_exact;
    std::shared_ptr<const Transform> m_transform;
};

/// Whether an ICC.1 tone curve (relative, code value 1 to linear 1) can hold the curve: not
/// when it decodes 1 above 1 (PQ: 100 with irid's scale; ACEScct: 222.86).
[[nodiscard]] bool icc_curve_can_hold(const TransferFunction& curve) noexcept;

/// The ICC version 4.3 display profile of `space` (see the file comment), built by lcms2, with
/// `description` ("" for "NAME (irid)") as its description tag and an MD5 profile ID. A sampled
/// curve is written as a curveType table of its samples. The profile is read back before it is
/// returned: throws irid::Error when lcms2 fails or when the profile would not give the same
/// space within 1e-4 (primaries, white, decoded curve): colorants beyond the range of ICC's
/// s15Fixed16Number, a sampled curve beyond [0, 1], or a curve icc_curve_can_hold refuses.
[[nodiscard]] std::vector<unsigned char> make_icc_profile(const RgbSpace& space,
                                                          std::string_view description = {});

/// The linear RGB space an OpenEXR file's "chromaticities" (red, green, blue, white x, y)
/// define, named `name`. Throws irid::Error naming `what` when there are not 8 finite values or
/// they make no RGB space (rgb_to_xyz_matrix's reasons).
[[nodiscard]] RgbSpace rgb_space_from_chromaticities(std::span<const float> chromaticities,
                                                     const std::string& name, const std::string& what);
/// The 8 chromaticities of a space, as EXR stores them.
[[nodiscard]] std::array<float, 8> exr_chromaticities(const RgbSpace& space) noexcept;
/// OpenEXR's chromaticities of CIE XYZ in the R, G and B channels (ImfChromaticities.h, and
/// "Technical Introduction to OpenEXR", CIE XYZ color): red (1, 0), green (0, 1), blue (0, 0),
/// white (1/3, 1/3), illuminant E.
inline constexpr std::array<float, 8> exr_xyz_chromaticities{1.0f, 0.0f, 0.0f, 1.0f, 0.0f, 0.0f, 1.0f / 3.0f,
                                                             1.0f / 3.0f};

/// The built-in space (irid/color/rgb.h) that `space` is, within `tolerance` in every
/// chromaticity and in the decoded value of the curve (TransferFunction::max_difference), or
/// nullptr. With `ignore_curve`, the primaries and white alone decide (a linear space).
[[nodiscard]] const RgbSpace* matching_builtin_space(const RgbSpace& space, double tolerance = 2e-4,
                                                     bool ignore_curve = false) noexcept;

/// What an image file says about the space of its values (image_space()).
struct ImageSpace {
    /// The space of the values, when it is known exactly (a matrix/TRC profile, EXR
    /// chromaticities, or the assumption below). A space matching a built-in one is that one.
    std::optional<RgbSpace> rgb;
    /// The built-in space rgb is (matching_builtin_space), or nullptr: a profile named "sRGB" that
    /// is not sRGB is not taken for it.
    const RgbSpace* builtin = nullptr;
    /// The values are encoded with rgb's transfer function (whatever a profile tags; for an
    /// untagged file, integer samples), else linear (EXR chromaticities; an untagged float file).
    bool encoded = false;
    /// A profile that is not matrix/TRC with one curve: the values go to XYZ through it.
    std::shared_ptr<const IccProfile> profile;
    /// The file says nothing: an integer file is taken as sRGB, a float one as linear sRGB.
    bool assumed = false;
    /// EXR chromaticities of CIE XYZ (exr_xyz_chromaticities): the values are X, Y and Z.
    bool xyz = false;
    /// The file states that its integer samples are linear light (a PNG's gAMA 1, a cICP linear
    /// transfer), so that taking them as such needs no note.
    bool linear_stated = false;
    /// Where the space came from, for messages: "the ICC profile 'Adobe RGB (1998)' (version 4.4,
    /// matrix/TRC)", "its EXR chromaticities", "no ICC profile or chromaticities".
    std::string origin;

    /// The space a clip pipeline starts from: xyz for a profile (its values go to XYZ through
    /// it) and for XYZ chromaticities, else rgb, encoded or linear. Points into this ImageSpace, which must outlive it and
    /// stay where it is.
    [[nodiscard]] ColorSpace colour_space() const noexcept;
};

/// The space of an image's values: its ICC profile (IccProfile::parse's refusals apply), else its
/// EXR chromaticities, else assumed (see ImageSpace). `what` names the file in errors.
[[nodiscard]] ImageSpace image_space(const io::Image& image, const std::string& what);

/// Throws irid::Error when what `image` carries (its ICC profile, its EXR chromaticities)
/// describes another space than `space`, whose name is `name`: other primaries or white (beyond
/// 2e-4 in x or y), for a profile another curve (beyond 2e-4 decoded), or a profile that is not
/// matrix/TRC with one curve (which cannot be compared). For a caller given both a space's name
/// and a profile or chromaticities to write (Python's write_image).
void check_tags_agree(const io::Image& image, const RgbSpace& space, const std::string& name);

/// Throws irid::Error when a file of `format` cannot hold values of `space` as its readers take
/// them: PQ or HLG in a JPEG, whose 8 lossy bits show the curve's steps and which carries no tag
/// for the curve (no ICC.1 curve holds it), so readers take its codes for sRGB. The message
/// names PNG or TIFF (16 bits) and EXR. tag_image checks it too; a command checks it before
/// its work.
void check_file_holds(const RgbSpace& space, io::ImageFormat format);

/// Marks `image`, about to be written to a file of `format`, as holding values of `space`:
/// color_space = the space's name (with "-linear" for EXR), and for PNG and TIFF the space's
/// ICC profile (make_icc_profile; none for a curve icc_curve_can_hold refuses: PQ, HLG, ACEScct), for EXR its chromaticities and, when the white is not D65's
/// (0.3127, 0.3290), the adoptedNeutral that tells readers assuming D65 otherwise. EXR values
/// are linear, PNG and TIFF values encoded with the space's curve. An image of fewer than three
/// channels (grey) gets only the name: an RGB profile does not describe it. Throws irid::Error
/// as check_file_holds does.
void tag_image(io::Image& image, const RgbSpace& space, io::ImageFormat format);
/// Marks `image`, about to be written to an EXR, as holding CIE XYZ (linear, in its R, G and B
/// channels): color_space "xyz" and exr_xyz_chromaticities, which image_space() reads back as
/// XYZ. No ICC profile or adoptedNeutral. (PNG, TIFF and JPEG have no XYZ encoding irid writes.)
void tag_image_xyz(io::Image& image);

}  // namespace irid
