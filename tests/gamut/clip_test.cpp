#include <irid/color/difference.h>
#include <irid/color/rgb.h>
#include <irid/color/spaces.h>
#include <irid/error.h>
#include <irid/gamut/clip.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

namespace irid {
namespace {

constexpr double inf = std::numeric_limits<double>::infinity();

/// Linear sRGB colours far outside the cube (Rec.2020 primaries and beyond), near its faces,
/// and dark and bright ones, from a fixed seed.
std::vector<Rgb> out_of_gamut_colours(int count = 2000) {
    std::mt19937 rng(20261122);
    std::uniform_real_distribution<double> u(-0.6, 1.6);
    std::vector<Rgb> out;
    while (static_cast<int>(out.size()) < count) {
        const Rgb c{u(rng), u(rng), u(rng)};
        const bool inside = c.r >= 0 && c.g >= 0 && c.b >= 0 && c.r <= 1 && c.g <= 1 && c.b <= 1;
        if (!inside) out.push_back(c);
    }
    return out;
}

double luminance(const Gamut& g, const Rgb& c) {
    const Vec3& l = g.luminance_row();
    return l[0] * c.r + l[1] * c.g + l[2] * c.b;
}

bool on_boundary(const Rgb& c, double max, double tol = 1e-9) {
    for (const double v : {c.r, c.g, c.b}) {
        if (std::abs(v) <= tol || std::abs(v - max) <= tol * max) return true;
    }
    return false;
}

TEST(ClipMethods, NamesRoundTripAndUnknownNamesListTheValidOnes) {
    for (const ClipMethod m : clip_methods()) EXPECT_EQ(parse_clip_method(clip_method_name(m)), m);
    EXPECT_EQ(clip_methods().size(), 12u);
    try {
        (void)parse_clip_method("perceptual");
        FAIL();
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("css-raytrace"), std::string::npos);
    }
}

TEST(ClipMethods, InGamutColoursAreUntouchedAndOutputsAreFiniteAndInside) {
    const Gamut gamut(srgb());
    std::vector<Rgb> inputs = out_of_gamut_colours(300);
    const Rgb inside[] = {{0.5, 0.4, 0.3}, {0, 0, 0}, {1, 1, 1}, {1, 0, 0.25}, {0, 1, 0}};
    const Rgb hostile[] = {{std::nan(""), 0.5, 0.5}, {inf, 0, 0}, {-inf, 0.2, 0.2},
                           {inf, -inf, 0.5}, {1e300, -1e300, 3}, {-0.0, 1e-320, 1}};
    for (const ClipMethod m : clip_methods()) {
        const GamutClipper clipper(m, gamut);
        // The soft methods (aces-rgc, smits-soft) compress in-gamut colours beyond their
        // threshold, and aces-rgc without clip leaves colours beyond its limit outside the cube
        // (as OCIO's does): their contracts are tested in their own files; finiteness holds for all.
        const bool untouched = !moves_in_gamut_colours(m);
        const bool confined = clipper.confines_to_cube();
        for (const Rgb& c : inside) {
            if (!untouched) break;
            const Rgb out = clipper.clip(c);
            EXPECT_EQ(out.r, c.r) << clip_method_name(m);
            EXPECT_EQ(out.g, c.g) << clip_method_name(m);
            EXPECT_EQ(out.b, c.b) << clip_method_name(m);
        }
        for (const Rgb& c : inputs) {
            const Rgb out = clipper.clip(c);
            if (confined) {
                EXPECT_TRUE(gamut.contains(out)) << clip_method_name(m) << " " << c.r << "," << c.g << "," << c.b;
            }
        }
        for (const Rgb& c : hostile) {
            const Rgb out = clipper.clip(c);
            EXPECT_TRUE(std::isfinite(out.r) && std::isfinite(out.g) && std::isfinite(out.b))
                << clip_method_name(m);
            if (confined) {
                EXPECT_TRUE(gamut.contains(out)) << clip_method_name(m);
            }
        }
    }
}

TEST(Smits, KeepsLuminanceAndMovesToTheBoundaryTowardTheGreyOfThatLuminance) {
    const Gamut gamut(srgb());
    const GamutClipper clipper(ClipMethod::smits, gamut);
    int checked = 0;
    for (const Rgb& c : out_of_gamut_colours()) {
        const double y = luminance(gamut, c);
        if (!(y > 0.0 && y < 1.0)) continue;
        const Rgb out = clipper.clip(c);
        EXPECT_NEAR(luminance(gamut, out), y, 1e-12);
        EXPECT_TRUE(on_boundary(out, 1.0));
        // The result lies on the segment from c to (y, y, y): out − c ∥ (y − c).
        const Vec3 a{out.r - c.r, out.g - c.g, out.b - c.b};
        const Vec3 b{y - c.r, y - c.g, y - c.b};
        const Vec3 cross{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
        EXPECT_NEAR(std::hypot(cross[0], cross[1], cross[2]), 0.0, 1e-12);
        ++checked;
    }
    EXPECT_GT(checked, 500);
}

TEST(Smits, BlackBelowZeroLuminanceAndWhiteAboveTheWhitesAndAnHdrPeak) {
    const GamutClipper sdr(ClipMethod::smits, Gamut(srgb()));
    const Rgb black = sdr.clip({-0.5, 0.1, 0.1});
    EXPECT_EQ(black.r, 0.0);
    EXPECT_EQ(black.g, 0.0);
    const Rgb white = sdr.clip({3.0, 1.5, 0.2});
    EXPECT_EQ(white.r, 1.0);
    EXPECT_EQ(white.b, 1.0);
    // With a peak of 4 the cube is [0, 4]³: (3, 1.5, 0.2) is inside; (6, 1, 1) is clipped at
    // constant luminance onto the face r = 4.
    const Gamut hdr(srgb(), 4.0);
    const GamutClipper h(ClipMethod::smits, hdr);
    const Rgb same = h.clip({3.0, 1.5, 0.2});
    EXPECT_EQ(same.r, 3.0);
    const Rgb out = h.clip({6.0, 1.0, 1.0});
    EXPECT_NEAR(out.r, 4.0, 1e-12);
    EXPECT_NEAR(luminance(hdr, out), luminance(hdr, {6.0, 1.0, 1.0}), 1e-12);
}

TEST(Smits, BothFormsOfTheThesisGiveTheSameColour) {
    for (const RgbSpace* space : builtin_rgb_spaces()) {
        const Gamut gamut(*space, 1.0);
        const GamutClipper rgb_form(ClipMethod::smits, gamut);
        const GamutClipper xyz_form(ClipMethod::smits_xyz, gamut);
        for (const Rgb& c : out_of_gamut_colours(500)) {
            const Rgb a = rgb_form.clip(c);
            const Rgb b = xyz_form.clip(c);
            const double scale = std::max({std::abs(a.r), std::abs(a.g), std::abs(a.b), 1e-3});
            EXPECT_NEAR(a.r, b.r, 1e-6 * scale) << space->name();
            EXPECT_NEAR(a.g, b.g, 1e-6 * scale) << space->name();
            EXPECT_NEAR(a.b, b.b, 1e-6 * scale) << space->name();
        }
        // And on XYZ input directly: clip_xyz of the XYZ form equals the RGB form's XYZ.
        const Vec3 x = space->to_xyz_matrix() * Vec3{1.4, -0.2, 0.3};
        const Xyz cx = xyz_form.clip_xyz({x[0], x[1], x[2]});
        const Rgb via_rgb = rgb_form.clip({1.4, -0.2, 0.3});
        const Xyz expected = space->to_xyz(via_rgb);
        EXPECT_NEAR(cx.X, expected.X, 1e-9);
        EXPECT_NEAR(cx.Y, expected.Y, 1e-9);
        EXPECT_NEAR(cx.Z, expected.Z, 1e-9);
    }
}

TEST(Table1, CountsFollowTheCrossMultipliedClip) {
    // Smits 1990, Table 1: 5-7 comparisons, 9-11 additions, 7 multiplications and 1-3 divisions
    // per clipped colour; an in-gamut colour costs only its comparisons. Ours compares the
    // planes' parameters by cross-multiplication (clip.h, smits_clip_rgb) and divides once: the
    // same additions, 2 more multiplications and 1 more comparison per plane after the first,
    // 1 division.
    const Table1 t = count_smits_operations();
    EXPECT_EQ(t.in_gamut.comparisons, 6);
    EXPECT_EQ(t.in_gamut.additions + t.in_gamut.multiplications + t.in_gamut.divisions, 0);
    const OperationCounts* clipped[] = {&t.one_plane, &t.two_planes, &t.three_planes};
    for (int planes = 1; planes <= 3; ++planes) {
        const OperationCounts& c = *clipped[planes - 1];
        // 4 for Y and the grey, 3 for the interpolation, 2 per plane after the first.
        EXPECT_EQ(c.multiplications, 7 + 2 * (planes - 1)) << planes;
        EXPECT_EQ(c.divisions, 1) << planes;
        // The colours cross red above 1, then green and blue below 0: 2 for Y, 3 + 3 for the
        // interpolation w + s (c − w), max − w once for the high plane, w − c per low plane.
        EXPECT_EQ(c.additions, 8 + planes) << planes;
        // 6 outcodes, the two luminance tests, one per plane after the first.
        EXPECT_EQ(c.comparisons, 8 + planes - 1) << planes;
    }
}

TEST(LuvLightnessHue, KeepsLightnessAndHueAndReachesTheBoundaryWithMaximalChroma) {
    const Gamut gamut(srgb());
    const GamutClipper clipper(ClipMethod::luv_lightness_hue, gamut);
    const Xyz white = srgb().white_xyz();
    int checked = 0;
    for (const Rgb& c : out_of_gamut_colours(500)) {
        const Xyz x = srgb().to_xyz(c);
        if (!(x.Y > 1e-3 && x.Y < 0.999) || x.X + 15 * x.Y + 3 * x.Z <= 0) continue;
        const LchUv in = luv_to_lch(xyz_to_luv(x, white));
        const Rgb out = clipper.clip(c);
        const LchUv got = luv_to_lch(xyz_to_luv(srgb().to_xyz(out), white));
        EXPECT_NEAR(got.L, in.L, 1e-9);
        if (got.C > 1e-6) {
            EXPECT_NEAR(std::abs(std::remainder(got.h - in.h, 360.0)), 0.0, 1e-7);
        }
        EXPECT_LE(got.C, in.C + 1e-9);
        EXPECT_TRUE(on_boundary(out, 1.0, 1e-9));
        ++checked;
    }
    EXPECT_GT(checked, 100);
}

TEST(LuvHue, KeepsHueAndIsNoFartherInDeltaEuvThanConstantLightness) {
    const Gamut gamut(srgb());
    const GamutClipper hue(ClipMethod::luv_hue, gamut);
    const GamutClipper lightness(ClipMethod::luv_lightness_hue, gamut);
    const Xyz white = srgb().white_xyz();
    int checked = 0;
    for (const Rgb& c : out_of_gamut_colours(300)) {
        const Xyz x = srgb().to_xyz(c);
        if (!(x.Y > 1e-3 && x.Y < 0.999) || x.X + 15 * x.Y + 3 * x.Z <= 0) continue;
        const Luv in = xyz_to_luv(x, white);
        const Luv a = xyz_to_luv(srgb().to_xyz(hue.clip(c)), white);
        const Luv b = xyz_to_luv(srgb().to_xyz(lightness.clip(c)), white);
        // Constant lightness is one candidate in the same hue plane: the nearest is no farther.
        EXPECT_LE(delta_e_uv(in, a), delta_e_uv(in, b) + 1e-6);
        const LchUv lin = luv_to_lch(in), la = luv_to_lch(a);
        if (la.C > 1e-3) {
            EXPECT_NEAR(std::abs(std::remainder(la.h - lin.h, 360.0)), 0.0, 1e-6);
        }
        ++checked;
    }
    EXPECT_GT(checked, 50);
}

TEST(Oklab, KeepsOklabLightnessAndHueWithMaximalChroma) {
    const Gamut gamut(srgb());
    const GamutClipper clipper(ClipMethod::oklab, gamut);
    int checked = 0;
    for (const Rgb& c : out_of_gamut_colours(500)) {
        const Oklch in = oklab_to_oklch(xyz_to_oklab(srgb().to_xyz(c)));
        if (!(in.L > 0.01 && in.L < 0.99)) continue;
        const Rgb out = clipper.clip(c);
        const Oklch got = oklab_to_oklch(xyz_to_oklab(srgb().to_xyz(out)));
        EXPECT_NEAR(got.L, in.L, 1e-9);
        if (got.C > 1e-6) {
            EXPECT_NEAR(std::abs(std::remainder(got.h - in.h, 360.0)), 0.0, 1e-6);
        }
        EXPECT_TRUE(on_boundary(out, 1.0, 1e-9)) << c.r << "," << c.g << "," << c.b;
        ++checked;
    }
    EXPECT_GT(checked, 200);
}

TEST(Oklab, JustBelowTheWhitesLightnessKeepsTheLightness) {
    // With Ottosson's published matrices Oklab's neutral axis left the cube within about 1.4e-4
    // below the white's L (they give the D65 white a chroma of 1.2e-4), no chroma of such a
    // colour's lightness and hue was inside, and the method could keep L only to 1e-3. CSS Color
    // 4's matrices put the white on the axis: the grey of every lightness up to the white's is
    // inside, and L is kept to rounding. Colours scaled to a lightness in the last 3e-4 below
    // the white's.
    for (const RgbSpace* space : {&srgb(), &display_p3(), &rec2020(), &adobe_rgb()}) {
        SCOPED_TRACE(space->name());
        const Gamut gamut(*space);
        const GamutClipper clipper(ClipMethod::oklab, gamut);
        const double white_l = xyz_to_oklab(space->to_xyz({1.0, 1.0, 1.0})).L;
        std::mt19937 rng(7);
        std::uniform_real_distribution<double> u(0.0, 1.0);
        int checked = 0;
        for (int k = 0; k < 2000; ++k) {
            const Rgb c{u(rng), u(rng), u(rng)};
            // Oklab L of k c is k^(1/3) L(c): scale to the target lightness.
            const double target = white_l * (1.0 - 3e-4 * u(rng));
            const double scale = std::pow(target / xyz_to_oklab(space->to_xyz(c)).L, 3.0);
            const Rgb in{c.r * scale, c.g * scale, c.b * scale};
            if (gamut.contains(in)) continue;
            const Rgb out = clipper.clip(in);
            EXPECT_TRUE(gamut.contains(out));
            EXPECT_NEAR(xyz_to_oklab(space->to_xyz(out)).L, target, 1e-9)
                << in.r << "," << in.g << "," << in.b;
            ++checked;
        }
        EXPECT_GT(checked, 1000);
    }
}

TEST(Css, FollowsTheSpecificationsBinarySearch) {
    // The result is in gamut and within the JND of the colour at the chroma it settled on: its
    // Oklab lightness is within 0.02 of the input's, and L ≥ 1 / L ≤ 0 give white / black.
    const Gamut gamut(srgb());
    const GamutClipper clipper(ClipMethod::css, gamut);
    for (const Rgb& c : out_of_gamut_colours(300)) {
        const Oklab in = xyz_to_oklab(srgb().to_xyz(c));
        if (!(in.L > 0.0 && in.L < 0.999)) continue;
        const Oklab got = xyz_to_oklab(srgb().to_xyz(clipper.clip(c)));
        EXPECT_NEAR(got.L, in.L, 0.02 + 1e-9);
    }
    const Rgb white = clipper.clip({1.5, 1.5, 1.5});
    EXPECT_EQ(white.g, 1.0);
    const Rgb black = clipper.clip({-0.5, -0.5, -0.5});
    EXPECT_EQ(black.g, 0.0);
    // A colour just outside (within the JND of its clamp) is simply clamped.
    const Rgb near = clipper.clip({1.001, 0.5, 0.5});
    EXPECT_NEAR(near.r, 1.0, 1e-12);
    EXPECT_NEAR(near.g, 0.5, 1e-12);  // through Oklab and back
    EXPECT_NEAR(near.b, 0.5, 1e-12);
}

TEST(ClipMethods, ARetiredMethodSaysWhy) {
    try {
        (void)parse_clip_method("smits-corrected");
        FAIL();
    } catch (const UnknownNameError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("retired"), std::string::npos) << what;
        EXPECT_NE(what.find("oklab"), std::string::npos) << what;
    }
}

TEST(Gamut, RejectsABadMaximum) {
    EXPECT_THROW(Gamut(srgb(), 0.0), Error);
    EXPECT_THROW(Gamut(srgb(), std::nan("")), Error);
    EXPECT_THROW(Gamut(srgb(), inf), Error);
}

}  // namespace
}  // namespace irid
