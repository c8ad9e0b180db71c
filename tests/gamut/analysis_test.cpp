#include <irid/color/observer.h>
#include <irid/color/rgb.h>
#include <irid/color/spaces.h>
#include <irid/error.h>
#include <irid/figures/clip_sets.h>
#include <irid/gamut/analysis.h>
#include <irid/gamut/clip.h>
#include <irid/gamut/report.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

namespace irid {
namespace {

constexpr double degrees_per_radian = 180.0 / std::numbers::pi;

/// The three sets of the clip report on sRGB. The interference set is made where films are
/// known (irid_figures, as for `irid clip-report`); here it is only data for the analysis.
const std::vector<ColorSet>& report_sets() {
    static const std::vector<ColorSet> sets{spectrum_color_set(),
                                            figures::interference_color_set(srgb()),
                                            rec2020_color_set(srgb())};
    return sets;
}

Vec3 cross(const Vec3& a, const Vec3& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

/// The angle between the plane spanned by a and b (through the origin) and the plane Y = const.
double plane_angle_to_constant_y_deg(const Vec3& a, const Vec3& b) {
    const Vec3 n = cross(a, b);
    return std::acos(std::abs(n[1]) / std::hypot(n[0], n[1], n[2])) * degrees_per_radian;
}

Vec3 xyz_of(const Xy& chromaticity) {
    const Xyz c = xy_to_xyz(chromaticity, 1.0);
    return {c.X, c.Y, c.Z};
}

TEST(FaceAngle, EqualsThePlaneOfTheOtherTwoPrimaries) {
    // Independent of the matrix: the face r = 0 is the set of colours mixed from green and blue
    // alone, the plane through the origin spanned by their XYZ (at any scale), so its normal is
    // G × B. Likewise g = 0 (R, B) and b = 0 (R, G); the faces at max are parallel to these.
    for (const RgbSpace* space : builtin_rgb_spaces()) {
        SCOPED_TRACE(space->name());
        const RgbPrimaries& p = space->primaries();
        const Vec3 r = xyz_of(p.red), g = xyz_of(p.green), b = xyz_of(p.blue);
        const std::array<double, 3> expected{plane_angle_to_constant_y_deg(g, b),
                                             plane_angle_to_constant_y_deg(r, b),
                                             plane_angle_to_constant_y_deg(r, g)};
        const std::array<double, 3> angles = face_angles_to_constant_y_deg(*space);
        for (int ch = 0; ch < 3; ++ch) {
            EXPECT_NEAR(angles[static_cast<std::size_t>(ch)], expected[static_cast<std::size_t>(ch)], 1e-9);
            EXPECT_EQ(face_angle_to_constant_y_deg(*space, ch), angles[static_cast<std::size_t>(ch)]);
            EXPECT_GE(angles[static_cast<std::size_t>(ch)], 0.0);
            EXPECT_LE(angles[static_cast<std::size_t>(ch)], 90.0);
        }
    }
}

TEST(FaceAngle, SrgbFromThePublishedMatrix) {
    // IEC 61966-2-1:1999 §5.2, the XYZ → RGB matrix to 4 decimals; its rows are the normals.
    const double rows[3][3] = {{3.2406, -1.5372, -0.4986}, {-0.9689, 1.8758, 0.0415}, {0.0557, -0.2040, 1.0570}};
    for (int ch = 0; ch < 3; ++ch) {
        const double* n = rows[ch];
        const double expected = std::acos(std::abs(n[1]) / std::hypot(n[0], n[1], n[2])) * degrees_per_radian;
        EXPECT_NEAR(face_angle_to_constant_y_deg(srgb(), ch), expected, 0.02) << ch;
    }
    // The green faces are the nearest to parallel with the planes of constant luminance: green
    // carries most of Y (0.7152 of the white's), so moving along g changes Y fastest.
    const auto a = face_angles_to_constant_y_deg(srgb());
    EXPECT_LT(a[1], a[0]);
    EXPECT_LT(a[1], a[2]);
    EXPECT_THROW((void)face_angle_to_constant_y_deg(srgb(), 3), Error);
    EXPECT_THROW((void)face_angle_to_constant_y_deg(srgb(), -1), Error);
}

TEST(GamutFace, IndexNameRoundTrip) {
    for (int i = 0; i < gamut_face_count; ++i) {
        const GamutFace f = GamutFace::from_index(i);
        EXPECT_EQ(f.index(), i);
    }
    EXPECT_EQ(gamut_face_name({0, false}), "r=0");
    EXPECT_EQ(gamut_face_name({1, true}), "g=max");
    EXPECT_EQ(gamut_face_name({2, false}), "b=0");
}

TEST(ClipAnalysis, ConstantLuminanceMethodsKeepLightnessAndCieluvHueOnEverySet) {
    // smits moves at constant Y along a line that is, in u'v', a line through the white: L* and
    // h_uv are constant exactly (docs/GAMUT.md), so to rounding.
    for (const ColorSet& set : report_sets()) {
        for (const ClipMethod m : {ClipMethod::smits, ClipMethod::smits_xyz, ClipMethod::luv_lightness_hue}) {
            SCOPED_TRACE(set.name + " " + std::string(clip_method_name(m)));
            const ClipAnalysis a = analyse_clip(set, Gamut(srgb()), m);
            ASSERT_EQ(a.colors.size(), set.colors.size());
            EXPECT_GT(a.summary.clipped, 100u);
            EXPECT_LT(a.summary.max_abs_delta_l_ab, 1e-9);
            EXPECT_LT(a.summary.max_abs_delta_l_uv, 1e-9);
            EXPECT_LT(a.summary.hue.uv.max, 1e-9);
            // Every clipped colour that has a CIELUV hue keeps one (none goes to a grey).
            EXPECT_EQ(a.summary.hue_undefined[0] + a.summary.hue.uv.count, a.summary.clipped);
            for (const ClipColorAnalysis& c : a.colors) {
                EXPECT_NEAR(c.delta_l_ab, 0.0, 1e-9);
                if (!std::isnan(c.hue_shift_uv)) {
                    EXPECT_NEAR(c.hue_shift_uv, 0.0, 1e-9);
                }
            }
            // ... but not the CIELAB or the Oklab hue.
            EXPECT_GT(a.summary.hue.ab.mean, 0.1);
            EXPECT_GT(a.summary.hue.oklab.mean, 0.1);
        }
    }
}

TEST(ClipAnalysis, ClampMovesLightnessAndHue) {
    const ClipAnalysis a = analyse_clip(spectrum_color_set(), Gamut(srgb()), ClipMethod::clamp);
    EXPECT_EQ(a.summary.clipped, 401u);
    EXPECT_GT(a.summary.max_abs_delta_l_ab, 10.0);
    EXPECT_GT(a.summary.hue.uv.max, 10.0);
    // L* is one function of Y in CIELAB and CIELUV.
    for (const ClipColorAnalysis& c : a.colors) EXPECT_NEAR(c.delta_l_ab, c.delta_l_uv, 1e-9);
}

TEST(ClipAnalysis, SmitsNeverRaisesSaturation) {
    // At constant Y, u'v' moves on the line toward the white's u'v' (the segment to the grey is
    // such a line), and s_uv = 13 |u'v' − u'v'_n| is the distance to the white: it can only fall.
    for (const ColorSet& set : report_sets()) {
        for (const ClipMethod m : {ClipMethod::smits, ClipMethod::smits_xyz}) {
            SCOPED_TRACE(set.name + " " + std::string(clip_method_name(m)));
            const ClipAnalysis a = analyse_clip(set, Gamut(srgb()), m);
            EXPECT_EQ(a.summary.saturation_lower, a.summary.clipped);
            EXPECT_EQ(a.summary.saturation_higher, 0u);
            EXPECT_TRUE(a.summary.saturation_exceptions.empty());
            for (const ClipColorAnalysis& c : a.colors) {
                if (!c.out_of_gamut) continue;
                EXPECT_LT(c.saturation_out, c.saturation_in);
                EXPECT_GE(c.saturation_out, 0.0);
            }
        }
    }
}

TEST(ClipAnalysis, SmitsOutputIsOnItsUvPrimeLineToTheWhite) {
    // The same fact checked in u'v' directly: the output lies between the white and the input.
    const UvPrime n = xyz_to_uv_prime(srgb().white_xyz());
    const ClipAnalysis a = analyse_clip(rec2020_color_set(srgb()), Gamut(srgb()), ClipMethod::smits);
    for (const ClipColorAnalysis& c : a.colors) {
        if (!c.out_of_gamut) continue;
        const UvPrime in = xyz_to_uv_prime(c.xyz_in, n), out = xyz_to_uv_prime(c.xyz_out, n);
        const double ax = in.u - n.u, ay = in.v - n.v, bx = out.u - n.u, by = out.v - n.v;
        const double length = std::hypot(ax, ay);
        EXPECT_NEAR((ax * by - ay * bx) / length, 0.0, 1e-12);    // collinear with the white
        EXPECT_GE((ax * bx + ay * by) / (length * length), 0.0);  // on the input's side
        EXPECT_NEAR(c.saturation_out / c.saturation_in, std::hypot(bx, by) / length, 1e-9);
    }
}

TEST(ClipAnalysis, SaturationCanRiseWhenLightnessIsNotKept) {
    // s_uv is chroma over lightness: a method that lowers L* (luv-hue: the nearest colour in ΔE*uv)
    // can raise it. Counts are consistent whatever they are.
    const ClipAnalysis a = analyse_clip(rec2020_color_set(srgb()), Gamut(srgb()), ClipMethod::luv_hue);
    const ClipClaimsSummary& s = a.summary;
    EXPECT_EQ(s.saturation_lower + s.saturation_equal + s.saturation_higher, s.clipped);
    EXPECT_EQ(s.saturation_exceptions.size(), s.saturation_equal + s.saturation_higher);
    EXPECT_GT(s.saturation_higher, 0u);
    for (const std::size_t i : s.saturation_exceptions) {
        const ClipColorAnalysis& c = a.colors.at(i);
        EXPECT_TRUE(c.out_of_gamut);
        EXPECT_GE(c.saturation_out, c.saturation_in * (1.0 - 1e-9));
        // Only a change of lightness makes room for it here: the hue in CIELUV is kept.
        EXPECT_GT(std::abs(c.delta_l_uv), 1e-6);
    }
}

TEST(ClipAnalysis, SmitsFaceIsTheFaceOfTheLargestParameter) {
    // Independently of the clip's code: the segment c + t (w − c) to the grey w of equal Y meets
    // the face of channel i at t_i = (c_i − bound)/(c_i − w); smits stops at the largest.
    const Gamut gamut(srgb());
    const Vec3 lum = gamut.luminance_row();
    const double inv_sum = 1.0 / (lum[0] + lum[1] + lum[2]);
    for (const ColorSet& set : report_sets()) {
        SCOPED_TRACE(set.name);
        const ClipAnalysis a = analyse_clip(set, Gamut(srgb()), ClipMethod::smits);
        EXPECT_EQ(a.summary.on_edge, 0u);
        std::size_t on_faces = 0;
        for (const ClipColorAnalysis& c : a.colors) {
            if (!c.out_of_gamut) {
                // In the gamut or within rounding of it (1e-9): at most rounding moves.
                EXPECT_NEAR(c.rgb_out.r, c.rgb_in.r, 1e-9);
                EXPECT_NEAR(c.rgb_out.g, c.rgb_in.g, 1e-9);
                EXPECT_NEAR(c.rgb_out.b, c.rgb_in.b, 1e-9);
                continue;
            }
            const double ch[3] = {c.rgb_in.r, c.rgb_in.g, c.rgb_in.b};
            const double w = (lum[0] * ch[0] + lum[1] * ch[1] + lum[2] * ch[2]) * inv_sum;
            double best = 0.0;
            GamutFace face;
            for (int i = 0; i < 3; ++i) {
                for (const bool upper : {false, true}) {
                    const double bound = upper ? 1.0 : 0.0;
                    if (upper ? ch[i] <= bound : ch[i] >= bound) continue;
                    const double t = (ch[i] - bound) / (ch[i] - w);
                    if (t > best) best = t, face = {i, upper};
                }
            }
            ASSERT_TRUE(c.on_face);
            EXPECT_EQ(c.faces_touched, 1);
            EXPECT_EQ(c.face, face);
            EXPECT_EQ(c.face_angle_deg, face_angle_to_constant_y_deg(srgb(), face.channel));
            ++on_faces;
        }
        std::size_t counted = 0;
        for (const FaceHueStatistics& f : a.summary.faces) {
            counted += f.count;
            EXPECT_EQ(f.angle_deg, face_angle_to_constant_y_deg(srgb(), f.face.channel));
        }
        EXPECT_EQ(counted, on_faces);
        std::size_t binned = 0;
        for (const AngleBinHueStatistics& b : a.summary.angle_bins) binned += b.count;
        EXPECT_EQ(binned, on_faces);
    }
}

TEST(ClipAnalysis, AngleBinsCoverZeroToNinety) {
    const ClipAnalysis a = analyse_clip(rec2020_color_set(srgb()), Gamut(srgb()), ClipMethod::smits);
    const auto& bins = a.summary.angle_bins;
    ASSERT_EQ(bins.size(), static_cast<std::size_t>(90.0 / clip_analysis_angle_bin_deg));
    EXPECT_EQ(bins.front().min_deg, 0.0);
    EXPECT_EQ(bins.back().max_deg, 90.0);
    for (std::size_t i = 1; i < bins.size(); ++i) EXPECT_EQ(bins[i].min_deg, bins[i - 1].max_deg);
    // sRGB's three angles (65°, 27°, 79°) fall in bins 4, 1 and 5; the face table agrees.
    const auto& f = a.summary.faces;
    EXPECT_EQ(bins[1].count, f[2].count + f[3].count);
    EXPECT_EQ(bins[4].count, f[0].count + f[1].count);
    EXPECT_EQ(bins[5].count, f[4].count + f[5].count);
    EXPECT_EQ(bins[0].count + bins[2].count + bins[3].count, 0u);
}

TEST(ClipAnalysis, HueStatisticsAgreeWithTheClipReport) {
    // The clip report measures |Δh| over the whole set by its own code; colours in the gamut
    // contribute 0, so its maximum and sum are the analysis' over the clipped colours.
    for (const ColorSet& set : report_sets()) {
        const ClipReport report = measure_clip_report(set, Gamut(srgb()), ClipReportOptions{0.0});
        for (const MethodClipReport& m : report.methods) {
            // The soft methods (aces-rgc, smits-soft) move in-gamut colours too, which the report
            // measures and the analysis (clipped colours only) does not.
            if (moves_in_gamut_colours(m.method)) continue;
            SCOPED_TRACE(set.name + " " + std::string(clip_method_name(m.method)));
            const ClipClaimsSummary s = analyse_clip(set, Gamut(srgb()), m.method).summary;
            EXPECT_EQ(s.clipped, report.out_of_gamut);
            EXPECT_NEAR(s.hue.ab.max, m.hue_lab.max, 1e-9);
            EXPECT_NEAR(s.hue.oklab.max, m.hue_oklab.max, 1e-9);
            EXPECT_NEAR(s.hue.uv.max, m.hue_luv.max, 1e-9);
            EXPECT_NEAR(s.hue.ab.mean * static_cast<double>(s.hue.ab.count),
                        m.hue_lab.mean * static_cast<double>(m.hue_lab.count), 1e-6);
            EXPECT_NEAR(s.hue.oklab.mean * static_cast<double>(s.hue.oklab.count),
                        m.hue_oklab.mean * static_cast<double>(m.hue_oklab.count), 1e-6);
            EXPECT_EQ(s.hue_undefined[1], m.hue_undefined);
        }
    }
}

TEST(ClipAnalysis, SignedHueChangesAreWrapped) {
    for (const ClipMethod m : clip_methods()) {
        const ClipAnalysis a = analyse_clip(spectrum_color_set(), Gamut(srgb()), m);
        for (const ClipColorAnalysis& c : a.colors) {
            for (const double h : {c.hue_shift_uv, c.hue_shift_ab, c.hue_shift_oklab}) {
                if (std::isnan(h)) continue;
                EXPECT_GT(h, -180.0);
                EXPECT_LE(h, 180.0);
            }
        }
    }
    // The violet end (380 nm, hue near 300° in CIELAB) and the red end (780 nm, near 40°) are on
    // either side of 0°: clamping pulls the violet toward blue (its hue falls), which must not
    // read as +300° or so. Every |Δh| of clamp on the spectrum stays far below 180°.
    const ClipAnalysis clamp = analyse_clip(spectrum_color_set(), Gamut(srgb()), ClipMethod::clamp);
    EXPECT_LT(clamp.summary.hue.ab.max, 90.0);
}

TEST(ClipAnalysis, OklabMethodKeepsOklabHueAlsoOnANonD65Space) {
    // NTSC 1953 has illuminant C: the analysis adapts to D65 by Bradford for Oklab, as the
    // clipper does, so the oklab method's Oklab hue change is still 0 to rounding.
    for (const RgbSpace* space : {&srgb(), &ntsc1953()}) {
        SCOPED_TRACE(space->name());
        const ClipAnalysis a = analyse_clip(rec2020_color_set(*space), Gamut(*space), ClipMethod::oklab);
        EXPECT_GT(a.summary.clipped, 10u);
        EXPECT_GT(a.summary.hue.oklab.count, 10u);
        EXPECT_LT(a.summary.hue.oklab.max, 1e-6);
        EXPECT_TRUE(std::isnan(a.summary.correlation_oklab));  // |Δh| constant 0
    }
}

TEST(ClipAnalysis, HdrPeakKeepsRelativeLightness) {
    // A gamut [0, 2]³: the set's XYZ is taken in the cube's units and measured relative to max.
    const Gamut hdr(srgb(), 2.0);
    const ClipAnalysis a = analyse_clip(spectrum_color_set(), hdr, ClipMethod::smits);
    EXPECT_EQ(a.max, 2.0);
    EXPECT_GT(a.summary.clipped, 300u);
    EXPECT_LT(a.summary.max_abs_delta_l_ab, 1e-9);
    for (const ClipColorAnalysis& c : a.colors) {
        EXPECT_NEAR(c.xyz_in.Y, 0.15, 1e-12);  // 0.3 of a white at Y = 2
        EXPECT_LE(std::max({c.rgb_out.r, c.rgb_out.g, c.rgb_out.b}), 2.0);
    }
}

TEST(ClipAnalysis, InGamutColoursAreUnchangedAndNotSummarised) {
    ColorSet inside{"inside", "", {}};
    for (const double v : {0.1, 0.5, 0.9}) inside.colors.push_back(srgb().to_xyz({v, 0.3, 1.0 - v}));
    for (const ClipMethod m : clip_methods()) {
        // The soft methods (aces-rgc, smits-soft) move in-gamut colours by design.
        if (moves_in_gamut_colours(m)) continue;
        const ClipAnalysis a = analyse_clip(inside, Gamut(srgb()), m);
        EXPECT_EQ(a.summary.clipped, 0u);
        EXPECT_EQ(a.summary.max_abs_delta_l_ab, 0.0);
        EXPECT_EQ(a.summary.hue.ab.count, 0u);
        for (const ClipColorAnalysis& c : a.colors) {
            EXPECT_FALSE(c.out_of_gamut);
            EXPECT_NEAR(c.delta_l_ab, 0.0, 1e-12);
            EXPECT_NEAR(c.hue_shift_ab, 0.0, 1e-9);
        }
    }
    EXPECT_THROW((void)analyse_clip(ColorSet{}, Gamut(srgb()), ClipMethod::smits), Error);
}

TEST(ClipAnalysis, CorrelationIsAFractionOrUndefined) {
    for (const ClipMethod m : clip_methods()) {
        const ClipClaimsSummary s = analyse_clip(rec2020_color_set(srgb()), Gamut(srgb()), m).summary;
        for (const double r : {s.correlation_uv, s.correlation_ab, s.correlation_oklab}) {
            if (!std::isnan(r)) {
                EXPECT_GE(r, -1.0);
                EXPECT_LE(r, 1.0);
            }
        }
    }
    // smits keeps h_uv: |Δh_uv| is constant (0), so its correlation with anything is undefined.
    const ClipClaimsSummary smits = analyse_clip(rec2020_color_set(srgb()), Gamut(srgb()), ClipMethod::smits).summary;
    EXPECT_TRUE(std::isnan(smits.correlation_uv));
    EXPECT_FALSE(std::isnan(smits.correlation_ab));
}

TEST(MonochromaticSet, AtTheReportLuminanceIsTheSpectrumSet) {
    const ColorSet a = monochromatic_color_set(spectrum_set_luminance);
    const ColorSet b = spectrum_color_set();
    ASSERT_EQ(a.colors.size(), b.colors.size());
    for (std::size_t i = 0; i < a.colors.size(); ++i) {
        EXPECT_EQ(a.colors[i].X, b.colors[i].X);
        EXPECT_EQ(a.colors[i].Y, b.colors[i].Y);
        EXPECT_EQ(a.colors[i].Z, b.colors[i].Z);
    }
    const ColorSet coarse = monochromatic_color_set(0.5, 400.0, 700.0, 10.0);
    ASSERT_EQ(coarse.colors.size(), 31u);
    // Chromaticity is that of the spectral locus.
    const Xy locus = spectral_locus_xy(550.0);
    const Xy xy = xyz_to_xy(coarse.colors[15]);
    EXPECT_NEAR(xy.x, locus.x, 1e-12);
    EXPECT_NEAR(xy.y, locus.y, 1e-12);
    EXPECT_EQ(coarse.colors[15].Y, 0.5);
    EXPECT_THROW((void)monochromatic_color_set(0.0), Error);
    EXPECT_THROW((void)monochromatic_color_set(0.3, 350.0), Error);
    EXPECT_THROW((void)monochromatic_color_set(0.3, 500.0, 400.0), Error);
    EXPECT_THROW((void)monochromatic_color_set(0.3, 380.0, 780.0, 0.0), Error);
    EXPECT_THROW((void)monochromatic_color_set(std::nan(""), 380.0), Error);
}

TEST(SpectrumHueSeries, OnePerMethodWithItsWavelengths) {
    const std::vector<ClipMethod> methods{ClipMethod::smits, ClipMethod::oklab};
    const auto series = spectrum_hue_series(Gamut(srgb()), methods, 0.2);
    ASSERT_EQ(series.size(), 2u);
    for (std::size_t k = 0; k < series.size(); ++k) {
        const SpectrumHueSeries& s = series[k];
        EXPECT_EQ(s.analysis.method, methods[k]);
        ASSERT_EQ(s.wavelength_nm.size(), 401u);
        ASSERT_EQ(s.analysis.colors.size(), 401u);
        EXPECT_EQ(s.wavelength_nm.front(), 380.0);
        EXPECT_EQ(s.wavelength_nm.back(), 780.0);
        EXPECT_NEAR(s.analysis.colors[0].xyz_in.Y, 0.2, 1e-12);
    }
    // The same numbers as analysing the set directly.
    const ClipAnalysis direct = analyse_clip(monochromatic_color_set(0.2), Gamut(srgb()), ClipMethod::smits);
    for (std::size_t i = 0; i < 401; i += 50) {
        EXPECT_EQ(series[0].analysis.colors[i].hue_shift_oklab, direct.colors[i].hue_shift_oklab);
    }
}

}  // namespace
}  // namespace irid
