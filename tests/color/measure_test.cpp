#include <irid/color/measure.h>
#include <irid/color/rgb.h>
#include <irid/color/spaces.h>
#include <irid/error.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numeric>
#include <vector>

namespace irid {
namespace {

std::vector<double> one_to(int n) {
    std::vector<double> v(static_cast<std::size_t>(n));
    std::iota(v.begin(), v.end(), 1.0);
    return v;
}

// Nearest rank (Hyndman & Fan 1996, definition 1; NIST e-Handbook 7.2.6.2's "nearest rank"):
// the ⌈p n⌉-th smallest.
TEST(Measure, PercentilesAreTheNearestRank) {
    const std::vector<double> v = one_to(100);
    EXPECT_EQ(percentile(v, 0.95), 95.0);
    EXPECT_EQ(percentile(v, 0.99), 99.0);
    EXPECT_EQ(percentile(v, 0.5), 50.0);
    EXPECT_EQ(percentile(v, 0.0), 1.0);
    EXPECT_EQ(percentile(v, 1.0), 100.0);
    // Just past a rank moves to the next value.
    EXPECT_EQ(percentile(v, 0.951), 96.0);
    // n = 20: ⌈19⌉ = 19 for p95; ⌈10⌉ for the median; five values: ⌈2.5⌉ = 3.
    EXPECT_EQ(percentile(one_to(20), 0.95), 19.0);
    EXPECT_EQ(percentile(one_to(20), 0.5), 10.0);
    EXPECT_EQ(percentile(one_to(5), 0.5), 3.0);
    // Order of the input does not matter.
    EXPECT_EQ(percentile({5.0, 1.0, 4.0, 2.0, 3.0}, 0.8), 4.0);
    // One value is every percentile; none gives 0.
    EXPECT_EQ(percentile({7.0}, 0.01), 7.0);
    EXPECT_EQ(percentile({}, 0.5), 0.0);
}

TEST(Measure, APercentileOutsideZeroToOneIsRefused) {
    EXPECT_THROW((void)percentile(one_to(3), -0.01), Error);
    EXPECT_THROW((void)percentile(one_to(3), 1.5), Error);
    EXPECT_THROW((void)percentile(one_to(3), std::nan("")), Error);
}

TEST(Measure, SummaryOfOneToAHundred) {
    const Statistics s = summarize(one_to(100));
    EXPECT_EQ(s.count, 100u);
    EXPECT_DOUBLE_EQ(s.mean, 50.5);
    EXPECT_EQ(s.median, 50.0);
    EXPECT_EQ(s.p95, 95.0);
    EXPECT_EQ(s.p99, 99.0);
    EXPECT_EQ(s.max, 100.0);
}

TEST(Measure, ANaNShowsInEveryFigureAndNothingIsZero) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const Statistics s = summarize({nan, 2.0, nan, 4.0});
    EXPECT_EQ(s.count, 4u);
    EXPECT_TRUE(std::isnan(s.mean));
    EXPECT_TRUE(std::isnan(s.median));
    EXPECT_TRUE(std::isnan(s.p95));
    EXPECT_TRUE(std::isnan(s.max));
    const Statistics none = summarize({});
    EXPECT_EQ(none.count, 0u);
    EXPECT_EQ(none.mean, 0.0);
    EXPECT_EQ(none.max, 0.0);
    // The first four fields keep ClipStatistics' order: {mean, p95, max, count}.
    const Statistics old_style{8.0, 9.0, 9.5, 4};
    EXPECT_EQ(old_style.p95, 9.0);
    EXPECT_EQ(old_style.max, 9.5);
    EXPECT_EQ(old_style.count, 4u);
    StatisticsCollector c;
    for (double v : one_to(10)) c.add(v);
    EXPECT_EQ(c.size(), 10u);
    EXPECT_EQ(c.statistics().p95, 10.0);
}

TEST(Measure, HueDifferenceWrapsToTheShortWayRound) {
    EXPECT_DOUBLE_EQ(hue_difference(10.0, 30.0), 20.0);
    EXPECT_DOUBLE_EQ(hue_difference(30.0, 10.0), -20.0);
    EXPECT_DOUBLE_EQ(hue_difference(350.0, 10.0), 20.0);
    EXPECT_DOUBLE_EQ(hue_difference(10.0, 350.0), -20.0);
    // Exactly opposite is +180 from either side: the interval is (−180, 180].
    EXPECT_DOUBLE_EQ(hue_difference(0.0, 180.0), 180.0);
    EXPECT_DOUBLE_EQ(hue_difference(180.0, 0.0), 180.0);
    EXPECT_DOUBLE_EQ(hue_difference(0.0, 720.0), 0.0);
    for (double a = 0.0; a < 360.0; a += 7.3)
        for (double b = 0.0; b < 360.0; b += 11.1) {
            const double d = hue_difference(a, b);
            EXPECT_GT(d, -180.0);
            EXPECT_LE(d, 180.0);
            // a + d is b, modulo 360.
            EXPECT_NEAR(std::remainder(a + d - b, 360.0), 0.0, 1e-9);
        }
}

TEST(Measure, AppearanceOfTheWhiteAndAGrey) {
    const AppearanceMeter meter(d65_xy);
    const Appearance white = meter(srgb().white_xyz());
    EXPECT_NEAR(white.lab.L, 100.0, 1e-9);
    EXPECT_NEAR(white.c_ab, 0.0, 1e-9);
    EXPECT_NEAR(white.l_uv, 100.0, 1e-9);
    EXPECT_NEAR(white.c_uv, 0.0, 1e-9);
    EXPECT_NEAR(white.saturation_uv, 0.0, 1e-9);
    EXPECT_NEAR(white.y, 1.0, 1e-12);
    // Oklab's white is D65: its chroma there is its matrices' residual (below 2e-4).
    EXPECT_LT(white.c_ok, 2e-4);
    // An 18 % grey: L* = 116 · 0.18^(1/3) − 16 (CIE 15:2004, eq. 8.1).
    const Xyz w = srgb().white_xyz();
    const Appearance grey = meter({0.18 * w.X, 0.18 * w.Y, 0.18 * w.Z});
    EXPECT_NEAR(grey.lab.L, 116.0 * std::cbrt(0.18) - 16.0, 1e-9);
    EXPECT_NEAR(grey.l_uv, grey.lab.L, 1e-9);
}

TEST(Measure, TheScaleMeasuresAGamutOfAnotherPeak) {
    // A colour of a gamut of peak 100 measured with scale 1/100 is the colour at peak 1.
    const AppearanceMeter unit(d65_xy), hdr(d65_xy, 0.01);
    const Xyz c{0.3, 0.2, 0.1};
    const Appearance a = unit(c), b = hdr({30.0, 20.0, 10.0});
    EXPECT_NEAR(a.lab.L, b.lab.L, 1e-9);
    EXPECT_NEAR(a.h_ab, b.h_ab, 1e-9);
    EXPECT_NEAR(a.c_ok, b.c_ok, 1e-12);
    EXPECT_NEAR(b.y, 0.2, 1e-12);
}

TEST(Measure, OklabIsMeasuredAfterAdaptingAnotherWhiteToD65) {
    // D50's white, measured relative to D50, is Oklab's white after Bradford: no chroma.
    const Xy d50{0.3457, 0.3585};
    const AppearanceMeter meter(d50);
    const Appearance white = meter(xy_to_xyz(d50));
    EXPECT_LT(white.c_ok, 2e-4);
    EXPECT_NEAR(white.c_ab, 0.0, 1e-9);
    // Without adaptation the same XYZ in Oklab is visibly yellow.
    const Oklch raw = oklab_to_oklch(xyz_to_oklab(xy_to_xyz(d50)));
    EXPECT_GT(raw.C, 0.01);
}

}  // namespace
}  // namespace irid
