// The highlight walk of tests/gamut/aces2_highlight_walk_test.cpp through every image path of
// `irid display IN OUT` (display_image): an 8-bit and a 16-bit encoded file and a linear EXR,
// each of 2²² bright colours per display (2¹⁶ under the sanitizers), on all 31 built-in displays
// and on custom ones of 100 to 250 cd/m². No sample may be non-finite and no bright colour black.
#include <irid/exchange/image_display.h>
#include <irid/gamut/aces2_display.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "aces2_walk.h"

namespace irid {
namespace {

#ifdef IRID_SANITIZED
constexpr int side = 256;  // 2¹⁶ colours
#else
constexpr int side = 2048;  // 2²² colours
#endif

struct Path {
    const char* name;
    io::ImageFormat format;
    int bits;
};
constexpr std::array<Path, 3> paths{Path{"8-bit", io::ImageFormat::png, 8},
                                    Path{"16-bit", io::ImageFormat::png, 16},
                                    Path{"EXR", io::ImageFormat::exr, 0}};

/// The encoding an integer file of the display is written in: its own, or for the two CIE XYZ
/// displays (which have none) the P3 one of its peak.
std::optional<std::string> integer_encoding(const Aces2DisplaySpec& spec) {
    if (default_display_encoding(spec) != nullptr) return std::nullopt;
    return spec.peak_nits * spec.linear_scale > 100.0 ? "p3-d65-pq" : "display-p3";
}

void walk(const Aces2DisplaySpec& spec) {
    const Aces2Output out(spec);
    const std::vector<float> colours = test::bright_colours(out, std::size_t(side) * side, 4096);
    for (const Path& path : paths) {
        const bool exr = path.format == io::ImageFormat::exr;
        DisplayImagePlan plan = plan_display_image(
            "aces2", spec.name, exr ? std::nullopt : integer_encoding(spec), path.format);
        if (!exr) plan.bits = path.bits;
        io::Image image = io::Image::blank(side, side, 3);
        image.pixels = colours;
        DisplayImageOptions options;
        options.from = color_space("aces2065-1-linear");
        (void)display_image(image, plan, options, path.format, "the walk");
        // Bright is a thousandth of the peak in linear light; in an encoding's signal, whose
        // curves all lift that far above 0.01, a signal of 0.01.
        const double peak = spec.peak_nits * out.output_scale() / 100.0;
        const double dark = exr ? 1e-3 * peak : 0.01;
        std::size_t non_finite = 0, black = 0;
        for (std::size_t i = 0; i < image.pixel_count(); ++i) {
            const float* p = &image.pixels[3 * i];
            if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2])) {
                ++non_finite;
            } else if (std::max({p[0], p[1], p[2]}) < dark) {
                ++black;
            }
        }
        EXPECT_EQ(non_finite, 0u) << spec.name << " " << path.name;
        EXPECT_EQ(black, 0u) << spec.name << " " << path.name;
    }
}

TEST(DisplayImageWalk, EveryImagePathOfEveryBuiltInDisplayKeepsHighlightsBright) {
    for (const Aces2DisplaySpec& spec : aces2_displays()) walk(spec);
}

TEST(DisplayImageWalk, EveryImagePathOfCustomDisplaysOf100To250NitsKeepsHighlightsBright) {
    for (const char* name : {"custom:peak=100,limiting=srgb", "custom:peak=150,limiting=display-p3",
                             "custom:peak=200,limiting=rec2020", "custom:peak=250,limiting=srgb"})
        walk(aces2_display(name));
}

}  // namespace
}  // namespace irid
