// The ACES 2.0 display chain's inverse over the whole limiting cube of every built-in display:
// its corners, edges, faces, the ramps to the primaries and secondaries, near white and random
// points. Where a display value has a scene value (Aces2Output::has_scene_value), the inverse
// is exact: forward(inverse(d)) = d to 1e-10 of the peak. Where it has none, how far the round
// trip misses is measured, per place; docs/DISPLAY.md ("The inverse") tabulates it.
#include <irid/error.h>
#include <irid/gamut/aces2.h>
#include <irid/gamut/aces2_display.h>
#include <irid/gamut/display_transform.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

namespace irid {
namespace {

enum Place { corners, edges, faces, ramps, near_white, inside, place_count };
constexpr std::array<const char*, place_count> place_names{"corners", "edges",      "faces",
                                                           "ramps",   "near white", "random"};

struct Sample {
    Vec3 rgb;  // limiting RGB in [0, 1]³ of the peak
    Place place;
};

/// The points of the unit cube the test walks.
std::vector<Sample> cube_samples(std::mt19937_64& rng) {
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::vector<Sample> s;
    for (int c = 0; c < 8; ++c)
        s.push_back({{double(c & 1), double((c >> 1) & 1), double((c >> 2) & 1)}, corners});
    // Edges: two coordinates at 0 or 1, one free.
    for (int axis = 0; axis < 3; ++axis)
        for (int fixed = 0; fixed < 4; ++fixed)
            for (int k = 0; k <= 64; ++k) {
                Vec3 v{};
                v[(axis + 1) % 3] = fixed & 1;
                v[(axis + 2) % 3] = (fixed >> 1) & 1;
                v[axis] = k / 64.0;
                s.push_back({v, edges});
            }
    // Faces: one coordinate at 0 or 1.
    for (int axis = 0; axis < 3; ++axis)
        for (int side = 0; side < 2; ++side)
            for (int k = 0; k < 400; ++k) {
                Vec3 v{u(rng), u(rng), u(rng)};
                v[axis] = side;
                s.push_back({v, faces});
            }
    // From black to the primaries and secondaries, and to the greys' white, in log steps.
    for (const Vec3 target : {Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{0, 0, 1}, Vec3{0, 1, 1},
                              Vec3{1, 0, 1}, Vec3{1, 1, 0}, Vec3{1, 1, 1}})
        for (int k = 0; k <= 96; ++k) {
            const double t = std::pow(2.0, -16.0 * (96 - k) / 96.0);
            s.push_back({{target[0] * t, target[1] * t, target[2] * t}, ramps});
        }
    // Near white: each channel within 1e-3 of the peak, a tenth of them neutral.
    for (int k = 0; k < 1000; ++k) {
        const double n = 1.0 - 1e-3 * u(rng);
        s.push_back({k % 10 == 0
                         ? Vec3{n, n, n}
                         : Vec3{1.0 - 1e-3 * u(rng), 1.0 - 1e-3 * u(rng), 1.0 - 1e-3 * u(rng)},
                     near_white});
    }
    for (int k = 0; k < 4000; ++k) s.push_back({{u(rng), u(rng), u(rng)}, inside});
    return s;
}

/// docs/DISPLAY.md's largest round-trip miss (of the peak, in the limiting RGB) where no scene
/// value exists, by the display's limiting gamut and peak.
double documented_worst_miss(const Aces2DisplaySpec& spec) {
    const bool rec2020 = spec.limiting.green.y > 0.75;
    const bool d60 = spec.limiting_white.x > 0.32;
    if (rec2020 && d60) return 0.13;
    if (rec2020) return 0.031;
    if (spec.peak_nits <= 100.0) return 0.0019;
    if (spec.peak_nits <= 225.0) return 0.0064;
    return 0.018;
}

struct Miss {
    int count = 0, without = 0;
    double worst = 0.0;  // of the peak
};

/// The walk on one display: every sample's inverse, its round trip, and has_scene_value at
/// 1e-10 (exact inside what the chain gives, and else what the round trip says at that
/// tolerance): true exactly where the round trip holds to 1e-10 of the peak. Returns the largest
/// miss, printing a row of docs/DISPLAY.md's table.
double walk(const Aces2DisplaySpec& spec, const std::vector<Sample>& samples) {
    const Aces2Output out(spec);
    const Mat3 to_xyz = rgb_to_xyz_matrix(spec.limiting, spec.limiting_white);
    const double peak = spec.peak_nits / 100.0;  // the cube's side, before the output scale
    const double scale = out.output_scale();
    std::array<Miss, place_count> misses{};
    double exact_worst = 0.0, worst_miss = 0.0;
    for (const Sample& sample : samples) {
        const Vec3 xyz_v =
            to_xyz * Vec3{sample.rgb[0] * peak, sample.rgb[1] * peak, sample.rgb[2] * peak};
        const Xyz xyz{xyz_v[0] * scale, xyz_v[1] * scale, xyz_v[2] * scale};
        const Vec3 scene = out.inverse(xyz);
        const std::string where = spec.name + " at " + std::to_string(sample.rgb[0]) + " " +
                                  std::to_string(sample.rgb[1]) + " " +
                                  std::to_string(sample.rgb[2]);
        EXPECT_TRUE(std::isfinite(scene[0]) && std::isfinite(scene[1]) && std::isfinite(scene[2]))
            << where;
        const double miss = out.inverse_miss(xyz);  // of the peak, in the limiting RGB
        Miss& m = misses[sample.place];
        ++m.count;
        if (out.has_scene_value(xyz, 0.0)) {
            // Inside what the chain gives: exact.
            exact_worst = std::max(exact_worst, miss);
            EXPECT_LE(miss, 1e-10) << where;
        }
        EXPECT_EQ(out.has_scene_value(xyz, 1e-10), miss <= 1e-10) << where << ": miss " << miss;
        if (miss > 1e-10) {
            ++m.without;
            m.worst = std::max(m.worst, miss);
            worst_miss = std::max(worst_miss, miss);
        }
    }
    std::printf("%-40s exact %.2g", spec.name.c_str(), exact_worst);
    for (std::size_t p = 0; p < place_count; ++p)
        std::printf(" | %s %d/%d %.2g", place_names[p], misses[p].without, misses[p].count,
                    misses[p].worst);
    std::printf("\n");
    return worst_miss;
}

TEST(Aces2Inverse, IsExactWhereverASceneValueExistsAndItsMissIsMeasuredElsewhere) {
    std::mt19937_64 rng(37);
    const std::vector<Sample> samples = cube_samples(rng);
    for (const Aces2DisplaySpec& spec : aces2_displays()) {
        // The largest miss docs/DISPLAY.md gives for the display's kind, with 10 % to spare.
        EXPECT_LE(walk(spec, samples), 1.1 * documented_worst_miss(spec)) << spec.name;
    }
}

// Custom displays whose limiting gamut is far wider than the reach gamut AP1, or whose white is
// far from the ACES white: there the chroma compression's most M, and the hull estimate's
// failure to give any M, bound what the chain shows.
TEST(Aces2Inverse, IsExactWhereverASceneValueExistsOnWideAndOddCustomDisplays) {
    std::mt19937_64 rng(38);
    const std::vector<Sample> samples = cube_samples(rng);
    for (const char* name :
         {"custom:peak=100,limiting=aces2065-1", "custom:peak=10000,limiting=aces2065-1",
          "custom:peak=100,limiting=acescg", "custom:peak=100,limiting=srgb,white=A",
          "custom:peak=1000,limiting=rec2020,white=E"})
        (void)walk(aces2_display(name), samples);
}

}  // namespace
}  // namespace irid

namespace irid {
namespace {

TEST(Aces2Inverse, ADisplayTransformSaysWhichDisplayColoursHaveASceneValue) {
    // Rec.2020's blue at 36 cd/m² on a 4000 cd/m² display has none (its source lies beyond AP1);
    // mid grey has one. In the display's RGB and in CIE XYZ alike.
    const DisplayTransform rgb(
        {"aces2", "hdr-4000nit-rec2020", "rec2020-linear", "aces2065-1", true});
    EXPECT_TRUE(rgb.has_scene_value({0.2, 0.2, 0.2}));
    EXPECT_FALSE(rgb.has_scene_value({0.0, 0.0, 0.36}));
    const std::vector<unsigned char> flags =
        rgb.scene_values_exist(std::vector<double>{0.2, 0.2, 0.2, 0, 0, 0.36});
    EXPECT_EQ(flags, (std::vector<unsigned char>{1, 0}));
    const Vec3 blue =
        rgb_to_xyz_matrix(rec2020().primaries(), rec2020().white()) * Vec3{0.0, 0.0, 0.36};
    const DisplayTransform xyz({"aces2", "hdr-4000nit-rec2020", "xyz", "aces2065-1", true});
    EXPECT_FALSE(xyz.has_scene_value(blue));
    // The question belongs to an inverse transform.
    const DisplayTransform forward({"aces2", "hdr-4000nit-rec2020", "aces2065-1", "xyz", false});
    EXPECT_THROW((void)forward.has_scene_value({0.2, 0.2, 0.2}), Error);
    EXPECT_THROW((void)rgb.scene_values_exist(std::vector<double>{1.0, 2.0}), Error);
    EXPECT_EQ(no_scene_value_note({2, 5, 6, 7, 8, 9, 10, 11, 12}, 20, "stdin line").substr(0, 60),
              "9 of 20 display colours (stdin lines 2, 5, 6, 7, 8, 9, 10, 1");
    EXPECT_NE(
        no_scene_value_note({2, 5, 6, 7, 8, 9, 10, 11, 12}, 20, "stdin line").find("11, ...)"),
        std::string::npos);
}

}  // namespace
}  // namespace irid
