// Tests of irid_texture's noise fields against closed forms and invariants: lattice-value
// reproduction and the Catmull–Rom bound (value noise), zero crossings and lattice gradients
// (gradient noise), C¹ continuity across cell faces, analytic gradients against central
// differences, determinism, spatial mean and variance, and the 1/2ⁱ amplitude falloff of
// turbulence (Smits 1990, eq. 30).
//
// Random sample points come from std::mt19937_64 with fixed seeds, turned into doubles by a
// fixed formula (not std::uniform_real_distribution, whose output is implementation-defined),
// so every run tests the same points.

#include <irid/texture/noise.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <random>
#include <thread>
#include <vector>

namespace irid {
namespace {

struct Point {
    double x, y, z;
};

/// Uniform double in [lo, hi) from the top 53 bits of a 64-bit draw.
double uniform(std::mt19937_64& rng, double lo, double hi) {
    return lo + (hi - lo) * (static_cast<double>(rng() >> 11) * 0x1p-53);
}

std::vector<Point> random_points(std::size_t count, double lo, double hi, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::vector<Point> points(count);
    for (Point& p : points) {
        p.x = uniform(rng, lo, hi);
        p.y = uniform(rng, lo, hi);
        p.z = uniform(rng, lo, hi);
    }
    return points;
}

/// Catmull–Rom weights of the points −1, 0, 1, 2, written from the matrix form
/// ½ [t³ t² t 1] [[−1 3 −3 1] [2 −5 4 −1] [−1 0 1 0] [0 2 0 0]] (Catmull and Rom 1974), as an
/// independent reference for the library's Horner form.
std::array<double, 4> reference_catmull_rom(double t) {
    const double t2 = t * t, t3 = t2 * t;
    return {0.5 * (-t3 + 2 * t2 - t), 0.5 * (3 * t3 - 5 * t2 + 2), 0.5 * (-3 * t3 + 4 * t2 + t),
            0.5 * (t3 - t2)};
}

/// Value noise summed directly over the 64 lattice points with the reference weights.
double reference_value_noise(const ValueNoise& field, double x, double y, double z) {
    const double fx = std::floor(x), fy = std::floor(y), fz = std::floor(z);
    const auto ix = static_cast<std::int64_t>(fx), iy = static_cast<std::int64_t>(fy),
               iz = static_cast<std::int64_t>(fz);
    const auto wx = reference_catmull_rom(x - fx), wy = reference_catmull_rom(y - fy),
               wz = reference_catmull_rom(z - fz);
    double sum = 0;
    for (int a = 0; a < 4; ++a)
        for (int b = 0; b < 4; ++b)
            for (int c = 0; c < 4; ++c)
                sum += wx[a] * wy[b] * wz[c] * field.lattice_value(ix + a - 1, iy + b - 1, iz + c - 1);
    return sum;
}

/// Smits 1990 eq. 30 summed directly.
template <class Field>
double reference_turbulence(const Field& field, double x, double y, double z, int octaves) {
    double sum = 0;
    for (int i = 0; i < octaves; ++i) {
        const double s = std::ldexp(1.0, i);
        sum += field.noise(s * x, s * y, s * z) / s;
    }
    return sum;
}

double distance_to_integer(double v) {
    return std::abs(v - std::round(v));
}

/// The worst-case bounds of Catmull–Rom value noise over lattice values in [0, 1], derived in
/// noise.h: [−61/128, 189/128].
constexpr double catmull_rom_lower = -61.0 / 128.0;
constexpr double catmull_rom_upper = 189.0 / 128.0;
/// ∫₀¹ Σᵢ wᵢ(t)² dt for the Catmull–Rom weights (exact, from the polynomials above).
constexpr double catmull_rom_square_integral = 57.0 / 70.0;

// --- Catmull–Rom weights and the bound -------------------------------------------------------

TEST(CatmullRom, WeightsMatchMatrixFormAndSumToOne) {
    for (int i = 0; i <= 1000; ++i) {
        const double t = i / 1000.0;
        const auto w = catmull_rom_weights(t);
        const auto r = reference_catmull_rom(t);
        const auto d = catmull_rom_derivative_weights(t);
        double sum = 0, dsum = 0;
        for (std::size_t k = 0; k < 4; ++k) {
            EXPECT_NEAR(w[k], r[k], 1e-15) << "t = " << t << ", weight " << k;
            // Derivative against a central difference of the reference cubic (exact up to
            // rounding for a cubic: the error term h²/6 · w‴ is 1e-12 here).
            const double h = 1e-6;
            const double fd =
                (reference_catmull_rom(t + h)[k] - reference_catmull_rom(t - h)[k]) / (2 * h);
            EXPECT_NEAR(d[k], fd, 1e-8) << "t = " << t << ", derivative " << k;
            sum += w[k];
            dsum += d[k];
        }
        EXPECT_NEAR(sum, 1.0, 1e-15);
        EXPECT_NEAR(dsum, 0.0, 1e-14);
    }
    const auto w0 = catmull_rom_weights(0.0);
    EXPECT_EQ(w0[0], 0.0);
    EXPECT_EQ(w0[1], 1.0);
    EXPECT_EQ(w0[2], 0.0);
    EXPECT_EQ(w0[3], 0.0);
}

TEST(CatmullRom, WorstCaseBoundIsAttainedAtCellCentre) {
    // The largest value any lattice values in [0, 1] can give at (tx, ty, tz) is the sum of the
    // positive product weights; scan a grid for its maximum and compare with 189/128 at
    // t = (1/2, 1/2, 1/2).
    double worst = 0;
    const int n = 32;
    for (int a = 0; a <= n; ++a)
        for (int b = 0; b <= n; ++b)
            for (int c = 0; c <= n; ++c) {
                const auto wx = catmull_rom_weights(a / double(n));
                const auto wy = catmull_rom_weights(b / double(n));
                const auto wz = catmull_rom_weights(c / double(n));
                double positive = 0;
                for (double u : wx)
                    for (double v : wy)
                        for (double w : wz) positive += std::max(0.0, u * v * w);
                worst = std::max(worst, positive);
            }
    EXPECT_NEAR(worst, catmull_rom_upper, 1e-14);
}

// --- Value noise ------------------------------------------------------------------------------

TEST(ValueNoise, ReproducesLatticeValuesExactly) {
    const ValueNoise field(7);
    std::mt19937_64 rng(1);
    for (int n = 0; n < 2000; ++n) {
        // Small, negative and large (|i| up to 10⁶) lattice points.
        const double range = n < 1000 ? 50.0 : 1e6;
        const auto i = static_cast<std::int64_t>(std::floor(uniform(rng, -range, range)));
        const auto j = static_cast<std::int64_t>(std::floor(uniform(rng, -range, range)));
        const auto k = static_cast<std::int64_t>(std::floor(uniform(rng, -range, range)));
        EXPECT_EQ(field.noise(double(i), double(j), double(k)), field.lattice_value(i, j, k))
            << i << ", " << j << ", " << k;
    }
}

TEST(ValueNoise, LatticeValuesAreUniformOnUnitInterval) {
    const ValueNoise field(3);
    constexpr int bins = 16;
    std::array<int, bins> histogram{};
    const int side = 40;  // 64000 lattice points
    double sum = 0, sum_sq = 0;
    for (int i = -side / 2; i < side / 2; ++i)
        for (int j = 0; j < side; ++j)
            for (int k = 0; k < side; ++k) {
                const double v = field.lattice_value(i, j, 1000 * k);
                ASSERT_GE(v, 0.0);
                ASSERT_LT(v, 1.0);
                ++histogram[static_cast<std::size_t>(v * bins)];
                sum += v;
                sum_sq += v * v;
            }
    const double n = double(side) * side * side;
    const double mean = sum / n, variance = sum_sq / n - mean * mean;
    // Standard errors: mean √(1/12/n) ≈ 1.1e-3, variance ≈ √(1/180/n) ≈ 2.9e-4; 5σ.
    EXPECT_NEAR(mean, 0.5, 6e-3);
    EXPECT_NEAR(variance, 1.0 / 12.0, 1.5e-3);
    // χ² with 15 degrees of freedom: the 0.9999 quantile is 42.6.
    const double expected = n / bins;
    double chi2 = 0;
    for (int count : histogram) chi2 += (count - expected) * (count - expected) / expected;
    EXPECT_LT(chi2, 42.6);
}

TEST(ValueNoise, LatticeValuesAlongAPeriodAreEveryBinCentreOnce) {
    // The value at (i, j, k) is (P[P[P[i] + j] + k] + 1/2)/period: along k, for fixed (i, j),
    // one period runs through every entry of the permutation once, so the values are exactly
    // the bin centres (m + 1/2)/period, m = 0..period − 1, each once.
    const ValueNoise field(47);
    const auto period = static_cast<std::int64_t>(ValueNoise::period);
    for (const std::int64_t i : {std::int64_t{-5000}, std::int64_t{0}, std::int64_t{777777}})
        for (const std::int64_t j : {std::int64_t{-1}, std::int64_t{3}, std::int64_t{-123456}}) {
            std::vector<int> seen(ValueNoise::period, 0);
            for (std::int64_t k = -period / 2; k < period / 2; ++k) {
                const double bin = field.lattice_value(i, j, k) * double(period) - 0.5;
                ASSERT_EQ(bin, std::floor(bin)) << i << ", " << j << ", " << k;
                ASSERT_GE(bin, 0.0);
                ASSERT_LT(bin, double(period));
                ++seen[static_cast<std::size_t>(bin)];
            }
            for (const int count : seen) ASSERT_EQ(count, 1);
        }
}

TEST(ValueNoise, HasPeriod1024) {
    const ValueNoise field(53);
    std::mt19937_64 rng(15);
    for (int n = 0; n < 2000; ++n) {
        // Dyadic fractions, so x and x + 1024 have exactly the same fraction.
        const double x = std::floor(uniform(rng, -3000, 3000) * 1024) / 1024;
        const double y = std::floor(uniform(rng, -3000, 3000) * 1024) / 1024;
        const double z = std::floor(uniform(rng, -3000, 3000) * 1024) / 1024;
        const double v = field.noise(x, y, z);
        EXPECT_EQ(field.noise(x + 1024, y, z), v);
        EXPECT_EQ(field.noise(x, y - 1024, z), v);
        EXPECT_EQ(field.noise(x, y, z + 2048), v);
        // Not a shorter period along the axis: half a period gives another value.
        EXPECT_NE(field.noise(x + 512, y, z), v);
    }
}

TEST(ValueNoise, MatchesDirectSumOverSixtyFourLatticePoints) {
    const ValueNoise field(11);
    for (const double range : {3.0, 1e3, 1e6}) {
        for (const Point& p : random_points(2000, -range, range, 5)) {
            const double expected = reference_value_noise(field, p.x, p.y, p.z);
            EXPECT_NEAR(field.noise(p.x, p.y, p.z), expected, 1e-14)
                << p.x << ", " << p.y << ", " << p.z;
        }
    }
}

TEST(ValueNoise, StaysWithinCatmullRomBound) {
    const ValueNoise field(1);
    double lo = 1, hi = 0;
    for (const Point& p : random_points(1'000'000, -1e3, 1e3, 2)) {
        const double v = field.noise(p.x, p.y, p.z);
        lo = std::min(lo, v);
        hi = std::max(hi, v);
    }
    EXPECT_GE(lo, catmull_rom_lower);
    EXPECT_LE(hi, catmull_rom_upper);
    // The cubic does overshoot [0, 1] (lattice values reach 1/2048 and 2047/2048), but random
    // lattice values stay far inside the worst case (noise.h quotes [−0.16, 1.15] for 4·10⁶
    // points).
    EXPECT_LT(lo, 0.0);
    EXPECT_GT(hi, 1.0);
    EXPECT_GT(lo, -0.25);
    EXPECT_LT(hi, 1.25);
}

TEST(ValueNoise, SpatialMeanAndVarianceMatchClosedForm) {
    // Lattice values are (nearly) independent and uniform (mean 1/2, variance 1/12, less
    // 1/(12·1024²) for the discrete bins); the weights sum to 1, so the mean is 1/2 everywhere
    // and the variance at cell position t is (1/12) Π_axes Σᵢ wᵢ(t)², whose average over the
    // cell is (1/12)(57/70)³.
    const ValueNoise field(19);
    const auto points = random_points(200'000, -1e4, 1e4, 3);
    double sum = 0, sum_sq = 0;
    for (const Point& p : points) {
        const double v = field.noise(p.x, p.y, p.z);
        sum += v;
        sum_sq += v * v;
    }
    const double n = double(points.size());
    const double mean = sum / n, variance = sum_sq / n - mean * mean;
    const double expected_variance = std::pow(catmull_rom_square_integral, 3) / 12.0;
    // σ ≈ 0.212: the mean's standard error is 4.7e-4 (tolerance 5σ); the variance's relative
    // standard error is about √(2/n) ≈ 0.3% (tolerance 3%).
    EXPECT_NEAR(mean, 0.5, 2.5e-3);
    EXPECT_NEAR(variance, expected_variance, 0.03 * expected_variance);
}

// --- Properties shared by both fields ---------------------------------------------------------

template <class Field>
class NoiseField : public ::testing::Test {};

using Fields = ::testing::Types<ValueNoise, GradientNoise>;
TYPED_TEST_SUITE(NoiseField, Fields);

TYPED_TEST(NoiseField, ValueAndGradientAreContinuousAcrossCellFaces) {
    const TypeParam field(5);
    std::mt19937_64 rng(4);
    const double eps = 1e-9;
    for (int n = 0; n < 3000; ++n) {
        // Faces near the origin (x = 0 is where truncation instead of floor would show), at
        // negative and at large coordinates.
        const double range = n < 1000 ? 4.0 : (n < 2000 ? 300.0 : 1e6);
        const double face = std::floor(uniform(rng, -range, range));
        const double a = uniform(rng, -range, range), b = uniform(rng, -range, range);
        for (int axis = 0; axis < 3; ++axis) {
            Point lo{a, b, a + b}, hi = lo;
            (axis == 0 ? lo.x : axis == 1 ? lo.y : lo.z) = face - eps;
            (axis == 0 ? hi.x : axis == 1 ? hi.y : hi.z) = face + eps;
            const double v_lo = field.noise(lo.x, lo.y, lo.z), v_hi = field.noise(hi.x, hi.y, hi.z);
            const NoiseGradient g_lo = field.dnoise(lo.x, lo.y, lo.z);
            const NoiseGradient g_hi = field.dnoise(hi.x, hi.y, hi.z);
            // Across 2e-9 the value moves by at most |∇| · 2e-9 (|∇| < 10) and the gradient by
            // the second derivative (< 50) times 2e-9; a jump would be of order 0.01–1.
            EXPECT_NEAR(v_lo, v_hi, 1e-7) << "axis " << axis << ", face " << face;
            EXPECT_NEAR(g_lo.x, g_hi.x, 1e-6) << "axis " << axis << ", face " << face;
            EXPECT_NEAR(g_lo.y, g_hi.y, 1e-6) << "axis " << axis << ", face " << face;
            EXPECT_NEAR(g_lo.z, g_hi.z, 1e-6) << "axis " << axis << ", face " << face;
        }
    }
}

/// Checks an analytic gradient against central differences at points at least `margin` from
/// every cell face of every octave (Catmull–Rom is only C¹: its second derivative jumps there).
template <class Value, class Gradient>
void expect_gradient_matches_central_differences(Value value, Gradient gradient, int octaves,
                                                 double h, std::uint64_t seed) {
    int checked = 0;
    for (const Point& p : random_points(3000, -50, 50, seed)) {
        bool near_face = false;
        for (int i = 0; i < octaves; ++i) {
            const double s = std::ldexp(1.0, i);
            for (const double c : {p.x, p.y, p.z})
                near_face = near_face || distance_to_integer(s * c) < 4 * s * h;
        }
        if (near_face) continue;
        ++checked;
        const NoiseGradient g = gradient(p.x, p.y, p.z);
        const double fx = (value(p.x + h, p.y, p.z) - value(p.x - h, p.y, p.z)) / (2 * h);
        const double fy = (value(p.x, p.y + h, p.z) - value(p.x, p.y - h, p.z)) / (2 * h);
        const double fz = (value(p.x, p.y, p.z + h) - value(p.x, p.y, p.z - h)) / (2 * h);
        const double norm = std::max(std::sqrt(g.x * g.x + g.y * g.y + g.z * g.z), 1.0);
        // Relative tolerance 1e-6: truncation h² f‴/6 and rounding ε f/h are both below 1e-8.
        EXPECT_NEAR(g.x, fx, 1e-6 * norm) << p.x << ", " << p.y << ", " << p.z;
        EXPECT_NEAR(g.y, fy, 1e-6 * norm) << p.x << ", " << p.y << ", " << p.z;
        EXPECT_NEAR(g.z, fz, 1e-6 * norm) << p.x << ", " << p.y << ", " << p.z;
    }
    EXPECT_GT(checked, 2500);
}

TYPED_TEST(NoiseField, DnoiseMatchesCentralDifferences) {
    const TypeParam field(13);
    expect_gradient_matches_central_differences(
        [&](double x, double y, double z) { return field.noise(x, y, z); },
        [&](double x, double y, double z) { return field.dnoise(x, y, z); }, 1, 1e-5, 6);
}

TYPED_TEST(NoiseField, DturbulenceMatchesCentralDifferences) {
    const TypeParam field(17);
    expect_gradient_matches_central_differences(
        [&](double x, double y, double z) { return field.turbulence(x, y, z); },
        [&](double x, double y, double z) { return field.dturbulence(x, y, z); }, 7, 1e-6, 7);
}

TYPED_TEST(NoiseField, SameSeedIsBitIdenticalAcrossObjectsAndThreads) {
    const auto points = random_points(5000, -1e5, 1e5, 8);
    const auto evaluate = [&points](std::vector<double>& out) {
        const TypeParam field(42);
        out.clear();
        for (const Point& p : points) {
            out.push_back(field.noise(p.x, p.y, p.z));
            const NoiseGradient g = field.dturbulence(p.x, p.y, p.z);
            out.push_back(g.x);
            out.push_back(g.y);
            out.push_back(g.z);
        }
    };
    std::vector<double> here;
    evaluate(here);
    std::array<std::vector<double>, 4> threaded;
    std::vector<std::thread> threads;
    for (auto& out : threaded) threads.emplace_back(evaluate, std::ref(out));
    for (auto& t : threads) t.join();
    for (const auto& out : threaded) {
        ASSERT_EQ(out.size(), here.size());
        for (std::size_t i = 0; i < here.size(); ++i) ASSERT_EQ(out[i], here[i]) << i;
    }
}

TYPED_TEST(NoiseField, DifferentSeedsGiveDifferentFields) {
    const TypeParam a(0), b(1), c(0x9e3779b97f4a7c15ULL);
    int differ_ab = 0, differ_ac = 0;
    const auto points = random_points(1000, -100, 100, 9);
    for (const Point& p : points) {
        differ_ab += a.noise(p.x, p.y, p.z) != b.noise(p.x, p.y, p.z);
        differ_ac += a.noise(p.x, p.y, p.z) != c.noise(p.x, p.y, p.z);
    }
    EXPECT_GT(differ_ab, 990);
    EXPECT_GT(differ_ac, 990);
    EXPECT_EQ(a.seed(), 0u);
    EXPECT_EQ(b.seed(), 1u);
}

TYPED_TEST(NoiseField, TurbulenceIsEquation30) {
    const TypeParam field(23);
    for (const Point& p : random_points(500, -20, 20, 10)) {
        EXPECT_EQ(field.turbulence(p.x, p.y, p.z, 1), field.noise(p.x, p.y, p.z));
        EXPECT_EQ(field.turbulence(p.x, p.y, p.z, 0), 0.0);
        EXPECT_EQ(field.turbulence(p.x, p.y, p.z, -3), 0.0);
        EXPECT_NEAR(field.turbulence(p.x, p.y, p.z), reference_turbulence(field, p.x, p.y, p.z, 7),
                    1e-14);
        EXPECT_NEAR(field.turbulence(p.x, p.y, p.z, 12),
                    reference_turbulence(field, p.x, p.y, p.z, 12), 1e-14);
        const NoiseGradient g0 = field.dturbulence(p.x, p.y, p.z, 0);
        EXPECT_EQ(g0.x, 0.0);
        const NoiseGradient g1 = field.dturbulence(p.x, p.y, p.z, 1);
        const NoiseGradient d = field.dnoise(p.x, p.y, p.z);
        EXPECT_EQ(g1.x, d.x);
        EXPECT_EQ(g1.y, d.y);
        EXPECT_EQ(g1.z, d.z);
    }
}

TYPED_TEST(NoiseField, TurbulenceResidualVarianceFallsFourfoldPerOctave) {
    // Octave i of eq. 30 is the field at frequency 2ⁱ with amplitude 2⁻ⁱ, so its variance over
    // space is σ²/4ⁱ; at points far from the origin (|p| ≥ 100) the octaves read unrelated
    // lattice points and are uncorrelated, so the residual R_k = turb₇ − turb_k (octaves k..6)
    // has variance σ² Σ_{i=k}^{6} 4⁻ⁱ. Check the ratios Var(R_k)/Var(R_{k+1}) against that
    // closed form (≈ 4, exactly 4(1 − 4^{k−7})/(1 − 4^{k−6})). Each variance has a relative
    // standard error of about √(2/n) ≈ 0.45% at n = 10⁵; the ratios are held to 4%.
    const TypeParam field(29);
    constexpr int octaves = 7;
    const auto points = random_points(100'000, 100, 1e4, 11);
    std::array<double, octaves> sum{}, sum_sq{};
    for (const Point& p : points) {
        const double total = field.turbulence(p.x, p.y, p.z, octaves);
        for (int k = 0; k < octaves; ++k) {
            const double r = total - field.turbulence(p.x, p.y, p.z, k);
            sum[k] += r;
            sum_sq[k] += r * r;
        }
    }
    const double n = double(points.size());
    std::array<double, octaves> variance{};
    for (int k = 0; k < octaves; ++k)
        variance[k] = sum_sq[k] / n - (sum[k] / n) * (sum[k] / n);
    for (int k = 0; k + 1 < octaves; ++k) {
        const double expected =
            4.0 * (1.0 - std::pow(4.0, k - octaves)) / (1.0 - std::pow(4.0, k + 1 - octaves));
        EXPECT_NEAR(variance[k] / variance[k + 1], expected, 0.04 * expected) << "k = " << k;
    }
}

TYPED_TEST(NoiseField, NonFiniteCoordinatesGiveNaN) {
    const TypeParam field(1);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    EXPECT_TRUE(std::isnan(field.noise(nan, 0.5, 0.5)));
    EXPECT_TRUE(std::isnan(field.noise(0.5, inf, 0.5)));
    EXPECT_TRUE(std::isnan(field.noise(0.5, 0.5, -inf)));
    EXPECT_TRUE(std::isnan(field.dnoise(nan, 0.5, 0.5).x));
}

// --- Gradient noise ---------------------------------------------------------------------------

TEST(GradientNoise, IsZeroAtLatticePointsWithTheLatticeGradient) {
    const GradientNoise field(31);
    std::mt19937_64 rng(12);
    for (int n = 0; n < 3000; ++n) {
        const double range = n < 1500 ? 600.0 : 1e6;
        const double i = std::floor(uniform(rng, -range, range));
        const double j = std::floor(uniform(rng, -range, range));
        const double k = std::floor(uniform(rng, -range, range));
        EXPECT_EQ(field.noise(i, j, k), 0.0) << i << ", " << j << ", " << k;
        // At a lattice point the fade weights select that corner alone and its dot product
        // vanishes, so ∇noise is the corner's gradient.
        const NoiseGradient g = field.dnoise(i, j, k);
        const NoiseGradient l = field.lattice_gradient(static_cast<std::int64_t>(i),
                                                       static_cast<std::int64_t>(j),
                                                       static_cast<std::int64_t>(k));
        EXPECT_EQ(g.x, l.x);
        EXPECT_EQ(g.y, l.y);
        EXPECT_EQ(g.z, l.z);
    }
}

TEST(GradientNoise, LatticeGradientsAreCubeEdgeDirectionsInPerlinsProportions) {
    // Perlin 2002: the 12 directions (±1, ±1, 0), (±1, 0, ±1), (0, ±1, ±1), indexed by the low 4
    // bits of the hash, with (1, 1, 0), (−1, 1, 0), (0, −1, 1), (0, −1, −1) repeated: z is the
    // zero component of 6 of the 16 entries, y of 4, x of 6, and the 16 sum to (0, 0, 0). Over
    // one full period the innermost index p[A + k] runs through every value 0..255 once for
    // each (i, j), so these proportions hold exactly.
    const GradientNoise field(37);
    const auto period = static_cast<std::int64_t>(GradientNoise::period);
    std::array<std::int64_t, 3> zero_component{};
    std::array<std::int64_t, 3> sum{};
    for (std::int64_t i = 0; i < period; ++i)
        for (std::int64_t j = -period; j < 0; ++j)  // negative indices wrap the same way
            for (std::int64_t k = 0; k < period; ++k) {
                const NoiseGradient g = field.lattice_gradient(i, j, k);
                const std::array<double, 3> c{g.x, g.y, g.z};
                int zeros = 0;
                for (std::size_t a = 0; a < 3; ++a) {
                    ASSERT_TRUE(c[a] == 0.0 || std::abs(c[a]) == 1.0);
                    if (c[a] == 0.0) {
                        ++zeros;
                        ++zero_component[a];
                    }
                    sum[a] += static_cast<std::int64_t>(c[a]);
                }
                ASSERT_EQ(zeros, 1);
            }
    const std::int64_t n = period * period * period;
    EXPECT_EQ(zero_component[0] * 16, 6 * n);
    EXPECT_EQ(zero_component[1] * 16, 4 * n);
    EXPECT_EQ(zero_component[2] * 16, 6 * n);
    EXPECT_EQ(sum[0], 0);
    EXPECT_EQ(sum[1], 0);
    EXPECT_EQ(sum[2], 0);
}

TEST(GradientNoise, HasPeriod256) {
    const GradientNoise field(41);
    std::mt19937_64 rng(13);
    for (int n = 0; n < 2000; ++n) {
        // Dyadic fractions, so x and x + 256 have exactly the same fraction.
        const double x = std::floor(uniform(rng, -1000, 1000) * 1024) / 1024;
        const double y = std::floor(uniform(rng, -1000, 1000) * 1024) / 1024;
        const double z = std::floor(uniform(rng, -1000, 1000) * 1024) / 1024;
        const double v = field.noise(x, y, z);
        EXPECT_EQ(field.noise(x + 256, y, z), v);
        EXPECT_EQ(field.noise(x, y - 256, z), v);
        EXPECT_EQ(field.noise(x, y, z + 512), v);
    }
}

TEST(GradientNoise, HasZeroMeanAndStaysWithinBound) {
    const GradientNoise field(43);
    const auto points = random_points(1'000'000, -1e4, 1e4, 14);
    double sum = 0, sum_sq = 0, lo = 0, hi = 0;
    for (const Point& p : points) {
        const double v = field.noise(p.x, p.y, p.z);
        sum += v;
        sum_sq += v * v;
        lo = std::min(lo, v);
        hi = std::max(hi, v);
    }
    const double n = double(points.size());
    const double mean = sum / n, sigma = std::sqrt(sum_sq / n - mean * mean);
    // Standard error σ/√n ≈ 2.5e-4 at σ ≈ 0.25; tolerance 6 standard errors. The period (256³
    // cells) holds ~16.7 million independent lattice gradients, far more than the sample uses.
    EXPECT_NEAR(mean, 0.0, 6.0 * sigma / std::sqrt(n));
    EXPECT_GT(sigma, 0.1);
    EXPECT_GE(lo, -1.5);
    EXPECT_LE(hi, 1.5);
    EXPECT_LT(lo, -0.7);
    EXPECT_GT(hi, 0.7);
}

}  // namespace
}  // namespace irid
