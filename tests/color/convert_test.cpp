// The converter between named spaces (irid/color/convert.h): Ottosson's published Oklab values,
// and the batch paths (the SIMD linear → Oklab kernel among them) against the per-colour one.

#include <irid/color/convert.h>
#include <irid/error.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <optional>
#include <random>
#include <string>
#include <utility>
#include <vector>

namespace irid {
namespace {

// Ottosson 2020, "A perceptual color space for image processing", table of XYZ (D65) → Oklab,
// given to three decimals.
TEST(Converter, OttossonTable) {
    const Converter c(color_space("xyz"), color_space("oklab"));
    const struct {
        Vec3 xyz, lab;
    } rows[] = {{{0.950, 1.000, 1.089}, {1.000, 0.000, 0.000}},
                {{1.000, 0.000, 0.000}, {0.450, 1.236, -0.019}},
                {{0.000, 1.000, 0.000}, {0.922, -0.671, 0.263}},
                {{0.000, 0.000, 1.000}, {0.153, -1.415, -0.449}}};
    for (const auto& r : rows) {
        const Vec3 lab = c(r.xyz);
        std::vector<double> batch{r.xyz[0], r.xyz[1], r.xyz[2]};
        c.convert(batch, batch);
        for (int k = 0; k < 3; ++k) {
            EXPECT_NEAR(lab[k], r.lab[k], 5e-4 + 1e-9) << k;
            EXPECT_NEAR(batch[k], r.lab[k], 5e-4 + 1e-9) << k;
        }
    }
}

std::vector<double> random_colours(std::size_t n, double lo, double hi) {
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(lo, hi);
    std::vector<double> v(3 * n);
    for (double& x : v) x = u(rng);
    return v;
}

// The SIMD kernel (every lane count: 1001 colours leave a tail) against the per-colour path.
TEST(Converter, BatchOklabMatchesPerColour) {
    for (const char* source : {"srgb-linear", "rec2020-linear", "xyz", "display-p3-linear"}) {
        const Converter c(color_space(source), color_space("oklab"));
        const std::vector<double> in = random_colours(1001, -0.5, 1.5);
        std::vector<double> out(in.size());
        c.convert(in, out);
        std::vector<float> in_f(in.begin(), in.end()), out_f(in.size());
        c.convert(in_f, out_f);
        for (std::size_t i = 0; i < in.size() / 3; ++i) {
            const Vec3 ref = c({in[3 * i], in[3 * i + 1], in[3 * i + 2]});
            const Vec3 ref_f = c({in_f[3 * i], in_f[3 * i + 1], in_f[3 * i + 2]});
            for (int k = 0; k < 3; ++k) {
                // 1e-12: the batch composes the matrices to LMS into one, whose rounding the cube
                // root amplifies near an LMS component of 0 (its slope grows as x^(-2/3)).
                ASSERT_NEAR(out[3 * i + k], ref[k], 1e-12) << source << " colour " << i;
                // float: the double result of the float input, rounded once.
                ASSERT_NEAR(out_f[3 * i + k], ref_f[k], 2e-7 * std::max(1.0, std::abs(ref_f[k]))) << source;
            }
        }
    }
}

// Zero, values beyond float's range, NaN and infinity take the scalar path inside a block and
// give what the per-colour path gives; in place works.
TEST(Converter, BatchOklabSpecialValues) {
    const Converter c(color_space("srgb-linear"), color_space("oklab"));
    const double inf = std::numeric_limits<double>::infinity();
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const Vec3 special[] = {{0, 0, 0}, {1e-40, 0, 0}, {1e35, 1, 0}, {nan, 1, 1},
                            {inf, 0, 0}, {-1, -1, -1}, {1e-310, 0, 0}, {0.5, 0.5, 0.5}};
    std::vector<double> v;
    for (int rep = 0; rep < 5; ++rep)
        for (const Vec3& s : special) v.insert(v.end(), {s[0], s[1], s[2]});
    std::vector<double> in = v;
    c.convert(v, v);  // in place
    for (std::size_t i = 0; i < in.size() / 3; ++i) {
        const Vec3 ref = c({in[3 * i], in[3 * i + 1], in[3 * i + 2]});
        for (int k = 0; k < 3; ++k) {
            if (std::isnan(ref[k])) {
                EXPECT_TRUE(std::isnan(v[3 * i + k])) << i;
            } else {
                EXPECT_NEAR(v[3 * i + k], ref[k], 1e-12 * std::max(1.0, std::abs(ref[k]))) << i;
            }
        }
    }
    EXPECT_EQ(v[0], 0.0);  // black is exactly black
}


TEST(ColorSpaceNames, AreFoundInAnyCaseAndNamedCanonically) {
    // Display names are found in any case (aces2_display.h); space names too (issue 37, item 9),
    // ASCII letters only, and the space found says its canonical (lower-case) name.
    const std::pair<const char*, const char*> names[] = {
        {"SRGB", "srgb"},           {"sRGB", "srgb"},
        {"Display-P3", "display-p3"}, {"ACEScg-Linear", "acescg-linear"},
        {"XYZ", "xyz"},             {"OkLab", "oklab"},
        {"Rec2100-PQ", "rec2100-pq"}, {"ACEScct", "acescct"},
        {"AdObE-rGb-LINEAR", "adobe-rgb-linear"},
    };
    for (const auto& [given, canonical] : names) {
        const std::optional<ColorSpace> s = find_color_space(given);
        ASSERT_TRUE(s.has_value()) << given;
        EXPECT_EQ(color_space_name(*s), canonical) << given;
        EXPECT_EQ(*s, color_space(canonical)) << given;
    }
    EXPECT_EQ(find_rgb_space("ACESCG"), &acescg());
    EXPECT_EQ(find_rgb_space("P3-D65-PQ"), &p3_d65_pq());
    EXPECT_FALSE(find_color_space("srgb-lin").has_value());
    EXPECT_FALSE(find_color_space("s rgb").has_value());
    // An unknown name is refused with the canonical names listed.
    try {
        (void)color_space("SRGBX");
        ADD_FAILURE() << "no error";
    } catch (const UnknownNameError& e) {
        EXPECT_NE(std::string(e.what()).find("'SRGBX'"), std::string::npos);
        EXPECT_NE(std::string(e.what()).find("srgb, srgb-linear"), std::string::npos);
    }
}

}  // namespace
}  // namespace irid
