#include <irid/color/convert.h>
#include <irid/error.h>
#include <irid/exchange/lut.h>
#include <irid/exchange/ocio_config.h>
#include <irid/gamut/pipeline.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace irid {
namespace {

ClipPipeline pipeline(ClipMethod method, const char* from, const char* to) {
    return ClipPipeline(method, color_space(from), color_space(to));
}

std::vector<std::string> lines_of(const std::string& text) {
    std::vector<std::string> out;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) out.push_back(line);
    return out;
}

/// A LUT whose nodes hold an affine map of their inputs: every interpolation reproduces it.
Lut3D affine_lut(int size, const LutDomain& domain) {
    Lut3D lut;
    lut.size = size;
    lut.domain = domain;
    lut.title = "affine";
    lut.source = "a";
    lut.destination = "b";
    for (int b = 0; b < size; ++b) {
        for (int g = 0; g < size; ++g) {
            for (int r = 0; r < size; ++r) {
                const double x = r / double(size - 1), y = g / double(size - 1), z = b / double(size - 1);
                lut.values.push_back(static_cast<float>(0.5 * x + 0.25 * y - 0.125 * z + 0.1));
                lut.values.push_back(static_cast<float>(-0.3 * x + 0.9 * y + 0.2 * z));
                lut.values.push_back(static_cast<float>(0.05 * x + 0.1 * y + 0.7 * z - 0.2));
            }
        }
    }
    return lut;
}

TEST(LutShaper, ShapeAndUnshapeAreInverses) {
    for (const LutDomain& d : {LutDomain{}, LutDomain{LutShaper::none, -0.5, 4.0, 14},
                               LutDomain{LutShaper::log2, 0.0, 16.0, 14},
                               LutDomain{LutShaper::log2, -0.01, 1.0, 8}}) {
        for (int i = 0; i <= 1000; ++i) {
            const double s = i / 1000.0;
            EXPECT_NEAR(lut_shape(d, lut_unshape(d, s)), s, 1e-12) << s;
        }
        EXPECT_EQ(lut_unshape(d, 0.0), d.min);
        EXPECT_DOUBLE_EQ(lut_unshape(d, 1.0), d.max);
        EXPECT_EQ(lut_shape(d, d.min - 1.0), 0.0);
        EXPECT_EQ(lut_shape(d, d.max + 1.0), 1.0);
        EXPECT_EQ(lut_shape(d, std::nan("")), 0.0);
    }
}

TEST(LutShaper, Log2NodesAreEvenInStopsBelowTheTop) {
    // s(x) = log2((x − min + e) / e) / log2(1 + 2^stops), e = (max − min) 2^−stops: well above
    // e, equal steps of s are equal ratios of x − min + e.
    const LutDomain d{LutShaper::log2, 0.0, 16.0, 14};
    const double e = 16.0 / std::exp2(14);
    const double step = std::log2(1.0 + std::exp2(14)) / 32.0;  // stops per node of a 33³ LUT
    for (int i = 1; i < 32; ++i) {
        const double ratio = (lut_unshape(d, (i + 1) / 32.0) + e) / (lut_unshape(d, i / 32.0) + e);
        EXPECT_NEAR(std::log2(ratio), step, 1e-12);
    }
    // Half the nodes lie in the seven stops below the top.
    EXPECT_NEAR(lut_unshape(d, 0.5) + e, std::sqrt(e * (16.0 + e)), 1e-12);
}

TEST(Lut, InterpolationsReproduceAnAffineMap) {
    std::mt19937 rng(13);
    for (const LutDomain& d : {LutDomain{}, LutDomain{LutShaper::none, -1.0, 3.0, 14}}) {
        const Lut3D lut = affine_lut(9, d);
        std::uniform_real_distribution<double> u(d.min, d.max);
        for (int k = 0; k < 500; ++k) {
            const Vec3 in{u(rng), u(rng), u(rng)};
            const double x = lut_shape(d, in[0]), y = lut_shape(d, in[1]), z = lut_shape(d, in[2]);
            const Rgb want{0.5 * x + 0.25 * y - 0.125 * z + 0.1, -0.3 * x + 0.9 * y + 0.2 * z,
                           0.05 * x + 0.1 * y + 0.7 * z - 0.2};
            for (const auto how : {LutInterpolation::trilinear, LutInterpolation::tetrahedral}) {
                const Rgb got = apply_lut(lut, in, how);
                EXPECT_NEAR(got.r, want.r, 1e-6);
                EXPECT_NEAR(got.g, want.g, 1e-6);
                EXPECT_NEAR(got.b, want.b, 1e-6);
            }
        }
    }
}

TEST(Lut, TetrahedralAndTrilinearDifferOffTheDiagonalOfACell) {
    // One cell, a value only at (1, 1, 0): trilinear weighs it by fr·fg·(1 − fb); tetrahedral
    // takes the tetrahedron the point lies in (fr > fg > fb: c000, c100, c110, c111) and gives
    // fg − fb.
    Lut3D lut;
    lut.size = 2;
    lut.values.assign(24, 0.0f);
    lut.values[3 * (1 + 2 * 1)] = 1.0f;
    const Vec3 p{0.7, 0.4, 0.1};
    EXPECT_NEAR(apply_lut(lut, p, LutInterpolation::trilinear).r, 0.7 * 0.4 * 0.9, 1e-7);
    EXPECT_NEAR(apply_lut(lut, p, LutInterpolation::tetrahedral).r, 0.4 - 0.1, 1e-7);
}

TEST(Lut, ClampOfASpaceOntoItselfIsTheIdentityAtEveryNode) {
    const Lut3D lut = bake_lut(pipeline(ClipMethod::clamp, "srgb-linear", "srgb-linear"), 17);
    ASSERT_EQ(lut.values.size(), 3u * 17 * 17 * 17);
    for (int b = 0; b < 17; ++b) {
        for (int g = 0; g < 17; ++g) {
            for (int r = 0; r < 17; ++r) {
                const float* v = &lut.values[3 * (r + 17 * (g + 17 * b))];
                EXPECT_FLOAT_EQ(v[0], static_cast<float>(r / 16.0));
                EXPECT_FLOAT_EQ(v[1], static_cast<float>(g / 16.0));
                EXPECT_FLOAT_EQ(v[2], static_cast<float>(b / 16.0));
            }
        }
    }
}

TEST(Lut, NodesHoldTheMethodAtTheirInputs) {
    // The double method (what `irid clip` prints) at each node's input, encoded: the float
    // batch path that baked the LUT agrees within 1e-5.
    const ClipPipeline p = pipeline(ClipMethod::oklab_cusp, "acescg-linear", "srgb");
    const LutDomain d{LutShaper::log2, 0.0, 4.0, 12};
    const Lut3D lut = bake_lut(p, 9, d);
    for (int b = 0; b < 9; ++b) {
        for (int g = 0; g < 9; ++g) {
            for (int r = 0; r < 9; ++r) {
                const std::vector<double> in{lut.node(r), lut.node(g), lut.node(b)};
                std::vector<double> out(3);
                p.clip(std::span<const double>(in), std::span<double>(out), 1);
                const float* v = &lut.values[3 * (r + 9 * (g + 9 * b))];
                for (int c = 0; c < 3; ++c) EXPECT_NEAR(v[c], out[c], 1e-5) << r << " " << g << " " << b;
            }
        }
    }
}

TEST(Lut, TitleNamesVersionMethodParametersAndSpaces) {
    ClipPipelineOptions o;
    o.settings.set("threshold", 0.7);
    const Lut3D lut = bake_lut(
        ClipPipeline(ClipMethod::smits_soft, color_space("rec2020-linear"), color_space("srgb"), o), 5);
    EXPECT_NE(lut.title.find("irid " + std::string(irid_version())), std::string::npos) << lut.title;
    EXPECT_NE(lut.title.find("--method smits-soft"), std::string::npos) << lut.title;
    EXPECT_NE(lut.title.find("threshold=0.7"), std::string::npos) << lut.title;
    EXPECT_NE(lut.title.find("--from rec2020-linear --to srgb"), std::string::npos) << lut.title;
    for (const LutFormat f : {LutFormat::cube, LutFormat::clf, LutFormat::spi3d}) {
        EXPECT_NE(lut_text(lut, f).find("threshold=0.7"), std::string::npos) << lut_format_name(f);
    }
}

TEST(LutText, CubeIsRedFastestAndStatesARangeOnlyWhenItIsNotTheUnitCube) {
    const Lut3D unit = affine_lut(3, {});
    const std::vector<std::string> lines = lines_of(lut_text(unit, LutFormat::cube));
    ASSERT_EQ(lines.size(), 2u + 1u + 27u);
    EXPECT_EQ(lines[0], "# affine");
    EXPECT_EQ(lines[2], "LUT_3D_SIZE 3");
    // Line 1 of the data is node (r = 1, g = 0, b = 0): 0.5·0.5 + 0.1 = 0.35, −0.15, −0.175.
    std::istringstream second(lines[4]);
    double r = 0, g = 0, b = 0;
    second >> r >> g >> b;
    EXPECT_NEAR(r, 0.35, 1e-7);
    EXPECT_NEAR(g, -0.15, 1e-7);
    EXPECT_NEAR(b, -0.175, 1e-7);

    const Lut3D wide = affine_lut(3, LutDomain{LutShaper::none, -0.25, 4.0, 14});
    const std::vector<std::string> w = lines_of(lut_text(wide, LutFormat::cube));
    EXPECT_EQ(w[2], "LUT_3D_INPUT_RANGE -0.25 4");  // ahead of the size: ffmpeg skips it there
    EXPECT_EQ(w[3], "LUT_3D_SIZE 3");
}

TEST(LutText, ClfIsBlueFastestAndSpi3dNamesItsIndices) {
    const Lut3D lut = affine_lut(3, {});
    const std::string clf = lut_text(lut, LutFormat::clf);
    EXPECT_NE(clf.find("<Array dim=\"3 3 3 3\">"), std::string::npos);
    EXPECT_NE(clf.find("interpolation=\"tetrahedral\""), std::string::npos);
    const std::vector<std::string> lines = lines_of(clf);
    std::size_t first = 0;
    while (first < lines.size() && lines[first].find("<Array") == std::string::npos) ++first;
    // The second entry is node (r = 0, g = 0, b = 1): −0.125·0.5 + 0.1, 0.1, 0.35 − 0.2.
    std::istringstream second(lines[first + 2]);
    double r = 0, g = 0, b = 0;
    second >> r >> g >> b;
    EXPECT_NEAR(r, 0.0375, 1e-7);
    EXPECT_NEAR(g, 0.1, 1e-7);
    EXPECT_NEAR(b, 0.15, 1e-7);

    const std::vector<std::string> spi = lines_of(lut_text(lut, LutFormat::spi3d));
    ASSERT_EQ(spi.size(), 3u + 27u + 1u);
    EXPECT_EQ(spi[0], "SPILUT 1.0");
    EXPECT_EQ(spi[2], "3 3 3");
    EXPECT_EQ(spi[4].substr(0, 6), "1 0 0 ");
    EXPECT_EQ(spi.back().substr(0, 9), "# affine;");
}

TEST(LutText, ClfLogShaperParametersAreTheShaper) {
    // OCIO's linToLog: y = logSideSlope · log2(linSideSlope · x + linSideOffset) + logSideOffset.
    const LutDomain d{LutShaper::log2, 0.0, 16.0, 14};
    Lut3D lut = affine_lut(3, d);
    const std::string clf = lut_text(lut, LutFormat::clf);
    auto attribute = [&](const std::string& name) {
        const std::size_t at = clf.find(name + "=\"");
        EXPECT_NE(at, std::string::npos) << name;
        return std::stod(clf.substr(at + name.size() + 2));
    };
    const double slope = attribute("logSideSlope"), offset = attribute("logSideOffset");
    const double lin_offset = attribute("linSideOffset"), lin_slope = attribute("linSideSlope");
    for (const double x : {0.0, 1e-4, 0.01, 0.18, 1.0, 7.5, 16.0}) {
        EXPECT_NEAR(slope * std::log2(lin_slope * x + lin_offset) + offset, lut_shape(d, x), 1e-12) << x;
    }
}

TEST(LutFormat, ExtensionsPickTheFormatAndAnotherIsRefused) {
    EXPECT_EQ(lut_format_for("look.cube"), LutFormat::cube);
    EXPECT_EQ(lut_format_for("dir.x/LOOK.CLF"), LutFormat::clf);
    EXPECT_EQ(lut_format_for("a.spi3d"), LutFormat::spi3d);
    EXPECT_THROW((void)lut_format_for("a.3dl"), UnknownNameError);
    EXPECT_THROW((void)lut_format_for("cube"), UnknownNameError);
}

TEST(LutRefusals, BadSizesDomainsAndFormatsAreRefusedWithTheirLimits) {
    const ClipPipeline p = pipeline(ClipMethod::smits, "srgb-linear", "srgb");
    EXPECT_THROW((void)bake_lut(p, 1), Error);
    EXPECT_THROW((void)bake_lut(p, 130), Error);
    EXPECT_THROW((void)bake_lut(p, 5, LutDomain{LutShaper::none, 1.0, 1.0, 14}), Error);
    EXPECT_THROW((void)bake_lut(p, 5, LutDomain{LutShaper::none, 0.0, std::nan(""), 14}), Error);
    EXPECT_THROW((void)bake_lut(p, 5, LutDomain{LutShaper::log2, 0.0, 1.0, 0}), Error);
    EXPECT_THROW((void)bake_lut(p, 5, {}, -1), Error);
    try {
        (void)bake_lut(p, 200);
        FAIL();
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("2 to 129"), std::string::npos) << e.what();
    }
    // A cube's axes are one range: Lab or xyY inputs are not.
    EXPECT_THROW((void)bake_lut(pipeline(ClipMethod::smits, "lab", "srgb"), 5), Error);

    const Lut3D shaped = bake_lut(p, 5, LutDomain{LutShaper::log2, 0.0, 8.0, 10});
    EXPECT_THROW((void)lut_text(shaped, LutFormat::cube), Error);
    EXPECT_THROW((void)lut_text(shaped, LutFormat::spi3d), Error);
    EXPECT_NO_THROW((void)lut_text(shaped, LutFormat::clf));
    const Lut3D wide = bake_lut(p, 5, LutDomain{LutShaper::none, 0.0, 2.0, 14});
    EXPECT_THROW((void)lut_text(wide, LutFormat::spi3d), Error);
    EXPECT_NO_THROW((void)lut_text(wide, LutFormat::cube));

    Lut3D bad = wide;
    bad.values.pop_back();
    EXPECT_THROW((void)lut_text(bad, LutFormat::cube), Error);
    bad = wide;
    bad.title = "two\nlines";
    EXPECT_THROW((void)lut_text(bad, LutFormat::cube), Error);
}

TEST(LutFile, WriteLutWritesTheTextAndNeverReplacesADirectory) {
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / "irid_lut_test";
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir / "taken.cube");
    const Lut3D lut = affine_lut(3, {});
    write_lut(dir / "look.spi3d", lut);
    std::ifstream in(dir / "look.spi3d");
    std::stringstream text;
    text << in.rdbuf();
    EXPECT_EQ(text.str(), lut_text(lut, LutFormat::spi3d));
    EXPECT_THROW(write_lut(dir / "taken.cube", lut), Error);
    EXPECT_TRUE(std::filesystem::is_directory(dir / "taken.cube"));
    std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace irid

namespace irid {
namespace {

TEST(OcioConfig, TheLookRunsInTheDisplaysLinearSpaceOnNodesThatHoldTheCube) {
    // acescg-linear to the srgb display with clamp: the look's LUT is the clamp itself on nodes
    // in srgb-linear, 0 and 1 among them, the shaper linear between nodes.
    OcioConfigOptions o;
    o.source = color_space("acescg-linear");
    o.display = color_space("srgb");
    o.methods = {ClipMethod::clamp};
    o.size = 17;
    const OcioConfig c = make_ocio_config(o);
    ASSERT_EQ(c.luts.size(), 1u);
    EXPECT_EQ(c.luts[0].first, "luts/irid-clamp.clf");
    const Lut3D& lut = c.luts[0].second;
    ASSERT_EQ(lut.domain.shaper, LutShaper::nodes);
    EXPECT_EQ(lut.source, "srgb-linear");
    EXPECT_EQ(lut.destination, "srgb-linear");
    const std::vector<double>& x = lut.domain.nodes;
    ASSERT_EQ(x.size(), 17u);
    EXPECT_NE(std::find(x.begin(), x.end(), 0.0), x.end());
    EXPECT_NE(std::find(x.begin(), x.end(), 1.0), x.end());
    // The domain holds every source colour of [-1, 16]^3: the corners, in srgb-linear.
    const Converter to_srgb(color_space("acescg-linear"), color_space("srgb-linear"));
    for (int k = 0; k < 8; ++k) {
        const Vec3 v = to_srgb(Vec3{(k & 1) ? 16.0 : -1.0, (k & 2) ? 16.0 : -1.0, (k & 4) ? 16.0 : -1.0});
        for (int i = 0; i < 3; ++i) {
            EXPECT_GE(v[i], lut.domain.min);
            EXPECT_LE(v[i], lut.domain.max);
        }
    }
    for (int i = 0; i < 17; ++i) {
        EXPECT_NEAR(lut.values[3 * static_cast<std::size_t>(i)], std::clamp(lut.node(i), 0.0, 1.0), 1e-6) << i;
    }
    // Inside the cube the LUT is the identity, between nodes too.
    for (const Vec3& in : {Vec3{0.3, 0.7, 0.01}, Vec3{1.0, 0.0, 0.5}, Vec3{0.999, 0.001, 0.123}}) {
        const Rgb out = apply_lut(lut, in, LutInterpolation::tetrahedral);
        EXPECT_NEAR(out.r, in[0], 1e-6);
        EXPECT_NEAR(out.g, in[1], 1e-6);
        EXPECT_NEAR(out.b, in[2], 1e-6);
    }
    EXPECT_NE(c.config.find("process_space: srgb-linear"), std::string::npos);
    EXPECT_NE(c.config.find("scene_linear: acescg-linear"), std::string::npos);
    EXPECT_NE(c.config.find("ExponentWithLinearTransform> {gamma: [2.4, 2.4, 2.4, 1], offset: "
                            "[0.055, 0.055, 0.055, 0], direction: inverse}"),
              std::string::npos)
        << c.config;
    o.display = color_space("lab");
    EXPECT_THROW((void)make_ocio_config(o), Error);
    o.display = color_space("srgb");
    o.methods = {ClipMethod::smits, ClipMethod::smits};
    EXPECT_THROW((void)make_ocio_config(o), Error);
    o.methods = {ClipMethod::clamp};
    o.size = ocio_look_min_size - 1;
    EXPECT_THROW((void)make_ocio_config(o), Error);
}

TEST(OcioConfig, LookNodesAreLaidOutForEverySizeAndPair) {
    for (const char* source : {"acescg-linear", "acescg", "aces2065-1", "srgb", "srgb-linear", "display-p3"}) {
        for (const char* display : {"srgb", "srgb-linear", "rec2020", "acescg"}) {
            for (int size = ocio_look_min_size; size <= lut_max_size; size += 31) {
                OcioConfigOptions o;
                o.source = color_space(source);
                o.display = color_space(display);
                o.size = size;
                const LutDomain d = ocio_look_domain(o);
                EXPECT_NO_THROW(check_lut_domain(d, size)) << source << " " << display << " " << size;
                EXPECT_NE(std::find(d.nodes.begin(), d.nodes.end(), 0.0), d.nodes.end());
                EXPECT_NE(std::find(d.nodes.begin(), d.nodes.end(), 1.0), d.nodes.end());
            }
        }
    }
}

TEST(LutShaper, NodesShaperIsPiecewiseLinearThroughTheNodes) {
    LutDomain d;
    d.shaper = LutShaper::nodes;
    d.step = 1.0 / 64;
    d.min = -2.0;
    d.max = 8.0;
    d.nodes = {-2.0, -0.5, 0.0, 0.25, 1.0, 3.0, 8.0};
    ASSERT_NO_THROW(check_lut_domain(d, 7));
    EXPECT_THROW(check_lut_domain(d, 8), Error);
    for (std::size_t i = 0; i < d.nodes.size(); ++i) {
        EXPECT_DOUBLE_EQ(lut_shape(d, d.nodes[i]), static_cast<double>(i) / 6.0);
        EXPECT_DOUBLE_EQ(lut_unshape(d, static_cast<double>(i) / 6.0), d.nodes[i]);
    }
    EXPECT_DOUBLE_EQ(lut_shape(d, 2.0), (4.0 + 0.5) / 6.0);  // halfway from 1 to 3
    EXPECT_DOUBLE_EQ(lut_unshape(d, (4.0 + 0.5) / 6.0), 2.0);
    LutDomain off = d;
    off.nodes[3] = 0.26;  // not a whole step
    EXPECT_THROW(check_lut_domain(off), Error);
    off = d;
    off.nodes[3] = 0.0;  // not increasing
    EXPECT_THROW(check_lut_domain(off), Error);
    // .cube and .spi3d cannot carry it; the .clf's LUT1D samples every step.
    Lut3D lut;
    lut.size = 7;
    lut.domain = d;
    lut.values.assign(3 * 7 * 7 * 7, 0.5f);
    EXPECT_THROW((void)lut_text(lut, LutFormat::cube), Error);
    EXPECT_THROW((void)lut_text(lut, LutFormat::spi3d), Error);
    const std::string clf = lut_text(lut, LutFormat::clf);
    EXPECT_NE(clf.find("<Array dim=\"641 1\">"), std::string::npos);
}

TEST(LutDomain, RangesFloat32ReadersCannotTellApartAreRefused) {
    EXPECT_THROW(check_lut_domain(LutDomain{LutShaper::log2, 0.0, 1e-10, 14}), Error);
    EXPECT_THROW(check_lut_domain(LutDomain{LutShaper::none, 0.0, 1e-7, 14}), Error);
    EXPECT_THROW(check_lut_domain(LutDomain{LutShaper::none, 1e5, 1e5 + 0.01, 14}), Error);
    EXPECT_NO_THROW(check_lut_domain(LutDomain{LutShaper::none, 0.0, 1e-5, 14}));
}

}  // namespace
}  // namespace irid
