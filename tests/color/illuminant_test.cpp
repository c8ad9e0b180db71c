#include <irid/color/illuminant.h>
#include <irid/color/observer.h>
#include <irid/color/spaces.h>
#include <irid/error.h>

#include "test_util.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace irid {
namespace {

/// Compares an illuminant with a 5 nm CIE table over the wavelengths both cover.
void expect_matches_table(const DenseSpectrum& s, const char* file, double abs_tol, double rel_tol) {
    const NumericTable t = test::read_data_table(file);
    int compared = 0;
    for (std::size_t i = 0; i < t.rows(); ++i) {
        const std::span<const double> row = t.row(i);
        if (row[0] < lambda_min_nm || row[0] > lambda_max_nm) continue;
        const double v = s(row[0]);
        EXPECT_NEAR(v, row[1], abs_tol + rel_tol * std::abs(row[1])) << file << " at " << row[0];
        ++compared;
    }
    EXPECT_GT(compared, 80);
}

TEST(Illuminant, D65IsTheCieTableNormalisedAt560) {
    const DenseSpectrum d65 = illuminant_d65();
    expect_matches_table(d65, "cie_illuminant_D65.csv", 0.0, 0.0);
    EXPECT_EQ(d65(560.0), 100.0);
}

TEST(Illuminant, OneNanometreValuesAreLinearBetweenTheFiveNanometreValues) {
    // CIE 015:2018: intermediate values of D65 by linear interpolation.
    const DenseSpectrum d65 = illuminant_d65();
    for (int nm = 361; nm < 365; ++nm) {
        const double f = (nm - 360) / 5.0;
        EXPECT_NEAR(d65(nm), (1 - f) * d65(360.0) + f * d65(365.0), 1e-12);
    }
}

TEST(Illuminant, D50FromTheDaylightBasisMatchesTheCieTable) {
    // The CIE table is the basis computation rounded to 3 decimals.
    expect_matches_table(illuminant_d50(), "cie_illuminant_D50.csv", 5.1e-4, 0.0);
}

TEST(Illuminant, D65FromTheDaylightBasisAt6504KMatchesTheTable) {
    expect_matches_table(daylight_illuminant(6500.0 * 1.4388 / 1.4380), "cie_illuminant_D65.csv",
                         1e-3, 0.0);
}

TEST(Illuminant, AFromItsDefiningFormulaMatchesTheCieTable) {
    // The table has 6 significant digits.
    expect_matches_table(illuminant_a(), "cie_illuminant_A.csv", 0.0, 5e-6);
    EXPECT_DOUBLE_EQ(illuminant_a()(560.0), 100.0);
}

TEST(Illuminant, AIsAPlanckianRadiatorAt2856K) {
    const DenseSpectrum a = illuminant_a();
    const DenseSpectrum bb = blackbody(2856.0);
    for (int i = 0; i < dense_sample_count; ++i) EXPECT_NEAR(bb[i] / a[i], 1.0, 1e-3);
}

TEST(Illuminant, DaylightChromaticityFollowsTheCieDaylightLocus) {
    // x_D of D65 and D50 (CCTs 6504 K and 5003 K) near their published whites 0.31271 and
    // 0.34567 (CIE 015:2018); y_D on
    // the daylight locus y = −3x² + 2.870x − 0.275.
    for (const auto& [cct, x] : {std::pair{6500.0 * 1.4388 / 1.4380, 0.31271},
                                 std::pair{5000.0 * 1.4388 / 1.4380, 0.34567}}) {
        const Xy c = daylight_chromaticity(cct);
        EXPECT_NEAR(c.x, x, 2e-5);  // x_D and the spectrum's own x differ by ~1e-5
        EXPECT_NEAR(c.y, -3.0 * c.x * c.x + 2.870 * c.x - 0.275, 1e-15);
    }
    // The spectrum built from the basis has the published D50 white, (0.34567, 0.35850).
    const Xy d50 = xyz_to_xy(illuminant_white(daylight_illuminant(5000.0 * 1.4388 / 1.4380)));
    EXPECT_NEAR(d50.x, 0.34567, 6e-5);
    EXPECT_NEAR(d50.y, 0.35850, 6e-5);
    // The two branches of x_D meet at 7000 K.
    EXPECT_NEAR(daylight_chromaticity(7000.0).x, daylight_chromaticity(7000.0001).x, 1e-5);
    EXPECT_THROW((void)daylight_chromaticity(3999.0), Error);
    EXPECT_THROW((void)daylight_chromaticity(25001.0), Error);
}

TEST(Planck, PeaksWhereWiensLawSays) {
    // Wien's displacement constant b = 2.897771955e-3 m·K (CODATA 2018).
    const double t = 5000.0;
    double best_nm = 0.0, best = 0.0;
    for (double nm = 500.0; nm < 650.0; nm += 0.01) {
        const double v = planck_radiance(nm, t);
        if (v > best) {
            best = v;
            best_nm = nm;
        }
    }
    EXPECT_NEAR(best_nm, 2.897771955e-3 / t * 1e9, 0.02);
}

TEST(Planck, IntegratesToStefanBoltzmannOverPi) {
    // ∫ L(λ) dλ = σ T⁴ / π, σ = 5.670374419e-8 W·m⁻²·K⁻⁴ (CODATA 2018). σ assumes the exact
    // c2 = 1.438776877e-2 m·K; the CIE's rounded c2 = 1.4388e-2 scales the integral by
    // (exact c2 / CIE c2)⁴.
    const double t = 3000.0;
    double sum = 0.0;
    // Trapezoid in log λ from 50 nm to 1 mm.
    const int n = 200000;
    const double a = std::log(50.0), b = std::log(1e6);
    for (int i = 0; i <= n; ++i) {
        const double l = std::exp(a + (b - a) * i / n);
        const double w = (i == 0 || i == n) ? 0.5 : 1.0;
        sum += w * planck_radiance(l, t) * l * (b - a) / n;
    }
    const double c2_scale = std::pow(1.438776877e-2 / planck_c2_m_k, 4.0);
    EXPECT_NEAR(sum / (5.670374419e-8 * std::pow(t, 4.0) / std::numbers::pi * c2_scale), 1.0, 1e-7);
}

TEST(Illuminant, BlackbodyIsNormalisedAt560AndChecked) {
    EXPECT_DOUBLE_EQ(blackbody(6500.0)(560.0), 100.0);
    EXPECT_THROW((void)blackbody(0.0), Error);
    EXPECT_THROW((void)blackbody(std::nan("")), Error);
}

TEST(Illuminant, NamesAreCaseInsensitiveAndErrorsListTheForms) {
    EXPECT_EQ(illuminant_by_name("d65")(500.0), illuminant_d65()(500.0));
    EXPECT_EQ(illuminant_by_name("E")(400.0), 100.0);
    EXPECT_EQ(illuminant_by_name("D9300")(400.0), daylight_illuminant(9300.0)(400.0));
    EXPECT_EQ(illuminant_by_name("blackbody:3000")(400.0), blackbody(3000.0)(400.0));
    // D55 is the daylight basis at 5500 × 1.4388/1.4380 K: x ≈ 0.33242 (CIE 015:2004 T.3).
    EXPECT_NEAR(xyz_to_xy(illuminant_white(illuminant_by_name("D55"))).x, 0.33242, 6e-5);
    try {
        (void)illuminant_by_name("F2");
        FAIL();
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("D65"), std::string::npos);
    }
    EXPECT_THROW((void)illuminant_by_name("D3000"), Error);
}

TEST(WhitePoint, NamedWhitesAndCustomChromaticities) {
    EXPECT_EQ(white_point_xy("D65").x, 0.31270);
    EXPECT_EQ(white_point_xy("D65").y, 0.32900);
    EXPECT_EQ(white_point_xy("c").x, 0.31006);
    const Xy custom = white_point_xy("0.3,0.31");
    EXPECT_EQ(custom.x, 0.3);
    EXPECT_EQ(custom.y, 0.31);
    EXPECT_THROW((void)white_point_xy("0.8,0.5"), Error);
    EXPECT_THROW((void)white_point_xy("D66"), Error);
}

}  // namespace
}  // namespace irid

namespace irid {
namespace {

// Without the rounding of M1 and M2, the daylight of a CCT's chromaticity is the CIE daylight
// illuminant of that CCT to within what rounding to three decimals changes: |ΔM| <= 0.0005
// times |S1| + |S2| (at most about 100 in the tables' range), and the basis' combination is
// what daylight_from_chromaticity gives.
TEST(Daylight, SpectrumFromChromaticityIsTheBasisWithUnroundedWeights) {
    const auto basis = daylight_basis();
    for (const double cct : {4000.0, 5003.0, 6504.0, 9300.0, 20000.0}) {
        const Xy c = daylight_chromaticity(cct);
        const DenseSpectrum a = daylight_from_chromaticity(c);
        const DenseSpectrum b = daylight_illuminant(cct);
        const DaylightWeights w = daylight_weights(c);
        for (int i = 0; i < dense_sample_count; ++i) {
            const double bound = 0.0005 * (std::abs(basis[1][i]) + std::abs(basis[2][i])) + 1e-9;
            EXPECT_NEAR(a[i], b[i], bound) << cct << " K at " << lambda_min_nm + i << " nm";
            EXPECT_NEAR(a[i], basis[0][i] + w.m1 * basis[1][i] + w.m2 * basis[2][i], 1e-9);
        }
        // And its chromaticity is the one asked for.
        const Xyz xyz = emission_to_xyz_relative(a);
        EXPECT_NEAR(xyz.X / (xyz.X + xyz.Y + xyz.Z), c.x, 1e-3) << cct;
        EXPECT_NEAR(xyz.Y / (xyz.X + xyz.Y + xyz.Z), c.y, 1e-3) << cct;
    }
    // S0 is 100 at 560 nm (its normalisation), S1 and S2 near 0 there.
    EXPECT_NEAR(basis[0][560 - lambda_min_nm], 100.0, 1e-9);
    // Far from the daylight locus the weights' denominator vanishes: refused.
    EXPECT_THROW((void)daylight_weights({0.6, 0.2}), Error);
    EXPECT_THROW((void)daylight_from_chromaticity({std::nan(""), 0.3}), Error);
}

}  // namespace
}  // namespace irid
