#include <irid/color/hdr_transfer.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace irid {
namespace {

// PQ: SMPTE ST 2084:2014 / ITU-R BT.2100-2 Table 4.
TEST(Pq, EndPointsAreTheStandardsClosedForms) {
    EXPECT_DOUBLE_EQ(pq_encode(10000.0), 1.0);  // (c1 + c2) / (1 + c3) = 1 exactly
    EXPECT_DOUBLE_EQ(pq_decode(1.0), 10000.0);
    // 0 cd/m² is c1^m2, as the formula gives.
    EXPECT_NEAR(pq_encode(0.0), std::pow(3424.0 / 4096.0, 2523.0 / 4096.0 * 128.0), 1e-18);
    EXPECT_EQ(pq_decode(pq_encode(0.0)), 0.0);
    EXPECT_EQ(pq_decode(0.0), 0.0);
}

TEST(Pq, ReferenceWhiteAndPeaksAsBt2408GivesThem) {
    // ITU-R BT.2408-7 Table 1: HDR reference white 203 cd/m² is 58 % PQ; 100 cd/m² is about
    // 51 % and 1000 cd/m² about 75 % (the percentages are rounded to 1 %).
    EXPECT_NEAR(pq_encode(203.0), 0.58, 0.005);
    EXPECT_NEAR(pq_encode(100.0), 0.51, 0.005);
    EXPECT_NEAR(pq_encode(1000.0), 0.75, 0.005);
}

TEST(Pq, OpenColorIOsPublishedValues) {
    // OpenColorIO's built-in transform tests (tests/cpu/transforms/BuiltinTransform_tests.cpp,
    // "CURVE - LINEAR_to_ST-2084" and its inverse, linear 1.0 = 100 cd/m²), at their 1e-5.
    EXPECT_NEAR(pq_encode(50.0), 0.440281573420, 1e-5);
    EXPECT_NEAR(pq_encode(40.0), 0.419284117712, 1e-5);
    EXPECT_NEAR(pq_encode(30.0), 0.392876186489, 1e-5);
    EXPECT_NEAR(pq_encode(20.0), 0.357012421, 1e-5);
    EXPECT_NEAR(pq_decode(0.5) / 100.0, 0.922457089941, 4e-5);
    EXPECT_NEAR(pq_decode(0.4) / 100.0, 0.324479178538, 4e-5);
    EXPECT_NEAR(pq_decode(0.3) / 100.0, 0.100382263105, 4e-5);
}

TEST(Pq, RoundTripsAndRisesEverywhere) {
    double last = -1.0;
    for (double nits = 0.0; nits <= 10000.0; nits += 0.37) {
        const double e = pq_encode(nits);
        EXPECT_GT(e, last) << nits;
        last = e;
        EXPECT_NEAR(pq_decode(e), nits, 1e-9 * std::max(1.0, nits)) << nits;
    }
    for (double nits : {1e-6, 1e-3, 0.005, 0.1}) EXPECT_NEAR(pq_decode(pq_encode(nits)), nits, 1e-12);
}

TEST(Pq, OutsideTheDomainIsClampedAndNaNIsZero) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    EXPECT_EQ(pq_encode(-5.0), pq_encode(0.0));
    EXPECT_EQ(pq_encode(2e4), 1.0);
    EXPECT_EQ(pq_encode(inf), 1.0);
    EXPECT_EQ(pq_encode(nan), pq_encode(0.0));
    EXPECT_EQ(pq_decode(-0.5), 0.0);
    EXPECT_EQ(pq_decode(1.5), 10000.0);
    EXPECT_EQ(pq_decode(nan), 0.0);
}

// HLG: ITU-R BT.2100-2 Table 5.
TEST(Hlg, TheOetfsBranchesMeetAtOneTwelfth) {
    EXPECT_DOUBLE_EQ(hlg_oetf(1.0 / 12.0), 0.5);
    // The log branch at E = 1/12: a ln(1 − b) + c = a ln(4a) + 0.5 − a ln(4a).
    EXPECT_NEAR(hlg_oetf(std::nextafter(1.0 / 12.0, 1.0)), 0.5, 1e-12);
    EXPECT_NEAR(hlg_oetf(1.0), 1.0, 1e-8);  // a ln(12 − b) + c = 1 to the table's 8 decimals
    EXPECT_EQ(hlg_oetf(0.0), 0.0);
    EXPECT_DOUBLE_EQ(hlg_oetf(1.0 / 48.0), 0.25);  // sqrt(3/48)
}

TEST(Hlg, TheInverseOetfRoundTrips) {
    for (double e = 0.0; e <= 1.0; e += 1.0 / 1024.0) {
        EXPECT_NEAR(hlg_inverse_oetf(hlg_oetf(e)), e, 1e-14) << e;
        // Signal 1 decodes to 1 + 5e-9 (a to 8 decimals), clamped to the OETF's domain [0, 1].
        EXPECT_NEAR(hlg_oetf(hlg_inverse_oetf(e)), e, e < 0.999 ? 1e-14 : 1e-8) << e;
    }
}

TEST(Hlg, SystemGammaFollowsThePeak) {
    EXPECT_DOUBLE_EQ(hlg_system_gamma(1000.0), 1.2);
    EXPECT_NEAR(hlg_system_gamma(2000.0), 1.2 + 0.42 * std::log10(2.0), 1e-15);
    EXPECT_NEAR(hlg_system_gamma(400.0), 1.2 + 0.42 * std::log10(0.4), 1e-15);
}

TEST(Hlg, ReferenceWhiteIs75PercentAt203Nits) {
    // ITU-R BT.2408-7 Table 1: on a 1000 cd/m² display, HDR reference white (203 cd/m²) is
    // 75 % HLG.
    const auto white = hlg_decode({0.75, 0.75, 0.75}, 1000.0);
    EXPECT_NEAR(white[0], 203.0, 0.5);
    EXPECT_NEAR(white[1], white[0], 1e-9);
    const auto signal = hlg_encode({203.0, 203.0, 203.0}, 1000.0);
    EXPECT_NEAR(signal[0], 0.75, 0.001);
    // Signal 1 is the display's peak.
    EXPECT_NEAR(hlg_decode({1.0, 1.0, 1.0}, 1000.0)[1], 1000.0, 1e-5);
}

TEST(Hlg, TheOotfRoundTripsForColoursAtEveryPeak) {
    for (double peak : {100.0, 400.0, 1000.0, 4000.0}) {
        for (double r = 0.0; r <= 1.0; r += 0.125)
            for (double g = 0.0; g <= 1.0; g += 0.25)
                for (double b = 0.0; b <= 1.0; b += 0.25) {
                    const auto d = hlg_ootf({r, g, b}, peak);
                    for (double v : d) {
                        EXPECT_GE(v, 0.0);
                        EXPECT_LE(v, 2.0 * peak);
                    }
                    const auto e = hlg_inverse_ootf(d, peak);
                    EXPECT_NEAR(e[0], r, 1e-12) << peak;
                    EXPECT_NEAR(e[1], g, 1e-12) << peak;
                    EXPECT_NEAR(e[2], b, 1e-12) << peak;
                }
    }
}

TEST(Hlg, HostileInputsGiveFiniteOutputs) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    for (const auto& v : {hlg_decode({nan, inf, -inf}, 1000.0), hlg_encode({nan, inf, -inf}, 1000.0),
                          hlg_ootf({2.0, -1.0, nan}, nan), hlg_inverse_ootf({1e300, -1.0, nan}, 1e9)})
        for (double x : v) EXPECT_TRUE(std::isfinite(x));
    EXPECT_EQ(hlg_oetf(nan), 0.0);
    EXPECT_EQ(hlg_inverse_oetf(2.0), hlg_inverse_oetf(1.0));
}

}  // namespace
}  // namespace irid
