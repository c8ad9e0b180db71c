// The highlight roll-off (irid/gamut/tone.h): identity below the knee, C¹ at it, strictly
// increasing, asymptotic to the display white, and the closed form of its distance to white.
#include <irid/error.h>
#include <irid/gamut/tone.h>

#include <gtest/gtest.h>

#include <cmath>

namespace irid {
namespace {

TEST(HighlightRolloff, IdentityUpToTheKnee) {
    const HighlightRolloff f(0.4);
    for (const double y : {0.0, 0.01, 0.18, 0.3999, 0.4}) EXPECT_EQ(f(y), y);
    EXPECT_EQ(f(-0.25), -0.25);
    EXPECT_TRUE(std::isnan(f(std::nan(""))));
}

// Value and slope meet at the knee: f(k + h) = k + h − h²/(1 − k) + O(h³) from the series of
// u/(1 + u); the one-sided difference quotients on both sides tend to 1.
TEST(HighlightRolloff, ContinuouslyDifferentiableAtTheKnee) {
    for (const double k : {0.0, 0.25, 0.5, 0.9}) {
        const HighlightRolloff f(k);
        for (const double h : {1e-3, 1e-5}) {
            EXPECT_NEAR((f(k + h) - f(k)) / h, 1.0, 2 * h / (1 - k)) << k;
            EXPECT_NEAR((f(k) - f(k - h)) / h, 1.0, 1e-9) << k;
        }
        EXPECT_EQ(f.slope(k), 1.0);
        EXPECT_NEAR(f.slope(k + 1e-9), 1.0, 3e-9 / (1 - k));
    }
}

// Strictly increasing with the analytic slope 1/(1 + u)², never reaching white, and
// 1 − f(Y) = (1 − k)² / (Y + 1 − 2k) above the knee (from u/(1 + u) = 1 − 1/(1 + u)).
TEST(HighlightRolloff, MonotonicAndAsymptoticToWhite) {
    const double k = 0.5;
    const HighlightRolloff f(k);
    double previous = f(0);
    for (double y = 0.01; y < 1e4; y *= 1.05) {
        const double v = f(y);
        EXPECT_GT(v, previous) << y;
        EXPECT_LT(v, 1.0) << y;
        if (y > k) {
            EXPECT_NEAR(1.0 - v, (1 - k) * (1 - k) / (y + 1 - 2 * k), 1e-12) << y;
            const double h = 1e-6 * y;
            EXPECT_NEAR((f(y + h) - f(y - h)) / (2 * h), f.slope(y), 1e-6 * f.slope(y) + 1e-12) << y;
        }
        previous = v;
    }
    EXPECT_NEAR(f(1e12), 1.0, 1e-12);
}

TEST(HighlightRolloff, RefusesKneesOutOfRange) {
    EXPECT_THROW(HighlightRolloff(-0.1), Error);
    EXPECT_THROW(HighlightRolloff(0.96), Error);
    EXPECT_THROW(HighlightRolloff(std::nan("")), Error);
    EXPECT_NO_THROW(HighlightRolloff(0.95));
}

}  // namespace
}  // namespace irid
