// The float SIMD kernels of smits-xyz, luv-lightness-hue and smits-soft (Google Highway, dynamic dispatch as in batch_simd.cpp; contract in kernels.h).
//
// Each kernel computes its method in float, lane by lane, following the double reference in
// clip.cpp / smits_soft.cpp step by step (FMA allowed: the contract is 1e-5 of the cube's size,
// not bits). A lane whose float result could differ from the reference by more than that is
// "hard": the vector is computed and stored, then every hard lane is recomputed with the double
// GamutClipper::clip (which is what batch.cpp does for the tail too). Hard in every kernel: a
// channel beyond 16 × max in magnitude (float rounding of Y, of the order of 6e-8 × 16 max,
// would no longer be far below the tolerance, and luminance near 0 can be a cancellation of
// large terms). Per kernel, the few cases the comment of each kernel names. On the benchmark's
// input (2^20 colours uniform in [-0.5, 1.5]^3, redrawn until out of sRGB) the hard lanes are:
// smits-xyz 0, luv-lightness-hue 0.8 %, smits-soft 0 (forward and inverse).

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE __BASE_FILE__
// foreach_target.h first, then highway.h, then the -inl.h headers (not sorted).
// clang-format off
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>
#include <hwy/contrib/math/math-inl.h>
// clang-format on

#include "simd_common-inl.h"

#include <irid/color/spaces.h>
#include <irid/gamut/clip.h>

#include "kernels.h"

#include <array>
#include <cmath>
#include <cstddef>

HWY_BEFORE_NAMESPACE();
namespace irid {
namespace HWY_NAMESPACE {
namespace {

namespace hn = hwy::HWY_NAMESPACE;
using simd::Df;
using simd::Mf;
using simd::Vf;

/// Lanes with a channel beyond 16 × max in magnitude (hard in every kernel, see the top).
HWY_INLINE Mf Huge(Vf r, Vf g, Vf b, Vf limit) {
    return hn::Gt(hn::Max(hn::Max(hn::Abs(r), hn::Abs(g)), hn::Abs(b)), limit);
}

/// min(|a|, |b|, |c|).
HWY_INLINE Vf MinAbs3(Vf a, Vf b, Vf c) {
    return hn::Min(hn::Min(hn::Abs(a), hn::Abs(b)), hn::Abs(c));
}

/// Lanes outside [0, max]³.
HWY_INLINE Mf Outside(Vf r, Vf g, Vf b, Vf zero, Vf max) {
    const Mf low = hn::Lt(hn::Min(hn::Min(r, g), b), zero);
    const Mf high = hn::Gt(hn::Max(hn::Max(r, g), b), max);
    return hn::Or(low, high);
}

HWY_INLINE Vf Clamp(Vf v, Vf zero, Vf max) {
    return hn::Min(hn::Max(v, zero), max);
}

/// The float parameters of the thesis' RGB clip (smits_clip_rgb).
struct SmitsParams {
    Vf l0, l1, l2, inv_sum, max, zero;
};
HWY_INLINE SmitsParams LoadSmits(Df d, const Gamut& gamut) {
    const Vec3& l = gamut.luminance_row();
    return {hn::Set(d, static_cast<float>(l[0])),
            hn::Set(d, static_cast<float>(l[1])),
            hn::Set(d, static_cast<float>(l[2])),
            hn::Set(d, static_cast<float>(1.0 / (l[0] + l[1] + l[2]))),
            hn::Set(d, static_cast<float>(gamut.max())),
            hn::Zero(d)};
}

/// smits_clip_rgb in float (with divisions: only within 1e-5 of the reference is needed here),
/// the face channel set exactly to its bound; lanes inside the cube are returned unchanged.
HWY_INLINE void Smits(const SmitsParams& P, Vf r, Vf g, Vf b, Vf& rr, Vf& gg, Vf& bb) {
    const Vf zero = P.zero, max = P.max;
    const Vf y = hn::MulAdd(P.l2, b, hn::MulAdd(P.l1, g, hn::Mul(P.l0, r)));
    const Vf w = hn::Mul(y, P.inv_sum);
    const Vf c[3] = {r, g, b};
    Vf t = zero;
    Vf o[3];
    Mf face[3], low[3];
    for (int k = 0; k < 3; ++k) {
        low[k] = hn::Lt(c[k], zero);
        const Mf high = hn::Gt(c[k], max);
        const Vf num = hn::IfThenElse(low[k], c[k], hn::Sub(c[k], max));
        const Vf tk = hn::Div(num, hn::Sub(c[k], w));
        face[k] = hn::And(hn::Or(low[k], high), hn::Gt(tk, t));
        t = hn::IfThenElse(face[k], tk, t);
    }
    // Only the last face that raised t is the one kept.
    face[0] = hn::AndNot(hn::Or(face[1], face[2]), face[0]);
    face[1] = hn::AndNot(face[2], face[1]);
    const Mf black = hn::Le(y, zero), white = hn::Ge(w, max);
    const Mf outside = Outside(r, g, b, zero, max);
    for (int k = 0; k < 3; ++k) {
        Vf v = hn::MulAdd(t, hn::Sub(w, c[k]), c[k]);
        v = hn::IfThenElse(face[k], hn::IfThenElseZero(hn::Not(low[k]), max), v);
        v = hn::IfThenZeroElse(black, hn::IfThenElse(white, max, v));
        o[k] = hn::IfThenElse(outside, v, c[k]);
    }
    rr = o[0];
    gg = o[1];
    bb = o[2];
}

/// atan2(y, x) in (−π, π], 0 for (0, 0), from Highway's Atan on min/max of |x|, |y| (in [0, 1],
/// where it is accurate to a few ulp).
HWY_INLINE Vf Atan2(Df d, Vf y, Vf x) {
    const Vf ax = hn::Abs(x), ay = hn::Abs(y);
    const Vf lo = hn::Min(ax, ay), hi = hn::Max(ax, ay);
    const Mf zero = hn::Eq(hi, hn::Zero(d));
    Vf a = hn::Atan(d, hn::Div(lo, hn::IfThenElse(zero, hn::Set(d, 1.0f), hi)));
    a = hn::IfThenElse(hn::Gt(ay, ax), hn::Sub(hn::Set(d, 1.57079632679489662f), a), a);
    a = hn::IfThenElse(hn::Lt(x, hn::Zero(d)), hn::Sub(hn::Set(d, 3.14159265358979324f), a), a);
    return hn::CopySign(a, y);
}

// --- smits-xyz -------------------------------------------------------------------------------

/// GamutClipper::smits_xyz through clip_finite: XYZ = M c, the plane values M⁻¹ XYZ, the
/// neutral point N = W Y / W_Y, the largest crossing parameter t, XYZ + t (N − XYZ), back to RGB,
/// clamped. In exact arithmetic the plane values are c itself (M⁻¹ M = I) and M⁻¹ N is the grey
/// (max k, max k, max k), k = Y / W_Y, so the kernel computes the same point in RGB: Y from M's
/// luminance row, the values from c, c + t (max k − c). A float round trip through XYZ would
/// add about 1e-6 of rounding to colours on a face, more than the near-boundary rule allows
/// (boundary_test). No hard lanes but huge ones.
std::size_t ClipSmitsXyz(const GamutClipper& clipper, const float* in, float* out,
                         std::size_t colours) {
    const Df d;
    const Mat3& m = clipper.rgb_to_xyz();
    const Vf m10 = hn::Set(d, static_cast<float>(m[1][0])),
             m11 = hn::Set(d, static_cast<float>(m[1][1])),
             m12 = hn::Set(d, static_cast<float>(m[1][2]));
    const Vf inv_wy = hn::Set(d, static_cast<float>(1.0 / clipper.white_xyz().Y));
    const Vf zero = hn::Zero(d), one = hn::Set(d, 1.0f);
    const Vf max = hn::Set(d, static_cast<float>(clipper.gamut().max()));
    const Vf huge = hn::Mul(max, hn::Set(d, 16.0f));
    return simd::RunKernel(d, clipper, in, out, colours, [&](Vf r, Vf g, Vf b, Vf& rr, Vf& gg, Vf& bb) {
        const Vf Y = hn::MulAdd(m12, b, hn::MulAdd(m11, g, hn::Mul(m10, r)));
        const Vf k = hn::Mul(Y, inv_wy);
        const Vf neutral = hn::Mul(max, k);
        const Vf v[3] = {r, g, b};
        Vf t = zero;
        for (int i = 0; i < 3; ++i) {
            const Mf low = hn::Lt(v[i], zero), high = hn::Gt(v[i], max);
            const Vf num = hn::IfThenElse(low, v[i], hn::Sub(v[i], max));
            const Vf ti = hn::Div(num, hn::Sub(v[i], neutral));
            t = hn::IfThenElse(hn::And(hn::Or(low, high), hn::Gt(ti, t)), ti, t);
        }
        Vf o[3];
        const Mf black = hn::Le(Y, zero), white_lane = hn::Ge(k, one);
        const Mf outside = Outside(r, g, b, zero, max);
        for (int i = 0; i < 3; ++i) {
            Vf x = hn::MulAdd(t, hn::Sub(neutral, v[i]), v[i]);
            x = hn::IfThenZeroElse(black, hn::IfThenElse(white_lane, max, x));
            o[i] = hn::IfThenElse(outside, Clamp(x, zero, max), v[i]);
        }
        rr = o[0];
        gg = o[1];
        bb = o[2];
        return hn::And(outside, Huge(r, g, b, huge));
    });
}

// --- luv-lightness-hue -----------------------------------------------------------------------

/// GamutClipper::luv_lightness_hue: constant Y and CIELUV hue, the chromaticity moved toward the
/// white's u'v' to the largest in-gamut s of luv_chroma_limit (each face linear in s). Hard:
/// X + 15Y + 3Z <= 1e-3 × max (no chromaticity, or one so far out that float loses it: the
/// reference falls back to smits there), and colours within 1e-4 max of the cube (float's
/// rounding would move them by more than the near-boundary rule of clip.h allows).
std::size_t ClipLuvLightnessHue(const GamutClipper& clipper, const float* in, float* out,
                                std::size_t colours) {
    const Df d;
    const Mat3& m = clipper.xyz_to_rgb();
    const simd::MatV to_xyz = simd::Broadcast(d, detail::to_float(clipper.rgb_to_xyz()));
    const simd::MatV to_rgb = simd::Broadcast(d, detail::to_float(m));
    const double max_d = clipper.gamut().max();
    const Xyz& white = clipper.white_xyz();
    const double wd = white.X + 15.0 * white.Y + 3.0 * white.Z;
    const double nu = 4.0 * white.X / wd, nv = 9.0 * white.Y / wd;  // the white's u'v'
    // Per channel i, N_i(u', v') = 9 m_i0 u' + 4 m_i1 v' + m_i2 (12 − 3u' − 20v') (clip.cpp,
    // luv_chroma_limit) = a_i u' + b_i v' + c_i, and its value n0_i at the white.
    Vf a[3], bcoef[3], c[3], n0[3], g0k[3];
    for (int i = 0; i < 3; ++i) {
        const double ai = 9.0 * m[i][0] - 3.0 * m[i][2], bi = 4.0 * m[i][1] - 20.0 * m[i][2];
        const double ci = 12.0 * m[i][2];
        const double n0i = ai * nu + bi * nv + ci;
        a[i] = hn::Set(d, static_cast<float>(ai));
        bcoef[i] = hn::Set(d, static_cast<float>(bi));
        c[i] = hn::Set(d, static_cast<float>(ci));
        n0[i] = hn::Set(d, static_cast<float>(n0i));
        g0k[i] = hn::Set(d, static_cast<float>(-4.0 * max_d * nv));
    }
    const Vf vnu = hn::Set(d, static_cast<float>(nu)), vnv = hn::Set(d, static_cast<float>(nv));
    const Vf zero = hn::Zero(d), one = hn::Set(d, 1.0f);
    const Vf max = hn::Set(d, static_cast<float>(max_d));
    const Vf four_max = hn::Set(d, static_cast<float>(4.0 * max_d));
    const Vf white_y = hn::Set(d, static_cast<float>(white.Y));
    const Vf huge = hn::Mul(max, hn::Set(d, 16.0f));
    const Vf no_chroma = hn::Mul(max, hn::Set(d, 1e-3f));
    const Vf near_tol = hn::Mul(max, hn::Set(d, 1e-4f));
    return simd::RunKernel(d, clipper, in, out, colours, [&](Vf r, Vf g, Vf b, Vf& rr, Vf& gg, Vf& bb) {
        Vf X, Y, Z;
        simd::Mul3(to_xyz, r, g, b, X, Y, Z);
        const Vf den = hn::MulAdd(hn::Set(d, 3.0f), Z, hn::MulAdd(hn::Set(d, 15.0f), Y, X));
        const Vf inv_den = hn::Div(one, den);
        const Vf u = hn::Mul(hn::Mul(hn::Set(d, 4.0f), X), inv_den);
        const Vf v = hn::Mul(hn::Mul(hn::Set(d, 9.0f), Y), inv_den);
        const Vf du = hn::Sub(u, vnu), dv = hn::Sub(v, vnv);
        Vf limit = one;
        for (int i = 0; i < 3; ++i) {
            const Vf n1 = hn::MulAdd(a[i], u, hn::MulAdd(bcoef[i], v, c[i]));
            // Lower face: n0 + s (n1 − n0) >= 0.
            const Mf lower = hn::And(hn::Lt(n1, zero), hn::Gt(n0[i], zero));
            limit =
                hn::IfThenElse(lower, hn::Min(limit, hn::Div(n0[i], hn::Sub(n0[i], n1))), limit);
            // Upper face: y N(s) − 4 max v'(s) <= 0.
            const Vf g0 = hn::MulAdd(Y, n0[i], g0k[i]);
            const Vf g1 = hn::NegMulAdd(four_max, v, hn::Mul(Y, n1));
            const Mf upper = hn::And(hn::Gt(g1, zero), hn::Lt(g0, zero));
            limit = hn::IfThenElse(upper, hn::Min(limit, hn::Div(g0, hn::Sub(g0, g1))), limit);
        }
        const Vf s = hn::Max(limit, zero);
        const Vf uu = hn::MulAdd(s, du, vnu), vv = hn::MulAdd(s, dv, vnv);
        const Vf y_over_4v = hn::Div(Y, hn::Mul(hn::Set(d, 4.0f), vv));
        const Vf ox = hn::Mul(hn::Mul(hn::Set(d, 9.0f), uu), y_over_4v);
        const Vf oz = hn::Mul(hn::NegMulAdd(hn::Set(d, 20.0f), vv,
                                            hn::NegMulAdd(hn::Set(d, 3.0f), uu, hn::Set(d, 12.0f))),
                              y_over_4v);
        Vf o0, o1, o2;
        simd::Mul3(to_rgb, ox, Y, oz, o0, o1, o2);
        const Mf black = hn::Le(Y, zero), white_lane = hn::Ge(Y, white_y);
        o0 = hn::IfThenZeroElse(black, hn::IfThenElse(white_lane, max, o0));
        o1 = hn::IfThenZeroElse(black, hn::IfThenElse(white_lane, max, o1));
        o2 = hn::IfThenZeroElse(black, hn::IfThenElse(white_lane, max, o2));
        const Mf outside = Outside(r, g, b, zero, max);
        rr = hn::IfThenElse(outside, Clamp(o0, zero, max), r);
        gg = hn::IfThenElse(outside, Clamp(o1, zero, max), g);
        bb = hn::IfThenElse(outside, Clamp(o2, zero, max), b);
        const Mf grey = hn::Or(black, white_lane);
        // Within 1e-4 max of the cube the reference moves a colour by a few times its distance
        // (boundary_test); float's round trip through u'v' would add about 1e-6.
        const Mf near = hn::Not(Outside(r, g, b, hn::Neg(near_tol), hn::Add(max, near_tol)));
        const Mf hard =
            hn::Or(hn::Or(Huge(r, g, b, huge), near), hn::AndNot(grey, hn::Le(den, no_chroma)));
        return hn::And(outside, hard);
    });
}

// --- smits-soft ------------------------------------------------------------------------------

/// GamutClipper::smits_soft (smits_soft.cpp), forward or inverse, with its prepared threshold,
/// limit, power, scale and 1/power. Powers as exp(p log x), arranged so that no power exceeds 1
/// (x^p for x <= 1, x^−p above). Hard lanes: only huge ones.
std::size_t ClipSmitsSoft(const GamutClipper& clipper, const float* in, float* out,
                          std::size_t colours) {
    const Df d;
    const SmitsParams P = LoadSmits(d, clipper.gamut());
    const SmitsSoftPrepared& k = clipper.smits_soft_prepared();
    const Vf thr = hn::Set(d, static_cast<float>(k.threshold)), lim = hn::Set(d, static_cast<float>(k.limit));
    const Vf pw = hn::Set(d, static_cast<float>(k.power)),
             scale = hn::Set(d, static_cast<float>(k.scale));
    const Vf inv_scale = hn::Set(d, static_cast<float>(1.0 / k.scale));
    const Vf inv_pw = hn::Set(d, static_cast<float>(k.inverse_power));
    const bool inverse = clipper.inverse();
    const Vf zero = hn::Zero(d), one = hn::Set(d, 1.0f), max = P.max;
    const Vf huge = hn::Mul(max, hn::Set(d, 16.0f));
    const Vf tiny = hn::Set(d, 1e-30f);
    return simd::RunKernel(d, clipper, in, out, colours, [&](Vf r, Vf g, Vf b, Vf& rr, Vf& gg, Vf& bb) {
        const Vf y = hn::MulAdd(P.l2, b, hn::MulAdd(P.l1, g, hn::Mul(P.l0, r)));
        const Vf w = hn::Mul(y, P.inv_sum);
        const Vf inv_room = hn::Div(one, hn::Sub(max, w));
        const Vf inv_w = hn::Div(one, w);
        const Vf c[3] = {r, g, b};
        Vf e[3];
        Vf dist = zero;
        for (int i = 0; i < 3; ++i) {
            e[i] = hn::Sub(c[i], w);
            const Vf ri = hn::IfThenElse(hn::Gt(e[i], zero), hn::Mul(e[i], inv_room),
                                         hn::Mul(hn::Neg(e[i]), inv_w));
            dist = hn::Max(dist, ri);
        }
        const Vf x = hn::Max(hn::Mul(hn::Sub(dist, thr), inv_scale), tiny);
        const Vf lx = hn::Log(d, x);
        Vf target;
        if (!inverse) {
            // x <= 1: thr + scale x (1 + x^p)^(−1/p); x > 1: thr + scale (1 + x^−p)^(−1/p).
            const Mf big = hn::Gt(x, one);
            const Vf q = hn::Exp(d, hn::Mul(hn::IfThenElse(big, hn::Neg(pw), pw), lx));
            const Vf f = hn::Exp(d, hn::Neg(hn::Mul(hn::Log1p(d, q), inv_pw)));
            target = hn::MulAdd(hn::Mul(scale, hn::IfThenElse(big, one, x)), f, thr);
            target = hn::IfThenElse(hn::Ge(dist, lim), one, target);
        } else {
            // thr + scale (x^p / (1 − x^p))^(1/p) = thr + scale x (1 − x^p)^(−1/p), x < 1 here.
            const Vf q = hn::Exp(d, hn::Mul(pw, lx));
            const Vf f = hn::Exp(d, hn::Neg(hn::Mul(hn::Log1p(d, hn::Neg(q)), inv_pw)));
            target = hn::MulAdd(hn::Mul(scale, x), f, thr);
            target = hn::IfThenElse(hn::Ge(dist, one), lim, target);
        }
        const Vf ratio = hn::Div(target, dist);
        const Mf keep = hn::Not(hn::Gt(dist, thr));
        const Mf black = hn::Le(y, zero), white = hn::Ge(w, max);
        Vf o[3];
        for (int i = 0; i < 3; ++i) {
            Vf v = hn::MulAdd(ratio, e[i], w);
            v = hn::IfThenElse(keep, c[i], v);
            v = hn::IfThenZeroElse(black, hn::IfThenElse(white, max, v));
            o[i] = inverse ? v : Clamp(v, zero, max);
        }
        rr = o[0];
        gg = o[1];
        bb = o[2];
        return Huge(r, g, b, huge);
    });
}

}  // namespace
}  // namespace HWY_NAMESPACE
}  // namespace irid
HWY_AFTER_NAMESPACE();

#if HWY_ONCE

namespace irid {
namespace {

IRID_EXPORT_KERNEL(ClipSmitsXyz)
IRID_EXPORT_KERNEL(ClipLuvLightnessHue)
IRID_EXPORT_KERNEL(ClipSmitsSoft)

}  // namespace

detail::Kernel detail::smits_family_kernel(ClipMethod method) noexcept {
    switch (method) {
        case ClipMethod::smits_xyz: return {ClipSmitsXyzDispatch, nullptr};
        case ClipMethod::luv_lightness_hue: return {ClipLuvLightnessHueDispatch, nullptr};
        case ClipMethod::smits_soft: return {ClipSmitsSoftDispatch, nullptr};
        default: return {};
    }
}

}  // namespace irid

#endif  // HWY_ONCE
