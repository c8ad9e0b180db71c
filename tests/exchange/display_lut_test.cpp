// bake_display_lut: the ACES 2.0 display transform as a LUT: the sources it takes, its domain
// (AP1, where the chain clamps), its nodes, and the ACES 2.0 views of an OCIO config
// (docs/DISPLAY.md, "LUTs and OpenColorIO 2.1"). How closely the LUT stands for the transform is
// display_lut_accuracy_test.cpp.
#include <irid/color/convert.h>
#include <irid/color/difference.h>
#include <irid/color/spaces.h>
#include <irid/error.h>
#include <irid/exchange/display_lut.h>
#include <irid/exchange/ocio_config.h>
#include <irid/gamut/aces2_display.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

namespace irid {
namespace {

DisplayTransform transform_to(const char* display, const char* target) {
    return DisplayTransform(display_lut_options("aces2", display, "aces2065-1", target));
}

TEST(DisplayLut, TheTargetDefaultsToTheDisplaysEncoding) {
    EXPECT_EQ(display_lut_options("aces2", "sdr-100nit-rec709", "aces2065-1", "").target, "srgb");
    EXPECT_EQ(display_lut_options("aces2", "hdr-1000nit-p3-d65", "aces2065-1", "").target, "p3-d65-pq");
    EXPECT_EQ(display_lut_options("aces2", "sdr-100nit-rec709", "acescg", "xyz").target, "xyz");
    EXPECT_THROW((void)display_lut_options("aces2", "sdr-100nit-p3-d60-in-xyz-e", "aces2065-1", ""), Error);
    EXPECT_THROW((void)display_lut_options("aces2", "no-such-display", "aces2065-1", ""), UnknownNameError);
}

TEST(DisplayLut, TheDefaultClfDomainIsLog2OverAp1UpToTheForwardLimit) {
    const DisplayTransform sdr = transform_to("sdr-100nit-rec709", "srgb");
    const LutDomain d = display_lut_domain(sdr, LutFormat::clf);
    EXPECT_EQ(d.shaper, LutShaper::log2);
    EXPECT_EQ(d.min, 0.0);
    // 8 (128 + 768 log(peak/100) / log(100)) of ACES 2.0 (issue 27): 1024 at 100 cd/m², 4096 at 1000.
    EXPECT_NEAR(d.max, 1024.0, 1e-9);
    EXPECT_EQ(d.stops, display_lut_stops);
    EXPECT_NEAR(display_lut_domain(transform_to("hdr-1000nit-p3-d65", "p3-d65-pq"), LutFormat::clf).max,
                4096.0, 1e-9);
    // The cube is in AP1: ACES2065-1 goes through AP0 to AP1, the matrix of Academy S-2014-004
    // (ACEScg), Table 3, to its 10 decimals.
    ASSERT_TRUE(d.matrix.has_value());
    EXPECT_EQ(d.matrix_space, "acescg-linear");
    const Mat3 ap0_to_ap1{{{{1.4514393161, -0.2365107469, -0.2149285693},
                            {-0.0765537734, 1.1762296998, -0.0996759264},
                            {0.0083161484, -0.0060324498, 0.9977163014}}}};
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) EXPECT_NEAR((*d.matrix)[i][j], ap0_to_ap1[i][j], 5e-10) << i << j;
    }
    // AP1 itself needs none; XYZ (D65 white) takes Bradford to the ACES white, so the D65 white
    // lands on AP1's (equal channels).
    const DisplayTransform cg(display_lut_options("aces2", "sdr-100nit-rec709", "acescg", "srgb"));
    EXPECT_FALSE(display_lut_domain(cg, LutFormat::clf).matrix.has_value());
    const DisplayTransform xyz(display_lut_options("aces2", "sdr-100nit-rec709", "xyz", "srgb"));
    const LutDomain x = display_lut_domain(xyz, LutFormat::clf);
    ASSERT_TRUE(x.matrix.has_value());
    const Xyz w = xy_to_xyz(d65_xy);
    const Vec3 white = *x.matrix * Vec3{w.X, w.Y, w.Z};
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(white[c], 1.0, 1e-9) << c;
    // A .cube (no shaper, no matrix) over linear scene values is refused, and over another
    // encoding than ACEScct; over ACEScct it is uniform over the code values [0, 1], for .clf too.
    EXPECT_THROW((void)display_lut_domain(sdr, LutFormat::cube), Error);
    const DisplayTransform srgb_source(display_lut_options("aces2", "sdr-100nit-rec709", "srgb", "srgb"));
    EXPECT_THROW((void)display_lut_domain(srgb_source, LutFormat::cube), Error);
    const DisplayTransform cct(display_lut_options("aces2", "sdr-100nit-rec709", "acescct", "srgb"));
    for (const LutFormat f : {LutFormat::cube, LutFormat::clf}) {
        const LutDomain u = display_lut_domain(cct, f);
        EXPECT_EQ(u.shaper, LutShaper::none);
        EXPECT_EQ(u.min, 0.0);
        EXPECT_EQ(u.max, 1.0);
        EXPECT_FALSE(u.matrix.has_value());
    }
}

TEST(DisplayLut, SourcesThatAreNotLightOrCodeValuesAreRefused) {
    // Issue 37: Lab through the log2 shaper and a [0, 1024] clamp gave a wrong LUT, silently.
    for (const char* name : {"xyy", "luv", "lab", "lchuv", "lchab", "oklab", "oklch"}) {
        try {
            check_display_lut_source(name);
            ADD_FAILURE() << name << " was taken";
        } catch (const UnknownNameError&) {
            ADD_FAILURE() << name << " was taken for an unknown name";
        } catch (const Error& e) {
            const std::string m = e.what();
            EXPECT_NE(m.find(std::string("not ") + name + ":"), std::string::npos) << m;
            EXPECT_NE(m.find("aces2065-1 or acescct"), std::string::npos) << m;
        }
        EXPECT_THROW((void)display_lut_options("aces2", "sdr-100nit-rec709", name, "srgb"), Error) << name;
        // A transform built without display_lut_options is refused where the LUT is made.
        DisplayTransformOptions o;
        o.display = "sdr-100nit-rec709";
        o.source = name;
        o.target = "srgb";
        const DisplayTransform t(o);
        EXPECT_THROW((void)display_lut_domain(t, LutFormat::clf), Error) << name;
        EXPECT_THROW((void)bake_display_lut(t, 3, LutDomain{}, 1), Error) << name;
    }
    for (const char* name : {"xyz", "aces2065-1", "acescg", "srgb-linear", "rec2020-linear", "acescct", "srgb"}) {
        EXPECT_NO_THROW(check_display_lut_source(name)) << name;
    }
    EXPECT_THROW(check_display_lut_source("no-such-space"), UnknownNameError);
}

TEST(DisplayLut, EveryNodeHoldsTheTransformOfItsInput) {
    const DisplayTransform t = transform_to("sdr-100nit-rec709", "srgb");
    const Lut3D lut = bake_display_lut(t, 9, display_lut_domain(t, LutFormat::clf), 2);
    EXPECT_EQ(lut.source, "aces2065-1");
    EXPECT_EQ(lut.destination, "srgb");
    for (const char* word : {"--view aces2", "--display sdr-100nit-rec709", "--size 9", "log2 shaper",
                             "16 stops in acescg-linear"}) {
        EXPECT_NE(lut.title.find(word), std::string::npos) << lut.title;
    }
    // The nodes lie in AP1; the input of each is its ACES2065-1 colour.
    const Converter ap1_to_aces(color_space("acescg-linear"), color_space("aces2065-1-linear"));
    for (int b = 0; b < 9; b += 4) {
        for (int g = 0; g < 9; ++g) {
            for (int r = 0; r < 9; r += 2) {
                const Vec3 expected = t(ap1_to_aces({lut.node(r), lut.node(g), lut.node(b)}));
                const float* v = &lut.values[3 * static_cast<std::size_t>(r + 9 * (g + 9 * b))];
                for (int c = 0; c < 3; ++c) EXPECT_NEAR(v[c], expected[c], 2e-5) << r << ' ' << g << ' ' << b;
            }
        }
    }
    DisplayTransformOptions inverse = t.options();
    inverse.inverse = true;
    std::swap(inverse.source, inverse.target);
    EXPECT_THROW((void)bake_display_lut(DisplayTransform(inverse), 9, {}, 1), Error);
    EXPECT_THROW((void)bake_display_lut(t, 1, {}, 1), Error);
}

TEST(DisplayLut, ColoursBeyondAp1TakeTheChainsOwnClampThroughTheLut) {
    // The chain clamps AP1 to [0, the forward limit] (aces2_display.h, step 1), and so does the
    // LUT's domain: an ACES2065-1 colour whose AP1 lies beyond a face of that cube, clamped onto
    // a node, comes out of the LUT as the transform gives it. (Over ACES2065-1 itself, the
    // domain's faces were not the chain's, and such colours fell inside cells.)
    const DisplayTransform t = transform_to("hdr-1000nit-p3-d65", "p3-d65-pq");
    const Lut3D lut = bake_display_lut(t, 17, display_lut_domain(t, LutFormat::clf), 0);
    const Converter ap1_to_aces(color_space("acescg-linear"), color_space("aces2065-1-linear"));
    const double limit = lut.domain.max;
    int checked = 0;
    for (int i = 1; i < 17; i += 3) {
        for (int j = 0; j < 17; j += 4) {
            for (const Vec3& ap1 : {Vec3{lut.node(i), lut.node(j), -0.25 * lut.node(i)},
                                    Vec3{-0.1, lut.node(i), lut.node(j)},
                                    Vec3{2.0 * limit, lut.node(j), lut.node(i)}}) {
                const Vec3 aces = ap1_to_aces(ap1);
                const Vec3 want = t(aces);
                const Rgb got = apply_lut(lut, aces, LutInterpolation::tetrahedral);
                EXPECT_NEAR(got.r, want[0], 3e-5) << ap1[0] << ' ' << ap1[1] << ' ' << ap1[2];
                EXPECT_NEAR(got.g, want[1], 3e-5) << ap1[0] << ' ' << ap1[1] << ' ' << ap1[2];
                EXPECT_NEAR(got.b, want[2], 3e-5) << ap1[0] << ' ' << ap1[1] << ' ' << ap1[2];
                ++checked;
            }
        }
    }
    EXPECT_EQ(checked, 6 * 5 * 3);
}

TEST(DisplayLut, TheClfCarriesTheMatrixAheadOfTheShaper) {
    const DisplayTransform t = transform_to("sdr-100nit-rec709", "srgb");
    const Lut3D lut = bake_display_lut(t, 3, display_lut_domain(t, LutFormat::clf), 1);
    const std::string text = lut_text(lut, LutFormat::clf);
    const std::size_t matrix = text.find("<Matrix"), range = text.find("<Range"), log = text.find("<Log"),
                      cube = text.find("<LUT3D");
    ASSERT_NE(matrix, std::string::npos) << text.substr(0, 800);
    EXPECT_LT(matrix, range);
    EXPECT_LT(range, log);
    EXPECT_LT(log, cube);
    // The first row of AP0 to AP1 (S-2014-004), as written (shortest round trip of the double).
    EXPECT_NE(text.find("1.45143931"), std::string::npos);
    // .cube and .spi3d cannot carry it.
    EXPECT_THROW((void)lut_text(lut, LutFormat::cube), Error);
    EXPECT_THROW(check_lut_format(LutFormat::spi3d, lut.domain), Error);
}

TEST(OcioConfig, AnHdrDisplayIsRefusedOnADisplaySpaceThatCannotHoldItsPeak) {
    // Issue 37: --to srgb --aces2 hdr-1000nit-p3-d65 baked extended sRGB up to 2.64, silently.
    OcioConfigOptions o;
    o.methods = {ClipMethod::clamp};
    o.size = 5;
    o.aces2_displays = std::vector<std::string>{"hdr-1000nit-p3-d65"};
    try {
        (void)ocio_aces2_displays(o);
        ADD_FAILURE() << "an HDR display was taken on sRGB";
    } catch (const Error& e) {
        const std::string m = e.what();
        for (const char* word : {"hdr-1000nit-p3-d65", "1000 cd/m²", "srgb", "100 cd/m²", "p3-d65-pq"}) {
            EXPECT_NE(m.find(word), std::string::npos) << word << " in: " << m;
        }
    }
    EXPECT_THROW((void)make_ocio_config(o), Error);
    // The cinema preset that shows 108 cd/m² is brighter than sRGB's code value 1 too.
    o.aces2_displays = std::vector<std::string>{"hdr-108nit-p3-d65"};
    EXPECT_THROW((void)ocio_aces2_displays(o), Error);
    // PQ holds 10000 cd/m²; a linear display space holds any value; 100 cd/m² fits sRGB.
    o.display = color_space("p3-d65-pq");
    o.aces2_displays = std::vector<std::string>{"hdr-1000nit-p3-d65", "sdr-100nit-p3-d65"};
    EXPECT_EQ(ocio_aces2_displays(o).size(), 2U);
    o.display = color_space("srgb-linear");
    o.aces2_displays = std::vector<std::string>{"hdr-4000nit-rec2020"};
    EXPECT_EQ(ocio_aces2_displays(o).size(), 1U);
    o.display = color_space("srgb");
    o.aces2_displays = std::vector<std::string>{"sdr-100nit-rec709", "sdr-100nit-rec709-d60-in-rec709-d65"};
    EXPECT_EQ(ocio_aces2_displays(o).size(), 2U);
}

TEST(OcioConfig, ADisplayIsRefusedOnADisplaySpaceWhoseGamutCannotHoldIt) {
    // Found by review of issue 37: --to srgb --aces2 sdr-100nit-p3-d65 baked codes from −0.51 to
    // 1.09, silently: pure P3 green is (−0.22, 1.04, −0.08) in linear sRGB (the primaries of
    // IEC 61966-2-1 and SMPTE EG 432-1), a red code of −0.51.
    OcioConfigOptions o;
    o.methods = {ClipMethod::clamp};
    o.size = 5;
    o.display = color_space("srgb");
    o.aces2_displays = std::vector<std::string>{"sdr-100nit-p3-d65"};
    try {
        (void)ocio_aces2_displays(o);
        ADD_FAILURE() << "a P3 display was taken on sRGB";
    } catch (const Error& e) {
        const std::string m = e.what();
        for (const char* word : {"sdr-100nit-p3-d65", "gamut", "srgb", "display-p3"}) {
            EXPECT_NE(m.find(word), std::string::npos) << word << " in: " << m;
        }
    }
    EXPECT_THROW((void)make_ocio_config(o), Error);
    // A Rec.709-D60 view whose white was scaled for P3-D65 has a white too red for sRGB (its red
    // channel 0.9 % above 1): the Rec.709-D65 one is the view for sRGB.
    o.aces2_displays = std::vector<std::string>{"sdr-100nit-rec709-d60-in-p3-d65"};
    EXPECT_THROW((void)ocio_aces2_displays(o), Error);
    // Rec.2020 views on P3 PQ: Rec.2020's primaries lie far outside P3.
    o.display = color_space("p3-d65-pq");
    o.aces2_displays = std::vector<std::string>{"hdr-1000nit-rec2020"};
    EXPECT_THROW((void)ocio_aces2_displays(o), Error);
    // P3's red lies just outside Rec.2020 (0.12 % of the peak in blue), and OpenColorIO's ACES
    // configs show P3-limited views on Rec.2100-PQ: every built-in display fits Rec.2100-PQ.
    o.display = color_space("rec2100-pq");
    std::vector<std::string> all;
    for (const Aces2DisplaySpec& d : aces2_displays()) all.push_back(d.name);
    o.aces2_displays = all;
    EXPECT_EQ(ocio_aces2_displays(o).size(), all.size());
    o.display = color_space("rec2020");
    o.aces2_displays = std::vector<std::string>{"sdr-100nit-p3-d65", "sdr-100nit-p3-d60-in-p3-d65"};
    EXPECT_EQ(ocio_aces2_displays(o).size(), 2U);
    // Every display fits its own encoding, and the views a config offers by default are those.
    for (const Aces2DisplaySpec& d : aces2_displays()) {
        const RgbSpace* own = default_display_encoding(d);
        if (own == nullptr) continue;
        o.display = color_space(own->name());
        o.aces2_displays = std::vector<std::string>{d.name};
        EXPECT_NO_THROW((void)ocio_aces2_displays(o)) << d.name;
    }
}

}  // namespace
}  // namespace irid
