#include <irid/error.h>
#include <irid/optics/material.h>
#include <irid/optics/multilayer.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <string>
#include <vector>

namespace irid {
namespace {

constexpr double pi = std::numbers::pi;
constexpr Polarization both_polarizations[] = {Polarization::s, Polarization::p};

double radians(double degrees) {
    return degrees * pi / 180.0;
}

Material medium(Complex n) {
    return Material::constant("test", n.real(), n.imag());
}

/// A stack of constant-index layers given as (index, thickness in nm).
FilmStack stack(double n0, const std::vector<std::pair<Complex, double>>& films, Complex ns) {
    std::vector<Layer> layers;
    for (const auto& [n, d] : films) layers.push_back({medium(n), d});
    return FilmStack(medium(n0), std::move(layers), medium(ns));
}

/// Normal-incidence reflectance of an interface, ((n1 - n2)/(n1 + n2))² in its complex form.
double normal_reflectance(Complex n1, Complex n2) {
    return std::norm((n1 - n2) / (n1 + n2));
}

// --- Snell's law in complex form -----------------------------------------------------------

TEST(ComplexSnell, PropagatingWaveInALosslessMediumHasARealCosine) {
    const double s = 1.0 * std::sin(radians(30.0));
    const Complex c = cos_theta(1.5, s);
    EXPECT_NEAR(c.real(), std::sqrt(1.0 - (s / 1.5) * (s / 1.5)), 1e-15);
    EXPECT_EQ(c.imag(), 0.0);
}

TEST(ComplexSnell, BeyondTheCriticalAngleTheWaveDecaysIntoTheRarerMedium) {
    // Glass to air at 60°: n cos θ = i sqrt(s² - 1) in air, decaying (Im > 0).
    const double s = 1.5 * std::sin(radians(60.0));
    const Complex q = 1.0 * cos_theta(1.0, s);
    EXPECT_NEAR(q.real(), 0.0, 1e-15);
    EXPECT_NEAR(q.imag(), std::sqrt(s * s - 1.0), 1e-15);
}

TEST(ComplexSnell, AbsorbingMediaGetTheDecayingRootOfSnellsLaw) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> n(0.05, 3.0), k(0.0, 6.0), s(0.0, 1.9);
    for (int i = 0; i < 1000; ++i) {
        const Complex index(n(rng), k(rng));
        const double invariant = s(rng);
        const Complex q = index * cos_theta(index, invariant);
        EXPECT_GE(q.imag(), 0.0);
        // n sin θ = s with sin² + cos² = 1.
        EXPECT_LT(std::abs(q * q - (index * index - invariant * invariant)), 1e-12);
    }
}

// --- One interface ---------------------------------------------------------------------------

TEST(Fresnel, NormalIncidenceReflectanceIsTheSquaredIndexContrast) {
    EXPECT_NEAR(std::norm(fresnel(1.0, 1.5, 0.0).r_s), 0.04, 1e-15);
    EXPECT_NEAR(stack(1.0, {}, 1.5).evaluate(550.0, 0.0, Polarization::unpolarized).R, 0.04, 1e-15);
    EXPECT_NEAR(stack(1.0, {}, 1.5).evaluate(550.0, 0.0, Polarization::unpolarized).T, 0.96, 1e-15);
    for (const auto& [n1, n2] : {std::pair{1.0, 1.33}, {1.33, 1.0}, {1.5, 2.4}, {1.0, 4.0}}) {
        const double expected = ((n1 - n2) / (n1 + n2)) * ((n1 - n2) / (n1 + n2));
        const FresnelCoefficients f = fresnel(n1, n2, 0.0);
        EXPECT_NEAR(std::norm(f.r_s), expected, 1e-15);
        // The tangential-field convention: r_p = r_s at normal incidence.
        EXPECT_NEAR(std::abs(f.r_p - f.r_s), 0.0, 1e-15);
        EXPECT_NEAR(std::abs(f.t_p - f.t_s), 0.0, 1e-15);
    }
}

TEST(Fresnel, AgreesWithBornAndWolfUpToTheStatedConventions) {
    // Born & Wolf §1.5.2: r⊥ = (n1 c1 - n2 c2)/(n1 c1 + n2 c2), r∥ = (n2 c1 - n1 c2)/(n2 c1 + n1
    // c2), t⊥ = 2 n1 c1/(n1 c1 + n2 c2), t∥ = 2 n1 c1/(n2 c1 + n1 c2) for full amplitudes.
    const double n1 = 1.2, n2 = 1.7;
    for (const double deg : {0.0, 15.0, 40.0, 70.0, 89.0}) {
        const double c1 = std::cos(radians(deg));
        const double c2 = std::sqrt(1.0 - std::pow(n1 * std::sin(radians(deg)) / n2, 2));
        const FresnelCoefficients f = fresnel(n1, n2, n1 * std::sin(radians(deg)));
        EXPECT_NEAR(f.r_s.real(), (n1 * c1 - n2 * c2) / (n1 * c1 + n2 * c2), 1e-13);
        EXPECT_NEAR(f.t_s.real(), 2 * n1 * c1 / (n1 * c1 + n2 * c2), 1e-13);
        EXPECT_NEAR(-f.r_p.real(), (n2 * c1 - n1 * c2) / (n2 * c1 + n1 * c2), 1e-13);
        EXPECT_NEAR(f.t_p.real() * c1 / c2, 2 * n1 * c1 / (n2 * c1 + n1 * c2), 1e-13);
    }
}

TEST(Fresnel, LosslessInterfaceConservesEnergy) {
    const double n1 = 1.0, n2 = 1.6;
    for (const double deg : {0.0, 30.0, 60.0, 85.0}) {
        const double s = n1 * std::sin(radians(deg));
        const Complex c1 = cos_theta(n1, s), c2 = cos_theta(n2, s);
        const FresnelCoefficients f = fresnel(n1, n2, s);
        // T = Re(η_t)/η_i |t|², η = n cos θ (s) and n / cos θ (p).
        EXPECT_NEAR(std::norm(f.r_s) + (n2 * c2).real() / (n1 * c1).real() * std::norm(f.t_s), 1.0,
                    1e-14);
        EXPECT_NEAR(std::norm(f.r_p) + (n2 / c2).real() / (n1 / c1).real() * std::norm(f.t_p), 1.0,
                    1e-14);
    }
}

TEST(Fresnel, BrewsterAngleExtinguishesTheReflectedP) {
    for (const auto& [n1, n2] : {std::pair{1.0, 1.5}, {1.0, 1.33}, {1.5, 1.0}, {1.33, 2.4}}) {
        const double brewster = std::atan(n2 / n1);
        const FilmStack bare = stack(n1, {}, n2);
        EXPECT_LT(bare.evaluate(550.0, brewster, Polarization::p).R, 1e-28) << n1 << " " << n2;
        EXPECT_LT(std::norm(fresnel(n1, n2, n1 * std::sin(brewster)).r_p), 1e-28);
        EXPECT_GT(bare.evaluate(550.0, brewster, Polarization::s).R, 0.01);
    }
}

TEST(Fresnel, GrazingIncidenceReflectsEverything) {
    // From air into n at cos θ → 0: r_s = (cos θ - q)/(cos θ + q) and
    // r_p = (q - n² cos θ)/(q + n² cos θ) with q = sqrt(n² - sin²θ), so to first order
    // 1 - R_s = 4 cos θ / sqrt(n² - 1) and 1 - R_p = 4 n² cos θ / sqrt(n² - 1).
    const double n = 1.5;
    const FilmStack bare = stack(1.0, {}, n);
    const double cos_grazing = 1e-7;
    const double grazing = std::acos(cos_grazing);
    const Optics s = bare.evaluate(550.0, grazing, Polarization::s);
    const Optics p = bare.evaluate(550.0, grazing, Polarization::p);
    EXPECT_NEAR((1.0 - s.R) / (4 * cos_grazing / std::sqrt(n * n - 1)), 1.0, 1e-5);
    EXPECT_NEAR((1.0 - p.R) / (4 * n * n * cos_grazing / std::sqrt(n * n - 1)), 1.0, 1e-5);
    EXPECT_NEAR(s.R + s.T, 1.0, 1e-12);
    EXPECT_NEAR(p.R + p.T, 1.0, 1e-12);
    // And R grows monotonically towards 1 for s.
    double previous = 0.0;
    for (double deg = 0.0; deg < 90.0; deg += 5.0) {
        const double r = bare.evaluate(550.0, radians(deg), Polarization::s).R;
        EXPECT_GT(r, previous);
        previous = r;
    }
}

TEST(Fresnel, BeyondTheCriticalAngleReflectionIsTotal) {
    // Glass (1.5) to air: critical angle asin(1/1.5) = 41.8°.
    const FilmStack glass_to_air = stack(1.5, {}, 1.0);
    for (const double deg : {45.0, 60.0, 80.0, 89.9}) {
        for (const Polarization pol : both_polarizations) {
            const Optics o = glass_to_air.evaluate(550.0, radians(deg), pol);
            EXPECT_NEAR(o.R, 1.0, 1e-14) << deg;
            EXPECT_EQ(o.T, 0.0) << deg;
        }
        const FresnelCoefficients f = fresnel(1.5, 1.0, 1.5 * std::sin(radians(deg)));
        EXPECT_NEAR(std::abs(f.r_s), 1.0, 1e-14);
        EXPECT_NEAR(std::abs(f.r_p), 1.0, 1e-14);
    }
}

TEST(Fresnel, AtTheCriticalAngleEverythingStaysFinite) {
    // cos θ = 0 in the air: the p admittance n / cos θ is infinite, R = 1 and T = 0 in the limit.
    const double critical = std::asin(1.0 / 1.5);
    const FilmStack glass_to_air = stack(1.5, {}, 1.0);
    const FilmStack with_films = stack(1.5, {{1.0, 100.0}, {1.2, 50.0}}, 1.0);
    for (const Polarization pol : both_polarizations) {
        for (const FilmStack* st : {&glass_to_air, &with_films}) {
            const Optics o = st->evaluate(550.0, critical, pol);
            EXPECT_NEAR(o.R, 1.0, 1e-6);
            EXPECT_NEAR(o.T, 0.0, 1e-6);
        }
    }
}

TEST(Fresnel, MetalAtNormalIncidenceReflectsByItsComplexIndex) {
    // R = ((n - 1)² + k²)/((n + 1)² + k²) from air; all the rest enters the metal (T = 1 - R).
    for (const Complex n : {Complex(0.2, 3.5), Complex(0.05, 3.093), Complex(1.5, 0.1)}) {
        const double expected = (std::pow(n.real() - 1, 2) + std::pow(n.imag(), 2)) /
                                (std::pow(n.real() + 1, 2) + std::pow(n.imag(), 2));
        const Optics o = stack(1.0, {}, n).evaluate(500.0, 0.0, Polarization::s);
        EXPECT_NEAR(o.R, expected, 1e-15);
        EXPECT_NEAR(o.T, 1.0 - expected, 1e-15);
    }
    const Material& silver = *find_material("silver");
    const Complex ag = silver.index(659.5);
    const FilmStack air_silver(*find_material("air"), {}, silver);
    EXPECT_NEAR(air_silver.evaluate(659.5, 0.0, Polarization::unpolarized).R,
                normal_reflectance(find_material("air")->index(659.5), ag), 1e-15);
    EXPECT_GT(air_silver.evaluate(659.5, 0.0, Polarization::unpolarized).R, 0.95);
}

// --- One film ----------------------------------------------------------------------------------

TEST(ThinFilm, ZeroThicknessFilmBetweenIdenticalMediaIsBlack) {
    for (const Complex film : {Complex(1.5, 0.0), Complex(2.4, 0.0), Complex(0.3, 2.5)}) {
        const FilmStack st = stack(1.33, {{film, 0.0}}, 1.33);
        for (const double deg : {0.0, 30.0, 60.0, 85.0}) {
            for (const Polarization pol : both_polarizations) {
                // Rounding leaves |r| ~ 1e-15, R ~ 1e-30.
                const Optics o = st.evaluate(550.0, radians(deg), pol);
                EXPECT_LT(o.R, 1e-28);
                EXPECT_NEAR(o.T, 1.0, 1e-14);
                const Optics airy = airy_film(1.33, film, 1.33, 0.0, 550.0, radians(deg), pol);
                EXPECT_LT(airy.R, 1e-28);
                EXPECT_NEAR(airy.T, 1.0, 1e-14);
            }
        }
    }
}

TEST(ThinFilm, FreeStandingFilmFollowsTheAiryFunction) {
    // Film between equal media: r12 = -r01, so R = F sin²β / (1 + F sin²β), F = 4 r01²/(1 - r01²)²
    // (Born & Wolf §7.6.1). It vanishes as β² when the film thins: a thin soap film is black.
    const double n0 = 1.0, n1 = 1.33, lambda = 550.0;
    for (const double deg : {0.0, 45.0, 75.0}) {
        const double s = n0 * std::sin(radians(deg));
        const FresnelCoefficients f = fresnel(n0, n1, s);
        for (const Polarization pol : both_polarizations) {
            const double r01 = (pol == Polarization::s ? f.r_s : f.r_p).real();
            const double big_f = 4 * r01 * r01 / std::pow(1 - r01 * r01, 2);
            for (const double d : {1e-3, 0.1, 1.0, 10.0, 123.4, 1000.0}) {
                const double beta = 2 * pi * n1 * d * cos_theta(n1, s).real() / lambda;
                const double sin2 = std::sin(beta) * std::sin(beta);
                const double expected = big_f * sin2 / (1 + big_f * sin2);
                const Optics o = stack(n0, {{n1, d}}, n0).evaluate(lambda, radians(deg), pol);
                EXPECT_NEAR(o.R, expected, 1e-12 * std::max(expected, 1e-6)) << deg << " " << d;
                EXPECT_NEAR(o.T, 1 - expected, 1e-12);
            }
        }
    }
}

TEST(ThinFilm, ZeroThicknessFilmEqualsTheBareInterface) {
    for (const Complex film : {Complex(2.0, 0.0), Complex(0.2, 3.0)}) {
        const FilmStack with_film = stack(1.0, {{film, 0.0}}, 1.5);
        const FilmStack bare = stack(1.0, {}, 1.5);
        for (const double deg : {0.0, 40.0, 80.0}) {
            for (const Polarization pol : both_polarizations) {
                const Optics a = with_film.evaluate(480.0, radians(deg), pol);
                const Optics b = bare.evaluate(480.0, radians(deg), pol);
                EXPECT_NEAR(a.R, b.R, 1e-15);
                EXPECT_NEAR(a.T, b.T, 1e-15);
            }
        }
    }
}

TEST(ThinFilm, FilmWithTheIndexOfItsSurroundingsIsInvisible) {
    for (const double d : {10.0, 250.0, 1234.5}) {
        for (const Polarization pol : both_polarizations) {
            const Optics same = stack(1.33, {{1.33, d}}, 1.33).evaluate(510.0, 0.4, pol);
            EXPECT_LT(same.R, 1e-28);
            EXPECT_NEAR(same.T, 1.0, 1e-14);
            // Matching the ambient, the film only moves the interface with the substrate.
            const Optics over_glass = stack(1.0, {{1.0, d}}, 1.5).evaluate(510.0, 0.4, pol);
            const Optics bare = stack(1.0, {}, 1.5).evaluate(510.0, 0.4, pol);
            EXPECT_NEAR(over_glass.R, bare.R, 1e-14);
            EXPECT_NEAR(over_glass.T, bare.T, 1e-14);
        }
    }
}

TEST(ThinFilm, AiryAndTransferMatrixAgreeForOneFilm) {
    std::mt19937 rng(1990);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const auto random_index = [&]() {
        switch (static_cast<int>(unit(rng) * 3.0)) {
            case 0: return Complex(1.0 + 2.0 * unit(rng), 0.0);                // dielectric
            case 1: return Complex(1.0 + 2.0 * unit(rng), 0.5 * unit(rng));    // lossy
            default: return Complex(0.05 + unit(rng), 1.0 + 5.0 * unit(rng));  // metal
        }
    };
    for (int i = 0; i < 3000; ++i) {
        const double n0 = 1.0 + 0.8 * unit(rng);
        const Complex n1 = random_index(), n2 = random_index();
        const double d = 2000.0 * unit(rng);
        const double lambda = 360.0 + 470.0 * unit(rng);
        const double angle = radians(89.0 * unit(rng));
        const FilmStack st = stack(n0, {{n1, d}}, n2);
        for (const Polarization pol :
             {Polarization::s, Polarization::p, Polarization::unpolarized}) {
            const Optics tmm = st.evaluate(lambda, angle, pol);
            const Optics airy = airy_film(n0, n1, n2, d, lambda, angle, pol);
            EXPECT_NEAR(tmm.R, airy.R, 1e-12) << n0 << " " << n1 << " " << n2 << " " << d;
            EXPECT_NEAR(tmm.T, airy.T, 1e-12) << n0 << " " << n1 << " " << n2 << " " << d;
        }
    }
}

// --- Quarter- and half-wave layers -------------------------------------------------------------

TEST(QuarterWave, SingleLayerReflectsByTheClosedForm) {
    // At λ0, normal incidence: R = ((n0 ns - n1²)/(n0 ns + n1²))² (Macleod ch. 3).
    const double lambda0 = 550.0, n0 = 1.0, ns = 1.52;
    for (const double n1 : {1.38, 1.8, 2.35}) {
        const double expected = std::pow((n0 * ns - n1 * n1) / (n0 * ns + n1 * n1), 2);
        const Optics o = stack(n0, {{n1, lambda0 / (4 * n1)}}, ns)
                             .evaluate(lambda0, 0.0, Polarization::unpolarized);
        EXPECT_NEAR(o.R, expected, 1e-12) << n1;
        EXPECT_NEAR(o.T, 1 - expected, 1e-12) << n1;
    }
    // The ideal antireflection coating n1 = sqrt(n0 ns) reflects nothing.
    const double ideal = std::sqrt(n0 * ns);
    EXPECT_LT(
        stack(n0, {{ideal, lambda0 / (4 * ideal)}}, ns).evaluate(lambda0, 0.0, Polarization::s).R,
        1e-28);
}

TEST(QuarterWave, HighLowStackMatchesItsClosedForm) {
    // (HL)^N H on a substrate at λ0, normal incidence: each quarter-wave layer turns the admittance
    // Y beneath it into n²/Y, so Y = (nH/nL)^{2N} nH²/ns and R = ((n0 - Y)/(n0 + Y))² (Macleod
    // ch. 5, quarter-wave stacks).
    const double lambda0 = 600.0, n0 = 1.0, ns = 1.52, nh = 2.35, nl = 1.46;
    for (int periods = 0; periods <= 8; ++periods) {
        std::vector<std::pair<Complex, double>> films;
        for (int i = 0; i < periods; ++i) {
            films.push_back({nh, lambda0 / (4 * nh)});
            films.push_back({nl, lambda0 / (4 * nl)});
        }
        films.push_back({nh, lambda0 / (4 * nh)});
        const double y = std::pow(nh / nl, 2 * periods) * nh * nh / ns;
        const double expected = std::pow((n0 - y) / (n0 + y), 2);
        const Optics o = stack(n0, films, ns).evaluate(lambda0, 0.0, Polarization::unpolarized);
        EXPECT_NEAR(o.R, expected, 1e-12) << periods;
        EXPECT_NEAR(o.T, 1 - expected, 1e-12) << periods;
    }
}

TEST(HalfWave, LayerIsAbsentAtItsDesignWavelength) {
    // δ = π: the characteristic matrix is -1, so the stack reflects like the bare substrate, at
    // normal and oblique incidence (d = λ0 / (2 n1 cos θ1)).
    const double lambda0 = 500.0, n0 = 1.0, n1 = 2.1, ns = 1.52;
    for (const double deg : {0.0, 35.0, 70.0}) {
        const double s = n0 * std::sin(radians(deg));
        const double d = lambda0 / (2 * n1 * cos_theta(n1, s).real());
        for (const Polarization pol : both_polarizations) {
            const Optics with_layer = stack(n0, {{n1, d}}, ns).evaluate(lambda0, radians(deg), pol);
            const Optics bare = stack(n0, {}, ns).evaluate(lambda0, radians(deg), pol);
            EXPECT_NEAR(with_layer.R, bare.R, 1e-12) << deg;
            EXPECT_NEAR(with_layer.T, bare.T, 1e-12) << deg;
        }
    }
    EXPECT_NEAR(stack(n0, {{n1, lambda0 / (2 * n1)}}, ns).evaluate(lambda0, 0.0, Polarization::s).R,
                normal_reflectance(n0, ns), 1e-12);
}

// --- Energy and reciprocity --------------------------------------------------------------------

/// Random lossless layers: n in [1.2, 2.6], d in [0, 600] nm.
std::vector<std::pair<Complex, double>> random_lossless_films(std::mt19937& rng, int count) {
    std::uniform_real_distribution<double> n(1.2, 2.6), d(0.0, 600.0);
    std::vector<std::pair<Complex, double>> films;
    for (int i = 0; i < count; ++i) films.push_back({n(rng), d(rng)});
    return films;
}

TEST(Energy, LosslessStacksConserveEnergy) {
    std::mt19937 rng(42);
    std::uniform_real_distribution<double> n0(1.0, 1.7), ns(1.0, 2.0), lambda(360.0, 830.0);
    std::uniform_int_distribution<int> count(1, 8);
    for (int i = 0; i < 300; ++i) {
        const FilmStack st = stack(n0(rng), random_lossless_films(rng, count(rng)), ns(rng));
        for (const double deg : {0.0, 20.0, 45.0, 70.0, 85.0}) {
            for (const Polarization pol : both_polarizations) {
                const Optics o = st.evaluate(lambda(rng), radians(deg), pol);
                EXPECT_NEAR(o.R + o.T, 1.0, 1e-12);
                EXPECT_GE(o.R, 0.0);
                EXPECT_GE(o.T, 0.0);
            }
        }
    }
}

TEST(Energy, ReversingALosslessStackBetweenEqualMediaKeepsR) {
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> n0(1.0, 1.6), lambda(360.0, 830.0);
    std::uniform_int_distribution<int> count(1, 8);
    for (int i = 0; i < 300; ++i) {
        const double outside = n0(rng);
        auto films = random_lossless_films(rng, count(rng));
        const FilmStack forward = stack(outside, films, outside);
        std::reverse(films.begin(), films.end());
        const FilmStack backward = stack(outside, films, outside);
        const double l = lambda(rng);
        for (const double deg : {0.0, 30.0, 60.0, 80.0}) {
            for (const Polarization pol : both_polarizations) {
                const Optics a = forward.evaluate(l, radians(deg), pol);
                const Optics b = backward.evaluate(l, radians(deg), pol);
                EXPECT_NEAR(a.R, b.R, 1e-12);
                EXPECT_NEAR(a.T, b.T, 1e-12);
            }
        }
    }
}

TEST(Energy, AbsorbingStackReflectsAndTransmitsLessThanItReceives) {
    const Material& silver = *find_material("silver");
    const FilmStack st(Material::constant("glass", 1.52),
                       {{Material::constant("oxide", 1.46), 80.0},
                        {silver, 20.0},
                        {Material::constant("oxide", 1.46), 80.0}},
                       Material::constant("glass", 1.52));
    for (int lambda = 380; lambda <= 780; lambda += 20) {
        for (const Polarization pol : both_polarizations) {
            const Optics o = st.evaluate(lambda, radians(30.0), pol);
            // 20 nm of silver absorbs about 1 % (red) to 4 % (violet) here.
            EXPECT_LT(o.R + o.T, 1.0 - 1e-3) << lambda;
            EXPECT_GT(o.R, 0.0);
            EXPECT_GT(o.T, 0.0);
        }
    }
    // Random absorbing stacks never create energy.
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> k(0.0, 4.0), d(0.0, 300.0), n(0.1, 2.5);
    for (int i = 0; i < 300; ++i) {
        const FilmStack lossy =
            stack(1.0, {{Complex(n(rng), k(rng)), d(rng)}, {Complex(n(rng), k(rng)), d(rng)}},
                  Complex(n(rng), 0.0));
        for (const Polarization pol : both_polarizations) {
            const Optics o = lossy.evaluate(550.0, radians(50.0), pol);
            EXPECT_LE(o.R + o.T, 1.0 + 1e-12);
            EXPECT_GE(o.T, 0.0);
        }
    }
}

TEST(Energy, UnpolarizedLightIsTheMeanOfSAndP) {
    const FilmStack st = stack(1.0, {{2.0, 120.0}, {1.4, 90.0}}, 1.5);
    const Optics s = st.evaluate(520.0, radians(55.0), Polarization::s);
    const Optics p = st.evaluate(520.0, radians(55.0), Polarization::p);
    const Optics u = st.evaluate(520.0, radians(55.0), Polarization::unpolarized);
    EXPECT_DOUBLE_EQ(u.R, 0.5 * (s.R + p.R));
    EXPECT_DOUBLE_EQ(u.T, 0.5 * (s.T + p.T));
    EXPECT_GT(std::abs(s.R - p.R), 0.01);
}

// --- Tunnelling and opaque layers --------------------------------------------------------------

TEST(Tunnelling, AirGapBeyondTheCriticalAngleLeaksLessAsItWidens) {
    // Frustrated total reflection between two glass blocks at 60°: T falls roughly as
    // exp(-4π d sqrt(s² - 1) / λ) while R + T = 1; a wide gap is total reflection.
    const double angle = radians(60.0);
    EXPECT_NEAR(stack(1.5, {{1.0, 0.0}}, 1.5).evaluate(550.0, angle, Polarization::s).T, 1.0,
                1e-15);
    double previous = 1.0;
    for (const double gap : {50.0, 100.0, 200.0, 400.0}) {
        const Optics o = stack(1.5, {{1.0, gap}}, 1.5).evaluate(550.0, angle, Polarization::s);
        EXPECT_LT(o.T, previous);
        EXPECT_NEAR(o.R + o.T, 1.0, 1e-12);
        previous = o.T;
    }
    for (const double gap : {5e4, 1e7}) {
        const Optics o = stack(1.5, {{1.0, gap}}, 1.5).evaluate(550.0, angle, Polarization::p);
        EXPECT_NEAR(o.R, 1.0, 1e-12) << gap;
        EXPECT_EQ(o.T, 0.0) << gap;
    }
}

TEST(Tunnelling, ThickMetalLayerActsAsTheSubstrate) {
    const Complex metal(0.05, 3.5);
    const double expected = normal_reflectance(1.0, metal);
    for (const double d : {5e3, 1e6}) {
        const Optics o = stack(1.0, {{metal, d}}, 1.5).evaluate(550.0, 0.0, Polarization::s);
        EXPECT_NEAR(o.R, expected, 1e-14) << d;
        EXPECT_EQ(o.T, 0.0) << d;
    }
}

// --- Validation --------------------------------------------------------------------------------

TEST(FilmStackValidation, RejectsNegativeOrNonFiniteThicknessNamingTheLayer) {
    try {
        (void)stack(1.0, {{1.5, 100.0}, {1.4, -5.0}}, 1.5);
        FAIL() << "a negative thickness was accepted";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("layer 2 thickness -5 nm must be >= 0"),
                  std::string::npos)
            << e.what();
    }
    EXPECT_THROW((void)stack(1.0, {{1.5, std::nan("")}}, 1.5), Error);
    EXPECT_THROW((void)stack(1.0, {{1.5, std::numeric_limits<double>::infinity()}}, 1.5), Error);
    EXPECT_NO_THROW((void)stack(1.0, {{1.5, 0.0}}, 1.5));
}

TEST(FilmStackValidation, RejectsAnAbsorbingAmbient) {
    EXPECT_THROW(FilmStack(*find_material("silver"), {}, *find_material("air")), Error);
    EXPECT_THROW(FilmStack(Material::constant("lossy", 1.5, 0.01), {}, medium(1.0)), Error);
    EXPECT_NO_THROW(FilmStack(*find_material("water"), {}, *find_material("silver")));
}

TEST(FilmStackValidation, AnglesOfIncidenceMustBeInZeroToHalfPi) {
    EXPECT_NO_THROW(check_incidence_angle(0.0));
    EXPECT_NO_THROW(check_incidence_angle(1.5));
    for (const double bad : {-0.1, pi / 2.0, 2.0, std::nan("")}) {
        EXPECT_THROW(check_incidence_angle(bad), Error) << bad;
    }
}

}  // namespace
}  // namespace irid
