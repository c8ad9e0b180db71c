#include <irid/color/observer.h>
#include <irid/color/spectrum.h>
#include <irid/error.h>

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include <cstdio>
#include <fstream>
#include <string>

namespace irid {
namespace {

TEST(DenseSpectrum, CoversTheCieRangeAtOneNanometre) {
    EXPECT_EQ(dense_sample_count, 471);
    EXPECT_EQ(DenseSpectrum::wavelength_nm(0), 360.0);
    EXPECT_EQ(DenseSpectrum::wavelength_nm(dense_sample_count - 1), 830.0);
}

TEST(DenseSpectrum, InterpolatesLinearlyAndIsZeroOutside) {
    const DenseSpectrum s = DenseSpectrum::from_function([](double l) { return 2.0 * l - 100.0; });
    EXPECT_DOUBLE_EQ(s(500.0), 900.0);
    EXPECT_DOUBLE_EQ(s(500.25), 900.5);
    EXPECT_DOUBLE_EQ(s(830.0), 1560.0);
    EXPECT_DOUBLE_EQ(s(360.0), 620.0);
    EXPECT_EQ(s(359.9), 0.0);
    EXPECT_EQ(s(830.1), 0.0);
}

TEST(DenseSpectrum, ArithmeticIsSampleBySample) {
    const DenseSpectrum a(2.0);
    const DenseSpectrum b = DenseSpectrum::from_function([](double l) { return l; });
    const DenseSpectrum p = a * b + b * 0.5;
    EXPECT_DOUBLE_EQ(p[10], 2.5 * 370.0);
    EXPECT_DOUBLE_EQ(a.sum(), 2.0 * dense_sample_count);
    // Σ λ over 360..830 = 471 × 595.
    EXPECT_DOUBLE_EQ(DenseSpectrum(1.0).dot(b), 471.0 * 595.0);
    EXPECT_DOUBLE_EQ(b.max_value(), 830.0);
}

TEST(PiecewiseLinearSpectrum, InterpolatesBetweenSamples) {
    const PiecewiseLinearSpectrum s({400.0, 500.0, 700.0}, {0.0, 1.0, 0.5});
    EXPECT_DOUBLE_EQ(s(450.0), 0.5);
    EXPECT_DOUBLE_EQ(s(600.0), 0.75);
    EXPECT_DOUBLE_EQ(s(500.0), 1.0);
}

TEST(PiecewiseLinearSpectrum, HoldsEndsOrIsZeroOutside) {
    const PiecewiseLinearSpectrum hold({400.0, 700.0}, {0.2, 0.8});
    EXPECT_DOUBLE_EQ(hold(380.0), 0.2);
    EXPECT_DOUBLE_EQ(hold(800.0), 0.8);
    const PiecewiseLinearSpectrum zero({400.0, 700.0}, {0.2, 0.8}, Extrapolation::zero);
    EXPECT_EQ(zero(380.0), 0.0);
    EXPECT_EQ(zero(800.0), 0.0);
    EXPECT_DOUBLE_EQ(zero(400.0), 0.2);
    EXPECT_DOUBLE_EQ(zero(700.0), 0.8);
}

TEST(PiecewiseLinearSpectrum, RejectsInvalidSamples) {
    EXPECT_THROW(PiecewiseLinearSpectrum({}, {}), Error);
    EXPECT_THROW(PiecewiseLinearSpectrum({400.0, 500.0}, {1.0}), Error);
    EXPECT_THROW(PiecewiseLinearSpectrum({500.0, 400.0}, {1.0, 1.0}), Error);
    EXPECT_THROW(PiecewiseLinearSpectrum({400.0, 400.0}, {1.0, 1.0}), Error);
    EXPECT_THROW(PiecewiseLinearSpectrum({-1.0, 400.0}, {1.0, 1.0}), Error);
    EXPECT_THROW(PiecewiseLinearSpectrum({400.0, 500.0}, {1.0, std::nan("")}), Error);
}

TEST(Resampling, DenseToPiecewiseAndBackIsExact) {
    const DenseSpectrum d = DenseSpectrum::from_function([](double l) { return std::sin(l / 37.0); });
    const DenseSpectrum back = DenseSpectrum::resample(PiecewiseLinearSpectrum::from_dense(d));
    for (int i = 0; i < dense_sample_count; ++i) EXPECT_EQ(back[i], d[i]);
    const PiecewiseLinearSpectrum p = PiecewiseLinearSpectrum::from_dense(d);
    EXPECT_DOUBLE_EQ(p(512.5), d(512.5));
}

TEST(Resampling, CoarseLinearDataIsReproducedExactlyAtOneNanometre) {
    // A linear function sampled every 10 nm resamples without error.
    std::vector<double> l, v;
    for (int nm = 360; nm <= 830; nm += 10) {
        l.push_back(nm);
        v.push_back(0.001 * nm);
    }
    const DenseSpectrum d = DenseSpectrum::resample(PiecewiseLinearSpectrum(l, v));
    for (int i = 0; i < dense_sample_count; ++i) {
        EXPECT_NEAR(d[i], 0.001 * DenseSpectrum::wavelength_nm(i), 1e-15);
    }
}

TEST(PiecewiseLinearSpectrum, ReadsCsvWithHeaderAndNamesTheLineOfAnError) {
    const std::string path = ::testing::TempDir() + "irid_spectrum_test.csv";
    {
        std::ofstream f(path);
        f << "wavelength_nm,a,b\n400,0.1,0.9\n500,0.3,0.7\n600,0.5,0.5\n";
    }
    const PiecewiseLinearSpectrum b = PiecewiseLinearSpectrum::read_csv(path, 2);
    EXPECT_DOUBLE_EQ(b(450.0), 0.8);
    {
        std::ofstream f(path);
        f << "wavelength_nm,a\n400,0.1\n500,0.3\n450,0.5\n";
    }
    try {
        (void)PiecewiseLinearSpectrum::read_csv(path, 1);
        FAIL() << "decreasing wavelengths were accepted";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find(path + ":4:"), std::string::npos) << e.what();
    }
    std::remove(path.c_str());
    EXPECT_THROW((void)PiecewiseLinearSpectrum::read_csv(path, 1), Error);
}

TEST(SampledWavelengths, HeroAndCompanionsAreEquallySpacedInRange) {
    for (const double u : {0.0, 0.3, 0.999999}) {
        const auto w = SampledWavelengths<4>::hero(u);
        for (int i = 0; i < 4; ++i) {
            EXPECT_GE(w[i], 360.0);
            EXPECT_LT(w[i], 830.0);
            EXPECT_DOUBLE_EQ(w.pdf(i), 1.0 / 470.0);
            const double step = std::fmod(w[i] - w[0] + 470.0, 470.0);
            EXPECT_NEAR(step, i * 470.0 / 4.0, 1e-9);
        }
    }
}

TEST(SampledSpectrum, EstimatorConvergesToTheIntegral) {
    // Averaging the hero-wavelength estimate over stratified u gives ∫ s x̄ dλ.
    const DenseSpectrum s = DenseSpectrum::from_function([](double l) { return 0.5 + 0.4 * std::sin(l / 50.0); });
    const ColorMatchingFunctions& cmf = color_matching_functions(Observer::cie1931_2deg);
    constexpr int strata = 4000;
    Xyz mean;
    for (int k = 0; k < strata; ++k) {
        const auto w = SampledWavelengths<4>::hero((k + 0.5) / strata);
        const Xyz e = estimate_xyz_integral(s.sample(w), w);
        mean.X += e.X / strata;
        mean.Y += e.Y / strata;
        mean.Z += e.Z / strata;
    }
    // The 1 nm sum is the trapezoid rule here up to the end samples, which are ~0.
    EXPECT_NEAR(mean.X / s.dot(cmf.x), 1.0, 1e-4);
    EXPECT_NEAR(mean.Y / s.dot(cmf.y), 1.0, 1e-4);
    EXPECT_NEAR(mean.Z / s.dot(cmf.z), 1.0, 1e-4);
}

TEST(SampledSpectrum, ResamplesToPiecewiseLinearInWavelengthOrder) {
    const auto w = SampledWavelengths<4>::hero(0.9);
    const DenseSpectrum d = DenseSpectrum::from_function([](double l) { return l / 1000.0; });
    const PiecewiseLinearSpectrum p = to_piecewise_linear(d.sample(w), w);
    ASSERT_EQ(p.wavelengths_nm().size(), 4u);
    EXPECT_TRUE(std::is_sorted(p.wavelengths_nm().begin(), p.wavelengths_nm().end()));
    // The function is linear, so the resampled one agrees between the sampled wavelengths.
    const double mid = 0.5 * (p.wavelengths_nm()[1] + p.wavelengths_nm()[2]);
    EXPECT_NEAR(p(mid), mid / 1000.0, 1e-12);
}

}  // namespace
}  // namespace irid
