// The float SIMD kernel of the ACES 2.0 display chain (aces2_kernel.h) against OpenColorIO's
// published vectors and against the double chain (Aces2Output), on every instruction set this
// machine runs; its handling of hostile values, and results that do not depend on threads or
// on how a buffer is split.

#include <irid/color/rgb.h>
#include <irid/error.h>
#include <irid/gamut/aces2_display.h>
#include <irid/gamut/aces2_kernel.h>
#include <irid/gamut/display_transform.h>

#include <gtest/gtest.h>
#include <hwy/targets.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iostream>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace irid {
namespace {

/// OpenColorIO's tolerance, and the kernel's against the double chain (docs/KERNELS.md).
constexpr double tolerance = 1e-5;

double relative_error(double got, double expected) {
    return std::abs(got - expected) / std::max(std::abs(expected), 1.0);
}

/// The rows of a vectors file of data/ocio-aces2: input 3, alpha, output 3.
std::vector<std::array<double, 7>> vectors(const std::string& name) {
    std::ifstream in(std::string(IRID_SOURCE_DIR) + "/data/ocio-aces2/" + name);
    EXPECT_TRUE(in.good()) << name;
    std::vector<std::array<double, 7>> rows;
    std::string line;
    while (std::getline(in, line)) {
        if (line.empty() || !(std::isdigit(static_cast<unsigned char>(line[0])) || line[0] == '-'))
            continue;
        std::replace(line.begin(), line.end(), ',', ' ');
        std::istringstream s(line);
        std::array<double, 7> r{};
        for (double& v : r) s >> v;
        rows.push_back(r);
    }
    return rows;
}

/// Hue differences wrap: 359.99999 and 0 are 1e-5 apart.
double hue_error(double got, double expected) {
    const double d = std::fmod(std::abs(got - expected), 360.0);
    return std::min(d, 360.0 - d) / std::max(std::abs(expected), 1.0);
}

std::vector<float> forward_colours(std::size_t n, std::uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(-0.5f, 64.0f);
    std::vector<float> v(3 * n);
    for (float& x : v) x = u(rng);
    return v;
}

/// XYZ of the display (1.0 = 100 cd/m²) inside its limiting cube: what the forward can produce.
std::vector<float> inverse_colours(const Aces2Output& out, std::size_t n, std::uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(0.0, out.spec().peak_nits / 100.0);
    const Mat3 to_xyz = rgb_to_xyz_matrix(out.spec().limiting, out.spec().limiting_white);
    std::vector<float> v(3 * n);
    for (std::size_t i = 0; i < n; ++i) {
        const Vec3 x = to_xyz * Vec3{u(rng), u(rng), u(rng)};
        for (std::size_t c = 0; c < 3; ++c)
            v[3 * i + c] = static_cast<float>(x[c] * out.output_scale());
    }
    return v;
}

/// The largest |kernel − double| / max(|double|, 1) over `in`, the double being Aces2Output's.
double worst_error(const Aces2Output& out, bool inverse, const std::vector<float>& in) {
    const Aces2Kernel kernel(out, inverse);
    std::vector<float> got(in.size());
    (void)kernel.run(in, got);
    double worst = 0.0;
    for (std::size_t i = 0; i < in.size(); i += 3) {
        Vec3 ref;
        if (!inverse) {
            const Xyz x = out.forward({in[i], in[i + 1], in[i + 2]});
            ref = {x.X, x.Y, x.Z};
        } else {
            ref = out.inverse({in[i], in[i + 1], in[i + 2]});
        }
        for (std::size_t c = 0; c < 3; ++c) {
            const double e = relative_error(got[i + c], ref[c]);
            worst = std::max(worst, std::isfinite(got[i + c]) ? e : 1e300);
        }
    }
    return worst;
}

const std::array<const char*, 4> displays{"sdr-100nit-rec709", "hdr-1000nit-p3-d65",
                                          "hdr-4000nit-rec2020",
                                          "sdr-100nit-rec709-d60-in-rec709-d65"};

TEST(Aces2Kernel, OpenColorIOsWholeTransformVectorsPassInFloat) {
    // The vectors are the rendering alone; the chain clamps its input to AP1 [0, forward_limit]
    // and its output to [0, peak]. hdr-1000nit-p3-d65 renders for these vectors' display and
    // shows P3-D65 without scaling, so with P3's XYZ → RGB as its output matrix the kernel gives
    // the vectors' outputs clamped to [0, 10], for every input that AP1's clamp leaves alone.
    const Aces2Output out(aces2_display("hdr-1000nit-p3-d65"));
    const Mat3 to_ap1 = acescg().from_xyz_matrix() * aces2065_1().to_xyz_matrix();
    const Aces2Kernel forward(out, false, Mat3::identity(), display_p3().from_xyz_matrix());
    const Aces2Kernel inverse(out, true, display_p3().to_xyz_matrix(), Mat3::identity());
    int checked = 0, round_trips = 0;
    for (const auto& r : vectors("aces_output_transform_20.csv")) {
        const Vec3 ap1 = to_ap1 * Vec3{r[0], r[1], r[2]};
        if (std::min({ap1[0], ap1[1], ap1[2]}) < 0.0) continue;
        const std::array<float, 3> in{static_cast<float>(r[0]), static_cast<float>(r[1]),
                                      static_cast<float>(r[2])};
        std::array<float, 3> got{}, back{};
        (void)forward.run(in, got);
        bool clamped = false;
        for (std::size_t c = 0; c < 3; ++c) {
            const double expected = std::clamp(r[4 + c], 0.0, 10.0);
            clamped = clamped || expected != r[4 + c];
            EXPECT_LE(relative_error(got[c], expected), tolerance)
                << r[0] << " " << r[1] << " " << r[2] << " channel " << c;
        }
        ++checked;
        if (clamped) continue;
        // OpenColorIO's round trip: 1e-4.
        (void)inverse.run(got, back);
        ++round_trips;
        for (std::size_t c = 0; c < 3; ++c)
            EXPECT_LE(relative_error(back[c], r[c]), 1e-4)
                << r[0] << " " << r[1] << " " << r[2] << " channel " << c;
    }
    // 3 of the 35 have a negative AP1 channel; 4 more an output beyond [0, 10].
    EXPECT_EQ(checked, 32);
    EXPECT_EQ(round_trips, 28);
}

TEST(Aces2Kernel, OpenColorIOsStageVectorsPassInFloat) {
    // The stages as run() computes them (at 1000 cd/m² its tonescale and gamut compression are
    // in double, docs/KERNELS.md), and all in float.
    const Aces2Output out(aces2_display("hdr-1000nit-p3-d65"));
    const Aces2Kernel kernel(out, false);
    const std::array<std::pair<const char*, Aces2Kernel::Stage>, 3> stages{{
        {"aces_rgb_to_jmh_20.csv", Aces2Kernel::Stage::rgb_to_jmh},
        {"aces_tonescale_compress_20.csv", Aces2Kernel::Stage::tonescale_and_chroma},
        {"aces_gamut_map_20.csv", Aces2Kernel::Stage::gamut_compression},
    }};
    for (const bool in_float : {false, true}) {
        for (const auto& [file, stage] : stages) {
            const auto rows = vectors(file);
            ASSERT_EQ(rows.size(), 27u) << file;
            std::vector<float> in, got(3 * rows.size());
            for (const auto& r : rows)
                in.insert(in.end(), {static_cast<float>(r[0]), static_cast<float>(r[1]),
                                     static_cast<float>(r[2])});
            kernel.run_stage(stage, in, got, in_float);
            double worst = 0.0;
            for (std::size_t i = 0; i < rows.size(); ++i) {
                const auto& r = rows[i];
                const double e = std::max({relative_error(got[3 * i], r[4]),
                                           relative_error(got[3 * i + 1], r[5]),
                                           hue_error(got[3 * i + 2], r[6])});
                worst = std::max(worst, e);
                EXPECT_LE(e, tolerance) << file << (in_float ? " in float, " : ", ") << r[0] << " "
                                        << r[1] << " " << r[2] << " gave " << got[3 * i] << " "
                                        << got[3 * i + 1] << " " << got[3 * i + 2];
            }
            std::cout << file << (in_float ? " all in float" : " as run()")
                      << ": largest relative error " << worst << "\n";
        }
    }
    const Aces2Kernel inverse(out, true);
    std::array<float, 3> x{};
    EXPECT_THROW(inverse.run_stage(Aces2Kernel::Stage::rgb_to_jmh, x, x), Error);
}

TEST(Aces2Kernel, RandomColoursMatchTheDoubleChainForwardAndInverse) {
    for (const char* name : displays) {
        const Aces2Output out(aces2_display(name));
        EXPECT_LE(worst_error(out, false, forward_colours(100000, 5)), tolerance)
            << name << " forward";
        EXPECT_LE(worst_error(out, true, inverse_colours(out, 50000, 6)), tolerance)
            << name << " inverse";
    }
}

// Near-neutral colours are where the model's opponent a and b are differences of nearly equal
// responses: greys from 2^-16 to 2^6 with each channel off by up to 1e-3, 1e-5 and 1e-7 of it,
// and the random colours, on every display.
TEST(Aces2Kernel, NearNeutralColoursMatchTheDoubleChainOnEveryDisplay) {
    std::mt19937 rng(9);
    std::uniform_real_distribution<float> stops(-16.0f, 6.0f), off(-1.0f, 1.0f);
    std::vector<float> in = forward_colours(10000, 10);
    for (const float spread : {1e-3f, 1e-5f, 1e-7f}) {
        for (int i = 0; i < 10000; ++i) {
            const float g = std::exp2(stops(rng));
            for (int c = 0; c < 3; ++c) in.push_back(g * (1.0f + spread * off(rng)));
        }
    }
    for (const Aces2DisplaySpec& spec : aces2_displays()) {
        const Aces2Output out(spec);
        EXPECT_LE(worst_error(out, false, in), tolerance) << spec.name;
    }
}

// error_of_largest bounds the error relative to a colour's largest channel, which is what an
// encoded file's dark and saturated colours need (image_display.cpp): shadows down to 2^-26
// with chroma, and the random colours, in each display's default encoding.
TEST(Aces2Kernel, TheErrorOfTheLargestChannelIsWithinItsBound) {
    std::mt19937 rng(12);
    std::uniform_real_distribution<float> stops(-26.0f, 7.0f), chroma(-0.1f, 1.0f);
    std::vector<float> in = forward_colours(5000, 13);
    for (int i = 0; i < 15000; ++i) {
        const float g = std::exp2(stops(rng));
        in.insert(in.end(), {g * chroma(rng), g * chroma(rng), g * chroma(rng)});
    }
    for (const Aces2DisplaySpec& spec : aces2_displays()) {
        const RgbSpace* encoding = default_display_encoding(spec);
        const Aces2Output out(spec);
        const Aces2Kernel kernel(
            out, false, Mat3::identity(),
            encoding != nullptr ? encoding->from_xyz_matrix() : Mat3::identity());
        std::vector<float> got(in.size());
        (void)kernel.run(in, got);
        double worst = 0.0;
        std::size_t at = 0;
        for (std::size_t i = 0; i < in.size(); i += 3) {
            const Vec3 ref = kernel.reference({in[i], in[i + 1], in[i + 2]});
            const double largest = std::max({std::abs(ref[0]), std::abs(ref[1]), std::abs(ref[2])});
            for (std::size_t c = 0; c < 3; ++c) {
                const double e = std::abs(got[i + c] - ref[c]) / std::max(largest, 1e-300);
                if (e > worst) worst = e, at = i;
            }
        }
        // Half the bound: it is three times the largest measured.
        EXPECT_LE(worst, kernel.error_of_largest() / 2.0)
            << spec.name << " at " << in[at] << " " << in[at + 1] << " " << in[at + 2] << ": "
            << got[at] << " " << got[at + 1] << " " << got[at + 2];
    }
}

TEST(Aces2Kernel, MatchesTheDoubleChainOnEveryCompiledTarget) {
    const Aces2Output sdr(aces2_display("sdr-100nit-rec709"));
    const Aces2Output hdr(aces2_display("hdr-4000nit-rec2020"));
    for (const std::int64_t target : hwy::SupportedAndGeneratedTargets()) {
        hwy::SetSupportedTargetsForTest(target);
        for (const Aces2Output* out : {&sdr, &hdr}) {
            EXPECT_LE(worst_error(*out, false, forward_colours(3001, 7)), tolerance)
                << out->spec().name << " forward, " << hwy::TargetName(target);
            EXPECT_LE(worst_error(*out, true, inverse_colours(*out, 1001, 8)), tolerance)
                << out->spec().name << " inverse, " << hwy::TargetName(target);
        }
    }
    hwy::SetSupportedTargetsForTest(0);
}

TEST(Aces2Kernel, HostileValuesGiveTheDoublePathsFiniteResults) {
    const float inf = std::numeric_limits<float>::infinity(),
                nan = std::numeric_limits<float>::quiet_NaN();
    const std::vector<float> specials{0.0f,   -0.0f,   nan,    inf,    -inf,    1e30f,
                                      -1e30f, 3e38f,   -3e38f, 1e-40f, -1e-40f, 1e-30f,
                                      0.18f,  1000.0f, -5.0f,  64.0f,  1e6f,    -1e7f};
    std::vector<float> in;
    for (const float a : specials)
        for (const float b : specials)
            for (const float c : {0.0f, nan, 0.5f, 1e30f, -inf, 1e-40f})
                in.insert(in.end(), {a, b, c});
    for (const char* name : {"sdr-100nit-rec709", "hdr-1000nit-p3-d65"}) {
        const Aces2Output out(aces2_display(name));
        for (const bool inverse : {false, true}) {
            const Aces2Kernel kernel(out, inverse);
            std::vector<float> got(in.size());
            (void)kernel.run(in, got);
            for (std::size_t i = 0; i < in.size(); i += 3) {
                const Vec3 ref = kernel.reference({in[i], in[i + 1], in[i + 2]});
                for (std::size_t c = 0; c < 3; ++c) {
                    ASSERT_TRUE(std::isfinite(got[i + c]))
                        << name << " " << in[i] << " " << in[i + 1] << " " << in[i + 2];
                    EXPECT_LE(relative_error(got[i + c], ref[c]), tolerance)
                        << name << (inverse ? " inverse " : " forward ") << in[i] << " "
                        << in[i + 1] << " " << in[i + 2];
                }
            }
        }
    }
}

TEST(Aces2Kernel, PlusInfinityIsTheBrightestAndNanAndMinusInfinityAreZero) {
    // +Inf (a half float's overflow) is taken as 65504, beyond every forward limit: a blown-out
    // white is the display's peak white, not black; -Inf and NaN are 0 (issue 37, item 3). The
    // kernel, its reference, the double chain and DisplayTransform take them alike, forward and
    // inverse.
    const float inf = std::numeric_limits<float>::infinity(), nan = std::numeric_limits<float>::quiet_NaN();
    for (const char* name : {"sdr-100nit-rec709", "hdr-1000nit-p3-d65", "hdr-4000nit-rec2020"}) {
        const Aces2Output out(aces2_display(name));
        const Xyz white = out.forward({inf, inf, inf});
        const double peak_y = out.spec().peak_nits / 100.0 * out.output_scale();
        EXPECT_NEAR(white.Y, peak_y, 1e-9 * peak_y) << name;
        EXPECT_EQ(white.X, out.forward({65504.0, 65504.0, 65504.0}).X) << name;
        const Xyz a = out.forward({nan, inf, -inf}), b = out.forward({0.0, 65504.0, 0.0});
        EXPECT_EQ(a.X, b.X) << name;
        EXPECT_EQ(a.Y, b.Y) << name;
        EXPECT_EQ(a.Z, b.Z) << name;
        const Vec3 back = out.inverse({inf, inf, inf}), clamped = out.inverse({65504.0, 65504.0, 65504.0});
        EXPECT_EQ(back[1], clamped[1]) << name;
        for (const bool inverse : {false, true}) {
            const Aces2Kernel kernel(out, inverse);
            const std::array<float, 9> in{inf, inf, inf, nan, inf, -inf, 0.18f, inf, 0.5f};
            const std::array<float, 9> as{65504.0f, 65504.0f, 65504.0f, 0.0f, 65504.0f, 0.0f, 0.18f, 65504.0f, 0.5f};
            std::array<float, 9> got{}, want{};
            (void)kernel.run(in, got);
            (void)kernel.run(as, want);
            for (std::size_t i = 0; i < 9; ++i) EXPECT_EQ(got[i], want[i]) << name << " " << i;
            for (std::size_t i = 0; i < 9; i += 3) {
                const Vec3 r = kernel.reference({in[i], in[i + 1], in[i + 2]});
                const Vec3 s = kernel.reference({as[i], as[i + 1], as[i + 2]});
                for (std::size_t c = 0; c < 3; ++c) EXPECT_EQ(r[c], s[c]) << name << " " << i;
            }
            if (!inverse) {
                EXPECT_NEAR(got[1], peak_y, tolerance * peak_y) << name;
            }
        }
        // DisplayTransform, in double and in float, from another space too: +Inf in every
        // channel of linear sRGB is peak white.
        const DisplayTransform t(DisplayTransformOptions{.display = name, .source = "srgb-linear", .target = "xyz"});
        EXPECT_NEAR(t({inf, inf, inf})[1], peak_y, 1e-9 * peak_y) << name;
        std::vector<float> f{inf, inf, inf};
        t.apply(f, f);
        EXPECT_NEAR(f[1], peak_y, tolerance * peak_y) << name;
    }
}

TEST(Aces2Kernel, ResultsAreTheSameBytesForAnyThreadCountSplitAndTail) {
    for (const bool inverse : {false, true}) {
        DisplayTransformOptions o;
        o.display = "hdr-1000nit-p3-d65";
        o.inverse = inverse;
        if (inverse) o.source = "xyz", o.target = "aces2065-1";
        const DisplayTransform t(o);
        const std::vector<float> in =
            inverse ? inverse_colours(t.output(), 10007, 9) : forward_colours(10007, 9);
        std::vector<float> one(in.size()), two(in.size()), seven(in.size());
        t.apply(in, one, 1);
        t.apply(in, two, 2);
        t.apply(in, seven, 7);
        EXPECT_EQ(std::memcmp(one.data(), two.data(), one.size() * sizeof(float)), 0) << inverse;
        EXPECT_EQ(std::memcmp(one.data(), seven.data(), one.size() * sizeof(float)), 0) << inverse;
        // Odd pieces (every tail length), in place.
        std::vector<float> pieces = in;
        const Aces2Kernel kernel(t.output(), inverse);
        std::vector<float> whole(in.size());
        (void)kernel.run(in, whole);
        std::size_t at = 0;
        for (std::size_t len = 1; at < in.size() / 3; len = len % 37 + 1) {
            const std::size_t n = std::min(len, in.size() / 3 - at);
            const std::span<float> piece(pieces.data() + 3 * at, 3 * n);
            (void)kernel.run(piece, piece);
            at += n;
        }
        EXPECT_EQ(std::memcmp(whole.data(), pieces.data(), whole.size() * sizeof(float)), 0)
            << inverse;
    }
}

TEST(Aces2Kernel, DisplayTransformUsesItBetweenLinearSpacesWithinTheTolerance) {
    // Scene colours in linear Rec.2020 to linear Display P3 and back: the converters' matrices
    // are folded into the kernel's; the double path is DisplayTransform's own, colour by colour.
    for (const bool inverse : {false, true}) {
        DisplayTransformOptions o;
        o.display = "hdr-1000nit-p3-d65";
        o.inverse = inverse;
        o.source = inverse ? "display-p3-linear" : "rec2020-linear";
        o.target = inverse ? "rec2020-linear" : "display-p3-linear";
        const DisplayTransform t(o);
        std::mt19937 rng(10);
        std::uniform_real_distribution<float> u(inverse ? 0.0f : -0.5f, inverse ? 10.0f : 64.0f);
        std::vector<float> in(3 * 20000);
        for (float& x : in) x = u(rng);
        std::vector<float> got(in.size());
        t.apply(in, got, 2);
        double worst = 0.0;
        for (std::size_t i = 0; i < in.size(); i += 3) {
            const Vec3 ref = t({in[i], in[i + 1], in[i + 2]});
            for (std::size_t c = 0; c < 3; ++c)
                worst = std::max(worst, relative_error(got[i + c], ref[c]));
        }
        EXPECT_LE(worst, tolerance) << (inverse ? "inverse" : "forward");
    }
}

}  // namespace
}  // namespace irid
