#include <irid/color/rgb.h>
#include <irid/color/spaces.h>
#include <irid/error.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <string>
#include <vector>

namespace irid {
namespace {

TEST(RgbSpace, SrgbMatrixMatchesIec61966) {
    // IEC 61966-2-1:1999, eq. (F.7): the published RGB → XYZ matrix (4 decimals).
    const double published[3][3] = {{0.4124, 0.3576, 0.1805},
                                    {0.2126, 0.7152, 0.0722},
                                    {0.0193, 0.1192, 0.9505}};
    const Mat3& m = srgb().to_xyz_matrix();
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) EXPECT_NEAR(m[i][j], published[i][j], 1e-4) << i << "," << j;
    }
}

TEST(RgbSpace, Rec2020LuminanceRowMatchesBt2020) {
    // ITU-R BT.2020-2 Table 4: Y' = 0.2627 R + 0.6780 G + 0.0593 B.
    const Mat3& m = rec2020().to_xyz_matrix();
    EXPECT_NEAR(m[1][0], 0.2627, 5e-5);
    EXPECT_NEAR(m[1][1], 0.6780, 5e-5);
    EXPECT_NEAR(m[1][2], 0.0593, 5e-5);
}

TEST(RgbSpace, Ntsc1953LuminanceRowMatchesTheFccWeights) {
    // FCC 1953: Y = 0.299 R + 0.587 G + 0.114 B (the NTSC luma weights, rounded to 3 decimals
    // from the primaries and illuminant C, hence the tolerance).
    const Mat3& m = ntsc1953().to_xyz_matrix();
    EXPECT_NEAR(m[1][0], 0.299, 1e-3);
    EXPECT_NEAR(m[1][1], 0.587, 1e-3);
    EXPECT_NEAR(m[1][2], 0.114, 1e-3);
}

TEST(RgbSpace, EveryBuiltinMapsWhiteToItsWhiteAndPrimariesToTheirChromaticities) {
    for (const RgbSpace* s : builtin_rgb_spaces()) {
        const Xyz w = s->to_xyz({1, 1, 1});
        EXPECT_NEAR(w.Y, 1.0, 1e-14) << s->name();
        const Xy wxy = xyz_to_xy(w);
        EXPECT_NEAR(wxy.x, s->white().x, 1e-14) << s->name();
        EXPECT_NEAR(wxy.y, s->white().y, 1e-14) << s->name();
        const Xy r = xyz_to_xy(s->to_xyz({1, 0, 0}));
        EXPECT_NEAR(r.x, s->primaries().red.x, 1e-14) << s->name();
        EXPECT_NEAR(r.y, s->primaries().red.y, 1e-14) << s->name();
        const Xy b = xyz_to_xy(s->to_xyz({0, 0, 1}));
        EXPECT_NEAR(b.x, s->primaries().blue.x, 1e-14) << s->name();
        EXPECT_EQ(find_rgb_space(s->name()), s);
    }
    EXPECT_EQ(builtin_rgb_spaces().size(), 8u);
    EXPECT_EQ(find_rgb_space("srgb-linear"), nullptr);
}

TEST(RgbSpace, LinearRgbRoundTripsThroughXyz) {
    for (const RgbSpace* s : builtin_rgb_spaces()) {
        for (const Rgb c : {Rgb{0.2, 0.5, 0.9}, Rgb{-0.3, 1.2, 0.0}, Rgb{1e-8, 0.0, 3.0}}) {
            const Rgb back = s->from_xyz(s->to_xyz(c));
            EXPECT_NEAR(back.r, c.r, 1e-13) << s->name();
            EXPECT_NEAR(back.g, c.g, 1e-13) << s->name();
            EXPECT_NEAR(back.b, c.b, 1e-13) << s->name();
        }
    }
}

TEST(TransferFunction, EncodingRoundTripsIncludingNegativeAndAboveOne) {
    for (const RgbSpace* s : builtin_rgb_spaces()) {
        for (const double v : {0.0, 1e-5, 0.002, 0.01, 0.018, 0.02, 0.18, 0.5, 1.0, 1.7, -0.25}) {
            const double e = s->transfer().encode(v);
            EXPECT_NEAR(s->transfer().decode(e), v, 1e-13 * std::max(1.0, std::abs(v))) << s->name();
            EXPECT_EQ(std::signbit(e), std::signbit(v)) << s->name();
        }
        EXPECT_NEAR(s->transfer().encode(1.0), 1.0, 1e-12) << s->name();
    }
}

TEST(TransferFunction, SrgbPiecesMeetAndMatchIec61966) {
    const TransferFunction f(TransferFunction::Kind::srgb);
    EXPECT_NEAR(f.encode(0.0031308), 12.92 * 0.0031308, 1e-15);
    EXPECT_NEAR(1.055 * std::pow(0.0031308, 1 / 2.4) - 0.055, 12.92 * 0.0031308, 1e-7);
    EXPECT_NEAR(f.decode(0.5), std::pow(0.555 / 1.055, 2.4), 1e-15);
    EXPECT_NEAR(f.decode(0.04), 0.04 / 12.92, 1e-17);
    // IEC's decoding switches at 0.04045; irid's exact inverse differs from it there by < 3e-9.
    EXPECT_NEAR(f.decode(0.04045), 0.04045 / 12.92, 3e-9);
}

TEST(TransferFunction, DecodingIsTheExactInverseAcrossEverySwitchPoint) {
    // Dense sweeps around each curve's break: sRGB 0.0031308, BT.2020 β; (BT.709's rounded
    // constants leave a 4e-5-wide band near 0.018 where the pieces overlap, see rgb.cpp.)
    for (const auto& [kind, knee] : {std::pair{TransferFunction::Kind::srgb, 0.0031308},
                                     std::pair{TransferFunction::Kind::rec2020, 0.018053968510807}}) {
        const TransferFunction f(kind);
        for (int i = -2000; i <= 2000; ++i) {
            const double v = knee * (1.0 + i * 1e-6);
            EXPECT_NEAR(f.decode(f.encode(v)), v, 1e-15) << v;
        }
    }
    const TransferFunction bt709(TransferFunction::Kind::rec709);
    for (const double v : {0.0, 0.001, 0.0179, 0.0182, 0.1, 0.9}) {
        EXPECT_NEAR(bt709.decode(bt709.encode(v)), v, 1e-15) << v;
    }
}

TEST(RgbSpace, MatricesMatchTheirPublishedValues) {
    // RGB → XYZ (D65 or C white), 7 decimals: Display P3 and Rec.2020 from CSS Color 4 §10;
    // Adobe RGB (1998) from its specification §4.3.4.1 (4 decimals); SMPTE-C and NTSC from
    // Lindbloom's RGB working space table, which scales to the ASTM E308 white XYZ instead of
    // the xy white: its Z row differs by 2.3e-4 (D65 Z 1.08883 vs 1.08906 from xy 0.3127,
    // 0.3290) and for NTSC by 1.2e-3 (C Z 1.18232 vs FCC's xy 0.310, 0.316 giving 1.18354).
    const struct {
        const RgbSpace* space;
        double m[3][3];
        double tolerance;
    } cases[] = {
        {&display_p3(),
         {{0.4865709, 0.2656677, 0.1982173}, {0.2289746, 0.6917385, 0.0792869}, {0.0, 0.0451134, 1.0439444}},
         1e-6},
        {&rec2020(),
         {{0.6369580, 0.1446169, 0.1688810}, {0.2627002, 0.6779981, 0.0593017}, {0.0, 0.0280727, 1.0609851}},
         1e-6},
        {&adobe_rgb(),
         {{0.5767, 0.1856, 0.1882}, {0.2974, 0.6273, 0.0753}, {0.0270, 0.0707, 0.9911}},
         3e-4},
        {&smpte_c(),
         {{0.3935891, 0.3652497, 0.1916313}, {0.2124132, 0.7010437, 0.0865432}, {0.0187423, 0.1119313, 0.9581563}},
         2.5e-4},
        {&ntsc1953(),
         {{0.6068909, 0.1735011, 0.2003480}, {0.2989164, 0.5865990, 0.1144845}, {0.0, 0.0660957, 1.1162243}},
         1.3e-3},
    };
    for (const auto& c : cases) {
        const Mat3& m = c.space->to_xyz_matrix();
        for (int i = 0; i < 3; ++i) {
            for (int j = 0; j < 3; ++j) {
                EXPECT_NEAR(m[i][j], c.m[i][j], c.tolerance) << c.space->name() << " " << i << "," << j;
            }
        }
    }
}

TEST(TransferFunction, Bt2020PiecesMeetAtBeta) {
    const TransferFunction f(TransferFunction::Kind::rec2020);
    const double beta = 0.018053968510807;
    EXPECT_NEAR(f.encode(beta * (1 - 1e-12)), f.encode(beta * (1 + 1e-12)), 1e-10);
    EXPECT_NEAR(f.encode(0.5), 1.09929682680944 * std::pow(0.5, 0.45) - 0.09929682680944, 1e-15);
}

TEST(TransferFunction, AdobeRgbIsAPurePowerLaw) {
    const TransferFunction& f = adobe_rgb().transfer();
    EXPECT_EQ(f.kind(), TransferFunction::Kind::gamma);
    EXPECT_DOUBLE_EQ(f.gamma(), 563.0 / 256.0);
    EXPECT_NEAR(f.decode(0.5), std::pow(0.5, 2.19921875), 1e-15);
    EXPECT_THROW(TransferFunction(TransferFunction::Kind::gamma, 0.0), Error);
}

TEST(RgbSpace, UserDefinedSpacesAreValidated) {
    const RgbSpace mine("mine", {{0.7, 0.3}, {0.2, 0.75}, {0.14, 0.05}}, {0.3127, 0.329},
                        TransferFunction(TransferFunction::Kind::gamma, 2.4));
    EXPECT_NEAR(mine.to_xyz({1, 1, 1}).Y, 1.0, 1e-14);
    EXPECT_THROW(RgbSpace("collinear", {{0.2, 0.2}, {0.3, 0.3}, {0.4, 0.4}}, {0.3127, 0.329},
                          TransferFunction(TransferFunction::Kind::linear)),
                 Error);
    EXPECT_THROW(RgbSpace("zero y", {{0.7, 0.0}, {0.2, 0.75}, {0.14, 0.05}}, {0.3127, 0.329},
                          TransferFunction(TransferFunction::Kind::linear)),
                 Error);
    EXPECT_THROW(RgbSpace("white outside", {{0.64, 0.33}, {0.30, 0.60}, {0.15, 0.06}}, {0.6, 0.2},
                          TransferFunction(TransferFunction::Kind::linear)),
                 Error);
    // ACES AP0 (SMPTE ST 2065-1) has an imaginary blue primary, y < 0; its white is ACES's
    // (0.32168, 0.33767) and its matrix's luminance row is 0.3439664, 0.7281661, −0.0721325.
    const RgbSpace ap0("aces-ap0", {{0.7347, 0.2653}, {0.0, 1.0}, {0.0001, -0.0770}},
                       {0.32168, 0.33767}, TransferFunction(TransferFunction::Kind::linear));
    EXPECT_NEAR(ap0.to_xyz_matrix()[1][0], 0.3439664, 1e-6);
    EXPECT_NEAR(ap0.to_xyz_matrix()[1][1], 0.7281661, 1e-6);
    EXPECT_NEAR(ap0.to_xyz_matrix()[1][2], -0.0721325, 1e-6);
}

// Academy S-2014-004 §4.1 and S-2008-001 (ST 2065-1) Annex: the published normalised primary
// matrices, to the ten decimals they are printed with.
TEST(RgbSpace, AcesMatricesAreThePublishedOnes) {
    const Mat3 ap0{{{{0.9525523959, 0.0000000000, 0.0000936786},
                    {0.3439664498, 0.7281660966, -0.0721325464},
                    {0.0000000000, 0.0000000000, 1.0088251844}}}};
    const Mat3 ap1{{{{0.6624541811, 0.1340042065, 0.1561876870},
                    {0.2722287168, 0.6740817658, 0.0536895174},
                    {-0.0055746495, 0.0040607335, 1.0103391003}}}};
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            EXPECT_NEAR(aces2065_1().to_xyz_matrix()[i][j], ap0[i][j], 1e-9) << i << j;
            EXPECT_NEAR(acescg().to_xyz_matrix()[i][j], ap1[i][j], 1e-9) << i << j;
        }
    }
    // AP1 → AP0 (S-2014-004 §4.3), same white: no adaptation.
    const Mat3 ap1_to_ap0 = aces2065_1().from_xyz_matrix() * acescg().to_xyz_matrix();
    const Mat3 published{{{{0.6954522414, 0.1406786965, 0.1638690622},
                          {0.0447945634, 0.8596711185, 0.0955343182},
                          {-0.0055258826, 0.0040252103, 1.0015006723}}}};
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) EXPECT_NEAR(ap1_to_ap0[i][j], published[i][j], 1e-9) << i << j;
    }
    EXPECT_EQ(find_rgb_space("aces2065-1"), &aces2065_1());
    EXPECT_EQ(find_rgb_space("acescg"), &acescg());
    EXPECT_EQ(acescg().transfer().kind(), TransferFunction::Kind::linear);
}


// --- ICC parametric and sampled curves -------------------------------------------------------

TEST(TransferFunction, ParametricTypesFollowIccTable68) {
    // ICC.1:2022 Table 68, each type at a few points against its formula.
    const double g = 2.2, a = 0.9, b = 0.1, c = 0.3, d = 0.2, e = 0.05, f = 0.01;
    const auto t0 = TransferFunction::parametric(0, std::vector{g});
    const auto t1 = TransferFunction::parametric(1, std::vector{g, a, b});
    const auto t2 = TransferFunction::parametric(2, std::vector{g, a, b, c});
    const auto t3 = TransferFunction::parametric(3, std::vector{g, a, b, c, d});
    const auto t4 = TransferFunction::parametric(4, std::vector{g, a, b, c, d, e, f});
    for (const double x : {0.0, 0.05, 0.15, 0.2, 0.5, 0.9, 1.0}) {
        EXPECT_NEAR(t0.decode(x), std::pow(x, g), 1e-15) << x;
        EXPECT_NEAR(t1.decode(x), std::pow(a * x + b, g), 1e-15) << x;  // -b/a < 0: always the power
        EXPECT_NEAR(t2.decode(x), std::pow(a * x + b, g) + c, 1e-15) << x;
        EXPECT_NEAR(t3.decode(x), x >= d ? std::pow(a * x + b, g) : c * x, 1e-15) << x;
        EXPECT_NEAR(t4.decode(x), x >= d ? std::pow(a * x + b, g) + e : c * x + f, 1e-15) << x;
    }
    // Type 1 below -b/a gives 0 (a curve that starts late).
    const auto late = TransferFunction::parametric(1, std::vector{2.0, 1.0, -0.25});
    EXPECT_EQ(late.decode(0.1), 0.0);
    EXPECT_NEAR(late.decode(0.75), 0.25, 1e-15);
}

TEST(TransferFunction, ParametricFormsOfTheBuiltinCurvesAreTheCurves) {
    using K = TransferFunction::Kind;
    for (const TransferFunction& t : {TransferFunction(K::srgb), TransferFunction(K::rec709),
                                     TransferFunction(K::rec2020), TransferFunction(K::gamma, 563.0 / 256.0),
                                     TransferFunction(K::linear)}) {
        const auto p = t.parameters();
        ASSERT_TRUE(p.has_value());
        const auto as_icc = TransferFunction::parametric(4, *p);
        for (int i = 0; i <= 1000; ++i) {
            const double x = i / 1000.0;
            EXPECT_NEAR(as_icc.decode(x), t.decode(x), 1e-12) << static_cast<int>(t.kind()) << " at " << x;
            EXPECT_NEAR(as_icc.encode(x), t.encode(x), 1e-12) << static_cast<int>(t.kind()) << " at " << x;
        }
        EXPECT_LT(as_icc.max_difference(t), 1e-12);
    }
}

TEST(TransferFunction, ParametricAndSampledCurvesRoundTripAndMirrorNegatives) {
    const auto p = TransferFunction::parametric(3, std::vector{2.4, 1 / 1.055, 0.055 / 1.055, 1 / 12.92, 0.04045});
    std::vector<double> table(1024);
    for (std::size_t i = 0; i < table.size(); ++i) table[i] = std::pow(static_cast<double>(i) / 1023.0, 1.8);
    const auto s = TransferFunction::sampled(table);
    for (const double v : {0.0, 1e-4, 0.002, 0.01, 0.2, 0.5, 0.99, 1.0, 1.5}) {
        EXPECT_NEAR(p.decode(p.encode(v)), v, 1e-12 * std::max(1.0, v)) << v;
        EXPECT_NEAR(s.decode(s.encode(v)), v, 1e-12 * std::max(1.0, v)) << v;
        EXPECT_EQ(p.encode(-v), -p.encode(v));
        EXPECT_EQ(s.decode(-v), -s.decode(v));
    }
    // At the nodes the table is the curve; between them, linear interpolation.
    EXPECT_DOUBLE_EQ(s.decode(512.0 / 1023.0), table[512]);
    EXPECT_NEAR(s.decode(512.5 / 1023.0), 0.5 * (table[512] + table[513]), 1e-15);
    // A flat run encodes to its lowest code.
    const auto flat = TransferFunction::sampled({0.0, 0.0, 0.5, 0.5, 1.0});
    EXPECT_DOUBLE_EQ(flat.encode(0.5), 0.5);
    EXPECT_DOUBLE_EQ(flat.encode(0.0), 0.0);
}

TEST(TransferFunction, NegativeOffsetsJumpsAndNanAreTakenAsTheyAre) {
    // Type 4 with e = f = -0.01: black decodes to -0.01 (not mirrored to +0.01).
    const auto t = TransferFunction::parametric(4, std::vector{2.2, 1.0, 0.0, 0.5, 0.0, -0.01, -0.01});
    EXPECT_DOUBLE_EQ(t.decode(0.0), -0.01);
    EXPECT_DOUBLE_EQ(t.decode(0.05), std::pow(0.05, 2.2) - 0.01);
    EXPECT_DOUBLE_EQ(t.decode(-0.05), -(std::pow(0.05, 2.2) - 0.01));  // mirrored by the input's sign
    // A curve that jumps up at d: encoding the top of the jump gives d, which decodes to it.
    const auto jump = TransferFunction::parametric(3, std::vector{1.0, 1.0, 0.12, 0.1, 0.2});
    const double top = jump.decode(0.2);
    EXPECT_DOUBLE_EQ(top, 0.32);
    EXPECT_GE(jump.encode(top), 0.2);
    EXPECT_DOUBLE_EQ(jump.decode(jump.encode(top)), top);
    EXPECT_DOUBLE_EQ(jump.encode(0.01), 0.1);   // the lower piece, 0.1 e
    EXPECT_DOUBLE_EQ(jump.encode(0.05), 0.2);   // inside the jump (0.02 to 0.32): d
    // NaN in, NaN out (no table index from it).
    const auto s = TransferFunction::sampled({0.0, 0.25, 1.0});
    EXPECT_TRUE(std::isnan(s.decode(std::nan(""))));
    EXPECT_TRUE(std::isnan(s.encode(std::nan(""))));
    EXPECT_TRUE(std::isnan(t.decode(std::nan(""))));
}

TEST(TransferFunction, RefusesCurvesThatAreNotDecodings) {
    // A type-4 curve that falls where its pieces meet.
    EXPECT_THROW((void)TransferFunction::parametric(4, std::vector{1.0, 1.0, 0.0, 1.0, 0.5, -0.3, 0.0}), Error);
    EXPECT_THROW((void)TransferFunction::parametric(5, std::vector{1.0}), Error);
    EXPECT_THROW((void)TransferFunction::parametric(3, std::vector{2.2, 1.0}), Error);
    EXPECT_THROW((void)TransferFunction::parametric(1, std::vector{2.2, -1.0, 0.0}), Error);
    EXPECT_THROW((void)TransferFunction::parametric(0, std::vector{0.0}), Error);
    EXPECT_THROW((void)TransferFunction::parametric(0, std::vector{std::nan("")}), Error);
    EXPECT_THROW((void)TransferFunction::parametric(3, std::vector{2.2, 1.0, 0.0, -1.0, 0.1}), Error);
    EXPECT_THROW((void)TransferFunction::sampled({0.5}), Error);
    EXPECT_THROW((void)TransferFunction::sampled({0.0, 0.6, 0.5, 1.0}), Error);
    EXPECT_THROW((void)TransferFunction::sampled({0.3, 0.3}), Error);
    EXPECT_THROW((void)TransferFunction(TransferFunction::Kind::sampled), Error);
}

// --- the display encodings ---------------------------------------------------------------

/// SMPTE ST 2084:2014 §5.3's inverse EOTF written out from its constants (BT.2100-2 Table 4),
/// for luminance in cd/m²: independent of irid/color/hdr_transfer.h.
double st2084_signal(double nits) {
    const double m1 = 2610.0 / 16384.0, m2 = 2523.0 / 4096.0 * 128.0;
    const double c1 = 3424.0 / 4096.0, c2 = 2413.0 / 4096.0 * 32.0, c3 = 2392.0 / 4096.0 * 32.0;
    const double y = std::pow(nits / 10000.0, m1);
    return std::pow((c1 + c2 * y) / (1.0 + c3 * y), m2);
}

TEST(TransferFunction, PqEncodesDisplayLightWithOneAtOneHundredNits) {
    const TransferFunction pq(TransferFunction::Kind::pq);
    for (const double nits : {0.0, 0.005, 1.0, 48.0, 100.0, 203.0, 1000.0, 4000.0, 10000.0}) {
        EXPECT_NEAR(pq.encode(nits / 100.0), st2084_signal(nits), 1e-12) << nits;
        EXPECT_NEAR(pq.decode(st2084_signal(nits)), nits / 100.0, 1e-9 * std::max(1.0, nits / 100.0)) << nits;
    }
    // ITU-R BT.2408-7 §2.2: the HDR reference white, 203 cd/m², is a PQ signal of 58 %.
    EXPECT_NEAR(pq.encode(2.03), 0.58, 0.001);
    // The signal holds 0 to 10000 cd/m²: beyond is clamped, a negative value is black, NaN too.
    EXPECT_DOUBLE_EQ(pq.encode(100.0), 1.0);
    EXPECT_DOUBLE_EQ(pq.encode(250.0), 1.0);
    EXPECT_EQ(pq.encode(-0.5), pq.encode(0.0));
    EXPECT_EQ(pq.encode(std::nan("")), pq.encode(0.0));
    EXPECT_EQ(pq.decode(-0.5), 0.0);
    EXPECT_EQ(pq.decode(pq.encode(0.0)), 0.0);
    EXPECT_DOUBLE_EQ(pq.decode(1.5), 100.0);
    EXPECT_EQ(pq.decode(std::nan("")), 0.0);
    EXPECT_FALSE(pq.parameters().has_value());
    // It rises and round-trips over its whole range.
    double last = -1.0;
    for (int i = 0; i <= 400; ++i) {
        const double v = 100.0 * std::pow(10.0, -0.02 * i);  // 100 down to 1e-6
        const double e = pq.encode(v);
        EXPECT_NEAR(pq.decode(e), v, 1e-9 * v + 1e-15) << v;
        if (i > 0) {
            EXPECT_LT(e, last) << v;
        }
        last = e;
    }
}

TEST(RgbSpace, DisplayEncodingsAreNamedSpacesButNotWorkingSpaces) {
    // BT.1886 with a black of 0 is a pure 2.4 power law on the BT.709 primaries.
    EXPECT_DOUBLE_EQ(rec1886().decode({0.5, 0.25, 1.0}).r, std::pow(0.5, 2.4));
    EXPECT_DOUBLE_EQ(p3_d65().decode({0.5, 0.25, 1.0}).g, std::pow(0.25, 2.6));
    const auto same_primaries = [](const RgbSpace& a, const RgbSpace& b) {
        for (int i = 0; i < 3; ++i) {
            for (int j = 0; j < 3; ++j) {
                if (a.to_xyz_matrix()[i][j] != b.to_xyz_matrix()[i][j]) return false;
            }
        }
        return true;
    };
    EXPECT_TRUE(same_primaries(rec1886(), srgb()));
    EXPECT_TRUE(same_primaries(rec2100_pq(), rec2020()));
    EXPECT_TRUE(same_primaries(rec1886_rec2020(), rec2020()));
    EXPECT_DOUBLE_EQ(rec1886_rec2020().decode({0.5, 0.25, 1.0}).r, std::pow(0.5, 2.4));
    EXPECT_TRUE(same_primaries(p3_d65_pq(), display_p3()));
    EXPECT_TRUE(same_primaries(p3_d65(), display_p3()));
    EXPECT_EQ(rec2100_pq().transfer().kind(), TransferFunction::Kind::pq);
    for (const RgbSpace* s : display_rgb_spaces()) {
        EXPECT_EQ(find_rgb_space(s->name()), s);
        for (const RgbSpace* w : builtin_rgb_spaces()) EXPECT_NE(w, s);
    }
    EXPECT_EQ(display_rgb_spaces().size(), 6U);
}

TEST(TransferFunction, AcesCctMatchesS2016001) {
    // Academy S-2016-001 §4.4: the toe 10.5402377416545 x + 0.0729055341958355 to x = 2^-7,
    // whose code value is 0.155251141552511; above, (log2 x + 9.72) / 17.52.
    const TransferFunction& t = acescct().transfer();
    EXPECT_EQ(t.kind(), TransferFunction::Kind::acescct);
    EXPECT_NEAR(t.encode(0.0), 0.0729055341958355, 1e-15);
    EXPECT_NEAR(t.encode(0.0078125), 0.155251141552511, 1e-14);
    EXPECT_NEAR(t.encode(0.18), (std::log2(0.18) + 9.72) / 17.52, 1e-15);
    EXPECT_NEAR(t.encode(0.18), 0.4135884, 1e-7);  // the ACEScct mid grey ACES documents
    EXPECT_NEAR(t.encode(1.0), 9.72 / 17.52, 1e-15);
    // Not mirrored: a negative takes the toe (S-2016-001 defines it on all reals).
    EXPECT_NEAR(t.encode(-0.01), 0.0729055341958355 - 0.105402377416545, 1e-15);
    EXPECT_NEAR(t.decode(1.0), std::exp2(7.8), 1e-10);  // 222.86
    EXPECT_NEAR(t.decode(0.0), -0.0729055341958355 / 10.5402377416545, 1e-15);
    // The pieces meet at the break (value and, nearly, slope).
    const double h = 1e-9;
    EXPECT_NEAR(t.encode(0.0078125 + h), t.encode(0.0078125), 1e-7);
    EXPECT_NEAR((t.encode(0.0078125 + h) - t.encode(0.0078125)) / h, 10.5402377416545, 1e-4);
    for (const double v : {-5.0, -0.5, -1e-6, 0.0, 1e-6, 0.0078125, 0.0078126, 0.18, 1.0, 16.0, 222.86, 65504.0}) {
        EXPECT_NEAR(t.decode(t.encode(v)), v, 1e-12 * std::max(1.0, std::abs(v))) << v;
    }
    for (const double e : {-0.5, 0.0, 0.1, 0.155251141552511, 0.2, 0.5, 1.0, 1.5}) {
        EXPECT_NEAR(t.encode(t.decode(e)), e, 1e-13) << e;
    }
}

TEST(RgbSpace, AcesCctIsAP1WithTheAcesWhiteAndNamedButNoWorkingSpace) {
    const RgbSpace& s = acescct();
    EXPECT_EQ(s.name(), "acescct");
    EXPECT_EQ(find_rgb_space("acescct"), &s);
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) EXPECT_EQ(s.to_xyz_matrix()[i][j], acescg().to_xyz_matrix()[i][j]);
    }
    for (const RgbSpace* w : builtin_rgb_spaces()) EXPECT_NE(w, &s);
    const std::vector<std::string> names = rgb_space_names();
    EXPECT_NE(std::find(names.begin(), names.end(), "acescct"), names.end());
}


// ITU-R BT.2100-2 Table 5: a = 0.17883277, b = 1 - 4a, c = 0.5 - a ln(4a); the OETF and its
// inverse, written here from the table for the tests.
constexpr double hlg_a = 0.17883277;
double bt2100_oetf(double e) {
    return e <= 1.0 / 12.0 ? std::sqrt(3.0 * e) : hlg_a * std::log(12.0 * e - (1.0 - 4.0 * hlg_a)) +
                                                      0.5 - hlg_a * std::log(4.0 * hlg_a);
}

TEST(RgbSpace, Rec2100HlgIsBt2100sHlgOnAThousandNitDisplay) {
    const RgbSpace& hlg = rec2100_hlg();
    EXPECT_EQ(find_rgb_space("rec2100-hlg"), &hlg);
    EXPECT_EQ(hlg.transfer().kind(), TransferFunction::Kind::hlg);
    EXPECT_FALSE(hlg.transfer().parameters().has_value());
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) EXPECT_EQ(hlg.to_xyz_matrix()[i][j], rec2020().to_xyz_matrix()[i][j]);
    // Signal 1 is the nominal peak, 1000 cd/m² (linear 10); signal 0.5 is scene light 1/12, shown
    // at 1000 (1/12)^1.2 cd/m² (system gamma 1.2 at 1000 cd/m², Table 5 note 5b).
    EXPECT_NEAR(hlg.decode({1.0, 1.0, 1.0}).g, 10.0, 1e-12);
    // (Table 5's a, b, c, given to 8 decimals, put the OETF of E = 1 at 1 - 4.9e-9.)
    EXPECT_NEAR(hlg.encode({10.0, 10.0, 10.0}).b, 1.0, 1e-8);
    EXPECT_NEAR(hlg.decode({0.5, 0.5, 0.5}).r, 10.0 * std::pow(1.0 / 12.0, 1.2), 1e-12);
    // ITU-R BT.2408-7 §2.2: the HDR reference white, 203 cd/m², is an HLG signal of 75 %.
    EXPECT_NEAR(hlg.encode({2.03, 2.03, 2.03}).r, 0.75, 0.001);
    EXPECT_NEAR(hlg.decode({0.75, 0.75, 0.75}).r * 100.0, 203.0, 1.0);
    // The single-value curve is the neutral axis.
    EXPECT_EQ(hlg.transfer().encode(2.03), hlg.encode({2.03, 2.03, 2.03}).g);
    EXPECT_EQ(hlg.transfer().decode(0.75), hlg.decode({0.75, 0.75, 0.75}).b);
    // The OOTF acts on luminance Y_S = 0.2627 R + 0.6780 G + 0.0593 B (Table 5), not per channel:
    // a pure red of display light F_R is scene light E_R = F_R / (L_W Y_S^0.2) with Y_S^1.2 =
    // 0.2627 F_R / L_W, and its signal differs from the same value of a grey.
    for (const double red : {0.05, 0.8, 2.0}) {
        const double f = 100.0 * red / 1000.0;              // F_D / L_W
        const double ys = std::pow(0.2627 * f, 1.0 / 1.2);  // Y_D / L_W = Y_S^γ
        const double e = f / std::pow(ys, 0.2);
        const Rgb signal = hlg.encode({red, 0.0, 0.0});
        EXPECT_NEAR(signal.r, bt2100_oetf(std::min(e, 1.0)), 1e-12) << red;
        EXPECT_EQ(signal.g, 0.0);
        EXPECT_GT(std::abs(signal.r - hlg.transfer().encode(red)), 0.01) << red;
        EXPECT_NEAR(hlg.decode(signal).r, e <= 1.0 ? red : hlg.decode(signal).r, 1e-12) << red;
    }
    // Every signal round-trips: decode, then encode, gives it back.
    std::mt19937 rng(2100);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int i = 0; i < 2000; ++i) {
        const Rgb s{unit(rng), unit(rng), unit(rng)};
        const Rgb back = hlg.encode(hlg.decode(s));
        EXPECT_NEAR(back.r, s.r, 1e-9);
        EXPECT_NEAR(back.g, s.g, 1e-9);
        EXPECT_NEAR(back.b, s.b, 1e-9);
    }
    // Not mirrored: a negative channel is 0 cd/m² (and NaN too); beyond what the signal holds
    // (above 1000 cd/m² of white, or scene light above 1) it is clamped; signals to [0, 1].
    EXPECT_EQ(hlg.encode({-0.5, 1.0, 1.0}).r, 0.0);
    EXPECT_EQ(hlg.encode({-0.5, 1.0, 1.0}).g, hlg.encode({0.0, 1.0, 1.0}).g);
    EXPECT_EQ(hlg.encode({std::nan(""), 1.0, 1.0}).g, hlg.encode({0.0, 1.0, 1.0}).g);
    EXPECT_EQ(hlg.encode({50.0, 50.0, 50.0}).r, hlg.encode({10.0, 10.0, 10.0}).r);
    EXPECT_NEAR(hlg.encode({50.0, 50.0, 50.0}).r, 1.0, 1e-8);
    EXPECT_EQ(hlg.encode({0.0, 0.0, 9.0}).b, hlg.encode({10.0, 10.0, 10.0}).b);  // blue alone is never that bright
    EXPECT_EQ(hlg.decode({1.5, 1.5, 1.5}).r, hlg.decode({1.0, 1.0, 1.0}).r);
    EXPECT_EQ(hlg.decode({-0.5, -0.5, -0.5}).r, 0.0);
    // A display encoding, not a working space.
    for (const RgbSpace* w : builtin_rgb_spaces()) EXPECT_NE(w, &hlg);
}

}  // namespace
}  // namespace irid
