// The float SIMD kernels of css (CSS Color 4 §13.2.2, binary search with local MINDE) and
// css-raytrace (CSS Color 4 "Ray Trace" gamut mapping), Google Highway with dynamic dispatch.
// Both follow their double references (GamutClipper::css in clip.cpp, css_raytrace.cpp) step by
// step, lane by lane, and are tested against them to 1e-5 × max (tests/gamut/css_raytrace_test.cpp).
// What differs from the references, and which lanes go back to them, is in docs/KERNELS.md.

// No floating-point contraction: the compensated products and sums need every product
// and sum rounded on its own (g++ would otherwise fuse them on the FMA targets). The pragma
// comes before every #include (as in batch_simd.cpp). Explicit MulAdd calls stay fused.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC optimize("fp-contract=off")
#endif
// oklab_pairs-inl.h checks that its includer turned contraction off.
#define IRID_FP_CONTRACT_OFF 1

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE __BASE_FILE__
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "simd_common-inl.h"
#include "oklab_pairs-inl.h"

#include <irid/color/spaces.h>
#include <irid/gamut/clip.h>

#include "kernels.h"

#include <cstddef>
#include <limits>

HWY_BEFORE_NAMESPACE();
namespace irid {
namespace HWY_NAMESPACE {
namespace {

namespace hn = hwy::HWY_NAMESPACE;
using simd::Df;
using simd::Mf;
using simd::Vf;
using namespace oklab_pairs;  // NOLINT(google-build-using-namespace): the kernels' arithmetic

/// CSS Color 4 §13.2.2: the JND and the search's resolution (as clip.cpp).
constexpr float css_jnd_f = 0.02f;
constexpr float css_epsilon_f = 0.0001f;
/// CSS Color 4 Ray Trace, footnote 1: the 32-bit anchor bound (low = 1e-6 max, high = max − low).
constexpr float raytrace_epsilon_f = 1e-6f;
/// CSS Color 4 Ray Trace, "cast a ray": a direction component at or below this is parallel to
/// its slab. The 64-bit 1e-12 of the specification, also in float (the contract gives
/// 1e-6 in float only for the anchor bounds): float holds 1e-12 with its full relative
/// precision, and with footnote 7's 1e-6 the components of the ray between two nearly equal
/// dark colours would be dropped where the double reference keeps them, ending elsewhere.
constexpr float parallel_epsilon_f = 1e-12f;
/// Beyond this magnitude a channel is not split for the compensated products (4097 x would
/// overflow near float's maximum); such a lane goes to the double path.
constexpr float split_limit = 1e30f;
/// Below this Oklab chroma the origin's hue is not resolved in float: the double path.
constexpr float hueless_chroma = 1e-6f;
/// Float rounding margins for the branch tests (flagged lanes go to the double path): the
/// lightness against white and black; a channel against the cube's faces, relative to max (the
/// accurate transforms below give a channel to about an ulp, 1.2e-7 max near max); ΔEOK
/// against its thresholds (Oklab components to about an ulp, 6e-8, so ΔEOK to about 1e-7: with
/// a margin of 3e-8, 14 of 2^20 benchmark colours branched differently and ended up to 6e-4
/// away; with 2e-7 none of them, 0.4 % of them flagged); and the search interval against
/// epsilon (relative).
constexpr float lightness_margin = 1e-5f;
constexpr float channel_margin = 5e-7f;
constexpr float delta_margin = 2e-7f;
constexpr float interval_margin = 1e-4f;
/// css-raytrace: a restore pass (i > 0) whose ray meets the face at t > 2 (it crossed the cube
/// from an anchor within rounding of the surface) or whose intersection moves by more than
/// grazing_gain times an error of its end (a ray grazing the face: the restore's float error
/// grows with each such pass, and the passes do not converge for colours near the white's
/// lightness; with plain float transforms an error of 1e-6 grew to 2.8e-5) sends the lane to the
/// double path.
constexpr float wild_ray_t = 2.0f;
constexpr float grazing_gain = 16.0f;
/// css-raytrace: a restore pass that moves the point more than diverging_ratio times as far as
/// the one before (the passes diverge and amplify rounding: ACES2065-1's restores near its
/// imaginary blue grew an error of 7e-7 to 2.3e-5 in one pass) sends the lane to the double
/// path.
constexpr float diverging_ratio = 2.0f;
/// css-raytrace: a lane whose anchor the float bounds (1e-6) keep where the double reference's
/// (1e-12) would move it, or where float cannot tell (a restored point within 1e-6 max of a
/// face), goes to the double path when that changes its passes by more than rounding: a dark
/// colour (brightest channel below dark_channel × max), or a next restored point within
/// wild_gap × max of the would-be anchor; so does a colour with a channel of its own between
/// rounding_channel × max and the float bound (near 0 or near max; fuzz finding clip-9: on
/// SMPTE-C at max 100, a channel of 4.8e-5 left the anchor in place in float and the result
/// 3e-5 max away).
constexpr float dark_channel = 1e-3f;
constexpr float wild_gap = 1e-5f;
constexpr float rounding_channel = 2e-7f;

/// What both kernels read from the clipper, once per call.
struct Params {
    Transforms T;
    Vf max, white_l;
    Vf k0, k1, k2;  // the anchor direction: OkLCh(L, 0, h) in linear RGB = L³ (k0, k1, k2)
    bool positive_lms;  // no entry of rgb_to_lms is negative
};

/// Reads the clipper once per call: its transforms as pairs, the cube, the white's lightness,
/// the anchor direction k and whether rgb_to_lms is non-negative.
HWY_INLINE Params LoadParams(Df d, const GamutClipper& clipper) {
    Params p{{LoadPairMatrix(d, clipper.rgb_to_lms()), LoadPairMatrix(d, clipper.lms_to_rgb()),
              LoadPairMatrix(d, oklab_m2), LoadPairMatrix(d, oklab_m2_inverse)},
             hn::Set(d, static_cast<float>(clipper.gamut().max())),
             hn::Set(d, static_cast<float>(clipper.white_oklab_lightness())), hn::Zero(d),
             hn::Zero(d), hn::Zero(d), true};
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) p.positive_lms = p.positive_lms && clipper.rgb_to_lms()[i][j] >= 0.0;
    }
    const Vec3 q = oklab_m2_inverse * Vec3{1.0, 0.0, 0.0};
    const Vec3 k = clipper.lms_to_rgb() * Vec3{q[0] * q[0] * q[0], q[1] * q[1] * q[1], q[2] * q[2] * q[2]};
    p.k0 = hn::Set(d, static_cast<float>(k[0]));
    p.k1 = hn::Set(d, static_cast<float>(k[1]));
    p.k2 = hn::Set(d, static_cast<float>(k[2]));
    return p;
}

/// Every channel in [lo, hi] (the cube, or the cube widened by a tolerance).
HWY_INLINE Mf InCube(Vf r, Vf g, Vf b, Vf lo, Vf hi) {
    return hn::And(hn::And(hn::And(hn::Ge(r, lo), hn::Le(r, hi)),
                           hn::And(hn::Ge(g, lo), hn::Le(g, hi))),
                   hn::And(hn::Ge(b, lo), hn::Le(b, hi)));
}

/// A channel within `margin` of 0 or of max.
HWY_INLINE Mf NearFace(Vf v, Vf zero, Vf max, Vf margin) {
    return hn::Or(hn::Lt(hn::Abs(hn::Sub(v, zero)), margin), hn::Lt(hn::Abs(hn::Sub(v, max)), margin));
}

/// std::clamp(v, 0, max) for non-NaN v.
HWY_INLINE Vf Clamp(Vf v, Vf zero, Vf max) {
    return hn::Min(hn::Max(v, zero), max);
}

/// The Oklab chroma sqrt(a² + b²).
HWY_INLINE Vf Chroma(Vf a, Vf b) {
    return hn::Sqrt(hn::MulAdd(a, a, hn::Mul(b, b)));
}


/// "Cast a ray" (CSS Color 4 Ray Trace) from start (s) to end (e) through the box [0, max]³,
/// lane by lane, as css_raytrace.cpp's cast_ray: returns the lanes where an intersection was
/// found and writes it to (x, y, z), its parameter along the ray to t, and in `grazing` the
/// lanes where it moves by more than grazing_gain times an error of `end`.
HWY_INLINE Mf CastRay(Df d, Vf s0, Vf s1, Vf s2, Vf e0, Vf e1, Vf e2, Vf zero, Vf max, Vf& x,
                      Vf& y, Vf& z, Vf& t, Mf& grazing) {
    const Vf inf = hn::Set(d, std::numeric_limits<float>::infinity());
    const Vf eps = hn::Set(d, parallel_epsilon_f);
    Vf tnear = hn::Neg(inf), tfar = inf;
    Mf parallel_outside = hn::Lt(zero, zero);  // all false
    const Vf d0 = hn::Sub(e0, s0), d1 = hn::Sub(e1, s1), d2 = hn::Sub(e2, s2);
    Vf dk_near = zero, dk_far = zero;  // the direction's component across the face hit
    const auto slab = [&](Vf a, Vf dir) {
        const Mf use = hn::Gt(hn::Abs(dir), eps);
        const Vf inv = hn::Div(hn::Set(d, 1.0f), dir);
        const Vf t1 = hn::Mul(hn::Sub(zero, a), inv);
        const Vf t2 = hn::Mul(hn::Sub(max, a), inv);
        const Vf lo_t = hn::Min(t1, t2), hi_t = hn::Max(t1, t2);
        dk_near = hn::IfThenElse(hn::And(use, hn::Gt(lo_t, tnear)), dir, dk_near);
        dk_far = hn::IfThenElse(hn::And(use, hn::Lt(hi_t, tfar)), dir, dk_far);
        tnear = hn::IfThenElse(use, hn::Max(lo_t, tnear), tnear);
        tfar = hn::IfThenElse(use, hn::Min(hi_t, tfar), tfar);
        parallel_outside = hn::Or(parallel_outside,
                                  hn::AndNot(use, hn::Or(hn::Lt(a, zero), hn::Gt(a, max))));
    };
    slab(s0, d0);
    slab(s1, d1);
    slab(s2, d2);
    const Mf miss = hn::Or(parallel_outside, hn::Or(hn::Gt(tnear, tfar), hn::Lt(tfar, zero)));
    const Mf from_inside = hn::Lt(tnear, zero);
    const Vf dk = hn::IfThenElse(from_inside, dk_far, dk_near);
    tnear = hn::IfThenElse(from_inside, tfar, tnear);
    // How much an error in `end` moves the intersection: t |d|∞ / |d across the face hit|, large
    // when the ray grazes the face; `grazing` where it exceeds grazing_gain.
    const Vf dmax = hn::Max(hn::Max(hn::Abs(d0), hn::Abs(d1)), hn::Abs(d2));
    grazing = hn::Gt(hn::Mul(hn::Abs(tnear), dmax), hn::Mul(hn::Set(d, grazing_gain), hn::Abs(dk)));
    const Mf found = hn::AndNot(miss, hn::IsFinite(tnear));
    x = hn::MulAdd(d0, tnear, s0);
    y = hn::MulAdd(d1, tnear, s1);
    z = hn::MulAdd(d2, tnear, s2);
    t = tnear;
    return found;
}


}  // namespace

/// css-raytrace on the largest multiple of the vector length of `colours` interleaved float RGB
/// colours from `in` to `out` (may be equal); returns how many (kernels.h). Each lane follows
/// GamutClipper::css_raytrace in float; flagged lanes are redone with GamutClipper::clip.
std::size_t ClipCssRayTrace(const GamutClipper& clipper, const float* in, float* out,
                            std::size_t colours) {
    const Df d;
    const Params p = LoadParams(d, clipper);
    const Vf zero = hn::Zero(d);
    const Vf low = hn::Mul(hn::Set(d, raytrace_epsilon_f), p.max);
    const Vf high = hn::Sub(p.max, low);
    const Vf tol = hn::Mul(hn::Set(d, static_cast<float>(oklab_rounding_tolerance)), p.max);
    const Vf low_d = hn::Mul(hn::Set(d, 1e-12f), p.max);
    const Vf high_d = hn::Sub(p.max, low_d);
    const Vf lmargin = hn::Set(d, lightness_margin);
    const Vf wild_t = hn::Set(d, wild_ray_t);
#if HWY_TARGET != HWY_SCALAR && HWY_HAVE_FLOAT64
    const DoubleTransforms TD{LoadDoubleMatrix(clipper.rgb_to_lms()), LoadDoubleMatrix(clipper.lms_to_rgb()),
                              LoadDoubleMatrix(oklab_m2), LoadDoubleMatrix(oklab_m2_inverse)};
#endif
    return simd::RunKernel(d, clipper, in, out, colours, [&](Vf r, Vf g, Vf b, Vf& out_r, Vf& out_g, Vf& out_b) {
        const Mf inside = InCube(r, g, b, zero, p.max);
        if (hn::AllTrue(d, inside)) {
            out_r = r, out_g = g, out_b = b;
            return hn::Not(inside);
        }
        Vf L, A, B;
#if HWY_TARGET != HWY_SCALAR && HWY_HAVE_FLOAT64
        ToOklabDouble(d, TD, r, g, b, L, A, B);
#else
        ToOklabAccurate(d, p.T, r, g, b, L, A, B);
#endif
        const Mf huge = hn::Or(hn::Or(hn::Gt(hn::Abs(r), hn::Set(d, split_limit)),
                                      hn::Gt(hn::Abs(g), hn::Set(d, split_limit))),
                               hn::Gt(hn::Abs(b), hn::Set(d, split_limit)));
        const Mf white = hn::Ge(L, p.white_l);
        const Mf black = hn::AndNot(white, hn::Le(L, zero));
        const Vf c0 = Chroma(A, B);
        // cos h and sin h of the origin's hue (a hueless lane is flagged below).
        const Vf inv_c0 = hn::Div(hn::Set(d, 1.0f), hn::Max(c0, hn::Set(d, hueless_chroma)));
        const Vf ua = hn::Mul(A, inv_c0), ub = hn::Mul(B, inv_c0);
#if HWY_TARGET != HWY_SCALAR && HWY_HAVE_FLOAT64
        Vd Ld[2], uad[2], ubd[2];
        SplitToDouble(L, Ld);
        SplitToDouble(ua, uad);
        SplitToDouble(ub, ubd);
#endif
        const Vf L3 = hn::Mul(hn::Mul(L, L), L);
        Vf a0 = hn::Mul(L3, p.k0), a1 = hn::Mul(L3, p.k1), a2 = hn::Mul(L3, p.k2);
        Vf c_r = r, c_g = g, c_b = b;
        Vf last_r = r, last_g = g, last_b = b;
        // Within rounding of the cube (oklab_rounding_tolerance, as css_raytrace.cpp): clamped.
        const Mf near_cube = InCube(r, g, b, hn::Neg(tol), hn::Add(p.max, tol));
        Mf active = hn::Not(hn::Or(hn::Or(inside, near_cube), hn::Or(white, black)));
        Mf wild = hn::Lt(zero, zero), grazing = wild, bounds_path = wild, diverging = wild;
        const Vf rounding = hn::Mul(hn::Set(d, rounding_channel), p.max);
        // A channel of the colour itself between the two bounds, by more than rounding.
        const auto between = [&](Vf v) {
            return hn::Or(hn::And(hn::Ge(v, rounding), hn::Le(v, low)),
                          hn::And(hn::Ge(v, high), hn::Le(v, hn::Sub(p.max, rounding))));
        };
        bounds_path = hn::And(active, hn::Or(hn::Or(between(r), between(g)), between(b)));
        const Vf dark = hn::Mul(hn::Set(d, dark_channel), p.max);
        const Vf wild_gap_max = hn::Mul(hn::Set(d, wild_gap), p.max);
        Vf last_moved = zero;
        // The previous pass's restored point and whether the double path may have moved the
        // anchor to it (below).
        Vf prev_r = zero, prev_g = zero, prev_b = zero;
        Mf prev_maybe_moved = hn::Lt(zero, zero);
        for (int it = 0; it < 4; ++it) {
            if (it > 0) {
                // Back onto the chroma line: the origin's L and h, the current chroma.
                // Only the lanes still in the loop: a lane that left it (no intersection)
                // keeps its last intersection.
                Vf nr, ng, nb;
#if HWY_TARGET != HWY_SCALAR && HWY_HAVE_FLOAT64
                RestoreDouble(d, TD, c_r, c_g, c_b, Ld, uad, ubd, nr, ng, nb);
#else
                const Vf c = ChromaAccurate(d, p.T, p.positive_lms, c_r, c_g, c_b);
                FromOklabAccurate(d, p.T, L, hn::Mul(c, ua), hn::Mul(c, ub), nr, ng, nb);
#endif
                // How far the restore moved the intersection: growing from pass to pass, the
                // passes diverge and amplify rounding (seen on ACES2065-1's imaginary blue).
                const Vf moved = hn::Max(hn::Max(hn::Abs(hn::Sub(nr, c_r)), hn::Abs(hn::Sub(ng, c_g))),
                                         hn::Abs(hn::Sub(nb, c_b)));
                if (it > 1) {
                    diverging = hn::Or(diverging, hn::And(active, hn::Gt(moved, hn::Mul(hn::Set(d, diverging_ratio), last_moved))));
                }
                last_moved = moved;
                c_r = hn::IfThenElse(active, nr, c_r);
                c_g = hn::IfThenElse(active, ng, c_g);
                c_b = hn::IfThenElse(active, nb, c_b);
            }
            Vf x, y, z, t;
            Mf grazes;
            const Mf found = CastRay(d, a0, a1, a2, c_r, c_g, c_b, zero, p.max, x, y, z, t, grazes);
            if (it > 0) {
                const Mf hit = hn::And(active, found);
                wild = hn::Or(wild, hn::And(hit, hn::Gt(t, wild_t)));
                grazing = hn::Or(grazing, hn::And(hit, grazes));
            }
            const Mf lost = hn::AndNot(found, active);
            c_r = hn::IfThenElse(lost, last_r, c_r);
            c_g = hn::IfThenElse(lost, last_g, c_g);
            c_b = hn::IfThenElse(lost, last_b, c_b);
            active = hn::And(active, found);
            if (it > 0) {
                const Mf below = hn::And(
                    hn::And(hn::And(hn::Lt(low, c_r), hn::Lt(c_r, high)),
                            hn::And(hn::Lt(low, c_g), hn::Lt(c_g, high))),
                    hn::And(hn::Lt(low, c_b), hn::Lt(c_b, high)));
                const Mf move = hn::And(active, below);
                // The double reference's bounds (1e-12) would move the anchor where these do
                // not: the double path takes the lane.
                const Mf below_double = hn::And(
                    hn::And(hn::And(hn::Lt(low_d, c_r), hn::Lt(c_r, high_d)),
                            hn::And(hn::Lt(low_d, c_g), hn::Lt(c_g, high_d))),
                    hn::And(hn::Lt(low_d, c_b), hn::Lt(c_b, high_d)));
                // Where the double bounds may move the anchor and these do not (the bounds
                // disagree, or float cannot tell: a channel within the float bound of a face,
                // |c| <= 1e-6 max from 0 or max), it matters for a dark colour (channels near
                // 1e-6 max themselves), and when the next pass's restored point lies within
                // wild_gap × max of this one: the double path's next ray then starts a rounding
                // error from its end and may leave through any face (the definition's own jump:
                // the continuity walk found sRGB (0.0048756, -0.029423, 1.1251) ending on g = 0
                // in double after an anchor 1e-10 from its target, and on r = 0 in float). For a
                // lighter colour with a longer next ray, the moved anchor changes the result by
                // rounding only.
                const auto unresolved = [&](Vf v) {
                    return hn::Or(hn::Le(hn::Abs(v), low), hn::Le(hn::Abs(hn::Sub(p.max, v)), low));
                };
                const Mf undecided = hn::Or(hn::Or(unresolved(c_r), unresolved(c_g)), unresolved(c_b));
                const Mf maybe_moved = hn::And(active, hn::Or(hn::AndNot(below, below_double), undecided));
                const Vf brightest = hn::Max(hn::Max(c_r, c_g), c_b);
                bounds_path = hn::Or(bounds_path, hn::And(maybe_moved, hn::Lt(brightest, dark)));
                if (it > 1) {
                    const Vf gap = hn::Max(hn::Max(hn::Abs(hn::Sub(c_r, prev_r)), hn::Abs(hn::Sub(c_g, prev_g))),
                                           hn::Abs(hn::Sub(c_b, prev_b)));
                    bounds_path = hn::Or(bounds_path, hn::And(hn::And(active, prev_maybe_moved),
                                                              hn::Lt(gap, wild_gap_max)));
                }
                prev_maybe_moved = maybe_moved;
                prev_r = c_r, prev_g = c_g, prev_b = c_b;
                a0 = hn::IfThenElse(move, c_r, a0);
                a1 = hn::IfThenElse(move, c_g, a1);
                a2 = hn::IfThenElse(move, c_b, a2);
            }
            c_r = hn::IfThenElse(active, x, c_r);
            c_g = hn::IfThenElse(active, y, c_g);
            c_b = hn::IfThenElse(active, z, c_b);
            last_r = c_r;
            last_g = c_g;
            last_b = c_b;
            if (hn::AllFalse(d, active)) break;
        }
        Vf rr = Clamp(c_r, zero, p.max), gg = Clamp(c_g, zero, p.max), bb = Clamp(c_b, zero, p.max);
        rr = hn::IfThenZeroElse(black, hn::IfThenElse(white, p.max, rr));
        gg = hn::IfThenZeroElse(black, hn::IfThenElse(white, p.max, gg));
        bb = hn::IfThenZeroElse(black, hn::IfThenElse(white, p.max, bb));
        rr = hn::IfThenElse(inside, r, rr);
        gg = hn::IfThenElse(inside, g, gg);
        bb = hn::IfThenElse(inside, b, bb);
        out_r = rr, out_g = gg, out_b = bb;
        const Mf near_l = hn::Or(hn::Lt(hn::Abs(hn::Sub(L, p.white_l)), lmargin),
                                 hn::Lt(hn::Abs(L), lmargin));
        return hn::AndNot(
            inside, hn::Or(hn::Or(hn::Or(near_l, huge), hn::Or(hn::Or(wild, grazing), hn::Or(bounds_path, diverging))),
                           hn::AndNot(hn::Or(white, black), hn::Lt(c0, hn::Set(d, hueless_chroma)))));
    });
}

/// css (the binary search) likewise: a lane-masked search until every lane has finished, each
/// lane following GamutClipper::css in float; flagged lanes are redone with GamutClipper::clip.
std::size_t ClipCssBinarySearch(const GamutClipper& clipper, const float* in, float* out,
                                std::size_t colours) {
    const Df d;
    const Params p = LoadParams(d, clipper);
    const Vf zero = hn::Zero(d);
    const Vf half = hn::Set(d, 0.5f);
    const Vf jnd = hn::Set(d, css_jnd_f), eps = hn::Set(d, css_epsilon_f);
    const Vf lmargin = hn::Set(d, lightness_margin);
    const Vf cmargin = hn::Mul(hn::Set(d, channel_margin), p.max);
    const Vf emargin = hn::Set(d, delta_margin);
    const Vf imargin = hn::Set(d, interval_margin * css_epsilon_f);
    // ΔEOK between the Oklab of clamp(candidate) and the current colour (L, ca, cb).
    // clip(candidate) as float pairs: a clamped channel is its bound exactly.
    const auto clamp_pair = [&](Vf v, Vf ve, Vf& out_e) {
        out_e = hn::IfThenZeroElse(hn::Or(hn::Lt(v, zero), hn::Gt(v, p.max)), ve);
        return Clamp(v, zero, p.max);
    };
    // ΔEOK between the Oklab of clip(candidate) (pairs) and the current colour (L, ca, cbk).
    const auto delta = [&](Vf cr, Vf cg, Vf cb, Vf cre, Vf cge, Vf cbe, Vf L, Vf ca, Vf cbk) {
        Vf l2, a2, b2;
        ToOklabPair(d, p.T, cr, cg, cb, cre, cge, cbe, l2, a2, b2);
        const Vf dl = hn::Sub(l2, L), da = hn::Sub(a2, ca), db = hn::Sub(b2, cbk);
        return hn::Sqrt(hn::MulAdd(dl, dl, hn::MulAdd(da, da, hn::Mul(db, db))));
    };
    return simd::RunKernel(d, clipper, in, out, colours, [&](Vf r, Vf g, Vf b, Vf& out_r, Vf& out_g, Vf& out_b) {
        const Mf inside = InCube(r, g, b, zero, p.max);
        if (hn::AllTrue(d, inside)) {
            out_r = r, out_g = g, out_b = b;
            return hn::Not(inside);
        }
        Vf L, A, B;
        ToOklabAccurate(d, p.T, r, g, b, L, A, B);
        const Mf huge = hn::Or(hn::Or(hn::Gt(hn::Abs(r), hn::Set(d, split_limit)),
                                      hn::Gt(hn::Abs(g), hn::Set(d, split_limit))),
                               hn::Gt(hn::Abs(b), hn::Set(d, split_limit)));
        const Mf white = hn::Ge(L, p.white_l);
        const Mf black = hn::AndNot(white, hn::Le(L, zero));
        const Vf c0 = Chroma(A, B);
        const Vf inv_c0 = hn::Div(hn::Set(d, 1.0f), hn::Max(c0, hn::Set(d, hueless_chroma)));
        const Vf ua = hn::Mul(A, inv_c0), ub = hn::Mul(B, inv_c0);
        Mf flagged = hn::Or(hn::Or(hn::Lt(hn::Abs(hn::Sub(L, p.white_l)), lmargin),
                                   hn::Lt(hn::Abs(L), lmargin)), huge);
        flagged = hn::Or(flagged, hn::AndNot(hn::Or(white, black),
                                             hn::Lt(c0, hn::Set(d, hueless_chroma))));
        // clipped = clip(current) at the origin's chroma; E < JND returns it.
        Vf cr, cg, cb, cre, cge, cbe;
        Vf ca = hn::Mul(c0, ua), cbk = hn::Mul(c0, ub);
        FromOklabPair(d, p.T, L, ca, cbk, cr, cg, cb, cre, cge, cbe);
        Vf kre, kge, kbe;
        Vf k_r = clamp_pair(cr, cre, kre), k_g = clamp_pair(cg, cge, kge), k_b = clamp_pair(cb, cbe, kbe);
        Vf e = delta(k_r, k_g, k_b, kre, kge, kbe, L, ca, cbk);
        Mf running = hn::Not(hn::Or(inside, hn::Or(white, black)));
        flagged = hn::Or(flagged, hn::And(running, hn::Lt(hn::Abs(hn::Sub(e, jnd)), emargin)));
        running = hn::AndNot(hn::Lt(e, jnd), running);
        Vf lo = zero, hi = c0;
        Mf lo_in_gamut = hn::Not(hn::Lt(zero, zero));  // all true
        for (;;) {
            const Vf width = hn::Sub(hi, lo);
            flagged = hn::Or(flagged, hn::And(running, hn::Lt(hn::Abs(hn::Sub(width, eps)), imargin)));
            running = hn::And(running, hn::Gt(width, eps));
            if (hn::AllFalse(d, running)) break;
            const Vf chroma = hn::Mul(hn::Add(lo, hi), half);
            ca = hn::Mul(chroma, ua);
            cbk = hn::Mul(chroma, ub);
            FromOklabPair(d, p.T, L, ca, cbk, cr, cg, cb, cre, cge, cbe);
            const Mf tested = hn::And(running, lo_in_gamut);
            flagged = hn::Or(flagged, hn::And(tested, hn::Or(hn::Or(NearFace(cr, zero, p.max, cmargin),
                                                                    NearFace(cg, zero, p.max, cmargin)),
                                                             NearFace(cb, zero, p.max, cmargin))));
            const Mf shortcut = hn::And(tested, InCube(cr, cg, cb, zero, p.max));
            lo = hn::IfThenElse(shortcut, chroma, lo);
            const Mf measured = hn::AndNot(shortcut, running);
            if (hn::AllFalse(d, measured)) continue;
            Vf nre, nge, nbe;
            const Vf nr = clamp_pair(cr, cre, nre), ng = clamp_pair(cg, cge, nge),
                     nb = clamp_pair(cb, cbe, nbe);
            k_r = hn::IfThenElse(measured, nr, k_r);
            k_g = hn::IfThenElse(measured, ng, k_g);
            k_b = hn::IfThenElse(measured, nb, k_b);
            e = delta(nr, ng, nb, nre, nge, nbe, L, ca, cbk);
            const Mf below = hn::And(measured, hn::Lt(e, jnd));
            const Vf slack = hn::Sub(jnd, e);
            flagged = hn::Or(flagged, hn::And(measured, hn::Lt(hn::Abs(hn::Sub(e, jnd)), emargin)));
            flagged = hn::Or(flagged, hn::And(below, hn::Lt(hn::Abs(hn::Sub(slack, eps)), emargin)));
            const Mf finished = hn::And(below, hn::Lt(slack, eps));
            const Mf raise = hn::AndNot(finished, below);
            lo_in_gamut = hn::AndNot(raise, lo_in_gamut);
            lo = hn::IfThenElse(raise, chroma, lo);
            hi = hn::IfThenElse(hn::AndNot(below, measured), chroma, hi);
            running = hn::AndNot(finished, running);
        }
        Vf rr = hn::IfThenZeroElse(black, hn::IfThenElse(white, p.max, k_r));
        Vf gg = hn::IfThenZeroElse(black, hn::IfThenElse(white, p.max, k_g));
        Vf bb = hn::IfThenZeroElse(black, hn::IfThenElse(white, p.max, k_b));
        rr = hn::IfThenElse(inside, r, rr);
        gg = hn::IfThenElse(inside, g, gg);
        bb = hn::IfThenElse(inside, b, bb);
        out_r = rr, out_g = gg, out_b = bb;
        return hn::AndNot(inside, flagged);
    });
}

}  // namespace HWY_NAMESPACE
}  // namespace irid
HWY_AFTER_NAMESPACE();

#if HWY_ONCE

namespace irid {
namespace {

IRID_EXPORT_KERNEL(ClipCssBinarySearch)
IRID_EXPORT_KERNEL(ClipCssRayTrace)

/// css: the kernel's margins on its Oklab comparisons are absolute; above a peak of 16 they no
/// longer cover float's rounding (at max 100, 2e-4 × max off; at 16, under 2e-6).
bool css_takes(const GamutClipper& clipper) noexcept { return clipper.gamut().max() <= 16.0; }

}  // namespace

detail::Kernel detail::css_kernel(ClipMethod method) noexcept {
    switch (method) {
        case ClipMethod::css: return {ClipCssBinarySearchDispatch, css_takes};
        case ClipMethod::css_raytrace: return {ClipCssRayTraceDispatch, nullptr};
        default: return {};
    }
}

}  // namespace irid

#endif  // HWY_ONCE
