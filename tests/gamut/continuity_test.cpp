// Continuity of every clip method over the whole input domain, searched for jumps.
//
// Random segments are walked through five families of colours (the issue 23 search): bright
// colours of linear RGB in [-1, 4.5]³ × max, colours near the white, near black, saturated
// colours around the primaries and secondaries, and far HDR colours (up to 100 × max), in
// sRGB, Display P3 and Rec.2020, at max 1 and at an HDR peak of 100. Along each segment the
// output is compared step by step in ΔE2000 (of the output relative to the white (max, max,
// max)); wherever neighbours differ by more than 2, the step is bisected down to 1e-10 of max
// (double) or to adjacent floats (the float kernels), and a step still above 1 there is a jump.
// A jump fails the test unless the method's definition forces it there (GAMUT.md, "Where a
// method may jump"), which each `allowed_jump` below checks from the two colours either side.
//
// The same walk runs on GamutClipper::clip (double) and on clip_batch with the SIMD kernels
// (float; each colour padded to a whole vector so that the kernel, not the scalar tail, takes
// it).

#include <irid/color/difference.h>
#include <irid/color/rgb.h>
#include <irid/color/spaces.h>
#include <irid/gamut/batch.h>
#include <irid/gamut/clip.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <functional>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace irid {
namespace {

constexpr double step_threshold = 2.0;  // ΔE2000 between neighbours that starts a bisection
constexpr double jump_threshold = 1.0;  // ΔE2000 across the bisected interval that is a jump
constexpr int steps_per_segment = 48;
constexpr int segments_per_family = 18;

Vec3 v3(const Rgb& c) { return {c.r, c.g, c.b}; }

/// v rounded to float and back. Through a volatile: g++ 12.2 at -O2 and above drops the round
/// trip when it vectorises two or more of them (Rgb{static_cast<float>(c.r), ..., ...} kept r and
/// g unrounded, and this walk took the kernels' neighbours for double ones).
double through_float(double v) {
    volatile float f = static_cast<float>(v);
    return f;
}

/// ΔE2000 of two outputs of a gamut, in CIELAB relative to the gamut's white (max, max, max).
double output_difference(const Gamut& gamut, const Rgb& a, const Rgb& b) {
    const Mat3& m = gamut.space().to_xyz_matrix();
    const double max = gamut.max();
    const Vec3 w = m * Vec3{max, max, max};
    const Xyz white{w[0], w[1], w[2]};
    const auto lab = [&](const Rgb& c) {
        const Vec3 x = m * v3(c);
        return xyz_to_lab({x[0], x[1], x[2]}, white);
    };
    return delta_e_2000(lab(a), lab(b));
}

/// A segment's end points, drawn from one family (in units of max).
enum class Family { bright, near_white, near_black, saturated, hdr };
constexpr std::array<Family, 5> families{Family::bright, Family::near_white, Family::near_black,
                                         Family::saturated, Family::hdr};
const char* family_name(Family f) {
    switch (f) {
        case Family::bright: return "bright";
        case Family::near_white: return "near white";
        case Family::near_black: return "near black";
        case Family::saturated: return "saturated";
        case Family::hdr: return "HDR";
    }
    return "";
}

Rgb draw(Family f, std::mt19937_64& rng, double max) {
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const auto uniform = [&](double lo, double hi) { return lo + (hi - lo) * u(rng); };
    Rgb c{};
    switch (f) {
        case Family::bright:
            c = {uniform(-1.0, 4.5), uniform(-1.0, 4.5), uniform(-1.0, 4.5)};
            break;
        case Family::near_white: {
            // Around the white, from a little below it to a few times above, with small tints.
            const double level = uniform(0.9, 4.2);
            c = {level + uniform(-0.05, 0.05), level + uniform(-0.05, 0.05), level + uniform(-0.05, 0.05)};
            break;
        }
        case Family::near_black:
            c = {uniform(-0.002, 0.004), uniform(-0.002, 0.004), uniform(-0.002, 0.004)};
            break;
        case Family::saturated: {
            // A primary or secondary, scaled and pushed outward a little.
            const int k = static_cast<int>(u(rng) * 6.0) % 6;
            const std::array<Rgb, 6> corners{Rgb{1, 0, 0}, Rgb{0, 1, 0}, Rgb{0, 0, 1},
                                             Rgb{0, 1, 1}, Rgb{1, 0, 1}, Rgb{1, 1, 0}};
            const double s = uniform(0.2, 2.0);
            const Rgb& q = corners[static_cast<std::size_t>(k)];
            c = {s * q.r + uniform(-0.3, 0.1), s * q.g + uniform(-0.3, 0.1), s * q.b + uniform(-0.3, 0.1)};
            break;
        }
        case Family::hdr:
            c = {uniform(-5.0, 100.0), uniform(-5.0, 100.0), uniform(-5.0, 100.0)};
            break;
    }
    return {c.r * max, c.g * max, c.b * max};
}

/// A jump between colours a and b (a hair apart), mapped to out_a and out_b, is forced by the
/// method's definition when the two took different branches of it
/// (GamutClipper::branch_signature: css's binary search, css-raytrace's passes, the pieces of the
/// Oklab methods' lines, the cusp's candidate, CIELUV's undefined chromaticity, luv-hue's local
/// minima). Every other jump is a defect.
/// oklab and oklab-adaptive: both outputs of a jump lie on the colour's own segment toward the
/// neutral axis (its Oklab hue, and one line through the colour in the (L, C) plane), so that
/// the jump is a choice between two pieces of that segment inside the cube, not a defect that
/// happens to meet a change in the number of pieces. (Not for oklab-cusp, whose L0 moves with
/// its cusp's candidate.)
bool both_on_the_segment(const GamutClipper& clipper, const Rgb& a, const Rgb& out_a, const Rgb& out_b) {
    const Oklab in = clipper.to_oklab(a), p = clipper.to_oklab(out_a), q = clipper.to_oklab(out_b);
    const double scale = std::cbrt(clipper.gamut().max());
    const double tol = 1e-6 * scale;
    const double hue = std::atan2(in.b, in.a);
    const auto chroma = [](const Oklab& c) { return std::hypot(c.a, c.b); };
    for (const Oklab& o : {p, q}) {
        if (chroma(o) > tol && std::abs(std::remainder(std::atan2(o.b, o.a) - hue, 2.0 * M_PI)) > 1e-5) {
            return false;
        }
    }
    // (L, C) of the two outputs relative to the colour's: parallel (collinear with it).
    const double l1 = p.L - in.L, c1 = chroma(p) - chroma(in), l2 = q.L - in.L, c2 = chroma(q) - chroma(in);
    return std::abs(l1 * c2 - l2 * c1) <= tol * (std::hypot(l1, c1) + std::hypot(l2, c2) + tol);
}

bool allowed_jump(const GamutClipper& clipper, const Rgb& a, const Rgb& b, const Rgb& out_a,
                  const Rgb& out_b) {
    if (clipper.branch_signature(a) == clipper.branch_signature(b)) return false;
    if (clipper.method() == ClipMethod::oklab || clipper.method() == ClipMethod::oklab_adaptive) {
        return both_on_the_segment(clipper, a, out_a, out_b);
    }
    if (clipper.method() != ClipMethod::luv_hue) return true;
    // luv-hue's branches are stricter to check than a changed signature: either CIELUV's
    // chromaticity is undefined on one side (X + 15Y + 3Z <= 0), or the two outputs are both
    // nearest points, at the same ΔE*uv from the colour (a tie between two local minima).
    const Mat3& m = clipper.rgb_to_xyz();
    const double max = clipper.gamut().max();
    const Vec3 wv = m * Vec3{max, max, max};
    const Xyz white{wv[0], wv[1], wv[2]};
    const auto luv = [&](const Rgb& c) {
        const Vec3 x = m * v3(c);
        return xyz_to_luv({x[0], x[1], x[2]}, white);
    };
    const auto undefined = [&](const Rgb& c) {
        const Vec3 x = m * v3(c);
        return !(x[0] + 15.0 * x[1] + 3.0 * x[2] > 0.0);
    };
    if (undefined(a) != undefined(b)) return true;
    const double da = delta_e_uv(luv(a), luv(out_a)), db = delta_e_uv(luv(b), luv(out_b));
    return std::abs(da - db) <= 1e-4 * std::max(1.0, da);
}

using ClipFunction = std::function<std::vector<Rgb>(const std::vector<Rgb>&)>;

struct WalkResult {
    int segments = 0, jumps = 0, allowed = 0;
    double largest_allowed = 0.0;
    double largest_unexplained = 0.0;
    std::string first_unexplained;
};

/// Walks the segment a → b and bisects every step above step_threshold; `resolution` is the
/// length (in the colour's units) at which a bisection stops.
void walk_segment(const GamutClipper& clipper, const ClipFunction& clip, const Rgb& a, const Rgb& b,
                  double resolution, bool float_path, WalkResult& result) {
    const Gamut& gamut = clipper.gamut();
    std::vector<Rgb> points(steps_per_segment + 1);
    // The colour at t, as the clip sees it: rounded to float on the float path.
    const auto at = [&](double t) {
        const Rgb c{a.r + t * (b.r - a.r), a.g + t * (b.g - a.g), a.b + t * (b.b - a.b)};
        return float_path ? Rgb{through_float(c.r), through_float(c.g), through_float(c.b)} : c;
    };
    for (int k = 0; k <= steps_per_segment; ++k) points[static_cast<std::size_t>(k)] = at(double(k) / steps_per_segment);
    const std::vector<Rgb> out = clip(points);
    const double length = std::sqrt((b.r - a.r) * (b.r - a.r) + (b.g - a.g) * (b.g - a.g) +
                                    (b.b - a.b) * (b.b - a.b));
    for (int k = 0; k < steps_per_segment; ++k) {
        const std::size_t i = static_cast<std::size_t>(k);
        if (!(output_difference(gamut, out[i], out[i + 1]) > step_threshold)) continue;
        double t0 = double(k) / steps_per_segment, t1 = double(k + 1) / steps_per_segment;
        Rgb o0 = out[i], o1 = out[i + 1];
        for (int it = 0; it < 200 && (t1 - t0) * length > resolution; ++it) {
            const double tm = 0.5 * (t0 + t1);
            const Rgb pm = at(tm);
            if (float_path) {
                const Rgb p0 = at(t0), p1 = at(t1);
                const auto same = [](const Rgb& x, const Rgb& y) { return x.r == y.r && x.g == y.g && x.b == y.b; };
                if (same(pm, p0) || same(pm, p1)) break;  // adjacent floats
            }
            const Rgb om = clip({pm})[0];
            if (output_difference(gamut, o0, om) >= output_difference(gamut, om, o1)) {
                t1 = tm;
                o1 = om;
            } else {
                t0 = tm;
                o0 = om;
            }
        }
        const double jump = output_difference(gamut, o0, o1);
        if (!(jump > jump_threshold)) continue;
        ++result.jumps;
        const Rgb ca = at(t0), cb = at(t1);
        if (allowed_jump(clipper, ca, cb, o0, o1)) {
            ++result.allowed;
            result.largest_allowed = std::max(result.largest_allowed, jump);
            continue;
        }
        if (jump > result.largest_unexplained) {
            result.largest_unexplained = jump;
            std::ostringstream s;
            s.precision(17);
            s << "ΔE2000 " << jump << " between (" << ca.r << ", " << ca.g << ", " << ca.b
              << ") → (" << o0.r << ", " << o0.g << ", " << o0.b << ") and (" << cb.r << ", "
              << cb.g << ", " << cb.b << ") → (" << o1.r << ", " << o1.g << ", " << o1.b << ")";
            result.first_unexplained = s.str();
        }
    }
    ++result.segments;
}

ClipSettings settings_for(ClipMethod m) {
    ClipSettings s;
    // aces-rgc as images take it (irid clip turns clip on for images): without it, the curve
    // leaves colours outside the cube, and its published definition returns a colour whose
    // largest channel is 0 or below unchanged (a jump there by design).
    if (m == ClipMethod::aces_rgc) s.set("clip", 1.0);
    return s;
}

struct GamutCase {
    const RgbSpace* space;
    double max;
};
std::vector<GamutCase> gamut_cases() {
    return {{&srgb(), 1.0}, {&display_p3(), 1.0}, {&rec2020(), 1.0}, {&srgb(), 100.0}, {&rec2020(), 100.0}};
}

void walk_method(ClipMethod method, bool float_path) {
    WalkResult census;  // over every gamut and family, printed for GAMUT.md
    for (const GamutCase& g : gamut_cases()) {
        const Gamut gamut(*g.space, g.max);
        const GamutClipper clipper(method, gamut, settings_for(method));
        ClipFunction clip;
        if (float_path) {
            clip = [&](const std::vector<Rgb>& in) {
                // Each colour repeated over 32 lanes: a whole vector on every target, so the SIMD
                // kernel, not the scalar tail, clips it.
                constexpr std::size_t lanes = 32;
                std::vector<float> buffer(in.size() * lanes * 3);
                for (std::size_t i = 0; i < in.size(); ++i) {
                    for (std::size_t k = 0; k < lanes; ++k) {
                        float* p = &buffer[3 * (i * lanes + k)];
                        p[0] = static_cast<float>(in[i].r);
                        p[1] = static_cast<float>(in[i].g);
                        p[2] = static_cast<float>(in[i].b);
                    }
                }
                clip_batch(clipper, std::span<float>(buffer), BatchOptions{.threads = 1});
                std::vector<Rgb> out(in.size());
                for (std::size_t i = 0; i < in.size(); ++i) {
                    const float* p = &buffer[3 * i * lanes];
                    out[i] = {p[0], p[1], p[2]};
                }
                return out;
            };
        } else {
            clip = [&](const std::vector<Rgb>& in) {
                std::vector<Rgb> out(in.size());
                for (std::size_t i = 0; i < in.size(); ++i) out[i] = clipper.clip(in[i]);
                return out;
            };
        }
        for (const Family f : families) {
            SCOPED_TRACE(std::string(g.space->name()) + " max " + std::to_string(g.max) + ", " +
                         family_name(f) + (float_path ? ", float kernels" : ", double"));
            std::mt19937_64 rng(20260 + static_cast<unsigned>(f) * 7919 + static_cast<unsigned>(method) * 104729);
            WalkResult result;
            for (int s = 0; s < segments_per_family; ++s) {
                const Rgb a = draw(f, rng, g.max), b = draw(f, rng, g.max);
                walk_segment(clipper, clip, a, b, 1e-10 * g.max, float_path, result);
            }
            census.segments += result.segments;
            census.jumps += result.jumps;
            census.allowed += result.allowed;
            census.largest_allowed = std::max(census.largest_allowed, result.largest_allowed);
            EXPECT_EQ(result.largest_unexplained, 0.0)
                << clip_method_name(method) << ": " << result.jumps - result.allowed
                << " jumps not forced by the definition over " << result.segments
                << " segments; largest: " << result.first_unexplained;
        }
    }
    std::printf("continuity of %s (%s): %d segments, %d jumps above ΔE2000 %g, %d of them where the "
                "definition branches (largest ΔE2000 %.3g)\n",
                std::string(clip_method_name(method)).c_str(), float_path ? "float kernels" : "double",
                census.segments, census.jumps, jump_threshold, census.allowed, census.largest_allowed);
}

class Continuity : public ::testing::TestWithParam<ClipMethod> {};

TEST_P(Continuity, DoubleReferenceJumpsOnlyWhereItsDefinitionForces) { walk_method(GetParam(), false); }

TEST_P(Continuity, FloatKernelsJumpOnlyWhereTheDefinitionForces) { walk_method(GetParam(), true); }

INSTANTIATE_TEST_SUITE_P(EveryMethod, Continuity, ::testing::ValuesIn(clip_methods().begin(), clip_methods().end()),
                         [](const ::testing::TestParamInfo<ClipMethod>& param) {
                             std::string name(clip_method_name(param.param));
                             std::replace(name.begin(), name.end(), '-', '_');
                             return name;
                         });

}  // namespace
}  // namespace irid
