// The float SIMD kernels of css (CSS Color 4 §13.2.2, binary search with local MINDE) and
// css-raytrace (CSS Color 4 "Ray Trace" gamut mapping), Google Highway with dynamic dispatch.
//
// Both follow their double references (GamutClipper::css in clip.cpp, GamutClipper::css_raytrace
// in css_raytrace.cpp) step by step in float, lane by lane, and are checked against them to
// 1e-5 × max (tests/gamut/css_raytrace_test.cpp). What differs, and why:
// - Hue: OkLCh(L, C, h) is formed as Oklab (L, C a0/C0, C b0/C0) with (a0, b0) and C0 the
//   origin's Oklab a, b and chroma: cos h = a0/C0, sin h = b0/C0, the same point without trig.
//   A lane whose origin has no hue to speak of (C0 < 1e-6) goes to the double path.
// - The anchor OkLCh(L, 0, h) in linear RGB is L³ k with k = lms_to_rgb · (M2⁻¹ (1, 0, 0))³
//   (the cube of a linear function of L), computed once per call in double.
// - Oklab ↔ linear RGB are computed to about an ulp of each result (ToOklabAccurate,
//   FromOklabAccurate: compensated products and sums, the cube root and the cubes as float
//   pairs): near an LMS component of 0 the cube root amplifies a plain float product's error
//   without bound (a colour's Oklab L was off by 6e-5 relative), and the rays' grazing
//   intersections amplify the restore steps' (up to 1e-6 max, grown to 2.8e-5).
//   css-raytrace's Oklab of the origin and restore steps (chroma, then back to RGB) are
//   computed in double instead (ToOklabDouble, RestoreDouble) on every target with double
//   vectors: as accurate, and about half the work.
// - The cube roots start without a division (CbrtStart: Halley steps with a 12-bit reciprocal).
// - css-raytrace uses the 32-bit anchor bounds of the specification's footnote 1 (1e-6), where
//   the double reference uses the 64-bit 1e-12, and the 64-bit parallel threshold 1e-12 of
//   footnote 7 in float as well (see parallel_epsilon_f).
// - The binary search (css) runs a lane-masked loop until every lane has finished. Its branches
//   compare float quantities against thresholds (in gamut or not, ΔEOK against the JND, the
//   JND − ΔEOK against epsilon, the lightness against white and black, the search interval
//   against epsilon): a lane where any such comparison was within float rounding of its
//   threshold could branch differently from the double reference and end far from it, so it is
//   recomputed with GamutClipper::clip in double ("flagged").
// - css-raytrace clamps a colour within oklab_rounding_tolerance × max of the cube, as its
//   reference does, and flags lanes whose lightness is within rounding of white or black, whose
//   origin has no hue, whose magnitude is beyond split_limit, whose rays or restores make them
//   sensitive to float rounding (wild_ray_t, grazing_gain, diverging_ratio), and those whose
//   anchor the two bounds treat differently (bounds_path).
// - On the benchmark's input (uniform in [-0.5, 1.5]^3 outside the sRGB cube, 2^20 colours)
//   0.31 % of the lanes of css-raytrace (0.47 % before its transforms went to double) and
//   0.40 % of those of css are flagged; the largest difference from the double reference was
//   2.5e-6 and 4.1e-7 (measured when the kernels were written; Display P3 and Rec.2020 alike). On ACES2065-1 css-raytrace flags 2.9 %; css
//   flags 0.4 % but 2 of 2^20 colours near its imaginary blue end up to 2.8e-5 away (the
//   origin's chroma, one ulp off in float, moves the candidate by an ulp, which ΔEOK there
//   amplifies 20-fold past the margin).

// No floating-point contraction: the compensated products and sums need every product
// and sum rounded on its own (g++ would otherwise fuse them on the FMA targets). The pragma
// comes before every #include (as in batch_simd.cpp). Explicit MulAdd calls stay fused.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC optimize("fp-contract=off")
#endif

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE __BASE_FILE__
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "simd_common-inl.h"

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

/// A double 3×3 matrix (row-major) as float pairs, m = hi + lo to about 2^-48 |m|.
struct PairMatrix {
    Vf hi[9], lo[9];
};

/// The pairs of a double matrix, broadcast.
HWY_INLINE PairMatrix LoadPairMatrix(Df d, const Mat3& m) {
    PairMatrix p;
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            const auto hi = static_cast<float>(m[i][j]);
            const auto lo = static_cast<float>(m[i][j] - static_cast<double>(hi));
            p.hi[3 * i + j] = hn::Set(d, hi);
            p.lo[3 * i + j] = hn::Set(d, lo);
        }
    }
    return p;
}

/// Knuth's TwoSum: s + err = a + b exactly.
HWY_INLINE Vf TwoSum(Vf a, Vf b, Vf& err) {
    const Vf s = hn::Add(a, b);
    const Vf bb = hn::Sub(s, a);
    err = hn::Add(hn::Sub(a, hn::Sub(s, bb)), hn::Sub(b, bb));
    return s;
}

/// p + e = a b exactly (barring overflow and underflow): the fused a b − p on the x86 targets
/// with FMA (AVX2, AVX-512), Dekker's split product (1971) on the others, which needs
/// |a|, |b| below about 1e34 (4097 x must not overflow).
HWY_INLINE Vf TwoProd(Df d, Vf a, Vf b, Vf& e) {
    const Vf p = hn::Mul(a, b);
#if HWY_ARCH_X86 && HWY_TARGET <= HWY_AVX2
    (void)d;
    e = hn::MulSub(a, b, p);
#else
    const Vf split = hn::Set(d, 4097.0f);
    const Vf ta = hn::Mul(split, a), tb = hn::Mul(split, b);
    const Vf ah = hn::Sub(ta, hn::Sub(ta, a)), bh = hn::Sub(tb, hn::Sub(tb, b));
    const Vf al = hn::Sub(a, ah), bl = hn::Sub(b, bh);
    e = hn::Add(hn::Add(hn::Add(hn::Sub(hn::Mul(ah, bh), p), hn::Mul(ah, bl)), hn::Mul(al, bh)),
                hn::Mul(al, bl));
#endif
    return p;
}

/// Row i of M times (x + xe) (x, xe: a vector as float pairs), as a pair s + se: compensated
/// products and sums, so that the result is within about an ulp of itself however much its
/// terms cancel (a plain float dot product loses up to 1e-7 of the terms' size).
HWY_INLINE Vf Dot3(Df d, const PairMatrix& M, int i, const Vf (&x)[3], const Vf (&xe)[3], Vf& se) {
    Vf p[3];
    Vf small = hn::Zero(d);
    for (int j = 0; j < 3; ++j) {
        const int k = 3 * i + j;
        Vf e;
        p[j] = TwoProd(d, M.hi[k], x[j], e);
        small = hn::Add(small, hn::Add(e, hn::Add(hn::Mul(M.hi[k], xe[j]), hn::Mul(M.lo[k], x[j]))));
    }
    Vf r1, r2;
    const Vf s1 = TwoSum(p[0], p[1], r1);
    const Vf s2 = TwoSum(s1, p[2], r2);
    const Vf tail = hn::Add(hn::Add(r1, r2), small);
    const Vf s = hn::Add(s2, tail);
    se = hn::Sub(tail, hn::Sub(s, s2));
    return s;
}

/// The real cube root of x, sign kept, to about 3e-7 relative over float's normal range (0
/// below it), without a division: simd_math::Cbrt's start from the exponent bits (within 7 %), then
/// two Halley steps written as corrections, y <- y (1 + (a - y^3)/(2 y^3 + a)), whose
/// quotient needs only a 12-bit reciprocal (its error scales the correction, not y). The start
/// of CbrtPair, whose exact Newton step squares this error.
HWY_INLINE Vf CbrtStart(Df d, Vf x) {
    const Vf a = hn::Abs(x);
    Vf y = simd_math::CbrtStart(d, a);  // src/color/simd_math-inl.h
    for (int it = 0; it < 2; ++it) {
        const Vf y3 = hn::Mul(hn::Mul(y, y), y);
        const Vf c = hn::Mul(hn::Sub(a, y3),
                             hn::ApproximateReciprocal(hn::MulAdd(hn::Set(d, 2.0f), y3, a)));
        y = hn::MulAdd(y, c, y);
    }
    y = hn::IfThenZeroElse(hn::Lt(a, hn::Set(d, simd_math::smallest_normal_float)), y);
    return hn::CopySign(y, x);
}

/// The real cube root of x as a pair y + dy, to about 2^-33 relative (2^-37 with AVX-512's
/// 14-bit reciprocal): CbrtStart, then one Newton step on the exact residual x - y^3
/// (dy = (x - y^3)/(3y^2); a 12-bit reciprocal is ample for a correction of a few ulp). 0
/// stays 0.
HWY_INLINE Vf CbrtPair(Df d, Vf x, Vf& dy) {
    const Vf y = CbrtStart(d, x);
    Vf pe, ce;
    const Vf p = TwoProd(d, y, y, pe);
    const Vf c = TwoProd(d, p, y, ce);
    const Vf residual = hn::Sub(hn::Sub(x, c), hn::MulAdd(pe, y, ce));
    const Vf inv = hn::ApproximateReciprocal(hn::Mul(hn::Set(d, 3.0f), p));
    dy = hn::IfThenZeroElse(hn::Eq(y, hn::Zero(d)), hn::Mul(residual, inv));
    return y;
}

/// The transforms of the kernels, as float pairs (accurate versions of simd::ToOklab and
/// simd::FromOklab): the float rounding of plain products, which a cube root near an LMS of 0
/// and the rays' grazing intersections amplify, would otherwise move results by more than 1e-5.
struct Transforms {
    PairMatrix to_lms, from_lms, m2, m2_inverse;
};

/// Oklab of linear RGB given as float pairs (r + re, ...), each component within about an ulp
/// of itself.
HWY_INLINE void ToOklabPair(Df d, const Transforms& T, Vf r, Vf g, Vf b, Vf re, Vf ge, Vf be,
                            Vf& L, Vf& A, Vf& B) {
    const Vf c[3] = {r, g, b}, ce[3] = {re, ge, be};
    Vf y[3], dy[3], unused;
    for (int i = 0; i < 3; ++i) y[i] = CbrtPair(d, Dot3(d, T.to_lms, i, c, ce, unused), dy[i]);
    L = Dot3(d, T.m2, 0, y, dy, unused);
    A = Dot3(d, T.m2, 1, y, dy, unused);
    B = Dot3(d, T.m2, 2, y, dy, unused);
}

/// Oklab of linear RGB, each component within about an ulp of itself.
HWY_INLINE void ToOklabAccurate(Df d, const Transforms& T, Vf r, Vf g, Vf b, Vf& L, Vf& A, Vf& B) {
    const Vf zero = hn::Zero(d);
    ToOklabPair(d, T, r, g, b, zero, zero, zero, L, A, B);
}

/// The Oklab chroma sqrt(a² + b²) of linear RGB, as ToOklabAccurate's a and b (L unused). For
/// a colour in the cube (non-negative channels) of a gamut whose rgb_to_lms has no negative
/// entry (`positive_lms`), the LMS sum has no cancellation and the plain float product is
/// within a few ulp of each component already.
HWY_INLINE Vf ChromaAccurate(Df d, const Transforms& T, bool positive_lms, Vf r, Vf g, Vf b) {
    const Vf zero = hn::Zero(d);
    const Vf c[3] = {r, g, b}, ce[3] = {zero, zero, zero};
    Vf y[3], dy[3], unused;
    if (positive_lms) {
        Vf lms[3];
        for (int i = 0; i < 3; ++i) {
            const int k = 3 * i;
            lms[i] = hn::MulAdd(T.to_lms.hi[k + 2], b,
                                hn::MulAdd(T.to_lms.hi[k + 1], g, hn::Mul(T.to_lms.hi[k], r)));
        }
        for (int i = 0; i < 3; ++i) y[i] = CbrtPair(d, lms[i], dy[i]);
    } else {
        for (int i = 0; i < 3; ++i) y[i] = CbrtPair(d, Dot3(d, T.to_lms, i, c, ce, unused), dy[i]);
    }
    const Vf A = Dot3(d, T.m2, 1, y, dy, unused);
    const Vf B = Dot3(d, T.m2, 2, y, dy, unused);
    return hn::Sqrt(hn::MulAdd(A, A, hn::Mul(B, B)));
}

/// Linear RGB of Oklab as float pairs r + re, ... (the cubes as pairs too), to about 2^-40 of
/// each channel.
HWY_INLINE void FromOklabPair(Df d, const Transforms& T, Vf L, Vf A, Vf B, Vf& r, Vf& g, Vf& b,
                              Vf& re, Vf& ge, Vf& be) {
    const Vf zero = hn::Zero(d);
    const Vf lab[3] = {L, A, B}, labe[3] = {zero, zero, zero};
    Vf cube[3], cube_e[3];
    for (int i = 0; i < 3; ++i) {
        Vf se, pe, ce;
        const Vf s = Dot3(d, T.m2_inverse, i, lab, labe, se);
        const Vf p = TwoProd(d, s, s, pe);
        pe = hn::MulAdd(hn::Add(s, s), se, pe);  // (s + se)² = p + pe to second order
        cube[i] = TwoProd(d, p, s, ce);
        cube_e[i] = hn::MulAdd(p, se, hn::MulAdd(pe, s, ce));
    }
    r = Dot3(d, T.from_lms, 0, cube, cube_e, re);
    g = Dot3(d, T.from_lms, 1, cube, cube_e, ge);
    b = Dot3(d, T.from_lms, 2, cube, cube_e, be);
}

/// The same, each channel rounded to float.
HWY_INLINE void FromOklabAccurate(Df d, const Transforms& T, Vf L, Vf A, Vf B, Vf& r, Vf& g, Vf& b) {
    Vf re, ge, be;
    FromOklabPair(d, T, L, A, B, r, g, b, re, ge, be);
}

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

#if HWY_TARGET != HWY_SCALAR && HWY_HAVE_FLOAT64
/// css-raytrace's restore step in double, on the targets with double vectors (all but SCALAR,
/// which keeps the float pairs): double has the pairs' accuracy at a fraction of their work.
using Dd = hn::Repartition<double, Df>;  // half as many lanes as Df
using Vd = hn::Vec<Dd>;

/// The lower and upper halves of a float vector, in double.
HWY_INLINE void SplitToDouble(Vf v, Vd (&out)[2]) {
    const Dd dd;
    const hn::Half<Df> dh;
    out[0] = hn::PromoteTo(dd, hn::LowerHalf(dh, v));
    out[1] = hn::PromoteTo(dd, hn::UpperHalf(dh, v));
}

/// The float vector of two double halves (rounded to nearest).
HWY_INLINE Vf JoinToFloat(Df d, const Vd (&v)[2]) {
    const hn::Half<Df> dh;
    return hn::Combine(d, hn::DemoteTo(dh, v[1]), hn::DemoteTo(dh, v[0]));
}

/// A double 3×3 matrix (row-major), broadcast.
struct DoubleMatrix {
    Vd m[9];
};

HWY_INLINE DoubleMatrix LoadDoubleMatrix(const Mat3& m) {
    const Dd dd;
    DoubleMatrix p;
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) p.m[3 * i + j] = hn::Set(dd, m[i][j]);
    }
    return p;
}

/// Row i of M times x, in double.
HWY_INLINE Vd DotD(const DoubleMatrix& M, int i, const Vd (&x)[3]) {
    return hn::MulAdd(M.m[3 * i + 2], x[2], hn::MulAdd(M.m[3 * i + 1], x[1], hn::Mul(M.m[3 * i], x[0])));
}

/// The transforms in double.
struct DoubleTransforms {
    DoubleMatrix to_lms, from_lms, m2, m2_inverse;
};

/// The cube roots of the LMS of linear RGB c (double halves) in y, lane by lane: the LMS in
/// double, the cube roots' start in float (CbrtStart, 3e-7), then one Newton step in double
/// (with a float reciprocal, 2^-12 of a correction of 3e-7), to about 1e-12 relative; an LMS
/// below float's normal range has the cube root 0, as CbrtPair.
HWY_INLINE void LmsRootsDouble(Df d, const DoubleTransforms& T, const Vd (&c)[3][2], Vd (&y)[2][3]) {
    for (int i = 0; i < 3; ++i) {
        Vd lms[2];
        for (int h = 0; h < 2; ++h) lms[h] = DotD(T.to_lms, i, {c[0][h], c[1][h], c[2][h]});
        const Vf yf = CbrtStart(d, JoinToFloat(d, lms));
        const Vf inv = hn::IfThenZeroElse(
            hn::Eq(yf, hn::Zero(d)), hn::ApproximateReciprocal(hn::Mul(hn::Set(d, 3.0f), hn::Mul(yf, yf))));
        Vd y0[2], inv_d[2];
        SplitToDouble(yf, y0);
        SplitToDouble(inv, inv_d);
        for (int h = 0; h < 2; ++h) {
            const Vd cube = hn::Mul(hn::Mul(y0[h], y0[h]), y0[h]);
            y[h][i] = hn::MulAdd(hn::Sub(lms[h], cube), inv_d[h], y0[h]);
        }
    }
}

/// Oklab of linear RGB through double (LmsRootsDouble, then M2), each component rounded to
/// float: the accuracy of ToOklabAccurate for less work. For |channels| up to split_limit.
HWY_INLINE void ToOklabDouble(Df d, const DoubleTransforms& T, Vf r, Vf g, Vf b, Vf& L, Vf& A, Vf& B) {
    Vd c[3][2];
    SplitToDouble(r, c[0]);
    SplitToDouble(g, c[1]);
    SplitToDouble(b, c[2]);
    Vd y[2][3];
    LmsRootsDouble(d, T, c, y);
    Vd lab[3][2];
    for (int h = 0; h < 2; ++h) {
        for (int i = 0; i < 3; ++i) lab[i][h] = DotD(T.m2, i, y[h]);
    }
    L = JoinToFloat(d, lab[0]);
    A = JoinToFloat(d, lab[1]);
    B = JoinToFloat(d, lab[2]);
}

/// The restore of css_raytrace.cpp's passes i > 0, lane by lane: the Oklab chroma of (r, g, b)
/// and then linear RGB of Oklab (L, C cos h, C sin h) (cos h = ua, sin h = ub; L, ua, ub given
/// in double halves), written to (nr, ng, nb) rounded to float; in double but for the cube
/// roots' start (LmsRootsDouble).
HWY_INLINE void RestoreDouble(Df d, const DoubleTransforms& T, Vf r, Vf g, Vf b, const Vd (&L)[2],
                              const Vd (&ua)[2], const Vd (&ub)[2], Vf& nr, Vf& ng, Vf& nb) {
    Vd c[3][2];
    SplitToDouble(r, c[0]);
    SplitToDouble(g, c[1]);
    SplitToDouble(b, c[2]);
    Vd y[2][3];
    LmsRootsDouble(d, T, c, y);
    Vd out[3][2];
    for (int h = 0; h < 2; ++h) {
        const Vd a = DotD(T.m2, 1, y[h]), bb = DotD(T.m2, 2, y[h]);
        const Vd chroma = hn::Sqrt(hn::MulAdd(a, a, hn::Mul(bb, bb)));
        const Vd lab[3] = {L[h], hn::Mul(chroma, ua[h]), hn::Mul(chroma, ub[h])};
        Vd cube[3];
        for (int i = 0; i < 3; ++i) {
            const Vd s = DotD(T.m2_inverse, i, lab);
            cube[i] = hn::Mul(hn::Mul(s, s), s);
        }
        for (int i = 0; i < 3; ++i) out[i][h] = DotD(T.from_lms, i, cube);
    }
    nr = JoinToFloat(d, out[0]);
    ng = JoinToFloat(d, out[1]);
    nb = JoinToFloat(d, out[2]);
}
#endif

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
