#include <irid/color/adaptation.h>
#include <irid/color/spaces.h>
#include <irid/error.h>

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace irid {
namespace {

constexpr ChromaticAdaptation methods[] = {ChromaticAdaptation::bradford, ChromaticAdaptation::cat02,
                                           ChromaticAdaptation::von_kries};

TEST(ChromaticAdaptation, MapsTheSourceWhiteOntoTheDestinationWhite) {
    const Xyz d65 = xy_to_xyz({0.3127, 0.3290});
    const Xyz a = xy_to_xyz({0.44757, 0.40745});
    for (const ChromaticAdaptation m : methods) {
        const Vec3 w = adaptation_matrix(d65, a, m) * Vec3{d65.X, d65.Y, d65.Z};
        EXPECT_NEAR(w[0], a.X, 1e-14);
        EXPECT_NEAR(w[1], a.Y, 1e-14);
        EXPECT_NEAR(w[2], a.Z, 1e-14);
    }
}

TEST(ChromaticAdaptation, ThereAndBackIsTheIdentity) {
    const Xyz d65 = xy_to_xyz({0.3127, 0.3290});
    const Xyz d50 = xy_to_xyz({0.34567, 0.35850});
    for (const ChromaticAdaptation m : methods) {
        const Mat3 p = adaptation_matrix(d50, d65, m) * adaptation_matrix(d65, d50, m);
        for (int i = 0; i < 3; ++i) {
            for (int j = 0; j < 3; ++j) EXPECT_NEAR(p[i][j], i == j ? 1.0 : 0.0, 1e-14);
        }
    }
}

TEST(ChromaticAdaptation, BradfordD65ToD50MatchesThePublishedMatrix) {
    // Lindbloom's Bradford D65 → D50 matrix, computed with the ASTM E308 whites
    // D65 (0.95047, 1, 1.08883) and D50 (0.96422, 1, 0.82521); 7 decimals.
    const double published[3][3] = {{1.0478112, 0.0228866, -0.0501270},
                                    {0.0295424, 0.9904844, -0.0170491},
                                    {-0.0092345, 0.0150436, 0.7521316}};
    const Mat3 m = adaptation_matrix({0.95047, 1.0, 1.08883}, {0.96422, 1.0, 0.82521});
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) EXPECT_NEAR(m[i][j], published[i][j], 1e-6);
    }
}

TEST(ChromaticAdaptation, NoneIsTheIdentityAndNamesParse) {
    const Mat3 m = adaptation_matrix({0.9, 1, 1.1}, {1.1, 1, 0.3}, ChromaticAdaptation::none);
    EXPECT_EQ(m[0][0], 1.0);
    EXPECT_EQ(m[0][1], 0.0);
    EXPECT_EQ(parse_chromatic_adaptation("cat02"), ChromaticAdaptation::cat02);
    EXPECT_EQ(parse_chromatic_adaptation("von-kries"), ChromaticAdaptation::von_kries);
    EXPECT_THROW((void)parse_chromatic_adaptation("cat16"), Error);
    EXPECT_THROW((void)adaptation_matrix({0, 0, 0}, {1, 1, 1}), Error);
}

}  // namespace
}  // namespace irid
