#include <irid/color/difference.h>
#include <irid/color/spaces.h>

#include "test_util.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace irid {
namespace {

TEST(Ciede2000, ReproducesAllSharmaWuDalalPairs) {
    const NumericTable t = test::read_data_table("sharma2005_ciede2000_pairs.csv");
    ASSERT_EQ(t.rows(), 34u);
    for (std::size_t i = 0; i < t.rows(); ++i) {
        const std::span<const double> r = t.row(i);
        const Lab a{r[0], r[1], r[2]};
        const Lab b{r[3], r[4], r[5]};
        EXPECT_NEAR(delta_e_2000(a, b), r[6], 1e-4) << "line " << t.line_numbers[i];
        // The formula is symmetric.
        EXPECT_NEAR(delta_e_2000(b, a), r[6], 1e-4);
    }
}

TEST(Ciede2000, IsZeroForEqualColoursAndScalesWithLightnessWeight) {
    const Lab c{50.0, 10.0, -20.0};
    EXPECT_EQ(delta_e_2000(c, c), 0.0);
    // Pure lightness difference at L̄ = 50: S_L = 1, so ΔE00 = ΔL / kL.
    EXPECT_NEAR(delta_e_2000({49.0, 0, 0}, {51.0, 0, 0}), 2.0, 1e-12);
    EXPECT_NEAR(delta_e_2000({49.0, 0, 0}, {51.0, 0, 0}, 2.0), 1.0, 1e-12);
}

TEST(DeltaE76, IsEuclideanInLab) {
    EXPECT_DOUBLE_EQ(delta_e_76({50, 0, 0}, {53, 4, 0}), 5.0);
}

TEST(DeltaEuv, SplitsIntoLightnessChromaAndHue) {
    // ΔE² = ΔL² + ΔC² + ΔH² (Smits 1990, eq. 13).
    const Luv a{50.0, 30.0, 10.0};
    const Luv b{55.0, 10.0, 35.0};
    const double de = delta_e_uv(a, b);
    const double dc = delta_c_uv(a, b);
    const double dh = delta_h_uv(a, b);
    EXPECT_NEAR(de * de, 25.0 + dc * dc + dh * dh, 1e-10);
    EXPECT_DOUBLE_EQ(de, std::sqrt(25.0 + 400.0 + 625.0));
    // Same hue, different chroma: no hue difference.
    EXPECT_NEAR(delta_h_uv({50, 10, 10}, {60, 20, 20}), 0.0, 1e-7);
    // Same chroma, opposite hue: ΔH is the chord, 2C.
    EXPECT_NEAR(delta_h_uv({50, 10, 0}, {50, -10, 0}), 20.0, 1e-12);
}

TEST(DeltaSuv, IsTheDifferenceOfCieluvSaturation) {
    // s_uv = C*uv / L*.
    EXPECT_DOUBLE_EQ(delta_s_uv({50, 30, 40}, {25, 30, 40}), 50.0 / 25.0 - 50.0 / 50.0);
    EXPECT_DOUBLE_EQ(delta_s_uv({0, 0, 0}, {50, 0, 25}), 0.5);
    // Scaling a colour towards black along a line through the origin keeps saturation.
    EXPECT_NEAR(delta_s_uv({80, 20, -10}, {40, 10, -5}), 0.0, 1e-15);
}

TEST(DeltaEok, IsEuclideanInOklab) {
    EXPECT_DOUBLE_EQ(delta_e_ok({0.5, 0, 0}, {0.5, 0.3, 0.4}), 0.5);
    // CSS Color 4's just-noticeable difference is 0.02 in these units: white vs 98% lightness.
    EXPECT_NEAR(delta_e_ok(xyz_to_oklab({0.95047, 1.0, 1.08883}), {0.98, 0, 0}), 0.02, 1e-3);
}

}  // namespace
}  // namespace irid
