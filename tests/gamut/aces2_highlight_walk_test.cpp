// No NaN and no black highlight: 2²² bright colours per display, walked through the band where
// the tonescaled J approaches the peak's J (where OpenColorIO's float code returns NaN for a few
// and irid's float kernel once wrote black), on all 31 built-in displays and on custom displays
// of 100, 150, 200 and 250 cd/m² (where the kernel runs in float). The double chain and the float
// kernel must give finite, bright results; the kernel within its error bound of the double chain.
// (The image paths are walked in tests/exchange/display_image_walk_test.cpp.)
#include <irid/gamut/aces2.h>
#include <irid/gamut/aces2_display.h>
#include <irid/gamut/aces2_kernel.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include "aces2_walk.h"

namespace irid {
namespace {

/// Colours per display: 2²² in the Release build; the sanitizer build walks 2¹⁶ (the same
/// generator, a sixty-fourth of the colours).
#ifdef IRID_SANITIZED
constexpr std::size_t colours_per_display = std::size_t{1} << 16;
#else
constexpr std::size_t colours_per_display = std::size_t{1} << 22;
#endif

struct Found {
    std::size_t non_finite = 0, black = 0, beyond_bound = 0;
    double darkest = 1e300;  // the smallest output Y of the peak's
};

Found walk(const Aces2DisplaySpec& spec) {
    const Aces2Output out(spec);
    const Aces2Kernel kernel(out, false);
    const std::vector<float> in = test::bright_colours(out, colours_per_display, 4096);
    std::vector<float> res(in.size());
    const double peak_y = spec.peak_nits * out.output_scale() / 100.0;
    const double bound = kernel.error_of_largest();
    const unsigned threads = std::max(1u, std::min(4u, std::thread::hardware_concurrency()));
    std::vector<Found> found(threads);
    std::vector<std::thread> pool;
    const std::size_t colours = in.size() / 3, share = (colours + threads - 1) / threads;
    for (unsigned t = 0; t < threads; ++t) {
        pool.emplace_back([&, t] {
            const std::size_t begin = t * share, end = std::min(colours, begin + share);
            if (begin >= end) return;
            kernel.run(std::span(in).subspan(3 * begin, 3 * (end - begin)),
                       std::span(res).subspan(3 * begin, 3 * (end - begin)));
            Found& f = found[t];
            for (std::size_t i = begin; i < end; ++i) {
                const Xyz x = out.forward({in[3 * i], in[3 * i + 1], in[3 * i + 2]});
                const std::array<double, 3> d{x.X, x.Y, x.Z};
                const std::array<double, 3> k{res[3 * i], res[3 * i + 1], res[3 * i + 2]};
                bool finite = true;
                double largest = 0.0;
                for (int c = 0; c < 3; ++c) {
                    finite = finite && std::isfinite(d[c]) && std::isfinite(k[c]);
                    largest = std::max(largest, std::abs(d[c]));
                }
                if (!finite) {
                    ++f.non_finite;
                    continue;
                }
                // Bright inputs are shown bright: black, or anything below a thousandth of the
                // peak, is the defect this test hunts.
                if (x.Y < 1e-3 * peak_y || k[1] < 1e-3 * peak_y) ++f.black;
                f.darkest = std::min({f.darkest, x.Y / peak_y, k[1] / peak_y});
                for (int c = 0; c < 3; ++c)
                    if (std::abs(k[c] - d[c]) > bound * largest) ++f.beyond_bound;
            }
        });
    }
    for (std::thread& t : pool) t.join();
    Found total;
    for (const Found& f : found) {
        total.non_finite += f.non_finite;
        total.black += f.black;
        total.beyond_bound += f.beyond_bound;
        total.darkest = std::min(total.darkest, f.darkest);
    }
    return total;
}

void expect_clean(const Aces2DisplaySpec& spec) {
    const Found f = walk(spec);
    EXPECT_EQ(f.non_finite, 0u) << spec.name;
    EXPECT_EQ(f.black, 0u) << spec.name;
    EXPECT_EQ(f.beyond_bound, 0u) << spec.name;
    std::printf("%-45s darkest output %.3f of the peak\n", spec.name.c_str(), f.darkest);
}

TEST(Aces2HighlightWalk, EveryBuiltInDisplayGivesFiniteBrightHighlights) {
    for (const Aces2DisplaySpec& spec : aces2_displays()) expect_clean(spec);
}

TEST(Aces2HighlightWalk, CustomDisplaysOf100To250NitsGiveFiniteBrightHighlights) {
    const std::array<const char*, 4> limits{"srgb", "display-p3", "rec2020", "srgb"};
    for (int peak = 100, k = 0; peak <= 250; peak += 50, ++k) {
        const std::string name = "custom:peak=" + std::to_string(peak) +
                                 ",limiting=" + limits[static_cast<std::size_t>(k)];
        expect_clean(aces2_display(name));
    }
}

}  // namespace
}  // namespace irid
