// The Preetham–Shirley–Smits daylight sky (irid/render/sky.h): the Perez function's closed form
// at the zenith, the zenith formulas at values worked out by hand from the paper's formulas, the
// zenith normalisation, symmetry about the sun's vertical plane, the circumsolar brightening,
// continuity at the horizon, turbidity's whitening of the sky, the daylight spectrum's
// chromaticity round trip, and the sun's attenuation.
#include <irid/color/illuminant.h>
#include <irid/color/observer.h>
#include <irid/error.h>
#include <irid/render/render.h>
#include <irid/render/scene.h>
#include <irid/render/sky.h>

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

namespace irid::render {
namespace {

constexpr double pi = std::numbers::pi;

std::array<double, 3> direction(double elevation_deg, double azimuth_deg) {
    const double e = elevation_deg * pi / 180, a = azimuth_deg * pi / 180;
    return {std::cos(e) * std::cos(a), std::sin(e), std::cos(e) * std::sin(a)};
}

// At the zenith (cos θ = 1) F = (1 + A e^B)(1 + C e^{Dγ} + E cos² γ), whatever the coefficients.
TEST(PreethamSky, PerezFunctionAtTheZenithIsItsClosedForm) {
    const PerezCoefficients p{-1.1, -0.32, 10.0, -3.0, 0.45};
    for (const double g : {0.0, 0.4, 1.2, 2.5}) {
        const double expect =
            (1 + p.a * std::exp(p.b)) * (1 + p.c * std::exp(p.d * g) + p.e * std::cos(g) * std::cos(g));
        EXPECT_NEAR(perez(p, 1.0, g), expect, 1e-12 * std::abs(expect));
    }
    // At the horizon e^{B / cos θ} → 0 for B < 0: the first factor is 1.
    EXPECT_NEAR(perez(p, 0.0, 0.3), 1 + p.c * std::exp(p.d * 0.3) + p.e * std::cos(0.3) * std::cos(0.3),
                1e-12);
}

// T = 2, θs = 0 by hand from Preetham 1999 Appendix A.2:
//   χ = (4/9 − 2/120) π = 0.4277778 π = 1.3439035, tan χ = 4.3314759,
//   Y_z = (4.0453·2 − 4.9710)·4.3314759 − 0.2155·2 + 2.4192 = 3.1196·4.3314759 + 1.9882 = 15.5007;
//   x_z = (T², T, 1) M_x (0, 0, 0, 1)ᵀ = 0·4 + 0.00394·2 + 0.25886 = 0.26674;
//   y_z = 0·4 + 0.00516·2 + 0.26688 = 0.27720.
TEST(PreethamSky, ZenithFormulasAtAValueWorkedByHand) {
    EXPECT_NEAR(preetham_zenith_luminance(2.0, 0.0), 15.5007, 1e-4);
    const Xy z = preetham_zenith_chromaticity(2.0, 0.0);
    EXPECT_NEAR(z.x, 0.26674, 1e-12);
    EXPECT_NEAR(z.y, 0.27720, 1e-12);
    // The coefficient matrices at T = 2: A_Y = 0.1787·2 − 1.4630 = −1.1056.
    EXPECT_NEAR(preetham_coefficients(2.0).Y.a, -1.1056, 1e-12);
    EXPECT_NEAR(preetham_coefficients(2.0).y.d, -0.0441 * 2 - 1.6537, 1e-12);
}

// The distribution is normalised at the zenith: there the sky has exactly the zenith values.
TEST(PreethamSky, ZenithRatioIsOneAtTheZenith) {
    for (const double t : {2.0, 4.5, 10.0}) {
        for (const double elev : {5.0, 30.0, 60.0, 89.0}) {
            const PreethamSky sky(t, direction(elev, 40));
            const Xyy c = sky.xyy({0, 1, 0});
            const Xy z = preetham_zenith_chromaticity(t, sky.sun_zenith());
            EXPECT_NEAR(c.Y, preetham_zenith_luminance(t, sky.sun_zenith()), 1e-12 * c.Y);
            EXPECT_NEAR(c.x, z.x, 1e-14);
            EXPECT_NEAR(c.y, z.y, 1e-14);
            EXPECT_NEAR(sky.sun_zenith(), (90 - elev) * pi / 180, 1e-12);
        }
    }
}

TEST(PreethamSky, SymmetricAboutTheSunsVerticalPlane) {
    const double sun_azimuth = 35;
    const PreethamSky sky(3.0, direction(40, sun_azimuth));
    for (const double elev : {2.0, 20.0, 50.0}) {
        for (const double off : {10.0, 60.0, 135.0}) {
            const Xyy a = sky.xyy(direction(elev, sun_azimuth + off));
            const Xyy b = sky.xyy(direction(elev, sun_azimuth - off));
            EXPECT_NEAR(a.Y, b.Y, 1e-9 * a.Y);
            EXPECT_NEAR(a.x, b.x, 1e-12);
            EXPECT_NEAR(a.y, b.y, 1e-12);
        }
    }
}

// At a fixed elevation the sky brightens towards the sun (the circumsolar term C e^{Dγ}, D < 0).
TEST(PreethamSky, BrighterTowardsTheSun) {
    for (const double t : {2.0, 3.0, 6.0, 10.0}) {
        const PreethamSky sky(t, direction(35, 0));
        double previous = 0;
        for (double off = 90; off >= 0; off -= 5) {
            const double y = sky.xyy(direction(35, off)).Y;
            EXPECT_GT(y, previous) << "T " << t << " azimuth off the sun " << off;
            previous = y;
        }
    }
}

// Approaching the horizon from above the sky converges (no 1/cos θ blow-up), and directions
// below it are taken at it.
TEST(PreethamSky, ContinuousAtTheHorizon) {
    const PreethamSky sky(4.0, direction(25, 80));
    for (const double az : {0.0, 80.0, 200.0}) {
        const Xyy at = sky.xyy(direction(0, az));
        const Xyy near = sky.xyy(direction(0.01, az));
        const Xyy below = sky.xyy(direction(-5, az));
        EXPECT_TRUE(std::isfinite(at.Y) && at.Y > 0);
        EXPECT_NEAR(near.Y, at.Y, 1e-3 * at.Y);
        EXPECT_NEAR(near.x, at.x, 1e-4);
        EXPECT_NEAR(below.Y, at.Y, 1e-12 * at.Y);
    }
}

// Preetham 1999: a hazier atmosphere gives a whiter sky. The zenith's chromaticity moves
// towards the white point (D65) as the turbidity rises, at every sun elevation.
TEST(PreethamSky, HigherTurbidityGivesAWhiterSky) {
    const Xy white{0.3127, 0.3290};
    for (const double theta_s : {0.0, 0.5, 1.0, 1.4}) {
        double previous = 1;
        for (double t = 2; t <= 10; t += 1) {
            const Xy z = preetham_zenith_chromaticity(t, theta_s);
            const double d = std::hypot(z.x - white.x, z.y - white.y);
            EXPECT_LT(d, previous) << "T " << t << " θs " << theta_s;
            previous = d;
        }
    }
}

// The sky's chromaticity → a CIE daylight spectrum (S0 + M1 S1 + M2 S2) → its chromaticity.
TEST(PreethamSky, DaylightSpectrumKeepsTheSkysChromaticity) {
    for (const double t : {2.0, 3.0, 6.0, 10.0}) {
        const PreethamSky sky(t, direction(30, 10));
        for (const double elev : {1.0, 15.0, 45.0, 90.0}) {
            for (const double az : {0.0, 30.0, 100.0, 180.0}) {
                const Xyy c = sky.xyy(direction(elev, az));
                const DenseSpectrum s = daylight_from_chromaticity({c.x, c.y});
                const Xyz xyz = emission_to_xyz_relative(s);
                const double sum = xyz.X + xyz.Y + xyz.Z;
                EXPECT_NEAR(xyz.X / sum, c.x, 1e-3) << t << " " << elev << " " << az;
                EXPECT_NEAR(xyz.Y / sum, c.y, 1e-3) << t << " " << elev << " " << az;
            }
        }
    }
}

// The sun through the atmosphere. At θs = 0 (m = 1/(1 + 0.15·93.885^−1.253) = 0.999494) and
// T = 2 at 550 nm, by hand: τ_R = exp(−0.008735·0.55^−4.08·m) = 0.904762,
// τ_a = exp(−(0.04608·2 − 0.04586)·0.55^−1.3·m) = 0.904234, τ_o = exp(−0.085·0.35·m) = 0.970703,
// no mixed-gas or water absorption there: 0.794147 of the table's 25503.8.
TEST(PreethamSky, SunRadianceIsTheSolarTableAttenuated) {
    const DenseSpectrum s = preetham_sun_radiance(2.0, 0.0);
    EXPECT_NEAR(s[550 - lambda_min_nm], 25503.8 * 0.794147, 25503.8 * 2e-6);
    // Lower and hazier suns are redder: x of the sun's chromaticity grows.
    auto x_of = [&](double t, double theta) {
        const Xyz c = emission_to_xyz_relative(preetham_sun_radiance(t, theta));
        return c.X / (c.X + c.Y + c.Z);
    };
    EXPECT_LT(x_of(3, 0.2), x_of(3, 1.2));
    EXPECT_LT(x_of(3, 1.2), x_of(3, 1.5));
    EXPECT_LT(x_of(2, 1.0), x_of(8, 1.0));
    EXPECT_THROW((void)preetham_sun_radiance(3, 1.7), Error);
}

// The rendered sky: a narrow view of the sky alone shows the model's luminance (times
// light.sky_scale) and, within the daylight spectrum's 1e-3, its chromaticity — and the same XYZ
// on both colour paths, which carry the same daylight spectrum (as RGB or per nanometre).
TEST(PreethamSky, RenderedSkyIsTheModelOnBothColourPaths) {
    const std::vector<std::string> set = {
        "image.width=8",           "image.height=6",           "image.spp=1",
        "camera.eye=[0,0,30]",     "camera.look_at=[0,10,50]", "camera.fov_deg=1",
        "light.sky=preetham",      "light.turbidity=3.5",      "light.sky_scale=0.2",
        "render.exposure=1"};
    Xyz xyz[2];
    int k = 0;
    for (const std::string path : {"table", "spectral"}) {
        std::vector<std::string> s = set;
        s.push_back("render.path=" + path);
        const Scene scene = load_scene("soap-bubbles", s);
        const RenderResult r = render(scene);
        const std::size_t centre = 3 * 8 + 4;
        xyz[k++] = {r.xyz.pixels[3 * centre], r.xyz.pixels[3 * centre + 1], r.xyz.pixels[3 * centre + 2]};
    }
    const Scene scene = load_scene("soap-bubbles", set);
    const PreethamSky sky(3.5, scene.light.sun_direction);
    const double len = std::hypot(10.0, 20.0);
    const Xyy model = sky.xyy({0, 10 / len, 20 / len});
    for (const Xyz& c : xyz) {
        // The pixel spans 1/8° of a sky whose luminance changes slowly there; float samples.
        EXPECT_NEAR(c.Y, 0.2 * model.Y, 2e-3 * c.Y);
        EXPECT_NEAR(c.X / (c.X + c.Y + c.Z), model.x, 1e-3);
        EXPECT_NEAR(c.Y / (c.X + c.Y + c.Z), model.y, 1e-3);
    }
    EXPECT_NEAR(xyz[0].X, xyz[1].X, 1e-5 * xyz[0].Y);
    EXPECT_NEAR(xyz[0].Y, xyz[1].Y, 1e-5 * xyz[0].Y);
    EXPECT_NEAR(xyz[0].Z, xyz[1].Z, 1e-5 * xyz[0].Y);
}

TEST(PreethamSky, RefusesOutOfRange) {
    EXPECT_THROW(PreethamSky(1.5, {0, 1, 0}), Error);
    EXPECT_THROW(PreethamSky(11, {0, 1, 0}), Error);
    EXPECT_THROW(PreethamSky(3, {1, -0.1, 0}), Error);
    EXPECT_THROW(PreethamSky(3, {0, 0, 0}), Error);
    EXPECT_NO_THROW(PreethamSky(3, {1, 0.01, 0}));
}

}  // namespace
}  // namespace irid::render
