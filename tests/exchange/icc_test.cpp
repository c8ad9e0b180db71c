// ICC profiles and EXR chromaticities (irid/exchange/icc.h): irid's exact reading of matrix/TRC
// profiles checked against Little CMS's own evaluation of the same profiles, on the real profiles
// Debian's colord-data ships, on profiles built here with lcms2, and on published primaries.
#include <irid/color/adaptation.h>
#include <irid/color/spaces.h>
#include <irid/error.h>
#include <irid/exchange/icc.h>
#include <irid/io/image.h>

#include <gtest/gtest.h>
#include <lcms2.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace irid {
namespace {
namespace fs = std::filesystem;

/// Debian's colord-data (scripts/install-deps installs it).
const fs::path colord_dir = "/usr/share/color/icc/colord";

std::vector<unsigned char> read_bytes(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::vector<unsigned char> save(cmsHPROFILE h) {
    cmsUInt32Number n = 0;
    EXPECT_TRUE(cmsSaveProfileToMem(h, nullptr, &n));
    std::vector<unsigned char> bytes(n);
    EXPECT_TRUE(cmsSaveProfileToMem(h, bytes.data(), &n));
    cmsCloseProfile(h);
    return bytes;
}

/// The RGB colorant profiles of colord-data, by file name (the two named-colour ones excluded).
const char* const colord_rgb[] = {
    "AdobeRGB1998.icc", "AppleRGB.icc",   "BestRGB.icc",     "BetaRGB.icc",          "Bluish.icc",
    "BruceRGB.icc",     "CIE-RGB.icc",    "ColorMatchRGB.icc", "DonRGB4.icc",        "ECI-RGBv1.icc",
    "ECI-RGBv2.icc",    "EktaSpacePS5.icc", "Gamma5000K.icc", "Gamma5500K.icc",      "Gamma6500K.icc",
    "NTSC-RGB.icc",     "PAL-RGB.icc",    "ProPhotoRGB.icc", "Rec709.icc",           "SMPTE-C-RGB.icc",
    "SwappedRedAndGreen.icc", "WideGamutRGB.icc", "sRGB.icc"};

/// irid's exact space, decoded and taken to XYZ under D65 (Bradford from the space's white).
Xyz exact_xyz(const RgbSpace& s, const Rgb& encoded) {
    const Xyz native = s.to_xyz(s.decode(encoded));
    const Vec3 v = adaptation_matrix(s.white_xyz(), xy_to_xyz({0.3127, 0.3290})) * Vec3{native.X, native.Y, native.Z};
    return {v[0], v[1], v[2]};
}

/// The largest |XYZ| difference between irid's exact space and lcms2's transform on a 9³ grid.
double worst_against_lcms(const IccProfile& p) {
    std::vector<float> rgb;
    for (int r = 0; r <= 8; ++r) {
        for (int g = 0; g <= 8; ++g) {
            for (int b = 0; b <= 8; ++b) {
                rgb.insert(rgb.end(), {static_cast<float>(r) / 8.0f, static_cast<float>(g) / 8.0f,
                                       static_cast<float>(b) / 8.0f});
            }
        }
    }
    std::vector<float> xyz(rgb.size());
    p.to_xyz(rgb, xyz, {0.3127, 0.3290}, 1);
    double worst = 0.0;
    for (std::size_t i = 0; i < rgb.size(); i += 3) {
        const Xyz e = exact_xyz(*p.rgb_space(), {rgb[i], rgb[i + 1], rgb[i + 2]});
        worst = std::max({worst, std::abs(e.X - xyz[i]), std::abs(e.Y - xyz[i + 1]), std::abs(e.Z - xyz[i + 2])});
    }
    return worst;
}

TEST(IccProfile, EveryColordRgbProfileIsTakenExactlyAndAgreesWithLittleCms) {
    for (const char* name : colord_rgb) {
        SCOPED_TRACE(name);
        const IccProfile p = IccProfile::parse(read_bytes(colord_dir / name), name);
        ASSERT_TRUE(p.rgb_space().has_value()) << p.not_exact_reason();
        EXPECT_FALSE(p.description().empty());
        EXPECT_EQ(p.version(), "4.4");
        // lcms2 evaluates the same tags in float: the two readings agree far below 1/255.
        EXPECT_LT(worst_against_lcms(p), 1e-4);
    }
}

TEST(IccProfile, ColordProfilesHoldThePublishedPrimaries) {
    struct Published {
        const char* file;
        RgbPrimaries primaries;
        Xy white;
    };
    const Published spaces[] = {
        // Adobe RGB (1998) Color Image Encoding 2005, §4.2 (D65 white).
        {"AdobeRGB1998.icc", {{0.64, 0.33}, {0.21, 0.71}, {0.15, 0.06}}, {0.3127, 0.3290}},
        // ROMM RGB, ISO 22028-2:2013 Table 1 (D50 white: 0.3457, 0.3585).
        {"ProPhotoRGB.icc", {{0.7347, 0.2653}, {0.1596, 0.8404}, {0.0366, 0.0001}}, {0.3457, 0.3585}},
        // IEC 61966-2-1:1999 / ITU-R BT.709-6.
        {"sRGB.icc", {{0.64, 0.33}, {0.30, 0.60}, {0.15, 0.06}}, {0.3127, 0.3290}},
        // SMPTE RP 145.
        {"SMPTE-C-RGB.icc", {{0.630, 0.340}, {0.310, 0.595}, {0.155, 0.070}}, {0.3127, 0.3290}},
    };
    for (const Published& s : spaces) {
        SCOPED_TRACE(s.file);
        const IccProfile p = IccProfile::parse(read_bytes(colord_dir / s.file), s.file);
        ASSERT_TRUE(p.rgb_space().has_value());
        const RgbPrimaries& got = p.rgb_space()->primaries();
        // The tags are s15Fixed16 numbers, and the makers' D65 and D50 are rounded differently.
        const double tol = 1.5e-3;
        EXPECT_NEAR(got.red.x, s.primaries.red.x, tol);
        EXPECT_NEAR(got.red.y, s.primaries.red.y, tol);
        EXPECT_NEAR(got.green.x, s.primaries.green.x, tol);
        EXPECT_NEAR(got.green.y, s.primaries.green.y, tol);
        EXPECT_NEAR(got.blue.x, s.primaries.blue.x, tol);
        EXPECT_NEAR(got.blue.y, s.primaries.blue.y, tol);
        EXPECT_NEAR(p.rgb_space()->white().x, s.white.x, tol);
        EXPECT_NEAR(p.rgb_space()->white().y, s.white.y, tol);
    }
    // The sRGB and Adobe RGB profiles are irid's built-in spaces, curve and all.
    const IccProfile srgb_icc = IccProfile::parse(read_bytes(colord_dir / "sRGB.icc"), "sRGB.icc");
    EXPECT_EQ(matching_builtin_space(*srgb_icc.rgb_space()), &srgb());
    const IccProfile adobe = IccProfile::parse(read_bytes(colord_dir / "AdobeRGB1998.icc"), "AdobeRGB1998.icc");
    EXPECT_EQ(matching_builtin_space(*adobe.rgb_space()), &adobe_rgb());
}

TEST(IccProfile, WrittenProfilesReadBackAsTheSameSpace) {
    for (const RgbSpace* s : builtin_rgb_spaces()) {
        SCOPED_TRACE(s->name());
        const std::vector<unsigned char> bytes = make_icc_profile(*s);
        const IccProfile p = IccProfile::parse(bytes, s->name());
        EXPECT_EQ(p.version(), "4.3");
        EXPECT_EQ(p.description(), s->name() + " (irid)");
        ASSERT_TRUE(p.rgb_space().has_value()) << p.not_exact_reason();
        const RgbSpace& r = *p.rgb_space();
        const auto near = [](const Xy& a, const Xy& b) {
            EXPECT_NEAR(a.x, b.x, 1e-4);
            EXPECT_NEAR(a.y, b.y, 1e-4);
        };
        near(r.primaries().red, s->primaries().red);
        near(r.primaries().green, s->primaries().green);
        near(r.primaries().blue, s->primaries().blue);
        near(r.white(), s->white());
        EXPECT_LT(r.transfer().max_difference(s->transfer()), 1e-4);
        EXPECT_EQ(matching_builtin_space(r), s);
        EXPECT_LT(worst_against_lcms(p), 1e-4);
    }
    // The same space gives the same bytes (reproducible outputs): the date is fixed and the
    // profile ID (ICC.1 §7.2.18, bytes 84-99) is set.
    const std::vector<unsigned char> a = make_icc_profile(display_p3());
    EXPECT_EQ(a, make_icc_profile(display_p3()));
    EXPECT_TRUE(std::any_of(a.begin() + 84, a.begin() + 100, [](unsigned char c) { return c != 0; }));
    EXPECT_EQ(a[24], 0x07);
    EXPECT_EQ(a[25], 0xEA);  // 2026
    // A space no profile holds is refused, not written wrongly: a sampled curve beyond [0, 1]
    // (a curveType table holds 16-bit values of [0, 1]).
    const RgbSpace high("high", srgb().primaries(), srgb().white(), TransferFunction::sampled({0.0, 2.0}));
    EXPECT_THROW((void)make_icc_profile(high), Error);
    // A sampled curve is written as a table and read back as one.
    std::vector<double> table(256);
    for (std::size_t i = 0; i < table.size(); ++i) table[i] = std::pow(static_cast<double>(i) / 255.0, 2.0);
    const RgbSpace custom("table", srgb().primaries(), srgb().white(), TransferFunction::sampled(table));
    const IccProfile p = IccProfile::parse(make_icc_profile(custom, "Ünïcode table"), "table");
    EXPECT_EQ(p.description(), "Ünïcode table");
    // The Basic Multilingual Plane round-trips; beyond it, U+FFFD (lcms2 2.14 keeps one UTF-16
    // unit per character).
    EXPECT_EQ(IccProfile::parse(make_icc_profile(srgb(), "Ω ≈ ∞"), "bmp").description(), "Ω ≈ ∞");
    EXPECT_EQ(IccProfile::parse(make_icc_profile(srgb(), "x \U0001F600"), "emoji").description(), "x \uFFFD");
    ASSERT_TRUE(p.rgb_space().has_value());
    EXPECT_LT(p.rgb_space()->transfer().max_difference(custom.transfer()), 1e-4);
}

TEST(IccProfile, ThreeDifferentCurvesGoThroughLittleCms) {
    // A matrix/TRC profile with γ 1.8, 2.2 and 2.6 on R, G, B: no single RgbSpace; lcms2 takes
    // it to XYZ, which must be the closed form M (r^1.8, g^2.2, b^2.6) adapted to D65.
    const cmsCIExyY white{0.3127, 0.3290, 1.0};
    const cmsCIExyYTRIPLE prim{{0.64, 0.33, 1.0}, {0.30, 0.60, 1.0}, {0.15, 0.06, 1.0}};
    cmsToneCurve* c[3] = {cmsBuildGamma(nullptr, 1.8), cmsBuildGamma(nullptr, 2.2), cmsBuildGamma(nullptr, 2.6)};
    const std::vector<unsigned char> bytes = save(cmsCreateRGBProfile(&white, &prim, c));
    for (cmsToneCurve* t : c) cmsFreeToneCurve(t);
    const IccProfile p = IccProfile::parse(bytes, "three-curves");
    EXPECT_FALSE(p.rgb_space().has_value());
    EXPECT_EQ(p.not_exact_reason(), "three different tone curves");
    const std::vector<float> rgb{0.5f, 0.25f, 0.75f, 1.0f, 1.0f, 1.0f, 0.1f, 0.9f, 0.3f};
    std::vector<float> xyz(rgb.size());
    p.to_xyz(rgb, xyz, {0.3127, 0.3290});
    for (std::size_t i = 0; i < rgb.size(); i += 3) {
        const Xyz e = srgb().to_xyz({std::pow(rgb[i], 1.8), std::pow(rgb[i + 1], 2.2), std::pow(rgb[i + 2], 2.6)});
        EXPECT_NEAR(xyz[i], e.X, 1e-4);
        EXPECT_NEAR(xyz[i + 1], e.Y, 1e-4);
        EXPECT_NEAR(xyz[i + 2], e.Z, 1e-4);
    }
}

TEST(IccProfile, AVersion2ProfileWithoutChadIsUnadaptedFromItsMediaWhite) {
    // A v2 profile as ICC.1:2001 makers wrote it: colorants Bradford-adapted to D50, the media
    // white the real white (D65), no chad tag.
    const Mat3 to_d50 = adaptation_matrix(xy_to_xyz({0.3127, 0.3290}), {0.9642, 1.0, 0.8249});
    cmsHPROFILE h = cmsCreateProfilePlaceholder(nullptr);
    cmsSetProfileVersion(h, 2.1);
    cmsSetDeviceClass(h, cmsSigDisplayClass);
    cmsSetColorSpace(h, cmsSigRgbData);
    cmsSetPCS(h, cmsSigXYZData);
    const Mat3& m = adobe_rgb().to_xyz_matrix();
    const cmsTagSignature tags[] = {cmsSigRedColorantTag, cmsSigGreenColorantTag, cmsSigBlueColorantTag};
    for (int j = 0; j < 3; ++j) {
        const Vec3 a = to_d50 * Vec3{m[0][static_cast<std::size_t>(j)], m[1][static_cast<std::size_t>(j)],
                                     m[2][static_cast<std::size_t>(j)]};
        const cmsCIEXYZ xyz{a[0], a[1], a[2]};
        ASSERT_TRUE(cmsWriteTag(h, tags[j], &xyz));
    }
    const Xyz w = adobe_rgb().white_xyz();
    const cmsCIEXYZ wtpt{w.X, w.Y, w.Z};
    ASSERT_TRUE(cmsWriteTag(h, cmsSigMediaWhitePointTag, &wtpt));
    cmsToneCurve* g = cmsBuildGamma(nullptr, 563.0 / 256.0);
    for (const cmsTagSignature t : {cmsSigRedTRCTag, cmsSigGreenTRCTag, cmsSigBlueTRCTag}) ASSERT_TRUE(cmsWriteTag(h, t, g));
    cmsFreeToneCurve(g);
    const IccProfile p = IccProfile::parse(save(h), "v2");
    EXPECT_EQ(p.version(), "2.1");
    ASSERT_TRUE(p.rgb_space().has_value());
    EXPECT_EQ(matching_builtin_space(*p.rgb_space()), &adobe_rgb());
}

TEST(IccProfile, RefusesProfilesThatDescribeNoRgbImage) {
    const auto refused = [](const std::vector<unsigned char>& bytes, const std::string& reason) {
        try {
            (void)IccProfile::parse(bytes, "photo.tif");
            ADD_FAILURE() << "accepted; expected: " << reason;
        } catch (const Error& e) {
            const std::string m = e.what();
            EXPECT_EQ(m.rfind("photo.tif: ICC profile: ", 0), 0u) << m;
            EXPECT_NE(m.find(reason), std::string::npos) << m;
        }
    };
    refused(read_bytes(colord_dir / "Crayons.icc"), "named-colour");
    refused(read_bytes(colord_dir / "x11-colors.icc"), "named-colour");
    cmsToneCurve* id = cmsBuildGamma(nullptr, 1.0);
    cmsToneCurve* curves[4] = {id, id, id, id};
    refused(save(cmsCreateLinearizationDeviceLink(cmsSigRgbData, curves)), "device link");
    refused(save(cmsCreateLinearizationDeviceLink(cmsSigCmykData, curves)), "device link");
    refused(save(cmsCreateGrayProfile(cmsD50_xyY(), id)), "greyscale");
    refused(save(cmsCreateLab4Profile(nullptr)), "abstract");
    cmsFreeToneCurve(id);
    std::vector<unsigned char> cmyk = read_bytes(colord_dir / "sRGB.icc");
    std::copy_n("CMYK", 4, cmyk.begin() + 16);  // the header's data colour space (ICC.1 §7.2.6)
    refused(cmyk, "a CMYK profile");
    std::vector<unsigned char> bytes = read_bytes(colord_dir / "sRGB.icc");
    refused(std::vector<unsigned char>(bytes.begin(), bytes.begin() + 300), "truncated");
    refused(std::vector<unsigned char>(bytes.begin(), bytes.begin() + 100), "only 100 bytes");
    std::copy_n("xxxx", 4, bytes.begin() + 36);  // the 'acsp' signature
    refused(bytes, "cannot be read");
    refused(std::vector<unsigned char>(4096, 0x41), "truncated: its header declares 1094795585 bytes");
    std::vector<unsigned char> junk(4096, 0x41);
    std::copy_n("\x00\x00\x10\x00", 4, junk.begin());  // 4096 bytes, as declared
    refused(junk, "cannot be read");
}

TEST(ImageSpace, ProfileThenChromaticitiesThenTheAssumption) {
    io::Image image = io::Image::blank(2, 2, 3);
    image.stored_integer = true;
    ImageSpace s = image_space(image, "a.png");
    EXPECT_TRUE(s.assumed);
    EXPECT_TRUE(s.encoded);
    EXPECT_EQ(s.rgb->name(), "srgb");
    image.stored_integer = false;
    s = image_space(image, "a.exr");
    EXPECT_TRUE(s.assumed);
    EXPECT_FALSE(s.encoded);

    // EXR chromaticities: a built-in space by its primaries, any other as it is; linear.
    tag_image(image, acescg(), io::ImageFormat::exr);
    EXPECT_EQ(image.color_space, "acescg-linear");
    ASSERT_EQ(image.adopted_neutral.size(), 2u);  // the ACES white is not D65
    EXPECT_FLOAT_EQ(image.adopted_neutral[0], 0.32168f);
    s = image_space(image, "a.exr");
    EXPECT_FALSE(s.assumed);
    EXPECT_FALSE(s.encoded);
    EXPECT_EQ(s.rgb->name(), "acescg");
    tag_image(image, srgb(), io::ImageFormat::exr);
    EXPECT_TRUE(image.adopted_neutral.empty());
    image.chromaticities = {0.7f, 0.3f, 0.2f, 0.7f, 0.1f, 0.1f, 0.33f, 0.34f};
    s = image_space(image, "a.exr");
    EXPECT_EQ(s.rgb->name(), "exr-chromaticities");
    EXPECT_NEAR(s.rgb->primaries().green.y, 0.7, 1e-7);
    image.chromaticities = {0.7f, 0.3f, 0.7f, 0.3f, 0.1f, 0.1f, 0.33f, 0.34f};
    EXPECT_THROW((void)image_space(image, "a.exr"), Error);

    // A profile comes first, and its values are encoded.
    tag_image(image, display_p3(), io::ImageFormat::png);
    EXPECT_TRUE(image.chromaticities.empty());
    s = image_space(image, "a.png");
    EXPECT_TRUE(s.encoded);
    EXPECT_EQ(s.rgb->name(), "display-p3");
    EXPECT_NE(s.origin.find("display-p3 (irid)"), std::string::npos) << s.origin;
    image.icc_profile.resize(200);
    EXPECT_THROW((void)image_space(image, "a.png"), Error);
    image.icc_profile.clear();
    image.icc_profile_rejected = true;
    EXPECT_THROW((void)image_space(image, "a.png"), Error);
}

TEST(IccProfile, ACurveThatDecodesAboveOneHasNoProfileAndItsImagesNone) {
    // ACEScct decodes 1 to 2^7.8 = 222.86 and PQ (irid's scale) to 100; an ICC.1 curve holds 0 to 1.
    EXPECT_FALSE(icc_curve_can_hold(acescct().transfer()));
    EXPECT_FALSE(icc_curve_can_hold(rec2100_pq().transfer()));
    EXPECT_TRUE(icc_curve_can_hold(srgb().transfer()));
    EXPECT_TRUE(icc_curve_can_hold(p3_d65().transfer()));
    for (const RgbSpace* s : {&acescct(), &p3_d65_pq()}) {
        try {
            (void)make_icc_profile(*s);
            ADD_FAILURE() << s->name() << " got a profile";
        } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find("cannot hold"), std::string::npos) << e.what();
            EXPECT_NE(std::string(e.what()).find(s->name()), std::string::npos) << e.what();
        }
    }
    io::Image image;
    image.channels = 3;
    image.icc_profile = {1, 2, 3};
    tag_image(image, acescct(), io::ImageFormat::tiff);
    EXPECT_EQ(image.color_space, "acescct");
    EXPECT_TRUE(image.icc_profile.empty());
}

}  // namespace
}  // namespace irid
