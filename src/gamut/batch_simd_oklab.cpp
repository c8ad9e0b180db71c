// The SIMD kernels of oklab, oklab-adaptive and oklab-cusp (Google Highway, dynamic dispatch as
// in batch_simd.cpp).
//
// All three move an out-of-gamut colour along the segment from (L0, 0, 0) to its Oklab (L, a, b)
// and stop where it last leaves the cube (oklab: L0 = L; oklab-adaptive: Ottosson's L0 around
// half the white's L; oklab-cusp: around the cusp's L), as their double references do
// (GamutClipper::oklab in clip.cpp, oklab_projection.cpp). Along (L0 + t (L − L0), t a, t b) each
// RGB channel is a cubic in t, f_i(t) = Σ_j lms_to_rgb_ij (P_j + t Q_j)³. Per lane, in float:
// 1. Each channel's cubic is sampled at t = 0 (the grey, which must be inside), at its
//    derivative's roots in (0, 1) and at t = 1 (the colour itself). Between those points it is
//    monotonic, so the samples say whether it leaves once for good (its inside set is [0, b_i])
//    or leaves and comes back. When every channel that leaves does so for good, the exit is
//    min b_i; a channel that comes back is allowed when another channel, out for good, is out
//    from a sample at or before the returning one's first out sample (some channel is then out
//    all the way from the first exit to the colour), and the search is kept before that sample.
// 2. The exit by Newton steps on the leaving channels (the smallest step of theirs, kept in the
//    bracket, else bisection), from the chord estimate, to 1e-4 relative, and one more step at
//    that t whose linear point f + f' Δt is the float result. A vector keeps it when on each
//    of its lanes float's rounding of the channels, times the exit's conditioning, is under
//    8e-7 max (estimate in ClipProjection; not on a gamut without the sectors' structure,
//    OklabProjectionPrepared::structured false). The estimate runs up to 4 times short of the error: at a bound of
//    6.4e-6 max, 2 million colours uniform in [-0.5, 1.5]³ found errors of 1.6e-5 (Display P3)
//    and 2.7e-5 (Adobe RGB); at 8e-7 the largest is 5e-7. Every other vector takes, in double, the
//    colour's Oklab (a Newton step on each float cube root), the cusp's L (a Newton step on
//    S_max and one on its cube root), L0, one Newton step on each leaving channel near its root
//    (the first root kept) and the point's RGB, its exit channel set exactly to its bound and the whole clamped
//    to [0, max]³. (In float alone the channels' rounding near the bound, 1e-6 max where their
//    terms cancel, would move the exit by 1e-6 max / f'.)
// 3. Hard lanes are recomputed by the double reference (GamutClipper::clip): a channel coming
//    back without the condition above, an interior extremum within 1e-5 max of a bound, a grey
//    not inside or within 1e-4 max of max (the segment starts at the cube's top, ill-conditioned
//    in float), a colour within 2 × the rounding tolerance of the cube (clip.h's rule, tested
//    first), L within 1e-5 of 0 or of the white's within 1e-4 (oklab) or 5e-3 (Ottosson's
//    projections, whose L0 lies just below the white's there), a chroma over 16 times the
//    white's L, an exit where the leaving
//    channel's slope is under 1/1024 of the channels' total (nearly tangent), a non-finite t, and
//    for oklab-cusp a cusp whose Halley iteration did not settle or that is not at S_max, and a
//    hue within 2e-5 (of the white's L, as a distance in a, b) of a primary's, where the cusp
//    may jump (CuspLightness).
// The cusp (oklab-cusp): the zero channel of the hue's sector (OklabProjectionPrepared, see
// prepare_oklab_projection), its S_max by three Halley steps on that channel's cubic in S from
// the per-gamut linear fit, then L_cusp = cbrt(max / largest channel at (1, S_max a', S_max b')).
// Where prepare_oklab_projection found the sectors' structure does not hold (ACES2065-1, whose
// blue primary has a negative Oklab L), the oklab-cusp kernel leaves every colour to the double
// reference (returns 0).

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE __BASE_FILE__
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include <irid/color/spaces.h>
#include <irid/gamut/clip.h>

#include "kernels.h"
#include "simd_common-inl.h"

#include <cstddef>
#include <cstdint>

HWY_BEFORE_NAMESPACE();
namespace irid {
namespace HWY_NAMESPACE {
namespace {

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

template <Projection kind>
std::size_t ClipProjection(const GamutClipper& clipper, const float* in, float* out,
                           std::size_t colours) {
    const D d;
    const OklabProjectionPrepared& prepared = clipper.oklab_projection_prepared();
    Setup s;
    s.mat = simd::LoadOklabMatrices(d, clipper);
    const double max_d = clipper.gamut().max();
    s.max = hn::Set(d, static_cast<float>(max_d));
    s.tol2 = hn::Set(d, static_cast<float>(2.0 * oklab_rounding_tolerance * max_d));
    s.white_l = hn::Set(d, static_cast<float>(clipper.white_oklab_lightness()));
    s.alpha = hn::Set(d, kind == Projection::constant_l
                             ? 0.0f
                             : static_cast<float>(clipper.parameters()[0].second));
    s.half = hn::Set(d, 0.5f);
    const detail::Mat3f m2i = detail::to_float(oklab_m2_inverse);
    const detail::Mat3f lms = detail::to_float(clipper.lms_to_rgb());
    for (std::size_t k = 0; k < 9; ++k) {
        s.m2i[k] = hn::Set(d, m2i.m[k]);
        s.lms[k] = hn::Set(d, lms.m[k]);
        s.fit[k] = hn::Set(d, static_cast<float>(prepared.s_max_fit[k / 3][k % 3]));
    }
    for (std::size_t k = 0; k < 6; ++k) s.prim[k] = hn::Set(d, static_cast<float>(prepared.primary_hue[k / 2][k % 2]));
    Exact exact{};
    for (std::size_t k = 0; k < 9; ++k) {
        const int row = static_cast<int>(k / 3);
        const std::size_t col = k % 3;
        exact.to_lms[k] = clipper.rgb_to_lms()[row][col];
        exact.lms[k] = clipper.lms_to_rgb()[row][col];
        exact.m2[k] = oklab_m2[row][col];
        exact.m2i[k] = oklab_m2_inverse[row][col];
    }
    exact.white_l = clipper.white_oklab_lightness();
    exact.alpha = kind == Projection::constant_l ? 0.0 : clipper.parameters()[0].second;
    exact.max = max_d;
    const V zero = hn::Zero(d), one = hn::Set(d, 1.0f), half = s.half;
    // The float result may stand without the double step (see its use below).
    const bool float_only = kind == Projection::constant_l || prepared.structured;
    const V float_bound = hn::Mul(hn::Set(d, 8.0f), s.max);
    const V near = hn::Mul(hn::Set(d, 1e-5f), s.max);
    const V lw_margin = hn::Mul(hn::Set(d, 1e-5f), s.white_l);
    // Within 1e-4 of the white (its L, or a grey channel of max) the exit is within a few 1e-2
    // of the grey and ill-conditioned in float.
    // Ottosson's projections near the white's L: L0 lies just below it, the grey at the segment's
    // start within a hair of the cube's top, and the exit ill-conditioned in float (2e-5 × max
    // off at 1e-3 from the white's L with little chroma, found by a review of issue 23): within
    // 5e-3 of it those lanes go to the double reference.
    const V white_margin = hn::Mul(hn::Set(d, kind == Projection::constant_l ? 1e-4f : 5e-3f), s.white_l);
    const V max_margin = hn::Mul(hn::Set(d, 1e-4f), s.max);
    const V big_c = hn::Mul(hn::Set(d, 16.0f), s.white_l);
    const V max_plus_tol = hn::Add(s.max, s.tol2);
    const V neg_tol = hn::Neg(s.tol2);
    return simd::RunKernel(d, clipper, in, out, colours, [&](V r, V g, V b, V& out_r, V& out_g, V& out_b) {
        const M outside = hn::Or(hn::Or(hn::Or(hn::Lt(r, zero), hn::Gt(r, s.max)),
                                        hn::Or(hn::Lt(g, zero), hn::Gt(g, s.max))),
                                 hn::Or(hn::Lt(b, zero), hn::Gt(b, s.max)));
        if (hn::AllFalse(d, outside)) {
            out_r = r, out_g = g, out_b = b;
            return outside;
        }
        V L, A, B;
        simd::ToOklab(d, s.mat, r, g, b, L, A, B);
        const V C = hn::Sqrt(hn::MulAdd(A, A, hn::Mul(B, B)));
        // Only the constant-lightness projection has a black and a white rule (L <= 0, L at or
        // above the white's); Ottosson's projections move every lightness toward their L0.
        const bool lightness_rule = kind == Projection::constant_l;
        const M black = lightness_rule ? hn::Not(hn::Gt(L, zero)) : hn::FirstN(d, 0);
        const M white = lightness_rule ? hn::Not(hn::Lt(L, s.white_l)) : hn::FirstN(d, 0);
        // Hard lanes, sent to the double reference.
        const M within_tol = hn::And(
            hn::And(hn::And(hn::Ge(r, neg_tol), hn::Ge(g, neg_tol)), hn::Ge(b, neg_tol)),
            hn::And(hn::And(hn::Le(r, max_plus_tol), hn::Le(g, max_plus_tol)),
                    hn::Le(b, max_plus_tol)));
        // L near 0 or near the white's: float may take the black or white verdict (or miss
        // it) where double does not, so those lanes are redone whatever float decided.
        const M near_verdict = hn::Or(hn::Lt(hn::Abs(L), lw_margin),
                                      hn::Lt(hn::Abs(hn::Sub(L, s.white_l)), white_margin));
        M hard = hn::Or(within_tol, near_verdict);
        hard = hn::Or(hard, hn::Gt(C, big_c));
        // A channel beyond 1e30 (what ±Inf becomes) is near float's range, where simd_math::Cbrt's
        // Halley step overflows (fuzz finding clip oklab-overflow-1: 2.55e38 on Display P3 at
        // max 4 came out black instead of white): the double reference takes those.
        // Their L is wrong, so even a black or white verdict is redone (below).
        const V magnitude = hn::Max(hn::Max(hn::Abs(r), hn::Abs(g)), hn::Abs(b));
        const M overflow = hn::Or(hn::Gt(magnitude, hn::Set(d, 1e30f)),
                                  hn::Not(hn::And(hn::IsFinite(L), hn::IsFinite(C))));
        hard = hn::Or(hard, overflow);

        // L0.
        V L0 = L;
        V centre = hn::Mul(half, s.white_l);
        V cusp_s = zero, cusp_zero = zero;
        if (kind != Projection::constant_l) {
            if (kind == Projection::cusp) {
                const M grey = hn::Not(hn::Gt(C, zero));
                const V inv_c = hn::Div(one, hn::IfThenElse(grey, one, C));
                const V au = hn::IfThenElse(grey, one, hn::Mul(A, inv_c));
                const V bu = hn::IfThenZeroElse(grey, hn::Mul(B, inv_c));
                centre = CuspLightness(s, au, bu, C, hard, cusp_s, cusp_zero);
                // Within [0.01, 0.99] × the white's L, as the reference (oklab_projection.cpp).
                centre = hn::Min(hn::Max(centre, hn::Mul(hn::Set(d, 0.01f), s.white_l)),
                                 hn::Mul(hn::Set(d, 0.99f), s.white_l));
            }
            L0 = AdaptiveL0(s, L, C, centre);
        }
        const V dL = hn::Sub(L, L0);
        V P[3], Q[3];
        for (int j = 0; j < 3; ++j) {
            P[j] = hn::Mul(s.m2i[3 * j], L0);
            Q[j] = hn::MulAdd(s.m2i[3 * j + 2], B,
                              hn::MulAdd(s.m2i[3 * j + 1], A, hn::Mul(s.m2i[3 * j], dL)));
        }
        // Classification of each channel (step 1).
        const V c1[3] = {r, g, b};
        V f0[3];
        V first_out[3], value_out[3];  // where each channel is first seen out, and its value there
        M leaves[3], leaves_high[3], returns[3];
        for (int ch = 0; ch < 3; ++ch) {
            // f' = α + β t + γ t²: α = 3 Σ F Q P², β = 6 Σ F Q² P, γ = 3 Σ F Q³.
            V al = zero, be = zero, ga = zero, v0 = zero;
            for (int j = 0; j < 3; ++j) {
                const V fq = hn::Mul(s.lms[3 * ch + j], Q[j]);
                al = hn::MulAdd(fq, hn::Mul(P[j], P[j]), al);
                be = hn::MulAdd(hn::Mul(fq, Q[j]), P[j], be);
                ga = hn::MulAdd(hn::Mul(fq, Q[j]), Q[j], ga);
                v0 = hn::MulAdd(hn::Mul(s.lms[3 * ch + j], P[j]), hn::Mul(P[j], P[j]), v0);
            }
            al = hn::Mul(hn::Set(d, 3.0f), al);
            be = hn::Mul(hn::Set(d, 6.0f), be);
            ga = hn::Mul(hn::Set(d, 3.0f), ga);
            f0[ch] = v0;
            // The grey must be inside, and not within 1e-4 max of max (a segment starting at the
            // cube's top is ill-conditioned in float). Its channels are all (L0 / L_white)³ max
            // (CSS Color 4's Oklab puts the white on the neutral axis), so a positive one is
            // positive, however dark.
            hard = hn::Or(hard, hn::Not(hn::Gt(v0, zero)));
            hard = hn::Or(hard, hn::Not(hn::Lt(v0, hn::Sub(s.max, max_margin))));
            // Derivative roots (stable form), kept when finite and in (0, 1), else 0.
            const V disc = hn::Sub(hn::Mul(be, be), hn::Mul(hn::Set(d, 4.0f), hn::Mul(al, ga)));
            const M real = hn::Gt(disc, zero);
            const V sq = hn::Sqrt(hn::IfThenElse(real, disc, zero));
            const V q = hn::Mul(hn::Set(d, -0.5f), hn::Add(be, hn::CopySign(sq, be)));
            // (To about 1e-4 (the approximate reciprocal): the extremum's value is flat there.)
            V ra = hn::Mul(q, hn::ApproximateReciprocal(hn::IfThenElse(hn::Eq(ga, zero), one, ga)));
            V rb = hn::Mul(al, hn::ApproximateReciprocal(hn::IfThenElse(hn::Eq(q, zero), one, q)));
            const M ra_ok = hn::And(real, hn::And(hn::Not(hn::Eq(ga, zero)),
                                                  hn::And(hn::Gt(ra, zero), hn::Lt(ra, one))));
            const M rb_ok = hn::And(real, hn::And(hn::Not(hn::Eq(q, zero)),
                                                  hn::And(hn::Gt(rb, zero), hn::Lt(rb, one))));
            ra = hn::IfThenElse(ra_ok, ra, zero);
            rb = hn::IfThenElse(rb_ok, rb, zero);
            const V t1 = hn::Min(ra, rb), t2 = hn::Max(ra, rb);
            const V v1 = ChannelAt(s, ch, P, Q, t1), v2 = ChannelAt(s, ch, P, Q, t2);
            // An interior extremum within `near` of a bound: the reference may see a touch.
            const auto close = [&](V v, M ok) {
                return hn::And(ok, hn::Or(hn::Lt(hn::Abs(v), near),
                                          hn::Lt(hn::Abs(hn::Sub(v, s.max)), near)));
            };
            hard = hn::Or(hard, hn::Or(close(v1, hn::Gt(t1, zero)), close(v2, hn::Gt(t2, zero))));
            const State x1 = StateOf(v1, zero, s.max), x2 = StateOf(v2, zero, s.max),
                        x3 = StateOf(c1[ch], zero, s.max);
            // Once out on one side, the later points must be out on the same side.
            const auto breaks = [&](const State& a, const State& next) {
                return hn::Or(hn::AndNot(next.low, a.low), hn::AndNot(next.high, a.high));
            };
            returns[ch] = hn::Or(breaks(x1, x2), breaks(x2, x3));
            const M out1 = hn::Or(x1.low, x1.high), out2 = hn::Or(x2.low, x2.high);
            leaves[ch] = hn::Or(hn::Or(out1, out2), hn::Or(x3.low, x3.high));
            // The side it first leaves through, where it is first seen out and its value there.
            leaves_high[ch] = hn::Or(x1.high, hn::AndNot(out1, hn::Or(x2.high, hn::AndNot(out2, x3.high))));
            first_out[ch] = hn::IfThenElse(out1, t1, hn::IfThenElse(out2, t2, one));
            value_out[ch] = hn::IfThenElse(out1, v1, hn::IfThenElse(out2, v2, c1[ch]));
        }
        // A channel that leaves and comes back: the segment's first exit is still where it last
        // leaves the cube when another channel, which leaves for good, is out from a point
        // o_j at or before the returning channel's first-out point o_i (then some channel is out
        // all along from the first exit to the colour). The search is then kept to [0, o_i],
        // where every channel crosses its bound at most once. Otherwise the lane is hard.
        V for_good = hn::Set(d, 2.0f), hi0 = one;
        for (int ch = 0; ch < 3; ++ch) {
            const M good = hn::AndNot(returns[ch], leaves[ch]);
            for_good = hn::IfThenElse(hn::And(good, hn::Lt(first_out[ch], for_good)),
                                      first_out[ch], for_good);
        }
        for (int ch = 0; ch < 3; ++ch) {
            hard = hn::Or(hard, hn::AndNot(hn::Le(for_good, first_out[ch]), returns[ch]));
            hi0 = hn::IfThenElse(hn::And(returns[ch], hn::Lt(first_out[ch], hi0)), first_out[ch],
                                 hi0);
        }
        // Step 2: the root of E(t) = max over leaving channels of their excess.
        V t = one;
        for (int ch = 0; ch < 3; ++ch) {
            // Chord estimate o (bound − f(0)) / (f(o) − f(0)) of each leaving channel, o its
            // first-out point.
            const V bound = hn::IfThenElse(leaves_high[ch], s.max, zero);
            const V denom = hn::Sub(value_out[ch], f0[ch]);
            const V safe = hn::IfThenElse(hn::Eq(denom, zero), one, denom);
            const V est = hn::Mul(first_out[ch], hn::Mul(hn::Sub(bound, f0[ch]),
                                                         hn::ApproximateReciprocal(safe)));
            t = hn::IfThenElse(hn::And(leaves[ch], hn::Lt(est, t)), est, t);
        }
        t = hn::Min(hn::Max(t, zero), hi0);
        V col_abs[3];
        for (int j = 0; j < 3; ++j) {
            col_abs[j] = hn::Add(hn::Add(hn::Abs(s.lms[j]), hn::Abs(s.lms[3 + j])), hn::Abs(s.lms[6 + j]));
        }
        V lo = zero, hi = hi0;
        const M active = hn::AndNot(hn::Or(hn::Or(black, white), hard), outside);
        // Each channel's excess over the bound it leaves through is sign · f − offset (sign +1
        // through max, offset max; −1 through 0, offset 0); a channel that does not leave has
        // sign 0 and offset 1e30 (never the largest excess, never rising).
        V sign[3], offset[3];
        for (int ch = 0; ch < 3; ++ch) {
            sign[ch] = hn::IfThenElseZero(leaves[ch],
                                          hn::IfThenElse(leaves_high[ch], one, hn::Neg(one)));
            offset[ch] = hn::IfThenElse(leaves[ch], hn::IfThenElseZero(leaves_high[ch], s.max),
                                        hn::Set(d, 1e30f));
        }
        for (int it = 0; it < 16; ++it) {
            V f[3], df[3];
            Channels(s, P, Q, t, f, df);
            // Each leaving channel's own Newton step; the smallest is taken (from inside it
            // heads for the first root, min b_i; one step on E alone would zigzag where the
            // largest excess switches channel).
            V excess = hn::Set(d, -1e30f);
            V next = hn::Set(d, 2.0f);
            for (int ch = 0; ch < 3; ++ch) {
                const V e = hn::MulSub(sign[ch], f[ch], offset[ch]);
                const V de = hn::Mul(sign[ch], df[ch]);
                excess = hn::Max(excess, e);
                const M rising = hn::Gt(de, zero);
                const V cand = hn::NegMulAdd(
                    e, hn::ApproximateReciprocal(hn::IfThenElse(rising, de, one)), t);
                next = hn::Min(next, hn::IfThenElse(rising, cand, hn::Set(d, 2.0f)));
            }
            const M beyond = hn::Gt(excess, zero);
            hi = hn::IfThenElse(beyond, t, hi);
            lo = hn::IfThenElse(beyond, lo, t);
            // Newton's step when it stays in the bracket (its ends included: at convergence
            // the step lands on t, now one of them), else the bracket's midpoint.
            const M inside_bracket = hn::And(hn::Ge(next, lo), hn::Le(next, hi));
            next = hn::IfThenElse(inside_bracket, next, hn::Mul(half, hn::Add(lo, hi)));
            const V step = hn::Abs(hn::Sub(next, t));
            t = next;
            const M moving = hn::And(active, hn::Gt(step, hn::Mul(hn::Set(d, 1e-4f), t)));
            if (hn::AllFalse(d, moving)) break;
        }
        V side[3];
        for (int ch = 0; ch < 3; ++ch) side[ch] = sign[ch];
        // At the exit: the slope of the channel with the largest excess, beside the channels'
        // total.
        // At the final t: the slope of the channel with the largest excess beside the channels'
        // total (how well the root is conditioned), and a last Newton step of the leaving
        // channels (the smallest, as in the loop), whose point f + f' Δt is the float result
        // (the loop's last step may have been a bisection of up to 1e-4 t; the step's error is
        // f'' Δt² / 2), with the channel that gave it.
        V slope = one, total = zero, exit_f = hn::Set(d, -1.0f), fe[3];
        {
            V f[3], df[3];
            Channels(s, P, Q, t, f, df);
            V excess = hn::Set(d, -1e30f), next = hn::Set(d, 2.0f);
            for (int ch = 0; ch < 3; ++ch) {
                const V e = hn::MulSub(sign[ch], f[ch], offset[ch]);
                const V de = hn::Mul(sign[ch], df[ch]);
                const M take = hn::Gt(e, excess);
                excess = hn::IfThenElse(take, e, excess);
                slope = hn::IfThenElse(take, de, slope);
                total = hn::Add(total, hn::Abs(df[ch]));
                const M rising = hn::Gt(de, zero);
                const V cand = hn::Sub(t, hn::Div(e, hn::IfThenElse(rising, de, one)));
                const M smaller = hn::And(rising, hn::Lt(cand, next));
                next = hn::IfThenElse(smaller, cand, next);
                exit_f = hn::IfThenElse(smaller, hn::Set(d, static_cast<float>(ch)), exit_f);
            }
            const V dt = hn::IfThenElseZero(hn::Ge(exit_f, zero), hn::Sub(next, t));
            for (int ch = 0; ch < 3; ++ch) fe[ch] = hn::MulAdd(df[ch], dt, f[ch]);
        }
        // Exits nearly tangent to the face (the root ill-conditioned), and anything not finite.
        hard = hn::Or(hard, hn::Lt(hn::Mul(hn::Set(d, 1024.0f), slope), total));
        hard = hn::Or(hard, hn::Not(hn::IsFinite(t)));
        // The point at t (the final step in double), its exit channel exactly on its bound,
        // inside [0, max]³.
        V res[3];
        V exit_ch = zero;  // set by Exact3: the exit channel, or −1
        // The float result is kept when, on every active lane, float's rounding of the channels
        // (about 1e-7 of the sum of their terms' sizes, Σ_j (Σ_i |M_ij|) |u_j|³) moved along
        // the exit by the conditioning (1 + total / slope) stays under 8 × 1e-7 max (see the
        // file comment for why not more); the
        // double step is taken for the whole vector otherwise, and always on a gamut without
        // the sectors' structure (OklabProjectionPrepared::structured false: ACES2065-1, where float alone was measured
        // 1.8e-5 max off with oklab-adaptive, for reasons this estimate does not capture).
        V terms = zero;
        for (int j = 0; j < 3; ++j) {
            const V u = hn::Abs(hn::MulAdd(t, Q[j], P[j]));
            terms = hn::MulAdd(col_abs[j], hn::Mul(hn::Mul(u, u), u), terms);
        }
        const M polish = hn::AndNot(
            hard, hn::And(active, hn::Gt(hn::Mul(terms, hn::Add(slope, total)),
                                         hn::Mul(float_bound, slope))));
        if (float_only && hn::AllFalse(d, polish)) {
            for (int ch = 0; ch < 3; ++ch) res[ch] = fe[ch];
            exit_ch = exit_f;
        } else {
            Exact3<kind>(exact, r, g, b, L, A, B, centre, cusp_s, cusp_zero, t, side, exit_ch,
                         res);
        }
        hard = hn::Or(hard, hn::Lt(exit_ch, zero));
        for (int ch = 0; ch < 3; ++ch) {
            const M on = hn::Eq(exit_ch, hn::Set(d, static_cast<float>(ch)));
            const V bound = hn::IfThenElse(leaves_high[ch], s.max, zero);
            res[ch] = hn::IfThenElse(on, bound, res[ch]);
            res[ch] = hn::Min(hn::Max(res[ch], zero), s.max);
            res[ch] = hn::IfThenZeroElse(black, hn::IfThenElse(white, s.max, res[ch]));
            res[ch] = hn::IfThenElse(outside, res[ch], c1[ch]);
        }
        out_r = res[0], out_g = res[1], out_b = res[2];
        // Black and white lanes are final unless within rounding of the cube (tested first),
        // beyond float's range for the transforms, or with L near the verdict's threshold (fuzz
        // finding clip-8: on Rec.2020 a colour of L 3e-8 below the white's came out white).
        return hn::And(outside, hn::Or(hn::Or(hn::Or(within_tol, overflow), near_verdict),
                                       hn::AndNot(hn::Or(black, white), hard)));
    });
}

}  // namespace

std::size_t ClipOklab(const GamutClipper& clipper, const float* in, float* out,
                      std::size_t colours) {
    return ClipProjection<Projection::constant_l>(clipper, in, out, colours);
}
std::size_t ClipOklabAdaptive(const GamutClipper& clipper, const float* in, float* out,
                              std::size_t colours) {
    return ClipProjection<Projection::adaptive>(clipper, in, out, colours);
}
std::size_t ClipOklabCusp(const GamutClipper& clipper, const float* in, float* out,
                          std::size_t colours) {
#if HWY_TARGET == HWY_SSE4 || HWY_TARGET == HWY_SSSE3 || HWY_TARGET == HWY_SCALAR || \
    HWY_TARGET == HWY_EMU128
    // Without fused multiply-add the float cusp search is not accurate enough everywhere (fuzz
    // finding clip-3: pure blue (0, 0, 3.45) on Rec.2020 at max 2 landed 8e-4 from the double
    // reference on SSE4): these targets leave every colour to the double reference.
    (void)clipper, (void)in, (void)out, (void)colours;
    return 0;
#else
    return ClipProjection<Projection::cusp>(clipper, in, out, colours);
#endif
}

}  // namespace HWY_NAMESPACE
}  // namespace irid
HWY_AFTER_NAMESPACE();

#if HWY_ONCE

namespace irid {
namespace {

IRID_EXPORT_KERNEL(ClipOklab)
IRID_EXPORT_KERNEL(ClipOklabAdaptive)
IRID_EXPORT_KERNEL(ClipOklabCusp)

/// oklab-cusp: the kernel finds the cusp from the sectors' structure of the gamut (one zero
/// channel per sector between primaries, the cusp at S_max; prepare_oklab_projection), which
/// ACES2065-1's imaginary blue breaks: such a gamut runs the double reference.
bool oklab_cusp_takes(const GamutClipper& clipper) noexcept {
    return clipper.oklab_projection_prepared().structured;
}

}  // namespace

detail::Kernel detail::oklab_kernel(ClipMethod method) noexcept {
    switch (method) {
        case ClipMethod::oklab: return {ClipOklabDispatch, nullptr};
        case ClipMethod::oklab_adaptive: return {ClipOklabAdaptiveDispatch, nullptr};
        case ClipMethod::oklab_cusp: return {ClipOklabCuspDispatch, oklab_cusp_takes};
        default: return {};
    }
}

}  // namespace irid

#endif  // HWY_ONCE
