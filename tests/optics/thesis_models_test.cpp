#include <irid/color/illuminant.h>
#include <irid/color/observer.h>
#include <irid/error.h>
#include <irid/optics/thesis_models.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <numbers>
#include <string>

namespace irid {
namespace {

constexpr double pi = std::numbers::pi;

double radians(double degrees) {
    return degrees * pi / 180.0;
}

/// The wavelength [nm] of the largest sample of a dense spectrum.
double peak_wavelength_nm(const DenseSpectrum& s) {
    const auto values = s.values();
    const auto peak = std::max_element(values.begin(), values.end());
    return DenseSpectrum::wavelength_nm(static_cast<int>(peak - values.begin()));
}

/// Eq. 25 typed straight from the thesis, for comparisons away from its poles.
double eq25_direct(double lambda_nm, double t_nm, int l, double K) {
    const double ratio =
        std::sin(2.0 * pi * (l + 1) * t_nm / lambda_nm) / std::sin(2.0 * pi * t_nm / lambda_nm);
    return 0.5 * K * ratio * ratio;
}

void expect_error_naming(const std::function<void()>& f, const std::string& parameter) {
    try {
        f();
        ADD_FAILURE() << "no irid::Error naming " << parameter;
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find(parameter), std::string::npos)
            << "message '" << e.what() << "' does not name " << parameter;
    }
}

// --- One film: eq. 19–24 ---------------------------------------------------------------------

TEST(ThesisFilm, ZeroThicknessWithPhaseChangeIsBlack) {
    // ρ = K² cos²(π/2) = 0.
    for (double lambda : {380.0, 550.0, 780.0})
        EXPECT_NEAR(thesis_film_reflectance(lambda, 0.0, 1.33, true, 0.9), 0.0, 1e-15);
}

TEST(ThesisFilm, ZeroThicknessWithoutPhaseChangeReflectsKSquared) {
    // ρ = K² cos²(0) = K².
    for (double lambda : {380.0, 550.0, 780.0})
        EXPECT_NEAR(thesis_film_reflectance(lambda, 0.0, 1.38, false, 0.8), 0.64, 1e-15);
}

TEST(ThesisFilm, IsPeriodicInThicknessWithPeriodHalfAWavelengthInTheFilm) {
    // cos² has period π in its argument 2πtn/λ, so ρ has period λ/(2n) in t.
    const double n = 1.33;
    for (bool phase : {true, false}) {
        for (double lambda : {400.0, 550.0, 700.0}) {
            const double period = lambda / (2.0 * n);
            for (double t : {0.0, 37.0, 123.4, 512.0}) {
                const double rho = thesis_film_reflectance(lambda, t, n, phase);
                EXPECT_NEAR(thesis_film_reflectance(lambda, t + period, n, phase), rho, 1e-12);
                EXPECT_NEAR(thesis_film_reflectance(lambda, t + 3.0 * period, n, phase), rho,
                            1e-12);
            }
        }
    }
}

TEST(ThesisFilm, WithPhaseChangeTheQuarterWaveFilmIsBrightestAndTheHalfWaveFilmBlack) {
    // 2πtn/λ + π/2 = π at t = λ/(4n): ρ = K²; = 3π/2 at t = λ/(2n): ρ = 0.
    const double n = 1.47, lambda = 560.0, K = 0.7;
    const double quarter = lambda / (4.0 * n);
    EXPECT_NEAR(thesis_film_reflectance(lambda, quarter, n, true, K), K * K, 1e-15);
    EXPECT_NEAR(thesis_film_reflectance(lambda, 2.0 * quarter, n, true, K), 0.0, 1e-15);
    EXPECT_LT(thesis_film_reflectance(lambda, quarter - 1.0, n, true, K), K * K);
    EXPECT_LT(thesis_film_reflectance(lambda, quarter + 1.0, n, true, K), K * K);
}

TEST(ThesisFilm, WithoutPhaseChangeTheQuarterWaveFilmIsBlackAndTheHalfWaveFilmBrightest) {
    const double n = 1.38, lambda = 550.0, K = 1.0;
    const double quarter = lambda / (4.0 * n);
    EXPECT_NEAR(thesis_film_reflectance(lambda, quarter, n, false, K), 0.0, 1e-15);
    EXPECT_NEAR(thesis_film_reflectance(lambda, 2.0 * quarter, n, false, K), 1.0, 1e-15);
}

TEST(ThesisFilm, KScalesTheReflectanceByKSquared) {
    for (bool phase : {true, false}) {
        const double rho1 = thesis_film_reflectance(470.0, 321.0, 1.33, phase, 1.0);
        EXPECT_NEAR(thesis_film_reflectance(470.0, 321.0, 1.33, phase, 0.5), 0.25 * rho1, 1e-15);
        EXPECT_NEAR(thesis_film_reflectance(470.0, 321.0, 1.33, phase, 3.0), 9.0 * rho1, 1e-14);
    }
}

TEST(ThesisFilm, PhaseChangeWhenExactlyOneReflectionIsFromAHigherIndex) {
    EXPECT_TRUE(thesis_phase_change(1.0, 1.33, 1.0));     // soap film in air
    EXPECT_TRUE(thesis_phase_change(1.0, 1.47, 1.33));    // oil on water
    EXPECT_TRUE(thesis_phase_change(1.5, 1.0, 1.5));      // air gap between glass plates
    EXPECT_FALSE(thesis_phase_change(1.0, 1.38, 1.5));    // MgF₂ on glass: index in between
    EXPECT_FALSE(thesis_phase_change(1.5, 1.38, 1.0));    // the same, seen from the glass
    EXPECT_FALSE(thesis_phase_change(1.33, 1.33, 1.33));  // no index step: no shift at all
    EXPECT_TRUE(thesis_phase_change(1.33, 1.33, 1.5));    // only the bottom step, to higher
}

TEST(ThesisFilm, EffectiveThicknessAtNormalIncidenceIsThicknessTimesIndex) {
    EXPECT_DOUBLE_EQ(thesis_effective_thickness_nm(400.0, 1.33, 0.0), 532.0);
    EXPECT_DOUBLE_EQ(thesis_film_angle_rad(0.0, 1.33), 0.0);
}

TEST(ThesisFilm, AngleInsideTheFilmFollowsSnellsLaw) {
    for (double n_ambient : {1.0, 1.33}) {
        for (double degrees : {10.0, 35.0, 70.0}) {
            const double theta = thesis_film_angle_rad(radians(degrees), 1.5, n_ambient);
            EXPECT_NEAR(1.5 * std::sin(theta), n_ambient * std::sin(radians(degrees)), 1e-15);
        }
    }
    // Glass (1.5) over water (1.33): beyond asin(1.33/1.5) ≈ 62.5° nothing crosses the film,
    // which is then treated as grazing: t′ = 0.
    const double theta = thesis_film_angle_rad(radians(70.0), 1.33, 1.5);
    EXPECT_DOUBLE_EQ(theta, pi / 2.0);
    EXPECT_NEAR(thesis_effective_thickness_nm(500.0, 1.33, theta), 0.0, 1e-12);
}

TEST(ThesisFilm, EffectiveThicknessInAirIsTRootOfNSquaredMinusSinSquared) {
    // n cos θ_film = n (1 − sin²θ/n²)^½ = (n² − sin²θ)^½: eq. 24 in air is eq. 26.
    const double t = 300.0, n = 1.33;
    double previous = t * n;
    for (double degrees = 5.0; degrees < 90.0; degrees += 5.0) {
        const double s = std::sin(radians(degrees));
        const double t_eff =
            thesis_effective_thickness_nm(t, n, thesis_film_angle_rad(radians(degrees), n));
        EXPECT_NEAR(t_eff, t * std::sqrt(n * n - s * s), 1e-12);
        EXPECT_LT(t_eff, previous);
        previous = t_eff;
    }
}

TEST(ThesisFilm, SpectrumAtNormalIncidenceIsEquation21) {
    const ThesisFilmParameters soap;  // water in air, phase change, K = 1
    const DenseSpectrum s = thesis_film_spectrum(soap, 250.0);
    for (int i = 0; i < dense_sample_count; i += 47) {
        const double lambda = DenseSpectrum::wavelength_nm(i);
        const double a = 2.0 * pi * 250.0 * 1.33 / lambda + pi / 2.0;
        EXPECT_NEAR(s[i], std::cos(a) * std::cos(a), 1e-14) << lambda;
    }
}

TEST(ThesisFilm, SpectrumAtAnAngleHasItsQuarterWavePeakAtFourTimesTheEffectiveThickness) {
    // n = 1.25 and sin θ = 0.75 in air: sin θ_film = 0.6, cos θ_film = 0.8, so t′ = t. With a
    // phase change ρ = sin²(2πt′/λ) is 1 at λ = 4t′ = 500 nm for t = 125 nm, its only maximum
    // in 360-830 nm (the next is at 4t′/3).
    ThesisFilmParameters film;
    film.n_film = 1.25;
    const DenseSpectrum s = thesis_film_spectrum(film, 125.0, std::asin(0.75) * 180.0 / pi);
    EXPECT_NEAR(s(500.0), 1.0, 1e-12);
    EXPECT_EQ(peak_wavelength_nm(s), 500.0);
}

// --- The table for n = 1 indexed by t′ (eq. 24, §3.3) -----------------------------------------

TEST(ThesisFilmTable, ZeroEffectiveThicknessIsBlackWithPhaseChangeAndWhiteWithout) {
    const DenseSpectrum d65 = illuminant_d65();
    const Xyz white = illuminant_white(d65);
    const ThesisFilmTable with(true, 1000.0, 1.0, d65);
    const ThesisFilmTable without(false, 1000.0, 1.0, d65);
    EXPECT_NEAR(with.at(0.0).Y, 0.0, 1e-15);
    EXPECT_NEAR(without.at(0.0).X, white.X, 1e-12);
    EXPECT_NEAR(without.at(0.0).Y, white.Y, 1e-12);
    EXPECT_NEAR(without.at(0.0).Z, white.Z, 1e-12);
}

TEST(ThesisFilmTable, ReproducesTheDirectColourForOtherIndicesAndAngles) {
    // Bound derived in the header: π²h²W/λ_min² for step h, W the white's largest component.
    const DenseSpectrum d65 = illuminant_d65();
    const Xyz white = illuminant_white(d65);
    const double h = 2.0;
    const double bound = pi * pi * h * h * std::max({white.X, white.Y, white.Z}) / (360.0 * 360.0);

    struct Case {
        double n_ambient, n_film, n_substrate;
    };
    for (const Case& c : {Case{1.0, 1.33, 1.0}, Case{1.0, 1.47, 1.33}, Case{1.0, 1.38, 1.5}}) {
        ThesisFilmParameters film;
        film.n_film = c.n_film;
        film.n_ambient = c.n_ambient;
        film.phase_change = thesis_phase_change(c.n_ambient, c.n_film, c.n_substrate);
        const ThesisFilmTable table(film.phase_change, 1500.0, h, d65);
        for (double degrees : {0.0, 25.0, 50.0, 75.0}) {
            for (double t = 0.0; t <= 1000.0; t += 37.3) {
                const Xyz direct = reflectance_to_xyz(thesis_film_spectrum(film, t, degrees), d65);
                const double t_eff = thesis_effective_thickness_nm(
                    t, c.n_film, thesis_film_angle_rad(radians(degrees), c.n_film));
                const Xyz looked_up = table.at(t_eff);
                EXPECT_NEAR(looked_up.X, direct.X, bound) << t << " nm at " << degrees << "°";
                EXPECT_NEAR(looked_up.Y, direct.Y, bound) << t << " nm at " << degrees << "°";
                EXPECT_NEAR(looked_up.Z, direct.Z, bound) << t << " nm at " << degrees << "°";
            }
        }
    }
}

TEST(ThesisFilmTable, LookupScalesWithKSquared) {
    const DenseSpectrum d65 = illuminant_d65();
    const ThesisFilmTable table(true, 800.0, 1.0, d65);
    ThesisFilmParameters film;
    film.n_film = 1.0;
    film.K = 0.6;
    const Xyz direct = reflectance_to_xyz(thesis_film_spectrum(film, 400.0), d65);
    EXPECT_NEAR(table.at(400.0, 0.6).Y, direct.Y, 1e-12);
    EXPECT_NEAR(table.at(400.0, 0.6).Y, 0.36 * table.at(400.0).Y, 1e-15);
}

TEST(ThesisFilmTable, ShrinksTheStepToDivideTheRangeAndClampsOutsideIt) {
    const DenseSpectrum d65 = illuminant_d65();
    const ThesisFilmTable table(false, 100.0, 3.0, d65);  // 34 intervals of 100/34 nm
    EXPECT_DOUBLE_EQ(table.step_nm(), 100.0 / 34.0);
    EXPECT_DOUBLE_EQ(table.max_effective_thickness_nm(), 100.0);
    EXPECT_EQ(table.at(250.0).Y, table.at(100.0).Y);
    EXPECT_EQ(table.at(-5.0).Y, table.at(0.0).Y);
}

// --- Multiple films: eq. 25–26 ----------------------------------------------------------------

TEST(ThesisMultilayer, NoPeriodsGivesHalfK) {
    // l = 0: ½K (sin x / sin x)² = ½K, also at the poles.
    for (double t : {0.0, 137.0, 250.0, 333.3, 500.0})
        EXPECT_NEAR(thesis_multilayer_reflectance(500.0, t, 0, 0.8), 0.4, 1e-15) << t;
}

TEST(ThesisMultilayer, AtTheSingularityTheValueIsItsLimitHalfKTimesLPlusOneSquared) {
    // sin((l+1)x)/sin(x) → ±(l+1) as x → mπ, i.e. at t = mλ/2.
    const double K = 0.7;
    for (int l : {1, 5, 12, 40}) {
        const double limit = 0.5 * K * (l + 1) * (l + 1);
        for (int m = 0; m <= 4; ++m) {
            EXPECT_NEAR(thesis_multilayer_reflectance(456.0, m * 228.0, l, K), limit, 1e-13 * limit)
                << "l = " << l << ", m = " << m;
        }
    }
}

TEST(ThesisMultilayer, IsContinuousApproachingThePoleFromBothSides) {
    const int l = 12;
    const double lambda = 531.0, pole = lambda / 2.0;
    const double limit = 0.5 * (l + 1) * (l + 1);
    for (double epsilon : {1e-6, 1e-8, 1e-10, 1e-12, 1e-14}) {
        for (double side : {-1.0, 1.0}) {
            const double t = pole * (1.0 + side * epsilon);
            EXPECT_NEAR(thesis_multilayer_reflectance(lambda, t, l), limit, 1e-9 * limit)
                << "t = pole × (1 " << (side < 0 ? "- " : "+ ") << epsilon << ")";
        }
    }
}

TEST(ThesisMultilayer, NearThePoleFollowsItsTaylorExpansion) {
    // x = mπ + δ: (sin(Nx)/sin x)² = N²[1 − (N² − 1)δ²/3 + O(N⁴δ⁴)], N = l + 1. At δ = 1e-4
    // the δ² term is 5.6e-7 of the value for N = 13 and the next one about 1e-13.
    const int l = 12;
    const double N = l + 1, lambda = 600.0, delta = 1e-4;
    const double t = (pi + delta) * lambda / (2.0 * pi);
    const double expected = 0.5 * N * N * (1.0 - (N * N - 1.0) * delta * delta / 3.0);
    EXPECT_NEAR(thesis_multilayer_reflectance(lambda, t, l), expected, 1e-11 * expected);
}

TEST(ThesisMultilayer, MatchesTheDirectFormulaAwayFromThePoles) {
    // Rounding 2πt/λ moves the direct formula by about 1e-15 of its argument; relative to the
    // peak ½K(l+1)² the two agree to 1e-12.
    for (int l : {1, 3, 12}) {
        const double K = 1.3, peak = 0.5 * K * (l + 1) * (l + 1);
        for (double lambda : {380.0, 455.0, 610.0, 777.0}) {
            for (double t = 3.0; t < 1200.0; t += 11.7) {
                if (std::abs(std::sin(2.0 * pi * t / lambda)) < 0.05) continue;
                EXPECT_NEAR(thesis_multilayer_reflectance(lambda, t, l, K),
                            eq25_direct(lambda, t, l, K), 1e-12 * peak)
                    << "l = " << l << ", λ = " << lambda << ", t = " << t;
            }
        }
    }
}

TEST(ThesisMultilayer, PeaksWhereTheEffectiveThicknessIsAWholeNumberOfHalfWaves) {
    const int l = 12;
    const double lambda = 500.0, peak = 0.5 * (l + 1) * (l + 1);
    for (int m = 1; m <= 4; ++m) {
        const double t = m * lambda / 2.0;
        EXPECT_NEAR(thesis_multilayer_reflectance(lambda, t, l), peak, 1e-12 * peak);
        EXPECT_LT(thesis_multilayer_reflectance(lambda, t - 0.5, l), peak);
        EXPECT_LT(thesis_multilayer_reflectance(lambda, t + 0.5, l), peak);
    }
}

TEST(ThesisMultilayer, IsZeroWhereTheLPlusOneBeamsCancel) {
    // sin((l+1)x) = 0 with sin x ≠ 0: x = kπ/(l+1), t = kλ/(2(l+1)), k not a multiple of l+1.
    const int l = 12;
    const double lambda = 520.0;
    for (int k : {1, 2, 6, 12, 14}) {
        const double t = k * lambda / (2.0 * (l + 1));
        EXPECT_NEAR(thesis_multilayer_reflectance(lambda, t, l), 0.0, 1e-20) << k;
    }
}

TEST(ThesisMultilayer, EffectiveThicknessIsTnAtNormalIncidenceAndFallsWithAngle) {
    const double t = 200.0, n = 1.56;
    EXPECT_DOUBLE_EQ(thesis_multilayer_effective_thickness_nm(t, n, 0.0), t * n);
    // At grazing incidence sin θ = 1: t (n² − 1)^½.
    EXPECT_NEAR(thesis_multilayer_effective_thickness_nm(t, n, pi / 2.0),
                t * std::sqrt(n * n - 1.0), 1e-12);
    double previous = t * n;
    for (double degrees = 1.0; degrees < 90.0; degrees += 1.0) {
        const double t_eff = thesis_multilayer_effective_thickness_nm(t, n, radians(degrees));
        EXPECT_LT(t_eff, previous) << degrees;
        previous = t_eff;
    }
}

TEST(ThesisMultilayer, SpectrumPeaksAtTwiceTheOpticalThickness) {
    // 2 t n = m λ: t = 160 nm, n = 1.5 gives 480 nm (m = 1); m = 2 is 240 nm, outside.
    ThesisMultilayerParameters stack;
    stack.n = 1.5;
    stack.periods = 8;
    const DenseSpectrum s = thesis_multilayer_spectrum(stack, 160.0);
    EXPECT_EQ(peak_wavelength_nm(s), 480.0);
    EXPECT_NEAR(s(480.0), 0.5 * 81.0, 1e-12);
}

// --- The Morpho wing: eq. 29 ------------------------------------------------------------------

TEST(Morpho, NormalIncidenceEffectiveThicknessIsD1PlusD2N) {
    const MorphoParameters wing;  // 150 nm, 50 nm, n = 1.56
    EXPECT_NEAR(morpho_effective_thickness_nm(wing, 0.0), 150.0 + 50.0 * 1.56, 1e-12);
    EXPECT_NEAR(morpho_effective_thickness_nm(wing, 0.0), 228.0, 1e-12);
}

TEST(Morpho, EffectiveThicknessFallsMonotonicallyWithAngle) {
    const MorphoParameters wing;
    double previous = morpho_effective_thickness_nm(wing, 0.0);
    for (double degrees = 0.5; degrees < 90.0; degrees += 0.5) {
        const double t_eff = morpho_effective_thickness_nm(wing, radians(degrees));
        EXPECT_LT(t_eff, previous) << degrees;
        previous = t_eff;
    }
}

TEST(Morpho, NormalIncidencePeakIsTheBlueFirstOrderAt456nm) {
    // 2 t_θ = m λ with t_θ = 228 nm: 456 nm (m = 1); m = 2 is 228 nm, outside 360-830 nm.
    const MorphoParameters wing;
    const DenseSpectrum s = morpho_spectrum(wing);
    EXPECT_EQ(peak_wavelength_nm(s), 456.0);
    EXPECT_NEAR(s(456.0), 0.5 * 13.0 * 13.0, 1e-9);
    const Xyz c = reflectance_to_xyz(s, illuminant_d65());
    EXPECT_GT(c.Z, c.X);
    EXPECT_GT(c.Z, c.Y);
}

TEST(Morpho, PeakMovesToShorterWavelengthsWithAngle) {
    const MorphoParameters wing;
    double previous = 456.0;
    for (double degrees : {10.0, 20.0, 30.0, 40.0}) {
        const double s = std::sin(radians(degrees));
        const double t_theta =
            150.0 * std::cos(radians(degrees)) + 50.0 * std::sqrt(1.56 * 1.56 - s * s);
        const double peak = peak_wavelength_nm(morpho_spectrum(wing, degrees));
        EXPECT_NEAR(peak, 2.0 * t_theta, 0.5) << degrees << "°";
        EXPECT_LT(peak, previous) << degrees << "°";
        previous = peak;
    }
}

TEST(Morpho, BlendOfTwoSamplesIsTheMeanOfTheThinnestAndThickestMullion) {
    const MorphoParameters wing;
    MorphoParameters thin = wing, thick = wing;
    thin.d2_nm = 50.0;
    thick.d2_nm = 150.0;
    const DenseSpectrum blend =
        morpho_blend_spectrum(wing, MorphoBlend{50.0, 150.0, 2, MorphoBlendThickness::d2}, 20.0);
    const DenseSpectrum a = morpho_spectrum(thin, 20.0), b = morpho_spectrum(thick, 20.0);
    for (int i = 0; i < dense_sample_count; ++i)
        EXPECT_NEAR(blend[i], 0.5 * (a[i] + b[i]), 1e-12 * (a[i] + b[i] + 1.0));
}

TEST(Morpho, DefaultBlendAveragesEveryWholeNanometreOfSpacingFrom50To150) {
    const MorphoParameters wing;
    const DenseSpectrum blend = morpho_blend_spectrum(wing, MorphoBlend{}, 0.0);
    for (double lambda : {400.0, 456.0, 600.0, 768.0}) {
        double sum = 0.0;
        for (int d1 = 50; d1 <= 150; ++d1)
            sum += thesis_multilayer_reflectance(lambda, d1 + 50.0 * 1.56, 12);
        EXPECT_NEAR(blend(lambda), sum / 101.0, 1e-12 * sum) << lambda;
    }
}

TEST(Morpho, DefaultBlendKeepsTheWingBlueAsInFigure9) {
    // The first-order poles 2(d₁ + 78) of d₁ = 50..150 nm lie in 256-456 nm: the wing reflects
    // most in the blue, so z̄ dominates: Z > X and Z > Y under D65.
    const Xyz c = reflectance_to_xyz(morpho_blend_spectrum(MorphoParameters{}, MorphoBlend{}), illuminant_d65());
    EXPECT_GT(c.Z, c.X);
    EXPECT_GT(c.Z, c.Y);
}

TEST(Morpho, BlendOverASingleThicknessIsThatWing) {
    MorphoParameters wing;
    wing.d1_nm = 80.0;
    const DenseSpectrum single = morpho_spectrum(wing, 35.0);
    const DenseSpectrum blend = morpho_blend_spectrum(wing, MorphoBlend{80.0, 80.0, 5}, 35.0);
    for (int i = 0; i < dense_sample_count; ++i)
        EXPECT_NEAR(blend[i], single[i], 1e-12 * (single[i] + 1.0));
}

TEST(Morpho, ChitinBlendSpreadsTheFirstOrderPeakFrom456To768nm) {
    // Each d₂ sample puts its pole 2(150 + 1.56 d₂) in 456-768 nm, worth ½·13² there. At 612 nm
    // (d₂ = 100) one of the 101 samples is at its pole and the others are ≥ 0.
    const DenseSpectrum blend = morpho_blend_spectrum(
        MorphoParameters{}, MorphoBlend{50.0, 150.0, 101, MorphoBlendThickness::d2});
    EXPECT_GE(blend(612.0), 0.5 * 169.0 / 101.0);
    EXPECT_GE(blend(768.0), 0.5 * 169.0 / 101.0);
}

TEST(Morpho, BlendCanVaryTheAirPathD1Instead) {
    const MorphoParameters wing;
    MorphoParameters narrow = wing, wide = wing;
    narrow.d1_nm = 50.0;
    wide.d1_nm = 150.0;
    MorphoBlend blend{50.0, 150.0, 2};
    blend.varies = MorphoBlendThickness::d1;
    const DenseSpectrum mean = morpho_blend_spectrum(wing, blend, 10.0);
    const DenseSpectrum a = morpho_spectrum(narrow, 10.0), b = morpho_spectrum(wide, 10.0);
    for (int i = 0; i < dense_sample_count; ++i)
        EXPECT_NEAR(mean[i], 0.5 * (a[i] + b[i]), 1e-12 * (a[i] + b[i] + 1.0));
}

TEST(MorphoTable, IsExactAtItsNodesAndLinearBetweenThem) {
    const DenseSpectrum d65 = illuminant_d65();
    const MorphoParameters wing;
    const MorphoTable table(wing, d65, Observer::cie1931_2deg, 2.0);
    for (double degrees : {0.0, 10.0, 36.0, 88.0}) {
        const Xyz direct = reflectance_to_xyz(morpho_spectrum(wing, degrees), d65);
        EXPECT_NEAR(table.at(degrees).X, direct.X, 1e-12 * direct.X);
        EXPECT_NEAR(table.at(degrees).Y, direct.Y, 1e-12 * direct.Y);
        EXPECT_NEAR(table.at(degrees).Z, direct.Z, 1e-12 * direct.Z);
        const Xyz next = table.at(degrees + 2.0);
        const Xyz mid = table.at(degrees + 1.0);
        const Xyz here = table.at(degrees);
        EXPECT_NEAR(mid.Y, 0.5 * (here.Y + next.Y), 1e-12 * (here.Y + next.Y));
    }
}

TEST(MorphoTable, BlendedTableHoldsTheColourOfTheBlendedSpectrum) {
    const DenseSpectrum d65 = illuminant_d65();
    const MorphoParameters wing;
    const MorphoBlend blend{50.0, 150.0, 11};
    const MorphoTable table(wing, d65, Observer::cie1931_2deg, 15.0, blend);
    for (double degrees : {0.0, 45.0}) {
        const Xyz direct = reflectance_to_xyz(morpho_blend_spectrum(wing, blend, degrees), d65);
        EXPECT_NEAR(table.at(degrees).Y, direct.Y, 1e-12 * direct.Y) << degrees;
        EXPECT_NEAR(table.at(degrees).Z, direct.Z, 1e-12 * direct.Z) << degrees;
    }
}

// --- Validation -------------------------------------------------------------------------------

TEST(ThesisModelsValidation, ErrorsNameTheParameterAndTheAllowedRange) {
    try {
        MorphoParameters wing;
        wing.d1_nm = -3.0;
        validate_morpho(wing);
        ADD_FAILURE() << "d1 = -3 nm accepted";
    } catch (const Error& e) {
        EXPECT_STREQ(e.what(), "morpho: d1 -3 nm must be finite and >= 0");
    }
}

TEST(ThesisModelsValidation, FilmParametersThicknessAndAngleAreChecked) {
    const ThesisFilmParameters ok;
    expect_error_naming([] { validate_thesis_film({0.0, 1.0, true, 1.0}); }, "n_film");
    expect_error_naming([] { validate_thesis_film({1.33, -1.0, true, 1.0}); }, "n_ambient");
    expect_error_naming([] { validate_thesis_film({1.33, 1.0, true, -0.5}); }, "K");
    expect_error_naming([&] { (void)thesis_film_spectrum(ok, -1.0); }, "thickness");
    expect_error_naming([&] { (void)thesis_film_spectrum(ok, std::nan("")); }, "thickness");
    expect_error_naming([&] { (void)thesis_film_spectrum(ok, 100.0, 90.0); }, "angle");
    expect_error_naming([&] { (void)thesis_film_spectrum(ok, 100.0, -1.0); }, "angle");
}

TEST(ThesisModelsValidation, MultilayerParametersAreChecked) {
    const ThesisMultilayerParameters ok;
    expect_error_naming([] { validate_thesis_multilayer({0.9, 12, 1.0}); }, "n");
    expect_error_naming([] { validate_thesis_multilayer({1.5, -1, 1.0}); }, "periods");
    expect_error_naming([] { validate_thesis_multilayer({1.5, 2'000'000, 1.0}); }, "periods");
    constexpr double inf = std::numeric_limits<double>::infinity();
    expect_error_naming([] { validate_thesis_multilayer({1.5, 12, inf}); }, "K");
    expect_error_naming([&] { (void)thesis_multilayer_spectrum(ok, -5.0); }, "thickness");
    expect_error_naming([&] { (void)thesis_multilayer_spectrum(ok, 100.0, 95.0); }, "angle");
}

TEST(ThesisModelsValidation, MorphoParametersAndBlendAreChecked) {
    expect_error_naming([] { validate_morpho({150.0, -1.0, 1.56, 12, 1.0}); }, "d2");
    expect_error_naming([] { validate_morpho({150.0, 50.0, 0.5, 12, 1.0}); }, "n");
    expect_error_naming([] { validate_morpho({150.0, 50.0, 1.56, -2, 1.0}); }, "periods");
    expect_error_naming([] { validate_morpho({150.0, 50.0, 1.56, 12, -1.0}); }, "K");
    expect_error_naming([] { (void)morpho_spectrum(MorphoParameters{}, 90.0); }, "angle");
    expect_error_naming([] { validate_morpho_blend({-1.0, 150.0, 101}); }, "min");
    expect_error_naming([] { validate_morpho_blend({100.0, 50.0, 101}); }, "max");
    expect_error_naming([] { validate_morpho_blend({50.0, 150.0, 1}); }, "samples");
}

TEST(ThesisModelsValidation, TableRangesAreChecked) {
    const DenseSpectrum d65 = illuminant_d65();
    expect_error_naming([&] { (void)ThesisFilmTable(true, 0.0, 1.0, d65); },
                        "max effective thickness");
    expect_error_naming([&] { (void)ThesisFilmTable(true, 1000.0, 0.0, d65); }, "step");
    expect_error_naming([&] { (void)ThesisFilmTable(true, 1000.0, 2000.0, d65); }, "step");
    expect_error_naming([&] { (void)ThesisFilmTable(true, 1e6, 1e-3, d65); }, "step");
    expect_error_naming([&] { (void)ThesisFilmTable(true, 1000.0, 1.0, DenseSpectrum()); },
                        "illuminant");
    expect_error_naming(
        [&] { (void)MorphoTable(MorphoParameters{}, d65, Observer::cie1931_2deg, 0.0); }, "step");
    expect_error_naming(
        [&] {
            (void)MorphoTable(MorphoParameters{}, d65, Observer::cie1931_2deg, 1.0,
                              MorphoBlend{50.0, 150.0, 0});
        },
        "samples");
}

// The closed form (Fejér kernel) against a midpoint-rule mean of eq. 25 with many samples, at
// angles, wavelengths and both varied thicknesses.
TEST(Morpho, ContinuousBlendEqualsTheMeanOverTheThicknessRange) {
    for (const auto varies : {MorphoBlendThickness::d1, MorphoBlendThickness::d2}) {
        const MorphoParameters wing;  // d1 150, d2 50, n 1.56, l 12, K 1
        const MorphoBlend blend{50.0, 150.0, 2, varies};
        for (const double theta : {0.0, 0.4, 1.0, 1.45}) {
            for (const double lambda : {380.0, 456.0, 512.5, 700.0}) {
                constexpr int n = 200000;
                MorphoParameters w = wing;
                double& varied = varies == MorphoBlendThickness::d1 ? w.d1_nm : w.d2_nm;
                double sum = 0.0;
                for (int i = 0; i < n; ++i) {
                    varied = 50.0 + 100.0 * (i + 0.5) / n;
                    sum += morpho_reflectance(w, lambda, theta);
                }
                const double expected = sum / n;
                EXPECT_NEAR(morpho_blend_reflectance_continuous(wing, blend, lambda, theta),
                            expected, 1e-6 * (1.0 + expected))
                    << "theta " << theta << " lambda " << lambda;
            }
        }
    }
}

TEST(Morpho, ContinuousBlendOfAnEmptyRangeIsTheWingItself) {
    MorphoParameters wing;
    wing.d1_nm = 120.0;
    const MorphoBlend blend{120.0, 120.0, 2, MorphoBlendThickness::d1};
    for (const double lambda : {400.0, 456.0, 600.0})
        EXPECT_DOUBLE_EQ(morpho_blend_reflectance_continuous(wing, blend, lambda, 0.3),
                         morpho_reflectance(wing, lambda, 0.3));
}

}  // namespace
}  // namespace irid
