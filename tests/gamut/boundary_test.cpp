// A colour within rounding of the gamut comes back within rounding of itself, for every method,
// through GamutClipper::clip, GamutClipper::clip_xyz and clip_batch (float, scalar and SIMD).
//
// The colours lie on the surface of the cube [0, max]³ (its 8 vertices, points along its 12
// edges, points on its 6 faces, many of them close to an edge) and are then pushed outward, off
// every face they lie on or off only some of them, by one ulp of max, 1e-12 max and 1e-9 max
// (and by 0: on the surface, inside). A colour at distance d outside the cube (the largest
// excess of a channel below 0 or above max) may move by at most
//
//     growth × d + rounding
//
// growth = 100: the methods that move a colour toward the grey of its luminance (smits,
// smits-xyz, luv-lightness-hue) move a colour at distance d from a face by up to d (1 − l)/l,
// where l is the smallest luminance weight of the space relative to their sum (sRGB blue
// 0.0722: 13 d; Rec.2020 blue 0.0593: 16 d); clamp, css and oklab move it by d; 100 leaves
// room. The defects this guards against: oklab moved colours by 4e-4 to 0.86 whatever d was;
// the retired smits-corrected by up to about 6000 d (6.4e-6 for d = 1e-9 on Rec.2020).
// rounding: in double 1e-12 max: the methods go through XYZ, CIELUV or Oklab (cube roots) and
// back, a few hundred ulps at most, and luv-hue's golden-section search settles L* to about
// 1e-13. In float 4 ulps of max (4 × 2^-23 max): the result is rounded to float (half an ulp)
// and the SIMD smits kernel computes in float (its w, t and c + t (w − c) are each rounded).

#include <irid/color/rgb.h>
#include <irid/color/spaces.h>
#include <irid/gamut/batch.h>
#include <irid/gamut/clip.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <random>
#include <span>
#include <sstream>
#include <string>
#include <vector>

namespace irid {
namespace {

constexpr double growth = 100.0;
constexpr double double_rounding = 1e-12;                                       // × max
constexpr double float_rounding = 4.0 * std::numeric_limits<float>::epsilon();  // × max

/// The gamuts: four spaces at max 1, and an HDR peak of 4 on two of them.
std::vector<Gamut> gamuts() {
    return {Gamut(srgb()),      Gamut(display_p3()), Gamut(rec2020()),
            Gamut(adobe_rgb()), Gamut(srgb(), 4.0),  Gamut(rec2020(), 4.0)};
}

std::string gamut_name(const Gamut& g) {
    std::ostringstream s;
    s << g.space().name() << " [0, " << g.max() << "]";
    return s.str();
}

/// A colour on the surface: its channels, and for each whether it lies on a face (at 0 or max).
struct SurfacePoint {
    std::array<double, 3> c{};
    std::array<bool, 3> on_face{};
};

/// A coordinate in [0, max]: half uniform, a quarter close to 0 and a quarter close to max (u⁴,
/// down to about 1e-8 max), so that the thin strips of a face along its edges are sampled too.
double coordinate(std::mt19937_64& rng, double max) {
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const double kind = u(rng), x = u(rng);
    if (kind < 0.5) return x * max;
    const double near = x * x * x * x * max;
    return kind < 0.75 ? near : max - near;
}

/// The vertices, 40 points along each edge and 300 on each face, from a fixed seed.
std::vector<SurfacePoint> surface(double max) {
    std::mt19937_64 rng(20240611);
    std::vector<SurfacePoint> points;
    for (int v = 0; v < 8; ++v) {
        points.push_back(
            {{(v & 1) ? max : 0.0, (v & 2) ? max : 0.0, (v & 4) ? max : 0.0}, {true, true, true}});
    }
    for (int free = 0; free < 3; ++free) {  // edges: one free channel, the other two at 0 or max
        for (int ends = 0; ends < 4; ++ends) {
            for (int k = 0; k < 40; ++k) {
                SurfacePoint p;
                const int a = (free + 1) % 3, b = (free + 2) % 3;
                p.c[free] = coordinate(rng, max);
                p.c[a] = (ends & 1) ? max : 0.0;
                p.c[b] = (ends & 2) ? max : 0.0;
                p.on_face = {true, true, true};
                p.on_face[free] = false;
                points.push_back(p);
            }
        }
    }
    for (int fixed = 0; fixed < 3; ++fixed) {  // faces: one channel at 0 or max
        for (int side = 0; side < 2; ++side) {
            for (int k = 0; k < 300; ++k) {
                SurfacePoint p;
                for (int i = 0; i < 3; ++i) p.c[i] = coordinate(rng, max);
                p.c[fixed] = side ? max : 0.0;
                p.on_face = {false, false, false};
                p.on_face[fixed] = true;
                points.push_back(p);
            }
        }
    }
    return points;
}

/// The point pushed outward by `nudge` off the faces in `which` (a subset of its faces, as a
/// bit mask over the channels).
std::array<double, 3> pushed(const SurfacePoint& p, unsigned which, double nudge, double max) {
    std::array<double, 3> c = p.c;
    for (int i = 0; i < 3; ++i) {
        if (!p.on_face[i] || !(which & (1u << i))) continue;
        c[i] = c[i] == 0.0 ? -nudge : max + nudge;
    }
    return c;
}

/// Every colour of the test on one gamut: each surface point pushed off each non-empty subset
/// of its faces, by each nudge (absolute, already multiplied by max).
std::vector<std::array<double, 3>> near_boundary_colours(double max,
                                                         std::span<const double> nudges) {
    std::vector<std::array<double, 3>> colours;
    for (const SurfacePoint& p : surface(max)) {
        unsigned faces = 0;
        for (int i = 0; i < 3; ++i) faces |= p.on_face[i] ? (1u << i) : 0u;
        for (unsigned which = 1; which < 8; ++which) {
            if ((which & faces) != which) continue;
            for (const double nudge : nudges) colours.push_back(pushed(p, which, nudge, max));
        }
    }
    return colours;
}

/// The distance outside [0, max]³: the largest excess of a channel.
double distance_outside(const std::array<double, 3>& c, double max) {
    double d = 0.0;
    for (const double v : c) d = std::max({d, -v, v - max});
    return d;
}

/// Collects the colours that moved too far; reports how many and the worst.
class Verdict {
public:
    void check(const std::array<double, 3>& in, const std::array<double, 3>& out, double allowed) {
        ++m_checked;
        double moved = 0.0;
        for (int i = 0; i < 3; ++i) moved = std::max(moved, std::abs(out[i] - in[i]));
        if (!(moved <= allowed)) {  // NaN fails too
            ++m_failed;
            if (!(moved - allowed <= m_worst_excess)) {
                m_worst_excess = moved - allowed;
                std::ostringstream s;
                s.precision(17);
                s << "(" << in[0] << ", " << in[1] << ", " << in[2] << ") -> (" << out[0] << ", "
                  << out[1] << ", " << out[2] << "): moved " << moved << ", allowed " << allowed;
                m_worst = s.str();
            }
        }
    }
    void expect_none(const std::string& what) const {
        EXPECT_GT(m_checked, 0u) << what;
        EXPECT_EQ(m_failed, 0u) << what << ": " << m_failed << " of " << m_checked
                                << " colours moved too far; worst " << m_worst;
    }

private:
    std::size_t m_checked = 0, m_failed = 0;
    double m_worst_excess = -1.0;
    std::string m_worst;
};

TEST(ClipNearTheGamut,
     EveryMethodReturnsAColourWithinRoundingOutsideTheCubeWithinRoundingOfItself) {
    for (const Gamut& gamut : gamuts()) {
        const double max = gamut.max();
        const double ulp = std::numeric_limits<double>::epsilon() * max;
        const std::array<double, 4> nudges{0.0, ulp, 1e-12 * max, 1e-9 * max};
        const std::vector<std::array<double, 3>> colours = near_boundary_colours(max, nudges);
        ASSERT_GT(colours.size(), 10000u);
        const Mat3& to_xyz = gamut.space().to_xyz_matrix();
        const Mat3& from_xyz = gamut.space().from_xyz_matrix();
        for (const ClipMethod method : clip_methods()) {
            // The soft methods (aces-rgc, smits-soft) move colours inside the gamut by design
            // (clip.h); their contracts are tested in their own files.
            if (moves_in_gamut_colours(method)) continue;
            const GamutClipper clipper(method, gamut);
            Verdict rgb, xyz;
            for (const std::array<double, 3>& c : colours) {
                const double allowed = growth * distance_outside(c, max) + double_rounding * max;
                const Rgb o = clipper.clip({c[0], c[1], c[2]});
                rgb.check(c, {o.r, o.g, o.b}, allowed);
                // The XYZ entry point: the same colour as XYZ, the result back in RGB (the two
                // matrix products add rounding of their own, well inside double_rounding).
                const Vec3 x = to_xyz * Vec3{c[0], c[1], c[2]};
                const Xyz ox = clipper.clip_xyz({x[0], x[1], x[2]});
                const Vec3 back = from_xyz * Vec3{ox.X, ox.Y, ox.Z};
                xyz.check(c, {back[0], back[1], back[2]}, allowed);
            }
            const std::string what =
                gamut_name(gamut) + ", " + std::string(clip_method_name(method));
            rgb.expect_none(what + ", GamutClipper::clip");
            xyz.expect_none(what + ", GamutClipper::clip_xyz");
        }
    }
}

TEST(ClipNearTheGamut,
     FloatBatchesScalarAndSimdReturnNearBoundaryColoursWithinRoundingOfThemselves) {
    for (const Gamut& gamut : gamuts()) {
        const double max = gamut.max();
        const auto fmax = static_cast<float>(max);
        // One float ulp of max outward is 2^-23 max, the first float above a channel at max.
        const double ulp = static_cast<double>(std::nextafter(fmax, 2.0f * fmax)) - max;
        const std::array<double, 4> nudges{0.0, ulp, 1e-12 * max, 1e-9 * max};
        std::vector<float> in;
        for (const std::array<double, 3>& c : near_boundary_colours(max, nudges)) {
            for (const double v : c) in.push_back(static_cast<float>(v));
        }
        ASSERT_GT(in.size(), 30000u);
        for (const ClipMethod method : clip_methods()) {
            // The soft methods (aces-rgc, smits-soft) move colours inside the gamut by design
            // (clip.h); their contracts are tested in their own files.
            if (moves_in_gamut_colours(method)) continue;
            const GamutClipper clipper(method, gamut);
            for (const bool simd : {false, true}) {
                std::vector<float> out(in.size());
                clip_batch(clipper, in, out, BatchOptions{1, simd});
                Verdict verdict;
                for (std::size_t i = 0; i < in.size(); i += 3) {
                    // The float colour is the input: its distance, not the double one it came from.
                    const std::array<double, 3> c{in[i], in[i + 1], in[i + 2]};
                    const std::array<double, 3> o{out[i], out[i + 1], out[i + 2]};
                    verdict.check(c, o, growth * distance_outside(c, max) + float_rounding * max);
                }
                verdict.expect_none(gamut_name(gamut) + ", " +
                                    std::string(clip_method_name(method)) + ", clip_batch " +
                                    (simd ? "SIMD" : "scalar"));
            }
        }
    }
}

TEST(ClipNearTheGamut, PureBlueOneUlpOutsideSrgbStaysPureBlueUnderOklab) {
    // The reported case: (0, 0, 1 + 2^-52) came back as (0, 0.0303, 0.786), 21 % of its chroma
    // lost. Oklab's line of constant lightness and hue through sRGB blue leaves the cube through
    // r = 0 at about 85 % of blue's chroma and meets it again only at the vertex.
    const GamutClipper oklab(ClipMethod::oklab, Gamut(srgb()));
    const Rgb out = oklab.clip({0.0, 0.0, std::nextafter(1.0, 2.0)});
    EXPECT_NEAR(out.r, 0.0, 1e-12);
    EXPECT_NEAR(out.g, 0.0, 1e-12);
    EXPECT_NEAR(out.b, 1.0, 1e-12);
}

}  // namespace
}  // namespace irid
