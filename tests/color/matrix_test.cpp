#include <irid/color/adaptation.h>
#include <irid/color/illuminant.h>
#include <irid/color/matrix.h>
#include <irid/color/observer.h>
#include <irid/color/spaces.h>
#include <irid/error.h>

#include <gtest/gtest.h>

namespace irid {
namespace {

TEST(Mat3, InverseTimesMatrixIsTheIdentity) {
    const Mat3 a{{{{2.0, -1.0, 0.5}, {0.3, 4.0, -2.0}, {1.0, 0.0, 3.0}}}};
    const Mat3 p = inverse(a) * a;
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) EXPECT_NEAR(p[i][j], i == j ? 1.0 : 0.0, 1e-15);
    }
    // det = 2(12 − 0) + 1(0.9 + 2) + 0.5(0 − 4) = 24.9.
    EXPECT_NEAR(a.determinant(), 24.9, 1e-13);
}

TEST(Mat3, SingularMatricesAreRefusedByName) {
    const Mat3 singular{{{{1.0, 2.0, 3.0}, {2.0, 4.0, 6.0}, {0.0, 1.0, 1.0}}}};
    try {
        (void)inverse(singular, "test matrix");
        FAIL();
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("test matrix"), std::string::npos);
    }
}

TEST(Mat3, ColumnsDiagonalAndProducts) {
    const Mat3 c = Mat3::from_columns({1, 2, 3}, {4, 5, 6}, {7, 8, 9});
    EXPECT_EQ(c[1][0], 2.0);
    EXPECT_EQ(c[0][1], 4.0);
    const Vec3 v = Mat3::diagonal({2, 3, 4}) * Vec3{1, 1, 1};
    EXPECT_EQ(v[2], 4.0);
    const Mat3 i = Mat3::identity() * c;
    EXPECT_EQ(i[2][2], 9.0);
}

TEST(ConeResponse, BradfordAndCat02AreNormalisedToEqualEnergyAndHpeToD65) {
    // Bradford and CAT02 rows each sum to 1 (E maps to equal cone responses); the von Kries
    // Hunt-Pointer-Estévez matrix maps D65 to (1, 1, 1).
    for (const ChromaticAdaptation m : {ChromaticAdaptation::bradford, ChromaticAdaptation::cat02}) {
        const Vec3 e = cone_response_matrix(m) * Vec3{1, 1, 1};
        for (const double r : e) EXPECT_NEAR(r, 1.0, 2e-4);
    }
    const Vec3 d65 = cone_response_matrix(ChromaticAdaptation::von_kries) * Vec3{0.95047, 1.0, 1.08883};
    for (const double r : d65) EXPECT_NEAR(r, 1.0, 3e-4);  // 4-decimal published matrix
    const Mat3 none = cone_response_matrix(ChromaticAdaptation::none);
    EXPECT_EQ(none[0][0], 1.0);
    EXPECT_EQ(none[0][1], 0.0);
}

TEST(WhitePoint, NamedWhitesAreTheChromaticitiesOfTheirSpectra) {
    // Every named white that has a spectrum in irid agrees with that spectrum's CIE 1931 white
    // to the 5 decimals of CIE 015:2004 Table T.3 (D65's name uses the 4-decimal 0.3127, 0.3290).
    for (const std::string& name : white_point_names()) {
        if (name == "C") continue;  // no spectrum of C in irid
        const Xy named = white_point_xy(name);
        const Xy computed = xyz_to_xy(illuminant_white(illuminant_by_name(name)));
        const double tolerance = name == "D65" ? 3.5e-5 : 6e-5;
        EXPECT_NEAR(named.x, computed.x, tolerance) << name;
        EXPECT_NEAR(named.y, computed.y, tolerance) << name;
    }
    EXPECT_EQ(white_point_xy(" 0.3 , 0.31 ").y, 0.31);
}

}  // namespace
}  // namespace irid
