// The arithmetic of the oklab, oklab-adaptive and oklab-cusp kernels (batch_simd_oklab.cpp):
// each RGB channel as a cubic along the projection's segment, the cusp's lightness and
// Ottosson's adaptive L0 in float, and the final step in double (docs/KERNELS.md). Included
// once per target after simd_common-inl.h; the include guard toggles with HWY_TARGET_TOGGLE.

#if defined(IRID_GAMUT_OKLAB_PROJECTION_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef IRID_GAMUT_OKLAB_PROJECTION_INL_H_
#undef IRID_GAMUT_OKLAB_PROJECTION_INL_H_
#else
#define IRID_GAMUT_OKLAB_PROJECTION_INL_H_
#endif

#include <hwy/highway.h>
#include <irid/color/spaces.h>
#include <irid/gamut/clip.h>

#include "simd_common-inl.h"

#include <cstddef>
#include <cstdint>

HWY_BEFORE_NAMESPACE();
namespace irid {
namespace HWY_NAMESPACE {
namespace oklab_projection {

namespace hn = hwy::HWY_NAMESPACE;
using D = hn::ScalableTag<float>;
using V = hn::Vec<D>;
using M = hn::Mask<D>;

enum class Projection { constant_l, adaptive, cusp };

/// What one call reads from the clipper, in float and broadcast.
struct Setup {
    simd::OklabMatrices mat;
    V max, tol2, white_l, alpha, half;
    V m2i[9];  // Ottosson's M2⁻¹, row-major
    V lms[9];  // the gamut's LMS → RGB
    V fit[9];   // [3 z + k]: S_max fit of zero channel z (OklabProjectionPrepared::s_max_fit)
    V prim[6];  // unit hues of R, G, B (OklabProjectionPrepared::primary_hue)
};

/// f_i(t) and f_i'(t) for the three channels at u_j = P_j + t Q_j.
HWY_INLINE void Channels(const Setup& s, const V P[3], const V Q[3], V t, V f[3], V df[3]) {
    V u2[3], u3[3], qu2[3];
    for (int j = 0; j < 3; ++j) {
        const V u = hn::MulAdd(t, Q[j], P[j]);
        u2[j] = hn::Mul(u, u);
        u3[j] = hn::Mul(u2[j], u);
        qu2[j] = hn::Mul(Q[j], u2[j]);
    }
    const V three = hn::Set(D(), 3.0f);
    for (int i = 0; i < 3; ++i) {
        f[i] = hn::MulAdd(s.lms[3 * i + 2], u3[2],
                          hn::MulAdd(s.lms[3 * i + 1], u3[1], hn::Mul(s.lms[3 * i], u3[0])));
        const V d = hn::MulAdd(s.lms[3 * i + 2], qu2[2],
                               hn::MulAdd(s.lms[3 * i + 1], qu2[1], hn::Mul(s.lms[3 * i], qu2[0])));
        df[i] = hn::Mul(three, d);
    }
}

/// Value of one channel's cubic at t (no derivative).
HWY_INLINE V ChannelAt(const Setup& s, int i, const V P[3], const V Q[3], V t) {
    V u3[3];
    for (int j = 0; j < 3; ++j) {
        const V u = hn::MulAdd(t, Q[j], P[j]);
        u3[j] = hn::Mul(hn::Mul(u, u), u);
    }
    return hn::MulAdd(s.lms[3 * i + 2], u3[2],
                      hn::MulAdd(s.lms[3 * i + 1], u3[1], hn::Mul(s.lms[3 * i], u3[0])));
}

/// The L of the cusp of each lane's hue (unit au, bu), with its S_max and zero channel (for the
/// final step in double); `hard` gains the lanes where it is not reliable (see the file comment).
HWY_INLINE V CuspLightness(const Setup& s, V au, V bu, V C, M& hard, V& s_max,
                           V& zero_channel) {
    const D d;
    const V zero = hn::Zero(d);
    // Sector of the hue: red → green reaches b = 0, green → blue r = 0, blue → red g = 0.
    const V cross_r = hn::Sub(hn::Mul(s.prim[0], bu), hn::Mul(s.prim[1], au));
    const V cross_g = hn::Sub(hn::Mul(s.prim[2], bu), hn::Mul(s.prim[3], au));
    const V cross_b = hn::Sub(hn::Mul(s.prim[4], bu), hn::Mul(s.prim[5], au));
    // At a primary's hue the cusp may jump: on Rec.2020 a ray just past the blue primary's hue
    // keeps a sliver of the cube near the primary (r dips below 0 and comes back), whose chroma
    // is the cusp, while a ray just before it misses the sliver (L_cusp 0.457 against 0.423;
    // fuzz finding clip-5). Float's hue cannot say which side a colour is on there: a colour
    // within 2e-5 of the white's L of a primary's hue line (|cross| C, float's error in a and b
    // is about 1e-7 of it) goes to the double reference.
    const V near = hn::Mul(hn::Set(d, 2e-5f), s.white_l);
    const V off_r = hn::Mul(hn::Abs(cross_r), C), off_g = hn::Mul(hn::Abs(cross_g), C),
            off_b = hn::Mul(hn::Abs(cross_b), C);
    hard = hn::Or(hard, hn::Lt(hn::Min(hn::Min(off_r, off_g), off_b), near));
    const M in_rg = hn::And(hn::Ge(cross_r, zero), hn::Lt(cross_g, zero));
    const M in_gb = hn::And(hn::Ge(cross_g, zero), hn::Lt(cross_b, zero));
    // Zero channel z: 2 in red → green, 0 in green → blue, 1 otherwise.
    V row[3], k[3];
    for (int j = 0; j < 3; ++j) {
        row[j] = hn::IfThenElse(in_rg, s.lms[6 + j], hn::IfThenElse(in_gb, s.lms[j], s.lms[3 + j]));
        k[j] = hn::IfThenElse(in_rg, s.fit[6 + j], hn::IfThenElse(in_gb, s.fit[j], s.fit[3 + j]));
    }
    V P[3], Q[3];
    for (int j = 0; j < 3; ++j) {
        P[j] = s.m2i[3 * j];
        Q[j] = hn::MulAdd(s.m2i[3 * j + 2], bu, hn::Mul(s.m2i[3 * j + 1], au));
    }
    V S = hn::MulAdd(k[2], bu, hn::MulAdd(k[1], au, k[0]));
    const V two = hn::Set(d, 2.0f), three = hn::Set(d, 3.0f), six = hn::Set(d, 6.0f);
    V f = zero;
    for (int it = 0; it < 3; ++it) {
        V f0 = zero, f1 = zero, f2 = zero;
        for (int j = 0; j < 3; ++j) {
            const V u = hn::MulAdd(S, Q[j], P[j]);
            const V ru = hn::Mul(row[j], u);
            f0 = hn::MulAdd(ru, hn::Mul(u, u), f0);
            f1 = hn::MulAdd(hn::Mul(ru, u), Q[j], f1);
            f2 = hn::MulAdd(hn::Mul(ru, Q[j]), Q[j], f2);
        }
        f1 = hn::Mul(three, f1);
        f2 = hn::Mul(six, f2);
        // Halley: S ← S − 2 f f' / (2 f'² − f f'').
        const V den = hn::Sub(hn::Mul(two, hn::Mul(f1, f1)), hn::Mul(f0, f2));
        S = hn::Sub(S, hn::Div(hn::Mul(two, hn::Mul(f0, f1)), den));
        f = f0;
    }
    // All three channels at S_max: the zero channel ≈ 0, the others ≥ 0; the largest gives L.
    V c[3], dc[3];
    Channels(s, P, Q, S, c, dc);
    const V settle = hn::Set(d, 1e-5f);
    const V fz = hn::IfThenElse(in_rg, c[2], hn::IfThenElse(in_gb, c[0], c[1]));
    hard = hn::Or(hard, hn::Not(hn::Lt(hn::Abs(fz), settle)));
    hard = hn::Or(hard, hn::Not(hn::Lt(hn::Abs(f), hn::Set(d, 1e-3f))));
    hard = hn::Or(hard, hn::Not(hn::Gt(S, zero)));
    const V neg = hn::Neg(settle);
    hard = hn::Or(hard, hn::Or(hn::Lt(c[0], neg), hn::Or(hn::Lt(c[1], neg), hn::Lt(c[2], neg))));
    V m = c[0], dm = dc[0];
    for (int i = 1; i < 3; ++i) {
        const M larger = hn::Gt(c[i], m);
        m = hn::IfThenElse(larger, c[i], m);
        dm = hn::IfThenElse(larger, dc[i], dm);
    }
    // The chroma S cbrt(max / m(S)) still grows at S_max when 3 m − S m' ≥ 0; otherwise the cusp
    // is before S_max and the double reference finds it.
    hard = hn::Or(hard, hn::Lt(hn::Sub(hn::Mul(three, m), hn::Mul(S, dm)), zero));
    hard = hn::Or(hard, hn::Not(hn::Gt(m, zero)));
    const V safe_m = hn::IfThenElse(hn::Gt(m, zero), m, hn::Set(d, 1.0f));
    s_max = S;
    zero_channel = hn::IfThenElse(in_rg, hn::Set(d, 2.0f),
                                  hn::IfThenElse(in_gb, zero, hn::Set(d, 1.0f)));
    return simd_math::Cbrt(d, hn::Div(s.max, safe_m));
}

/// Ottosson's adaptive L0 (oklab_projection.cpp's oklab_adaptive_l0) in float.
HWY_INLINE V AdaptiveL0(const Setup& s, V L, V C, V l_centre) {
    const D d;
    const V one = hn::Set(d, 1.0f), two = hn::Set(d, 2.0f);
    const V inv_w = hn::Div(one, s.white_l);
    const V lr = hn::Mul(L, inv_w), cr = hn::Mul(C, inv_w), lc = hn::Mul(l_centre, inv_w);
    const V ld = hn::Sub(lr, lc);
    const M above = hn::Gt(ld, hn::Zero(d));
    const V k = hn::Mul(two, hn::IfThenElse(above, hn::Sub(one, lc), lc));
    const V ald = hn::Abs(ld);
    const V a = hn::MulAdd(s.half, k, ald);         // ½ k + |ΔL|
    const V bc = hn::Div(hn::Mul(s.alpha, cr), k);  // α C / k
    const V e1 = hn::Add(a, bc);
    // ½ (e1 − √(e1² − 2 k |ΔL|)) as ½ 2 k |ΔL| / (e1 + √(e1² − 2 k |ΔL|)): the same value
    // without the cancellation of the difference when the chroma term makes e1 large; and
    // e1² − 2 k |ΔL| as (½ k − |ΔL|)² + b (2a + b), a sum of non-negative terms: near the
    // white's lightness with little chroma it is a difference of two numbers near 1 whose
    // float rounding moved L0 by 2e-5 × max (found by a review of issue 23).
    const V x = hn::Mul(hn::Mul(two, k), ald);
    const V gap = hn::Sub(hn::Mul(s.half, k), ald);
    const V arg = hn::MulAdd(gap, gap, hn::Mul(bc, hn::MulAdd(two, a, bc)));
    const V sum = hn::Add(e1, hn::Sqrt(arg));
    const V step =
        hn::Mul(s.half, hn::Div(x, hn::IfThenElse(hn::Gt(sum, hn::Zero(d)), sum, one)));
    return hn::Mul(s.white_l, hn::Add(lc, hn::IfThenElse(above, step, hn::Neg(step))));
}

/// Channel state of a value: -1 below 0, +1 above max, 0 inside (as float masks).
struct State {
    M low, high;
};
HWY_INLINE State StateOf(V v, V zero, V max) { return {hn::Lt(v, zero), hn::Gt(v, max)}; }

/// The double constants of the final step.
struct Exact {
    std::array<double, 9> to_lms, lms, m2, m2i;
    double white_l, alpha, max;
};

/// 1 / v to float's precision (about 1e-7 relative), for v in float's normal range: the divisor
/// of a Newton correction in double, which is itself small (1e-4 of its value or less), so the
/// correction keeps about 1e-11 of that value (a float division on half the lanes is cheaper
/// than a double one).
template <class DD>
HWY_INLINE hn::Vec<DD> StepReciprocal(DD dd, hn::Vec<DD> v) {
    const hn::Rebind<float, DD> df;
    return hn::PromoteTo(dd, hn::Div(hn::Set(df, 1.0f), hn::DemoteTo(df, v)));
}

/// The final step in double, on one half of the lanes: the colour's Oklab (the float one
/// polished by a Newton step on each cube root), for oklab-cusp the cusp's L (the float one
/// polished), Ottosson's L0 around `centre` (or L0 = L), one
/// Newton step from the float t on each leaving channel's cubic f_i(t) − bound_i (side[i] +1
/// leaving through max, −1 through 0, 0 not leaving), the smallest kept (two channels may leave
/// within rounding of each other, at a corner), and in `c` the RGB of the point at that t, in
/// `exit` the channel that gave it (−1 when none was near its root: the lane is then hard). Float's rounding of the channels near the bound (their terms cancel to
/// about 1e-6 max) would otherwise move t, and with it the other channels, by 1e-6 max / f'.
template <Projection kind, class DD>
HWY_INLINE void ExactHalf(DD dd, const Exact& x, hn::Vec<DD> c[3], hn::Vec<DD> lab[3],
                          hn::Vec<DD> centre, hn::Vec<DD> cusp_s, hn::Vec<DD> cusp_zero,
                          hn::Vec<DD> t, const hn::Vec<DD> side[3], hn::Vec<DD>& exit) {
    using VD = hn::Vec<DD>;
    const auto mul3 = [&](const std::array<double, 9>& m, const VD v[3], VD o[3]) {
        for (std::size_t i = 0; i < 3; ++i) {
            o[i] = hn::MulAdd(hn::Set(dd, m[3 * i + 2]), v[2],
                              hn::MulAdd(hn::Set(dd, m[3 * i + 1]), v[1],
                                         hn::Mul(hn::Set(dd, m[3 * i]), v[0])));
        }
    };
    VD lms[3], y[3];
    mul3(x.to_lms, c, lms);
    mul3(x.m2i, lab, y);  // the float cube roots, to about 1e-7
    // (An LMS cube root under 1e-15 keeps its float value: its channels' terms are below
    // 1e-45, far under max ≥ 1e-6.)
    const VD one = hn::Set(dd, 1.0), three = hn::Set(dd, 3.0), tiny = hn::Set(dd, 1e-30);
    for (std::size_t j = 0; j < 3; ++j) {
        const VD y2 = hn::Mul(y[j], y[j]);
        const auto ok = hn::Gt(y2, tiny);
        const VD step = hn::Mul(hn::Sub(hn::Mul(y2, y[j]), lms[j]),
                                StepReciprocal(dd, hn::Mul(three, hn::IfThenElse(ok, y2, one))));
        y[j] = hn::IfThenElse(ok, hn::Sub(y[j], step), y[j]);
    }
    // Oklab from the polished roots: only L for oklab (its segment is y − L m2⁻¹ e₀ below).
    if (kind == Projection::constant_l) {
        lab[0] = hn::MulAdd(hn::Set(dd, x.m2[2]), y[2],
                            hn::MulAdd(hn::Set(dd, x.m2[1]), y[1], hn::Mul(hn::Set(dd, x.m2[0]), y[0])));
    } else {
        mul3(x.m2, y, lab);
    }
    const VD L = lab[0], A = lab[1], B = lab[2];
    VD l0 = L;
    if (kind == Projection::cusp) {
        // The cusp in double: a Newton step on the zero channel's cubic in S from the float
        // S_max, then a Newton step on cbrt(max / largest channel) from the float L_cusp.
        const VD C = hn::Sqrt(hn::MulAdd(A, A, hn::Mul(B, B)));
        const auto grey = hn::Not(hn::Gt(C, hn::Zero(dd)));
        const VD inv_c = hn::Div(one, hn::IfThenElse(grey, one, C));
        const VD au = hn::IfThenElse(grey, one, hn::Mul(A, inv_c));
        const VD bu = hn::IfThenZeroElse(grey, hn::Mul(B, inv_c));
        VD P[3], Q[3];
        for (std::size_t j = 0; j < 3; ++j) {
            P[j] = hn::Set(dd, x.m2i[3 * j]);
            Q[j] = hn::MulAdd(hn::Set(dd, x.m2i[3 * j + 2]), bu,
                              hn::Mul(hn::Set(dd, x.m2i[3 * j + 1]), au));
        }
        const auto ray = [&](VD S, VD f[3], VD df[3]) {
            VD u3[3], qu2[3];
            for (std::size_t j = 0; j < 3; ++j) {
                const VD u = hn::MulAdd(S, Q[j], P[j]);
                const VD u2 = hn::Mul(u, u);
                u3[j] = hn::Mul(u2, u);
                qu2[j] = hn::Mul(Q[j], u2);
            }
            mul3(x.lms, u3, f);
            mul3(x.lms, qu2, df);
        };
        VD f[3], df[3];
        ray(cusp_s, f, df);
        VD fz = f[0], dz = df[0];
        for (std::size_t i = 1; i < 3; ++i) {
            const auto on = hn::Eq(cusp_zero, hn::Set(dd, static_cast<double>(i)));
            fz = hn::IfThenElse(on, f[i], fz);
            dz = hn::IfThenElse(on, df[i], dz);
        }
        dz = hn::Mul(three, dz);
        const auto usable = hn::Gt(hn::Abs(dz), tiny);
        const VD S =
            hn::Sub(cusp_s, hn::Mul(fz, StepReciprocal(dd, hn::IfThenElse(usable, dz, one))));
        ray(hn::IfThenElse(usable, S, cusp_s), f, df);
        const VD m = hn::Max(hn::Max(f[0], f[1]), f[2]);
        const VD target = hn::Div(hn::Set(dd, x.max), hn::IfThenElse(hn::Gt(m, hn::Zero(dd)), m, one));
        const VD y2 = hn::Mul(centre, centre);
        centre = hn::Sub(centre, hn::Mul(hn::Sub(hn::Mul(y2, centre), target),
                                         StepReciprocal(dd, hn::Mul(three, y2))));
    }
    if (kind != Projection::constant_l) {
        const VD two = hn::Set(dd, 2.0), half = hn::Set(dd, 0.5);
        const VD inv_w = hn::Set(dd, 1.0 / x.white_l);
        const VD C = hn::Sqrt(hn::MulAdd(A, A, hn::Mul(B, B)));
        const VD lr = hn::Mul(L, inv_w), cr = hn::Mul(C, inv_w), lc = hn::Mul(centre, inv_w);
        const VD ld = hn::Sub(lr, lc);
        const auto above = hn::Gt(ld, hn::Zero(dd));
        const VD k = hn::Mul(two, hn::IfThenElse(above, hn::Sub(one, lc), lc));
        const VD ald = hn::Abs(ld);
        const VD e1 =
            hn::Add(hn::MulAdd(half, k, ald), hn::Div(hn::Mul(hn::Set(dd, x.alpha), cr), k));
        const VD arg =
            hn::Max(hn::Zero(dd), hn::Sub(hn::Mul(e1, e1), hn::Mul(hn::Mul(two, k), ald)));
        const VD move = hn::Mul(half, hn::Sub(e1, hn::Sqrt(arg)));
        l0 = hn::Mul(hn::Set(dd, x.white_l),
                     hn::Add(lc, hn::IfThenElse(above, move, hn::Neg(move))));
    }
    // The segment's cube roots of LMS, P + t Q: P = m2⁻¹ (l0, 0, 0) and, since m2⁻¹ (L, a, b)
    // is y (to rounding), Q = y − P.
    VD P[3], Q[3];
    for (std::size_t j = 0; j < 3; ++j) {
        P[j] = hn::Mul(hn::Set(dd, x.m2i[3 * j]), l0);
        Q[j] = hn::Sub(y[j], P[j]);
    }
    const auto channels = [&](VD at, VD f[3], VD* df) {
        VD u3[3], qu2[3];
        for (std::size_t j = 0; j < 3; ++j) {
            const VD u = hn::MulAdd(at, Q[j], P[j]);
            const VD u2 = hn::Mul(u, u);
            u3[j] = hn::Mul(u2, u);
            qu2[j] = hn::Mul(Q[j], u2);
        }
        mul3(x.lms, u3, f);
        if (df != nullptr) mul3(x.lms, qu2, df);
    };
    VD f[3], df[3];
    channels(t, f, df);
    const VD zero = hn::Zero(dd), max = hn::Set(dd, x.max);
    VD best = hn::Set(dd, 2.0);
    for (std::size_t i = 0; i < 3; ++i) {
        const auto high = hn::Gt(side[i], zero), low = hn::Lt(side[i], zero);
        const VD e = hn::IfThenElse(high, hn::Sub(f[i], max), hn::Neg(f[i]));
        const VD de = hn::Mul(three, hn::IfThenElse(high, df[i], hn::Neg(df[i])));
        const auto rising = hn::And(hn::Or(high, low), hn::Gt(de, zero));
        // (A slope under float's range gives an infinite or NaN step, never taken.)
        const VD cand = hn::Sub(t, hn::Mul(e, StepReciprocal(dd, hn::IfThenElse(rising, de, one))));
        // Only a step within the float search's reach of t (1e-4 t, and float's rounding of the
        // channels over a slope of at least 1/1024 of theirs), with room: a channel far from its
        // own root is not the exit, and its step could undershoot anywhere.
        const auto near_t = hn::Le(hn::Abs(hn::Sub(cand, t)),
                                   hn::MulAdd(hn::Set(dd, 1e-3), t, hn::Set(dd, 1e-5)));
        const auto take = hn::And(hn::And(rising, near_t), hn::Lt(cand, best));
        best = hn::IfThenElse(take, cand, best);
        exit = hn::IfThenElse(take, hn::Set(dd, static_cast<double>(i)), exit);
    }
    // No channel near its root: exit −1, which makes the lane hard.
    const auto found = hn::Lt(best, hn::Set(dd, 2.0));
    t = hn::IfThenElse(found, best, t);
    exit = hn::IfThenElse(found, exit, hn::Set(dd, -1.0));
    channels(t, c, nullptr);
}

/// ExactHalf on whole float vectors, in two halves of doubles (one lane on the SCALAR target),
/// the RGB of the exit point in `res`.
template <Projection kind>
HWY_INLINE void Exact3(const Exact& x, V r, V g, V b, V L, V A, V B, V centre, V cusp_s,
                       V cusp_zero, V t, const V side[3], V& exit, V res[3]) {
    const D d;
#if HWY_TARGET == HWY_SCALAR
    const hn::Rebind<double, D> dd;
    const auto p = [&](V v) { return hn::PromoteTo(dd, v); };
    hn::Vec<hn::Rebind<double, D>> c[3] = {p(r), p(g), p(b)}, lab[3] = {p(L), p(A), p(B)};
    const hn::Vec<hn::Rebind<double, D>> sd[3] = {p(side[0]), p(side[1]), p(side[2])};
    auto e = p(exit);
    ExactHalf<kind>(dd, x, c, lab, p(centre), p(cusp_s), p(cusp_zero), p(t), sd, e);
    for (int i = 0; i < 3; ++i) res[i] = hn::DemoteTo(d, c[i]);
    exit = hn::DemoteTo(d, e);
#else
    const hn::Half<D> dh;
    const hn::Repartition<double, D> dd;
    using VD = hn::Vec<hn::Repartition<double, D>>;
    const auto lo = [&](V v) { return hn::PromoteTo(dd, hn::LowerHalf(dh, v)); };
    const auto hi = [&](V v) { return hn::PromoteTo(dd, hn::UpperHalf(dh, v)); };
    VD c_lo[3] = {lo(r), lo(g), lo(b)}, lab_lo[3] = {lo(L), lo(A), lo(B)};
    VD c_hi[3] = {hi(r), hi(g), hi(b)}, lab_hi[3] = {hi(L), hi(A), hi(B)};
    const VD s_lo[3] = {lo(side[0]), lo(side[1]), lo(side[2])};
    const VD s_hi[3] = {hi(side[0]), hi(side[1]), hi(side[2])};
    VD e_lo = lo(exit), e_hi = hi(exit);
    ExactHalf<kind>(dd, x, c_lo, lab_lo, lo(centre), lo(cusp_s), lo(cusp_zero), lo(t), s_lo, e_lo);
    ExactHalf<kind>(dd, x, c_hi, lab_hi, hi(centre), hi(cusp_s), hi(cusp_zero), hi(t), s_hi, e_hi);
    for (int i = 0; i < 3; ++i) {
        res[i] = hn::Combine(d, hn::DemoteTo(dh, c_hi[i]), hn::DemoteTo(dh, c_lo[i]));
    }
    exit = hn::Combine(d, hn::DemoteTo(dh, e_hi), hn::DemoteTo(dh, e_lo));
#endif
}

}  // namespace oklab_projection
}  // namespace HWY_NAMESPACE
}  // namespace irid
HWY_AFTER_NAMESPACE();

#endif  // IRID_GAMUT_OKLAB_PROJECTION_INL_H_
