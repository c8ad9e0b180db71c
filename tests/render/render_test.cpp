// The renderer end to end: closed forms (a lossless film in a uniform white world is invisible;
// a flat film seen from above has the exact film's colour), determinism, the two colour paths
// against each other, and the thin-film anti-aliasing.
#include "carriers.h"
#include "film_table.h"
#include "world.h"

#include <irid/color/difference.h>
#include <irid/color/illuminant.h>
#include <irid/color/spaces.h>
#include <irid/error.h>
#include <irid/io/image.h>
#include <irid/optics/film_color.h>
#include <irid/optics/material.h>
#include <irid/render/render.h>
#include <irid/render/scene.h>

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>
#include <vector>

namespace irid::render {
namespace {

std::vector<std::string> small(int w, int h, int spp) {
    return {"image.width=" + std::to_string(w), "image.height=" + std::to_string(h),
            "image.spp=" + std::to_string(spp)};
}

std::vector<std::string> operator+(std::vector<std::string> a, const std::vector<std::string>& b) {
    a.insert(a.end(), b.begin(), b.end());
    return a;
}

RenderResult render_with(const std::string& scene, const std::vector<std::string>& set,
                         int threads = 0) {
    RenderOptions o;
    o.threads = threads;
    return render(load_scene(scene, set), o);
}

// A lossless film has R + T = 1 at every wavelength: in a world of uniform white light, with
// the floor as white as the sky, the bubbles must vanish — on both colour paths, with either
// optics.
TEST(Render, LosslessBubblesInAUniformWhiteWorldAreInvisible) {
    const Xyz white = Colorimeter().white();  // D65, Y = 1
    for (const std::string path : {"table", "spectral", "fourier"}) {
        for (const std::string optics : {"exact", "thesis"}) {
            if (path == "fourier" && optics == "thesis") continue;  // the exact film only
            const RenderResult r = render_with(
                "soap-bubbles",
                small(40, 30, 1) + std::vector<std::string>{
                                       "render.path=" + path, "render.optics=" + optics,
                                       "light.sky=gradient", "light.sun_intensity=0", "light.sky_zenith=[1,1,1]",
                                       "light.sky_horizon=[1,1,1]", "light.ground=[1,1,1]",
                                       "soap.floor_albedo=[1,1,1]", "soap.floor_albedo_alt=[1,1,1]",
                                       "render.max_depth=32"});
            double worst = 0;
            for (std::size_t i = 0; i < r.xyz.pixel_count(); ++i) {
                worst = std::max({worst, std::abs(r.xyz.pixels[3 * i] - white.X),
                                  std::abs(r.xyz.pixels[3 * i + 1] - white.Y),
                                  std::abs(r.xyz.pixels[3 * i + 2] - white.Z)});
            }
            // Both models keep R + T = 1 by construction (T = 1 − R); what is left is float
            // storage of the samples.
            EXPECT_LT(worst, 1e-5) << path << " " << optics;
        }
    }
}

// Seen from straight above through a narrow field, a flat oil film of constant thickness under
// a uniform white sky, on black pavement, shows exactly the film's colour at normal incidence.
TEST(Render, FlatFilmSeenFromAboveHasTheExactFilmColour) {
    const SingleFilm film{*find_material("air"), *find_material("mineral-oil"),
                          *find_material("water")};
    const Colorimeter colorimeter;
    const PreparedFilm prepared(film, 0.0);
    for (const double t : {150.0, 320.0, 610.0}) {
        const Lab expected = colorimeter.lab(prepared.color(t, colorimeter).xyz);
        for (const std::string path : {"table", "spectral", "fourier"}) {
            const RenderResult r = render_with(
                "oil-slick",
                small(16, 12, 1) +
                    std::vector<std::string>{
                        "render.path=" + path, "render.optics=exact", "render.antialias=none",
                        "render.exposure=1",
                        "oil.k1=0", "oil.min_thickness_nm=0",
                        "oil.max_thickness_nm=" + std::to_string(t), "pavement.bump_height=0",
                        "pavement.fine_height=0", "pavement.albedo=[0,0,0]",
                        "light.sky=gradient", "light.sun_intensity=0", "light.sky_zenith=[1,1,1]",
                        "light.sky_horizon=[1,1,1]", "camera.eye=[0,5,0]",
                        "camera.look_at=[0,0,0]", "camera.up=[0,0,-1]", "camera.fov_deg=2"});
            for (std::size_t i = 0; i < r.xyz.pixel_count(); ++i) {
                const Lab got = colorimeter.lab(
                    {r.xyz.pixels[3 * i], r.xyz.pixels[3 * i + 1], r.xyz.pixels[3 * i + 2]});
                ASSERT_LT(delta_e_2000(got, expected), 0.05) << path << " t " << t << " pixel " << i;
            }
        }
    }
}

// The rough pavement's sun glint spreads the sun's disc without creating or losing light: the
// lobe integrated over the sphere is the disc's radiance × its solid angle, for any roughness up
// to the 20° allowed, and it falls off monotonically away from the sun.
TEST(Render, TheRoughGlintConservesTheSunsEnergy) {
    const Scene scene = load_scene("oil-slick", small(8, 8, 1));
    const World world(scene);
    const Vec3 sun = normalize(Vec3{scene.light.sun_direction[0], scene.light.sun_direction[1],
                                    scene.light.sun_direction[2]});
    // The disc's radiance from the environment: with the sun minus without it (the green channel,
    // divided by the sun's colour there).
    const double disc = (world.environment(sun)[1] - world.environment(sun, false)[1]) / world.sun_rgb()[1];
    const double s = scene.light.sun_radius_deg * std::numbers::pi / 180.0;
    const double solid_angle = 2.0 * std::numbers::pi * (1.0 - std::cos(s));
    // A frame about the sun, and the integral over the whole sphere in the polar angle from the
    // sun and the azimuth about it (midpoint rule, finer near the sun where the lobe lives).
    const Vec3 u = normalize(cross(sun, Vec3{0, 0, 1})), v = cross(sun, u);
    for (const double sigma_deg : {0.5, 1.5, 4.0, 20.0}) {
        const double sigma = sigma_deg * std::numbers::pi / 180.0;
        double integral = 0.0, previous = 1e300;
        const int rings = 40000, spokes = 8;
        const double dt = std::numbers::pi / rings;
        for (int i = 0; i < rings; ++i) {
            const double t = (i + 0.5) * dt;
            const Vec3 r = std::cos(t) * sun + std::sin(t) * u;
            const double here = world.sun_lobe(r, sigma);
            EXPECT_LE(here, previous);
            previous = here;
            // The lobe is symmetric about the sun: the spokes check it.
            for (int k = 0; k < spokes; ++k) {
                const double phi = 2.0 * std::numbers::pi * (k + 0.5) / spokes;
                const Vec3 d = std::cos(t) * sun + std::sin(t) * (std::cos(phi) * u + std::sin(phi) * v);
                integral += world.sun_lobe(d, sigma) * std::sin(t) * dt * (2.0 * std::numbers::pi / spokes);
            }
        }
        EXPECT_NEAR(integral / (disc * solid_angle), 1.0, 2e-3) << sigma_deg;
    }
}

/// The mean CIELAB (D65 white) of an XYZ image.
Lab mean_lab(const io::Image& xyz) {
    Xyz sum;
    const auto n = static_cast<double>(xyz.pixel_count());
    for (std::size_t i = 0; i < xyz.pixel_count(); ++i) {
        sum.X += xyz.pixels[3 * i] / n;
        sum.Y += xyz.pixels[3 * i + 1] / n;
        sum.Z += xyz.pixels[3 * i + 2] / n;
    }
    return Colorimeter().lab(sum);
}

// The Morpho at its defaults (the exact stack) is the saturated structural blue of real wings,
// turning violet away from the normal: a patch of the right forewing between its veins, seen
// through a narrow field under a uniform white sky, from straight above and from 35° off.
TEST(Render, TheMorphoWingIsSaturatedBlueTurningVioletWithAngle) {
    const auto patch = [](const std::string& eye) {
        return render_with("morpho", small(8, 8, 1) + std::vector<std::string>{
                                         "light.sky=gradient", "light.sun_intensity=0", "light.sky_zenith=[1,1,1]",
                                         "light.sky_horizon=[1,1,1]", "light.ground=[1,1,1]",
                                         "morpho.bump_height=0", "camera.eye=" + eye,
                                         "camera.look_at=[0.944,0.287,-0.18]", "camera.fov_deg=1"});
    };
    // The wing's normal there: tilted by the 18° dihedral about z, (−sin 18°, cos 18°, 0).
    const Lab above = mean_lab(patch("[-0.601,5.043,-0.18]").xyz);
    const double hue = std::atan2(above.b, above.a) * 180.0 / std::numbers::pi + 360.0;
    EXPECT_GT(std::hypot(above.a, above.b), 40.0);  // saturated
    EXPECT_GT(hue, 260.0);                          // blue: CIELAB hue 260°-300°
    EXPECT_LT(hue, 300.0);
    const Lab off = mean_lab(patch("[2.406,5.069,-0.18]").xyz);
    const double hue_off = std::atan2(off.b, off.a) * 180.0 / std::numbers::pi + 360.0;
    EXPECT_GT(hue_off, hue + 5.0);  // towards violet
    EXPECT_GT(std::hypot(off.a, off.b), 20.0);
}

// An environment image replaces the procedural sky: a uniform white one gives the same
// invisible bubbles as a uniform white sky.
TEST(Render, EnvironmentImagesLightTheScene) {
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / "irid_render_test";
    std::filesystem::create_directories(dir);
    io::Image env = io::Image::blank(16, 8, 3);
    for (float& v : env.pixels) v = 1.0f;
    io::write_image(dir / "white.exr", env);
    const Xyz white = Colorimeter().white();
    const RenderResult r = render_with(
        "soap-bubbles", small(24, 18, 1) + std::vector<std::string>{
                                               "light.environment_image=" + (dir / "white.exr").string(),
                                               "light.sun_intensity=0", "soap.floor_albedo=[1,1,1]",
                                               "soap.floor_albedo_alt=[1,1,1]", "render.max_depth=32"});
    for (std::size_t i = 0; i < r.xyz.pixel_count(); ++i)
        ASSERT_NEAR(r.xyz.pixels[3 * i + 1], white.Y, 1e-5) << i;
    // Half the image dark, half bright: the sky's mean (the ambient light) is between.
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 16; ++x)
            for (int c = 0; c < 3; ++c) env.at(x, y, c) = x < 8 ? 0.0f : 2.0f;
    io::write_image(dir / "half.exr", env);
    const RenderResult h = render_with(
        "soap-bubbles", small(24, 18, 1) + std::vector<std::string>{
                                               "light.environment_image=" + (dir / "half.exr").string()});
    EXPECT_NE(h.xyz.pixels, r.xyz.pixels);
    std::filesystem::remove_all(dir);
}

// An OBJ mesh replaces the procedural wings: a quad filling the view shows the wing's colour,
// blue near normal incidence (Smits 1990 Figure 9), in every pixel.
TEST(Render, WingMeshesFromObjFilesCarryTheMorphoColour) {
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / "irid_wing_test";
    std::filesystem::create_directories(dir);
    {
        std::ofstream obj(dir / "wing.obj");
        obj << "v -50 0.2 -50\nv 50 0.2 -50\nv 50 0.2 50\nv -50 0.2 50\nf 1 2 3 4\n";
    }
    const RenderResult r = render_with(
        "morpho", small(16, 12, 1) + std::vector<std::string>{
                                         "morpho.wing_mesh=" + (dir / "wing.obj").string(),
                                         "morpho.bump_height=0", "camera.eye=[0,30,0.01]",
                                         "camera.look_at=[0,0,0]", "camera.fov_deg=10"});
    // The body is in the middle; look at the corners.
    for (const int x : {0, 15}) {
        for (const int y : {0, 11}) {
            const float red = r.linear.at(x, y, 0), blue = r.linear.at(x, y, 2);
            EXPECT_GT(blue, 1.5f * red) << x << "," << y;
            EXPECT_GT(blue, 1.5f * r.linear.at(x, y, 1)) << x << "," << y;
        }
    }
    std::filesystem::remove_all(dir);
}

TEST(Render, ImagesAreBitIdenticalForAnyThreadCount) {
    for (const std::string scene : {"oil-slick", "soap-bubbles", "morpho"}) {
        const RenderResult one = render_with(scene, small(37, 23, 4), 1);
        const RenderResult two = render_with(scene, small(37, 23, 4), 2);
        EXPECT_EQ(one.display.pixels, two.display.pixels) << scene;
        EXPECT_EQ(one.xyz.pixels, two.xyz.pixels) << scene;
        const RenderResult again = render_with(scene, small(37, 23, 4), 2);
        EXPECT_EQ(two.xyz.pixels, again.xyz.pixels) << scene;
    }
}

// Nested bubbles seen near grazing incidence split every ray in two at each film; the budget
// per camera ray keeps the work bounded whatever render.max_depth allows.
TEST(Render, RaysPerCameraRayAreBounded) {
    const RenderResult r = render_with(
        "soap-bubbles",
        small(16, 12, 1) + std::vector<std::string>{
                               "render.max_depth=32",
                               R"(soap.bubbles=[{"radius": 1.2}, {"radius": 1.0}, {"radius": 0.8},
                                               {"radius": 0.6}, {"radius": 0.4}])"});
    EXPECT_GT(r.stats.rays, 4 * r.stats.camera_rays);
    EXPECT_LE(r.stats.rays, 513 * r.stats.camera_rays);
}

TEST(Render, TheSeedChangesTheSamplesAndTheTextures) {
    const RenderResult a = render_with("oil-slick", small(24, 18, 2));
    const RenderResult b = render_with("oil-slick", small(24, 18, 2) + std::vector<std::string>{"render.seed=2"});
    EXPECT_NE(a.xyz.pixels, b.xyz.pixels);
}

// The small reference render: the spectral path (a spectrum per ray, products per wavelength)
// is the reference for the thesis' table path; the issue asks for a mean ΔE2000 below 1.
TEST(Render, TablePathMatchesTheSpectralPathWithinOneDeltaE) {
    for (const std::string scene : {"oil-slick", "soap-bubbles", "morpho"}) {
        const RenderResult table = render_with(scene, small(48, 36, 1));
        const RenderResult spectral =
            render_with(scene, small(48, 36, 1) + std::vector<std::string>{"render.path=spectral"});
        const ImageDifference d = delta_e_2000_images(table.xyz, spectral.xyz);
        EXPECT_LT(d.mean, 1.0) << scene;
        EXPECT_GT(d.max, 0.0) << scene << ": the two paths cannot agree to the last bit";
    }
}

// Against a 64-sample reference, one sample per pixel with the footprint filter is closer than
// one point sample, on a slick thick enough to alias.
TEST(Render, FootprintFilteringReducesThinFilmAliasing) {
    const std::vector<std::string> base =
        small(48, 36, 1) + std::vector<std::string>{"oil.max_thickness_nm=6000"};
    const RenderResult reference =
        render_with("oil-slick", small(48, 36, 64) + std::vector<std::string>{
                                                         "oil.max_thickness_nm=6000",
                                                         "render.antialias=none"});
    const RenderResult none =
        render_with("oil-slick", base + std::vector<std::string>{"render.antialias=none"});
    const RenderResult footprint =
        render_with("oil-slick", base + std::vector<std::string>{"render.antialias=footprint"});
    const double e_none = delta_e_2000_images(none.xyz, reference.xyz).mean;
    const double e_footprint = delta_e_2000_images(footprint.xyz, reference.xyz).mean;
    EXPECT_LT(e_footprint, 0.8 * e_none) << "none " << e_none << ", footprint " << e_footprint;
}

TEST(Render, OutputsAreFiniteAndTheDisplayImageIsInRange) {
    const RenderResult r = render_with("soap-bubbles", small(32, 24, 1));
    for (const float v : r.display.pixels) {
        ASSERT_TRUE(std::isfinite(v));
        ASSERT_GE(v, 0.0f);
        ASSERT_LE(v, 1.0f);
    }
    for (const float v : r.linear.pixels) ASSERT_TRUE(std::isfinite(v));
    EXPECT_EQ(r.stats.camera_rays, 32u * 24u);
    EXPECT_GT(r.stats.rays, r.stats.camera_rays);
}

TEST(Render, ValuesThatOnlyTheRendererChecksAreErrorsNamingTheKey) {
    auto message = [](const std::vector<std::string>& set) {
        try {
            (void)render_with("morpho", small(8, 8, 1) + set);
        } catch (const Error& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    EXPECT_NE(message({"render.space=cmyk"}).find("'render.space'"), std::string::npos);
    EXPECT_NE(message({"render.clip=nearest"}).find("'render.clip'"), std::string::npos);
    EXPECT_NE(message({"camera.up=[0,1,0]", "camera.eye=[0,5,0]", "camera.look_at=[0,0,0]"})
                  .find("camera"),
              std::string::npos);
    // Another scene's section is refused, not read and then ignored.
    EXPECT_NE(message({"oil.film=unobtainium"}).find("'oil' is a section of the oil-slick scene"),
              std::string::npos);
}

TEST(DeltaEImages, IdenticalImagesDifferByZeroAndSizesMustMatch) {
    io::Image a = io::Image::blank(4, 3, 3);
    for (float& v : a.pixels) v = 0.3f;
    const ImageDifference d = delta_e_2000_images(a, a);
    EXPECT_EQ(d.mean, 0.0);
    EXPECT_EQ(d.max, 0.0);
    EXPECT_THROW((void)delta_e_2000_images(a, io::Image::blank(3, 4, 3)), Error);
}

// --- The building blocks ---------------------------------------------------------------------

TEST(SpectralBasis, UpsampledRgbRoundTripsExactlyAndGreysAreFlat) {
    const SpectralBasis basis;
    for (const Rgb3 rgb : {Rgb3{0.2, 0.5, 0.9}, Rgb3{1, 0, 0}, Rgb3{0.05, 0.3, 0.02}, Rgb3{2, 2, 2}}) {
        const SpectralCarrier s = basis.from_rgb(rgb);
        const Rgb back = basis.colorimeter().linear_rgb(basis.xyz(s));
        EXPECT_NEAR(back.r, rgb[0], 1e-9);
        EXPECT_NEAR(back.g, rgb[1], 1e-9);
        EXPECT_NEAR(back.b, rgb[2], 1e-9);
        // The RGB carrier's XYZ is the same colour.
        const Xyz a = basis.xyz(s), b = basis.xyz(RgbCarrier{rgb});
        EXPECT_NEAR(a.X, b.X, 1e-9);
        EXPECT_NEAR(a.Y, b.Y, 1e-9);
        EXPECT_NEAR(a.Z, b.Z, 1e-9);
    }
    const SpectralCarrier grey = basis.from_rgb({0.4, 0.4, 0.4});
    for (const double v : grey.v) EXPECT_DOUBLE_EQ(v, 0.4);
}

// The footprint lookup is the mean of the piecewise-linear colour over the interval: compare
// with a fine midpoint sum of point lookups.
TEST(FilmTable, FootprintLookupIsTheMeanOverTheThicknessInterval) {
    const FilmTable table(100.0, 2.0, 0.0, 3, [](double c, const std::vector<double>& ts) {
        std::vector<Rgb3> out;
        for (const double t : ts) out.push_back({std::sin(t / 7.0) + c, t * t * 1e-4, c});
        return out;
    });
    for (const double t : {10.0, 33.3, 70.0}) {
        for (const double f : {3.0, 11.0, 40.0}) {
            for (const double c : {0.0, 0.25, 1.0}) {
                // Thicknesses are never negative: the interval is cut at 0.
                const double a = std::max(0.0, t - f / 2), b = t + f / 2;
                constexpr int n = 20000;
                Rgb3 sum{0, 0, 0};
                for (int i = 0; i < n; ++i) {
                    const Rgb3 p = table.at(a + (b - a) * (i + 0.5) / n, 0.0, c);
                    for (int k = 0; k < 3; ++k) sum[k] += p[k] / n;
                }
                const Rgb3 got = table.at(t, f, c);
                for (int k = 0; k < 3; ++k) EXPECT_NEAR(got[k], sum[k], 1e-6) << t << " " << f;
            }
        }
    }
    // Below half a step the lookup is the point value.
    EXPECT_EQ(table.at(33.3, 0.5, 0.5), table.at(33.3, 0.0, 0.5));
}

}  // namespace
}  // namespace irid::render
