// The ACES 2.0 rendering against OpenColorIO's published test vectors (data/ocio-aces2), at
// OpenColorIO's tolerance: |error| / max(|expected|, 1) <= 1e-5 forward.
#include <irid/error.h>
#include <irid/gamut/aces2.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace irid {
namespace {

constexpr double ocio_tolerance = 1e-5;

/// The rows of a vectors file: 7 numbers (input 3, alpha, output 3).
std::vector<std::array<double, 7>> vectors(const std::string& name) {
    std::ifstream in(std::string(IRID_SOURCE_DIR) + "/data/ocio-aces2/" + name);
    EXPECT_TRUE(in.good()) << name;
    std::vector<std::array<double, 7>> rows;
    std::string line;
    while (std::getline(in, line)) {
        if (line.empty() || line[0] == '#' || !(std::isdigit(static_cast<unsigned char>(line[0])) || line[0] == '-'))
            continue;
        std::replace(line.begin(), line.end(), ',', ' ');
        std::istringstream s(line);
        std::array<double, 7> r{};
        for (double& v : r) s >> v;
        EXPECT_FALSE(s.fail()) << line;
        rows.push_back(r);
    }
    return rows;
}

double relative_error(double got, double expected) {
    return std::abs(got - expected) / std::max(std::abs(expected), 1.0);
}

/// Hue differences wrap: 359.99999 and 0 are 1e-5 apart.
double hue_error(double got, double expected) {
    double d = std::fmod(std::abs(got - expected), 360.0);
    return std::min(d, 360.0 - d) / std::max(std::abs(expected), 1.0);
}

const Aces2Display p3_1000{1000.0, {{0.680, 0.320}, {0.265, 0.690}, {0.150, 0.060}}, {0.3127, 0.3290}};

const Aces2Rendering& rendering() {
    static const Aces2Rendering r(p3_1000);
    return r;
}

TEST(Aces2, RgbToJmhMatchesOpenColorIO) {
    const auto rows = vectors("aces_rgb_to_jmh_20.csv");
    ASSERT_EQ(rows.size(), 27u);
    for (const auto& r : rows) {
        const Aces2Jmh j = rendering().input_model().rgb_to_jmh({r[0], r[1], r[2]});
        EXPECT_LE(relative_error(j.J, r[4]), ocio_tolerance) << r[0] << " " << r[1] << " " << r[2];
        EXPECT_LE(relative_error(j.M, r[5]), ocio_tolerance) << r[0] << " " << r[1] << " " << r[2];
        EXPECT_LE(hue_error(j.h, r[6]), ocio_tolerance) << r[0] << " " << r[1] << " " << r[2];
    }
}

TEST(Aces2, TonescaleAndChromaCompressionMatchOpenColorIO) {
    const auto rows = vectors("aces_tonescale_compress_20.csv");
    ASSERT_EQ(rows.size(), 27u);
    for (const auto& r : rows) {
        const Aces2Jmh j = rendering().tonescale_and_chroma_forward({r[0], r[1], r[2]});
        EXPECT_LE(relative_error(j.J, r[4]), ocio_tolerance) << r[0] << " " << r[1] << " " << r[2];
        EXPECT_LE(relative_error(j.M, r[5]), ocio_tolerance) << r[0] << " " << r[1] << " " << r[2];
        EXPECT_LE(hue_error(j.h, r[6]), ocio_tolerance);
    }
}

TEST(Aces2, GamutCompressionMatchesOpenColorIO) {
    const auto rows = vectors("aces_gamut_map_20.csv");
    ASSERT_EQ(rows.size(), 27u);
    for (const auto& r : rows) {
        const Aces2Jmh j = rendering().gamut_compress_forward({r[0], r[1], r[2]});
        EXPECT_LE(relative_error(j.J, r[4]), ocio_tolerance) << r[0] << " " << r[1] << " " << r[2];
        EXPECT_LE(relative_error(j.M, r[5]), ocio_tolerance) << r[0] << " " << r[1] << " " << r[2];
        EXPECT_LE(hue_error(j.h, r[6]), ocio_tolerance);
    }
}

TEST(Aces2, TheWholeTransformMatchesOpenColorIO) {
    const auto rows = vectors("aces_output_transform_20.csv");
    ASSERT_EQ(rows.size(), 35u);
    for (const auto& r : rows) {
        const Vec3 out = rendering().forward({r[0], r[1], r[2]});
        for (int c = 0; c < 3; ++c)
            EXPECT_LE(relative_error(out[c], r[4 + c]), ocio_tolerance) << r[0] << " " << r[1] << " " << r[2] << " channel " << c;
    }
}

TEST(Aces2, ForwardThenInverseReturnsTheVectorsInputs) {
    // OpenColorIO's round-trip tolerance is 1e-4; the double inverse is far closer.
    for (const auto& r : vectors("aces_output_transform_20.csv")) {
        const Vec3 back = rendering().inverse(rendering().forward({r[0], r[1], r[2]}));
        for (int c = 0; c < 3; ++c) EXPECT_LE(relative_error(back[c], r[c]), 1e-9) << r[0] << " " << r[1] << " " << r[2];
    }
}

TEST(Aces2, GreysAreNeutralAndMidGreyIsThePublishedLuminance) {
    // ACES 2.0 shows 18 % grey at 10 cd/m² on a 100 cd/m² display (aces-docs, "Output
    // Transforms"; the curve's anchor c_d = 10.013 makes it 10.00). Brighter displays show it
    // brighter (w_g = 0.14 per stop of peak).
    const Aces2Display rec709_100{100.0, {{0.64, 0.33}, {0.30, 0.60}, {0.15, 0.06}}, {0.3127, 0.3290}};
    EXPECT_NEAR(Aces2Rendering(rec709_100).forward({0.18, 0.18, 0.18})[1], 0.1000, 0.0001);
    EXPECT_GT(rendering().forward({0.18, 0.18, 0.18})[1], 0.1);
    for (const Aces2Display& d : {rec709_100, p3_1000}) {
        const Aces2Rendering r(d);
        // Greys stay neutral (the ACES white becomes the display's) and rise with exposure,
        // from near black to beyond the roof.
        double last = -1.0;
        for (double e = 1.0 / 1024.0; e <= 4096.0; e *= 1.25) {
            const Vec3 out = r.forward({e, e, e});
            EXPECT_NEAR(out[0], out[1], 1e-9 * std::max(1.0, out[1])) << e;
            EXPECT_NEAR(out[2], out[1], 1e-9 * std::max(1.0, out[1])) << e;
            EXPECT_GT(out[1], last) << e;
            last = out[1];
        }
    }
}

TEST(Aces2, PeaksOutsideTheTransformsRangeAreRefused) {
    Aces2Display d = p3_1000;
    for (double peak : {99.0, 10001.0, std::nan("")}) {
        d.peak_nits = peak;
        EXPECT_THROW(Aces2Rendering{d}, Error) << peak;
    }
}

}  // namespace
}  // namespace irid
