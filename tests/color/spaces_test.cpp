#include <irid/color/rgb.h>
#include <irid/color/spaces.h>

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include <vector>

namespace irid {
namespace {

const Xyz d65_white = xy_to_xyz({0.3127, 0.3290});

/// Colours inside and far outside any display gamut, near black and brighter than white.
std::vector<Xyz> test_colours() {
    return {{0.95047, 1.0, 1.08883}, {0.2, 0.3, 0.4},    {0.4124, 0.2126, 0.0193},
            {0.1805, 0.0722, 0.9505}, {0.001, 0.0008, 0.0005}, {1e-6, 2e-6, 1e-6},
            {0.5, 0.2, 0.0},          {0.1, 0.7, 0.05},   {2.0, 2.2, 2.5},
            {0.17, 0.005, 0.82},      {0.0, 0.05, 0.0},   {0.3, 0.3, 0.3}};
}

void expect_xyz_near(const Xyz& a, const Xyz& b, double tol) {
    EXPECT_NEAR(a.X, b.X, tol);
    EXPECT_NEAR(a.Y, b.Y, tol);
    EXPECT_NEAR(a.Z, b.Z, tol);
}

TEST(Spaces, EverySpaceRoundTripsThroughXyz) {
    for (const Xyz& c : test_colours()) {
        expect_xyz_near(xyy_to_xyz(xyz_to_xyy(c)), c, 1e-12);
        expect_xyz_near(luv_to_xyz(xyz_to_luv(c, d65_white), d65_white), c, 1e-12);
        expect_xyz_near(lab_to_xyz(xyz_to_lab(c, d65_white), d65_white), c, 1e-12);
        expect_xyz_near(luv_to_xyz(lch_to_luv(luv_to_lch(xyz_to_luv(c, d65_white))), d65_white), c, 1e-12);
        expect_xyz_near(lab_to_xyz(lch_to_lab(lab_to_lch(xyz_to_lab(c, d65_white))), d65_white), c, 1e-12);
        expect_xyz_near(oklab_to_xyz(xyz_to_oklab(c)), c, 1e-12);
        expect_xyz_near(oklab_to_xyz(oklch_to_oklab(oklab_to_oklch(xyz_to_oklab(c)))), c, 1e-12);
    }
}

TEST(Spaces, BlackIsDefinedEverywhere) {
    const Xyz black{};
    const Xyy xyy = xyz_to_xyy(black, {0.3127, 0.3290});
    EXPECT_EQ(xyy.x, 0.3127);
    EXPECT_EQ(xyy.Y, 0.0);
    const Luv luv = xyz_to_luv(black, d65_white);
    EXPECT_EQ(luv.L, 0.0);
    EXPECT_EQ(luv.u, 0.0);
    EXPECT_EQ(luv.v, 0.0);
    const Lab lab = xyz_to_lab(black, d65_white);
    EXPECT_NEAR(lab.L, 0.0, 1e-14);
    EXPECT_NEAR(lab.a, 0.0, 1e-14);
    EXPECT_EQ(luv_to_xyz({0.0, 10.0, 10.0}, d65_white).Y, 0.0);
    EXPECT_EQ(xyz_to_oklab(black).L, 0.0);
}

TEST(Spaces, WhiteHasLightness100AndNoChroma) {
    const Luv luv = xyz_to_luv(d65_white, d65_white);
    EXPECT_NEAR(luv.L, 100.0, 1e-12);
    EXPECT_NEAR(luv.u, 0.0, 1e-12);
    EXPECT_NEAR(luv.v, 0.0, 1e-12);
    const Lab lab = xyz_to_lab(d65_white, d65_white);
    EXPECT_NEAR(lab.L, 100.0, 1e-12);
    EXPECT_NEAR(lab.a, 0.0, 1e-12);
    EXPECT_NEAR(lab.b, 0.0, 1e-12);
}

TEST(Lightness, HasTheCieLinearSegmentThatSmitsEquation10Omits) {
    // At Y/Yn = (6/29)³ both branches give L* = 8 (116 × 6/29 − 16).
    EXPECT_NEAR(cie_lightness(cie_epsilon), 8.0, 1e-12);
    EXPECT_NEAR(cie_lightness(cie_epsilon * (1 + 1e-12)), 8.0, 1e-9);
    // Below it L* = κ Y/Yn = (29/3)³ Y/Yn; the cube-root formula alone would go negative.
    EXPECT_NEAR(cie_lightness(0.001), 24389.0 / 27.0 * 0.001, 1e-12);
    EXPECT_LT(116.0 * std::cbrt(0.001) - 16.0, 0.0);
    EXPECT_NEAR(cie_lightness(0.18), 49.496107, 1e-6);  // middle grey, 116 × 0.18^(1/3) − 16
    for (const double L : {0.5, 5.0, 8.0, 20.0, 50.0, 99.0}) {
        EXPECT_NEAR(cie_lightness(cie_lightness_to_relative_luminance(L)), L, 1e-12);
    }
}

TEST(Lab, SrgbPrimariesHaveTheirPublishedCoordinates) {
    // sRGB primaries in CIELAB (D65): red (53.24, 80.09, 67.20), green (87.73, −86.18, 83.18),
    // blue (32.30, 79.19, −107.86); to 0.05, the spread between published D65 whites.
    const RgbSpace& s = srgb();
    const struct {
        Rgb rgb;
        Lab lab;
    } cases[] = {{{1, 0, 0}, {53.24, 80.09, 67.20}},
                 {{0, 1, 0}, {87.73, -86.18, 83.18}},
                 {{0, 0, 1}, {32.30, 79.19, -107.86}}};
    for (const auto& c : cases) {
        const Lab lab = xyz_to_lab(s.to_xyz(c.rgb), s.white_xyz());
        EXPECT_NEAR(lab.L, c.lab.L, 0.05);
        EXPECT_NEAR(lab.a, c.lab.a, 0.05);
        EXPECT_NEAR(lab.b, c.lab.b, 0.05);
    }
}

TEST(Luv, ChromaticityAndSaturationFollowTheCieDefinitions) {
    // D65 (0.3127, 0.3290): u' = 4x/(−2x + 12y + 3) = 0.19783, v' = 9y/(…) = 0.46832.
    const UvPrime n = xy_to_uv_prime({0.3127, 0.3290});
    EXPECT_NEAR(n.u, 0.197830, 1e-6);
    EXPECT_NEAR(n.v, 0.468320, 1e-6);
    const UvPrime from_xyz = xyz_to_uv_prime(d65_white);
    EXPECT_NEAR(from_xyz.u, n.u, 1e-14);
    const Xy back = uv_prime_to_xy(n);
    EXPECT_NEAR(back.x, 0.3127, 1e-14);
    EXPECT_NEAR(back.y, 0.3290, 1e-14);
    const Xyz c{0.3, 0.2, 0.1};
    const LchUv lch = luv_to_lch(xyz_to_luv(c, d65_white));
    EXPECT_NEAR(saturation_uv(c, d65_white), lch.C / lch.L, 1e-12);
}

TEST(Oklab, ReproducesOttossonsPublishedTable) {
    // Ottosson 2020, "A perceptual color space for image processing", table of XYZ → Oklab
    // (3 decimals).
    const struct {
        Xyz xyz;
        Oklab lab;
    } cases[] = {{{0.950, 1.000, 1.089}, {1.000, 0.000, 0.000}},
                 {{1.000, 0.000, 0.000}, {0.450, 1.236, -0.019}},
                 {{0.000, 1.000, 0.000}, {0.922, -0.671, 0.263}},
                 {{0.000, 0.000, 1.000}, {0.153, -1.415, -0.449}}};
    for (const auto& c : cases) {
        const Oklab lab = xyz_to_oklab(c.xyz);
        EXPECT_NEAR(lab.L, c.lab.L, 6e-4);
        EXPECT_NEAR(lab.a, c.lab.a, 6e-4);
        EXPECT_NEAR(lab.b, c.lab.b, 6e-4);
    }
}

TEST(Oklab, TheRefittedMatricesPutTheD65WhiteOnTheNeutralAxis) {
    // CSS Color 4's matrices: the D65 white (0.3127, 0.3290) is Oklab (1, 0, 0) to rounding;
    // Ottosson's published ones give it a chroma of about 1.2e-4, and differ from the refitted
    // ones by under 3.1e-4 in every element.
    const Xyz white = xy_to_xyz({0.3127, 0.3290});
    const Oklab lab = xyz_to_oklab(white);
    EXPECT_NEAR(lab.L, 1.0, 1e-15);
    EXPECT_NEAR(lab.a, 0.0, 1e-15);
    EXPECT_NEAR(lab.b, 0.0, 1e-15);
    const Vec3 lms = ottosson_published_oklab_m1 * Vec3{white.X, white.Y, white.Z};
    const Vec3 published = ottosson_published_oklab_m2 * Vec3{std::cbrt(lms[0]), std::cbrt(lms[1]), std::cbrt(lms[2])};
    EXPECT_GT(std::hypot(published[1], published[2]), 1e-4);
    EXPECT_LT(std::hypot(published[1], published[2]), 1.3e-4);
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            EXPECT_NEAR(oklab_m1[i][j], ottosson_published_oklab_m1[i][j], 3.1e-4);
            EXPECT_NEAR(oklab_m2[i][j], ottosson_published_oklab_m2[i][j], 3.1e-4);
        }
    }
}

TEST(Hue, IsInDegreesInZeroTo360) {
    EXPECT_EQ(hue_degrees(0.0, 0.0), 0.0);
    EXPECT_DOUBLE_EQ(hue_degrees(1.0, 1.0), 45.0);
    EXPECT_DOUBLE_EQ(hue_degrees(0.0, -1.0), 270.0);
    const double h = hue_degrees(1.0, -1e-300);
    EXPECT_GE(h, 0.0);
    EXPECT_LT(h, 360.0);
    const LchAb lch{50.0, 30.0, 120.0};
    const LchAb back = lab_to_lch(lch_to_lab(lch));
    EXPECT_NEAR(back.C, 30.0, 1e-12);
    EXPECT_NEAR(back.h, 120.0, 1e-12);
}

TEST(Xyy, ChromaticityOfXyzAndBack) {
    const Xyz c = xy_to_xyz({0.64, 0.33}, 0.2126);
    EXPECT_NEAR(c.X, 0.64 / 0.33 * 0.2126, 1e-15);
    EXPECT_NEAR(c.Z, 0.03 / 0.33 * 0.2126, 1e-15);
    const Xy xy = xyz_to_xy(c);
    EXPECT_NEAR(xy.x, 0.64, 1e-15);
    EXPECT_NEAR(xy.y, 0.33, 1e-15);
}

}  // namespace
}  // namespace irid
