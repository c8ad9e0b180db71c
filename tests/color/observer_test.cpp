#include <irid/color/illuminant.h>
#include <irid/color/observer.h>
#include <irid/color/spaces.h>
#include <irid/error.h>

#include "test_util.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

namespace irid {
namespace {

TEST(ColorMatchingFunctions, AreTheCieTablesDigitForDigit) {
    for (const auto& [file, observer] :
         {std::pair{"cie1931_2deg_xyz_cmf.csv", Observer::cie1931_2deg},
          std::pair{"cie1964_10deg_xyz_cmf.csv", Observer::cie1964_10deg}}) {
        const NumericTable t = test::read_data_table(file);
        const ColorMatchingFunctions& cmf = color_matching_functions(observer);
        ASSERT_EQ(t.rows(), static_cast<std::size_t>(dense_sample_count));
        for (int i = 0; i < dense_sample_count; ++i) {
            ASSERT_EQ(t.row(i)[0], DenseSpectrum::wavelength_nm(i));
            EXPECT_EQ(cmf.x[i], t.row(i)[1]);
            EXPECT_EQ(cmf.y[i], t.row(i)[2]);
            EXPECT_EQ(cmf.z[i], t.row(i)[3]);
        }
    }
}

TEST(ColorMatchingFunctions, YBarPeaksAtOneAt555nmAndIntegratesToThePublishedArea) {
    const ColorMatchingFunctions& cmf = color_matching_functions(Observer::cie1931_2deg);
    EXPECT_DOUBLE_EQ(cmf.y(555.0), 1.0);
    // Σ ȳ(λ) Δλ over 360-830 nm at 1 nm for the CIE 1931 observer: 106.857 (CIE 015:2018 data;
    // the integral is 683 lm/W × this in lumens per watt-nm units).
    EXPECT_NEAR(cmf.y.sum(), 106.857, 1e-3);
    // The three functions have (nearly) equal areas: equal-energy white is x = y = 1/3.
    EXPECT_NEAR(cmf.x.sum() / cmf.y.sum(), 1.0, 1e-3);
    EXPECT_NEAR(cmf.z.sum() / cmf.y.sum(), 1.0, 1e-3);
}

TEST(Colorimetry, EqualEnergySpectrumIsAtOneThird) {
    for (const Observer o : {Observer::cie1931_2deg, Observer::cie1964_10deg}) {
        const Xy xy = xyz_to_xy(illuminant_white(illuminant_e(), o));
        EXPECT_NEAR(xy.x, 1.0 / 3.0, 2e-4);
        EXPECT_NEAR(xy.y, 1.0 / 3.0, 2e-4);
    }
}

TEST(Colorimetry, PerfectReflectorHasYOneAndBlackHasZero) {
    const DenseSpectrum d65 = illuminant_d65();
    EXPECT_NEAR(reflectance_to_xyz(DenseSpectrum(1.0), d65).Y, 1.0, 1e-15);
    const Xyz black = reflectance_to_xyz(DenseSpectrum(0.0), d65);
    EXPECT_EQ(black.X, 0.0);
    EXPECT_EQ(black.Y, 0.0);
    EXPECT_EQ(black.Z, 0.0);
}

TEST(Colorimetry, IsLinearInTheReflectance) {
    const DenseSpectrum d65 = illuminant_d65();
    const DenseSpectrum a = DenseSpectrum::from_function([](double l) { return l < 550 ? 0.8 : 0.1; });
    const DenseSpectrum b = DenseSpectrum::from_function([](double l) { return (l - 360) / 470; });
    const Xyz xa = reflectance_to_xyz(a, d65);
    const Xyz xb = reflectance_to_xyz(b, d65);
    const Xyz sum = reflectance_to_xyz(a * 0.25 + b * 0.5, d65);
    EXPECT_NEAR(sum.X, 0.25 * xa.X + 0.5 * xb.X, 1e-14);
    EXPECT_NEAR(sum.Y, 0.25 * xa.Y + 0.5 * xb.Y, 1e-14);
    EXPECT_NEAR(sum.Z, 0.25 * xa.Z + 0.5 * xb.Z, 1e-14);
}

TEST(Colorimetry, IlluminantWhitesMatchTheCiePublishedChromaticities) {
    // CIE 015:2004 Table T.3 (5 decimals), computed from the same tables.
    struct Case {
        const char* name;
        Observer observer;
        double x, y;
    };
    const Case cases[] = {
        {"D65", Observer::cie1931_2deg, 0.31272, 0.32903},
        {"D65", Observer::cie1964_10deg, 0.31382, 0.33100},
        {"D50", Observer::cie1931_2deg, 0.34567, 0.35850},
        {"D50", Observer::cie1964_10deg, 0.34773, 0.35952},
        {"A", Observer::cie1931_2deg, 0.44757, 0.40745},
        {"A", Observer::cie1964_10deg, 0.45117, 0.40594},
    };
    for (const Case& c : cases) {
        const Xy xy = xyz_to_xy(illuminant_white(illuminant_by_name(c.name), c.observer));
        EXPECT_NEAR(xy.x, c.x, 6e-5) << c.name << " " << observer_name(c.observer);
        EXPECT_NEAR(xy.y, c.y, 6e-5) << c.name << " " << observer_name(c.observer);
    }
}

TEST(SpectralLocus, MatchesTheCie1931PublishedChromaticities) {
    // CIE 1931 spectral chromaticity coordinates (CIE 015:2018 data tables, 4 decimals).
    struct Case {
        double nm, x, y;
    };
    const Case cases[] = {{380, 0.1741, 0.0050}, {450, 0.1566, 0.0177}, {500, 0.0082, 0.5384},
                          {520, 0.0743, 0.8338}, {550, 0.3016, 0.6923}, {600, 0.6270, 0.3725},
                          {700, 0.7347, 0.2653}};
    for (const Case& c : cases) {
        const Xy xy = spectral_locus_xy(c.nm);
        EXPECT_NEAR(xy.x, c.x, 1e-4) << c.nm << " nm";
        EXPECT_NEAR(xy.y, c.y, 1e-4) << c.nm << " nm";
    }
}

TEST(SpectralLocus, InterpolatesBetweenTableWavelengthsAndRejectsOthers) {
    const Xyz a = monochromatic_xyz(555.0);
    const Xyz b = monochromatic_xyz(556.0);
    const Xyz m = monochromatic_xyz(555.5);
    EXPECT_DOUBLE_EQ(m.Y, 0.5 * (a.Y + b.Y));
    EXPECT_THROW((void)spectral_locus_xy(359.0), Error);
    EXPECT_THROW((void)spectral_locus_xy(std::nan("")), Error);
}

TEST(Emission, AbsoluteLuminanceUsesTheMaximumLuminousEfficacy) {
    // 1 W·sr⁻¹·m⁻²·nm⁻¹ in the 1 nm band at 555 nm, where ȳ = 1: 683 cd/m².
    DenseSpectrum line;
    line[555 - lambda_min_nm] = 1.0;
    const Xyz c = emission_to_xyz_absolute(line);
    EXPECT_DOUBLE_EQ(c.Y, 683.0);
    const Xyz r = emission_to_xyz_relative(line);
    EXPECT_DOUBLE_EQ(r.Y, 1.0);
    EXPECT_DOUBLE_EQ(r.X / r.Z, c.X / c.Z);
    EXPECT_THROW((void)emission_to_xyz_relative(DenseSpectrum()), Error);
}

TEST(Observer, ParsesNamesAndListsThemOnError) {
    EXPECT_EQ(parse_observer("cie1931"), Observer::cie1931_2deg);
    EXPECT_EQ(parse_observer("cie1964"), Observer::cie1964_10deg);
    EXPECT_EQ(parse_observer("2"), Observer::cie1931_2deg);
    EXPECT_EQ(parse_observer("10"), Observer::cie1964_10deg);
    EXPECT_EQ(observer_name(Observer::cie1964_10deg), "cie1964");
    EXPECT_EQ(parse_observer(observer_name(Observer::cie1931_2deg)), Observer::cie1931_2deg);
    try {
        (void)parse_observer("cie2006");
        FAIL();
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("cie1931, cie1964"), std::string::npos);
    }
}

}  // namespace
}  // namespace irid

namespace irid {
namespace {

// The diagram of real colours: the CIE 1931 locus at 380 nm is (0.1741, 0.0050) and at 700 nm
// (0.7347, 0.2653) (CIE 015:2018 Table 11); the purple line between them passes y = 0.0635 at
// x = 0.3, and 520 nm is at (0.0743, 0.8338).
TEST(Chromaticity, RealColoursOnly) {
    for (const Xy& w : {Xy{0.3127, 0.3290}, Xy{1.0 / 3, 1.0 / 3}, Xy{0.44757, 0.40745}, Xy{0.3, 0.1},
                        Xy{0.1, 0.7}, Xy{0.6, 0.35}}) {
        EXPECT_TRUE(is_real_chromaticity(w)) << w.x << ", " << w.y;
        EXPECT_NO_THROW(check_white_chromaticity(w));
    }
    for (const Xy& w : {Xy{0.3, 0.01}, Xy{0.05, 0.05}, Xy{0.9, 0.05}, Xy{0.05, 0.9}, Xy{0.5, 1e-300},
                        Xy{1e-300, 0.5}, Xy{0.2, 0.9}, Xy{std::nan(""), 0.3}}) {
        EXPECT_FALSE(is_real_chromaticity(w)) << w.x << ", " << w.y;
    }
    try {
        check_white_chromaticity({0.3, 0.01}, "--white");
        FAIL();
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("--white (0.3, 0.01) lies outside"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace irid
