#include <irid/color/rgb.h>
#include <irid/color/spaces.h>
#include <irid/error.h>

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

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
    EXPECT_EQ(builtin_rgb_spaces().size(), 6u);
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
    EXPECT_NEAR(f.decode(0.04045), 0.04045 / 12.92, 1e-15);
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
}

}  // namespace
}  // namespace irid
