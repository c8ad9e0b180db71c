#include <irid/color/primaries.h>
#include <irid/error.h>

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include <algorithm>

namespace irid {
namespace {

TEST(PrimaryMatchingFunctions, EachPrimaryIsMatchedByItselfAlone) {
    // At a primary's own wavelength the other two functions vanish.
    const PrimaryMatchingFunctions f = monochromatic_primary_matching_functions();
    const double peak = std::max({f.r.max_value(), f.g.max_value(), f.b.max_value()});
    EXPECT_NEAR(f.g(645.0), 0.0, 1e-12 * peak);
    EXPECT_NEAR(f.b(645.0), 0.0, 1e-12 * peak);
    EXPECT_NEAR(f.r(526.0), 0.0, 1e-12 * peak);
    EXPECT_NEAR(f.b(526.0), 0.0, 1e-12 * peak);
    EXPECT_NEAR(f.r(444.0), 0.0, 1e-12 * peak);
    EXPECT_NEAR(f.g(444.0), 0.0, 1e-12 * peak);
    EXPECT_GT(f.r(645.0), 0.0);
}

TEST(PrimaryMatchingFunctions, EqualEnergyWhiteNeedsEqualAmounts) {
    const PrimaryMatchingFunctions f = monochromatic_primary_matching_functions();
    const double y_area = color_matching_functions(Observer::cie1931_2deg).y.sum();
    EXPECT_NEAR(f.r.sum(), y_area, 1e-9 * y_area);
    EXPECT_NEAR(f.g.sum(), y_area, 1e-9 * y_area);
    EXPECT_NEAR(f.b.sum(), y_area, 1e-9 * y_area);
}

TEST(PrimaryMatchingFunctions, HaveTheNegativeLobesOfFigure2) {
    // Between the blue and green primaries spectral colours need negative red (Smits 1990,
    // Figure 2); beyond the green primary towards red they need negative blue.
    const PrimaryMatchingFunctions f = monochromatic_primary_matching_functions();
    EXPECT_LT(f.r(480.0), 0.0);
    EXPECT_LT(f.b(560.0), 0.0);
    EXPECT_LT(f.g(420.0), 0.0);
}

TEST(PrimaryMatchingFunctions, AreALinearTransformOfTheCieFunctions) {
    const PrimaryMatchingFunctions f = monochromatic_primary_matching_functions(700.0, 546.1, 435.8);
    const ColorMatchingFunctions& cmf = color_matching_functions(Observer::cie1931_2deg);
    const Mat3 back = inverse(f.xyz_to_rgb);
    for (int i = 0; i < dense_sample_count; i += 7) {
        const Vec3 xyz = back * Vec3{f.r[i], f.g[i], f.b[i]};
        EXPECT_NEAR(xyz[0], cmf.x[i], 1e-12);
        EXPECT_NEAR(xyz[1], cmf.y[i], 1e-12);
        EXPECT_NEAR(xyz[2], cmf.z[i], 1e-12);
    }
}

TEST(PrimaryMatchingFunctions, CieRgbPrimariesGiveTheCie1931RgbLuminanceRatios) {
    // With the CIE 1931 RGB primaries (700, 546.1, 435.8 nm) and equal-energy normalisation,
    // the luminances of the unit primaries are in the ratio 1 : 4.5907 : 0.0601 (CIE 1931).
    const PrimaryMatchingFunctions f = monochromatic_primary_matching_functions(700.0, 546.1, 435.8);
    const Mat3 rgb_to_xyz = inverse(f.xyz_to_rgb);
    EXPECT_NEAR(rgb_to_xyz[1][1] / rgb_to_xyz[1][0], 4.5907, 2e-3);
    EXPECT_NEAR(rgb_to_xyz[1][2] / rgb_to_xyz[1][0], 0.0601, 2e-4);
}

TEST(PrimaryMatchingFunctions, RejectsBadWavelengths) {
    EXPECT_THROW((void)monochromatic_primary_matching_functions(900.0, 526.0, 444.0), Error);
    EXPECT_THROW((void)monochromatic_primary_matching_functions(526.0, 526.0, 444.0), Error);
}

}  // namespace
}  // namespace irid
