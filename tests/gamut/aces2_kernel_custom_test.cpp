// The float kernel on custom displays (aces2_display.h's custom form): within its tolerance of the
// double chain on the colours that are hardest for it (bright ones next to the peak's J, and
// bright ones on AP1's faces) for peaks of 100 to 500 cd/m² and limiting gamuts from Rec.709 to
// AP1; and a limiting gamut beyond AP1 (AP0's) handed to the double chain whole (KERNELS.md).
#include <irid/gamut/aces2_display.h>
#include <irid/gamut/aces2_kernel.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "aces2_walk.h"

namespace irid {
namespace {

/// Bright ACES2065-1 colours on AP1's faces (one AP1 channel 0), from 2^-4 to 2^8.
std::vector<float> ap1_faces(std::size_t n, std::uint32_t seed) {
    const RgbPrimaries ap0{{0.7347, 0.2653}, {0.0, 1.0}, {0.0001, -0.0770}};
    const RgbPrimaries ap1{{0.713, 0.293}, {0.165, 0.830}, {0.128, 0.044}};
    const Xy white{0.32168, 0.33767};
    const Mat3 ap1_to_ap0 = inverse(rgb_to_xyz_matrix(ap0, white)) * rgb_to_xyz_matrix(ap1, white);
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::vector<float> v;
    for (std::size_t i = 0; i < n; ++i) {
        Vec3 c{u(rng), u(rng), u(rng)};
        c[static_cast<int>(i % 3)] = 0.0;
        const double s = std::exp2(12.0 * u(rng) - 4.0);
        const Vec3 x = ap1_to_ap0 * Vec3{c[0] * s, c[1] * s, c[2] * s};
        v.insert(v.end(),
                 {static_cast<float>(x[0]), static_cast<float>(x[1]), static_cast<float>(x[2])});
    }
    return v;
}

/// The largest |kernel − double| / max(|double|, 1), and how many colours the kernel handed over.
std::pair<double, std::size_t> kernel_error(const Aces2Output& out, const std::vector<float>& in) {
    const Aces2Kernel kernel(out, false);
    std::vector<float> got(in.size());
    const std::size_t handed = kernel.run(in, got);
    double worst = 0.0;
    for (std::size_t i = 0; i < in.size(); i += 3) {
        const Xyz x = out.forward({in[i], in[i + 1], in[i + 2]});
        const double ref[3] = {x.X, x.Y, x.Z};
        for (std::size_t c = 0; c < 3; ++c)
            worst = std::max(worst, std::isfinite(got[i + c]) ? std::abs(got[i + c] - ref[c]) /
                                                                    std::max(std::abs(ref[c]), 1.0)
                                                              : 1e300);
    }
    return {worst, handed};
}

TEST(Aces2KernelCustom, BrightColoursOfCustomDisplaysStayWithinTheTolerance) {
    // Before the float path stopped at 100 cd/m²: 1.0e-5 at 150 (AP1), 1.1e-5 at 200 and 1.4e-5
    // at 225 (Rec.2020, AP1).
    for (const char* name :
         {"custom:peak=100,limiting=srgb", "custom:peak=100,limiting=acescg",
          "custom:peak=100,limiting=ntsc1953", "custom:peak=100,limiting=srgb,white=A",
          "custom:peak=120,limiting=acescg", "custom:peak=150,limiting=acescg",
          "custom:peak=200,limiting=rec2020", "custom:peak=225,limiting=acescg",
          "custom:peak=250,limiting=display-p3", "custom:peak=500,limiting=rec2020,white=E"}) {
        const Aces2Output out(aces2_display(name));
        std::vector<float> in = test::bright_colours(out, 1 << 16, 21);
        const std::vector<float> faces = ap1_faces(30000, 22);
        in.insert(in.end(), faces.begin(), faces.end());
        EXPECT_LE(kernel_error(out, in).first, 1e-5) << name;
    }
}

TEST(Aces2KernelCustom, ALimitingGamutBeyondAp1GoesToTheDoubleChainWhole) {
    for (const char* name :
         {"custom:peak=100,limiting=aces2065-1", "custom:peak=200,limiting=aces2065-1"}) {
        const Aces2Output out(aces2_display(name));
        // Issue 37's colour, which the float kernel took to peak white 6 % from the double
        // chain's, and the hard colours above.
        std::vector<float> in{26.198932647705078f, 165.05447387695312f, 275.1459045410156f};
        const std::vector<float> faces = ap1_faces(3000, 23);
        in.insert(in.end(), faces.begin(), faces.end());
        const auto [worst, handed] = kernel_error(out, in);
        EXPECT_EQ(handed, in.size() / 3) << name;
        EXPECT_LE(worst, 1e-7) << name;  // the double chain's result rounded to float
        EXPECT_EQ(Aces2Kernel(out, false).error_of_largest(), 1e-7) << name;
    }
    // A limiting gamut inside AP1 keeps the kernel.
    const Aces2Output sdr(aces2_display("custom:peak=100,limiting=acescg"));
    EXPECT_EQ(kernel_error(sdr, ap1_faces(3000, 24)).second, 0u);
}

}  // namespace
}  // namespace irid
