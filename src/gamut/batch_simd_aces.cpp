// The SIMD batch kernel of aces-rgc (Google Highway, dynamic dispatch), forward and inverse.
//
// Per vector of colours, the scalar reference's steps (aces_rgc.cpp): the non-finite rule,
// ach = max(r, g, b), per channel d = (ach − c)·(1/|ach|), and beyond the threshold the curve,
// through L = ln nd (Highway's Exp, Log and Log1p, hwy/contrib/math/math-inl.h):
//   forward  D = thr + s·exp(min(L, 0) − log1p(exp(−p|L|))/p)
//            (= thr + s·nd/(1 + nd^p)^(1/p), with no exponent above 0: no overflow), in float;
//   inverse  D = thr + s·exp(L − log1p(−u)/p), u = exp(p L) = nd^p, for d below the asymptote
//            thr + s (unchanged from there on), in double: its slope (1 − u)^(−(1+p)/p) grows
//            without bound toward the asymptote and amplifies float's rounding of d beyond
//            1e-5 (measured: 9e-6 with float up to u = 0.9);
// then ach − D·|ach|, capped at ±1e30 (a compressed channel, as the reference), and clamped
// into [0, max] when the clipper confines. A channel whose lanes are all below the threshold
// skips the curve.
//
// Lanes sent to the double reference (GamutClipper::clip, written over the vector's result):
// - forward: |ach| < 1e-30 (not 0, which gives 0 here as in the reference), where 1/|ach| may
//   overflow; |ach| > 1e30; and, when confined, ach > 16·max, where float's rounding of
//   ach − D·|ach| (a few 1e-7 of |ach|) could exceed 1e-5·max inside the cube;
// - inverse: u > 1 − 1e-4 (the slope beyond 2e7 would amplify even double's rounding toward
//   1e-8), and d within 1e-9 (relative) above the asymptote, where the inverse jumps from +inf
//   back to the identity and rounding may put d on the other side.
// On the benchmark's input (uniform in [-0.5, 1.5]^3 outside the sRGB cube, as ACEScg) the
// forward sends no lane; the inverse a few in 10^4 (tests/gamut/aces_rgc_test.cpp counts them).

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE __BASE_FILE__
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>
#include <hwy/contrib/math/math-inl.h>

#include "kernels.h"

#include <cstddef>
#include <limits>

HWY_BEFORE_NAMESPACE();
namespace irid {
namespace HWY_NAMESPACE {
namespace {

namespace hn = hwy::HWY_NAMESPACE;

/// The float (forward) or double (inverse) parameters of one channel's curve.
template <class V>
struct ChannelV {
    V thr, scale, inv_scale, asymptote;
};

/// The parameters of a call, broadcast once, in the kernel's precision.
template <class D>
struct AcesV {
    using V = hn::Vec<D>;
    ChannelV<V> ch[3];
    V power, inv_power, max, large;  // |ach| above `large` goes to the double reference
    bool inverse, confined;

    AcesV(D d, const GamutClipper& clipper, double large_confined, double large_free) {
        using T = hn::TFromD<D>;
        const auto& x = clipper.derived();
        for (std::size_t k = 0; k < 3; ++k) {
            ch[k].thr = hn::Set(d, static_cast<T>(x[k]));
            ch[k].scale = hn::Set(d, static_cast<T>(x[3 + k]));
            ch[k].inv_scale = hn::Set(d, static_cast<T>(1.0 / x[3 + k]));
            ch[k].asymptote = hn::Set(d, static_cast<T>(x[8 + k]));
        }
        power = hn::Set(d, static_cast<T>(x[6]));
        inv_power = hn::Set(d, static_cast<T>(x[7]));
        const double m = clipper.gamut().max();
        max = hn::Set(d, static_cast<T>(m));
        inverse = clipper.inverse();
        confined = clipper.confines_to_cube();
        large = hn::Set(d, static_cast<T>(confined ? large_confined * m : large_free));
    }
};

/// The non-finite rule of clip.h (NaN → 0, ±Inf → ±1e30) in either precision.
template <class D, class V = hn::Vec<D>>
HWY_INLINE V FiniteOrDefault(D d, V v) {
    using T = hn::TFromD<D>;
    v = hn::IfThenZeroElse(hn::IsNaN(v), v);
    return hn::IfThenElse(hn::IsInf(v), hn::CopySign(hn::Set(d, static_cast<T>(1e30)), v), v);
}

/// Compresses (or, inverse, uncompresses) one channel c against ach; flags lanes for the double
/// reference in `hard` (inverse near its asymptote, where its slope exceeds `steep`: u > 1 − ...).
template <class D, class V = hn::Vec<D>, class M = hn::Mask<D>>
HWY_INLINE V Channel(D d, const AcesV<D>& P, const ChannelV<V>& C, V c, V ach, V abs_ach,
                     V inv_abs, V u_max, V band, M& hard) {
    using T = hn::TFromD<D>;
    const V dist = hn::Mul(hn::Sub(ach, c), inv_abs);
    M active = hn::Ge(dist, C.thr);
    if (P.inverse) {
        // The inverse jumps from +inf back to the identity at the asymptote: a lane within
        // rounding of d above it may belong below it.
        hard = hn::Or(hard, hn::And(hn::Ge(dist, C.asymptote), hn::Lt(dist, hn::Mul(C.asymptote, band))));
        active = hn::And(active, hn::Lt(dist, C.asymptote));
    }
    if (hn::AllFalse(d, active)) return c;
    // nd clamped into [smallest normal, 1e30]: Log is finite; the clamped ends change nothing
    // that shows (below, nd compresses to thr; beyond 1e30, to thr + s, to float precision).
    const V nd = hn::Min(hn::Max(hn::Mul(hn::Sub(dist, C.thr), C.inv_scale),
                                 hn::Set(d, std::numeric_limits<T>::min())),
                         hn::Set(d, static_cast<T>(1e30)));
    const V L = hn::Log(d, nd);
    V f;
    if (!P.inverse) {
        const V e = hn::Exp(d, hn::Neg(hn::Mul(P.power, hn::Abs(L))));
        f = hn::Exp(d, hn::NegMulAdd(hn::Log1p(d, e), P.inv_power, hn::Min(L, hn::Zero(d))));
    } else {
        const V u = hn::Exp(d, hn::Mul(P.power, L));
        hard = hn::Or(hard, hn::And(active, hn::Gt(u, u_max)));
        const V safe_u = hn::Min(u, u_max);
        f = hn::Exp(d, hn::NegMulAdd(hn::Log1p(d, hn::Neg(safe_u)), P.inv_power, L));
    }
    const V D_ = hn::MulAdd(C.scale, f, C.thr);
    // Capped at ±1e30 as the reference caps a compressed channel (aces_rgc.cpp).
    const V cap = hn::Set(d, static_cast<T>(1e30));
    const V out = hn::Min(hn::Max(hn::NegMulAdd(D_, abs_ach, ach), hn::Neg(cap)), cap);
    return hn::IfThenElse(active, out, c);
}

/// One vector of colours in the precision of D (float, or double with the colours loaded and
/// stored as floats through DF = Rebind<float, D>). Returns false when a lane needs the double
/// reference (the results are then in r, g, b for the others and `hard` says which).
template <class D, class V = hn::Vec<D>, class M = hn::Mask<D>>
HWY_INLINE void Colours(D d, const AcesV<D>& P, V& r, V& g, V& b, V tiny, V u_max, V band,
                        M& hard) {
    using T = hn::TFromD<D>;
    r = FiniteOrDefault(d, r);
    g = FiniteOrDefault(d, g);
    b = FiniteOrDefault(d, b);
    const V zero = hn::Zero(d), one = hn::Set(d, static_cast<T>(1.0));
    const V ach = hn::Max(r, hn::Max(g, b));
    const V abs_ach = hn::Abs(ach);
    const M is_zero = hn::Eq(ach, zero);
    hard = hn::AndNot(is_zero, hn::Or(hn::Lt(abs_ach, tiny), hn::Gt(abs_ach, P.large)));
    // Zero and hard lanes divide by 1 here; their results are replaced.
    const V inv_abs = hn::Div(one, hn::IfThenElse(hn::Or(is_zero, hard), one, abs_ach));
    V ro = Channel(d, P, P.ch[0], r, ach, abs_ach, inv_abs, u_max, band, hard);
    V go = Channel(d, P, P.ch[1], g, ach, abs_ach, inv_abs, u_max, band, hard);
    V bo = Channel(d, P, P.ch[2], b, ach, abs_ach, inv_abs, u_max, band, hard);
    r = hn::IfThenZeroElse(is_zero, ro);
    g = hn::IfThenZeroElse(is_zero, go);
    b = hn::IfThenZeroElse(is_zero, bo);
    if (P.confined) {
        r = hn::Min(hn::Max(r, zero), P.max);
        g = hn::Min(hn::Max(g, zero), P.max);
        b = hn::Min(hn::Max(b, zero), P.max);
    }
}

/// Writes n colours of `result` to out, those flagged in `flag` recomputed by the double
/// reference from `in` (read before `out`, which may be the same memory, is written).
HWY_INLINE void Patch(const GamutClipper& clipper, const float* in, float* out, float* result,
                      const float* flag, std::size_t n) {
    for (std::size_t k = 0; k < n; ++k) {
        if (flag[k] == 0.0f) continue;
        const float* c = in + 3 * k;
        const Rgb o = clipper.clip({c[0], c[1], c[2]});
        result[3 * k] = static_cast<float>(o.r);
        result[3 * k + 1] = static_cast<float>(o.g);
        result[3 * k + 2] = static_cast<float>(o.b);
    }
    for (std::size_t k = 0; k < 3 * n; ++k) out[k] = result[k];
}

constexpr std::size_t max_float_lanes = HWY_MAX_BYTES / sizeof(float);

/// The forward in float.
std::size_t Forward(const GamutClipper& clipper, const float* in, float* out, std::size_t colours) {
    using D = hn::ScalableTag<float>;
    const D d;
    using V = hn::Vec<D>;
    const std::size_t n = hn::Lanes(d);
    const AcesV<D> P(d, clipper, 16.0, 1e30);
    const V tiny = hn::Set(d, 1e-30f), u_max = hn::Zero(d), band = hn::Zero(d);
    std::size_t i = 0;
    for (; i + n <= colours; i += n) {
        V r, g, b;
        hn::LoadInterleaved3(d, in + 3 * i, r, g, b);
        hn::Mask<D> hard;
        Colours(d, P, r, g, b, tiny, u_max, band, hard);
        if (HWY_LIKELY(hn::AllFalse(d, hard))) {
            hn::StoreInterleaved3(r, g, b, d, out + 3 * i);
            continue;
        }
        alignas(64) float result[3 * max_float_lanes];
        alignas(64) float flag[max_float_lanes];
        hn::StoreInterleaved3(r, g, b, d, result);
        hn::Store(hn::IfThenElseZero(hard, hn::Set(d, 1.0f)), d, flag);
        Patch(clipper, in + 3 * i, out + 3 * i, result, flag, n);
    }
    return i;
}

/// The inverse in double (its slope grows without bound toward the asymptote and would amplify
/// float's rounding beyond 1e-5), colours loaded and stored as float.
std::size_t Inverse(const GamutClipper& clipper, const float* in, float* out, std::size_t colours) {
    using D = hn::ScalableTag<double>;
    using DF = hn::Rebind<float, D>;
    const D d;
    const DF df;
    using V = hn::Vec<D>;
    using VF = hn::Vec<DF>;
    const std::size_t n = hn::Lanes(d);
    // In double the rounding of ach − D |ach| stays far below 1e-5 of max for any ach up to 1e30.
    const AcesV<D> P(d, clipper, 1e30, 1e30);
    const V tiny = hn::Set(d, 1e-300), u_max = hn::Set(d, 1.0 - 1e-4),
            band = hn::Set(d, 1.0 + 1e-9);
    std::size_t i = 0;
    for (; i + n <= colours; i += n) {
        VF rf, gf, bf;
        hn::LoadInterleaved3(df, in + 3 * i, rf, gf, bf);
        V r = hn::PromoteTo(d, rf), g = hn::PromoteTo(d, gf), b = hn::PromoteTo(d, bf);
        hn::Mask<D> hard;
        Colours(d, P, r, g, b, tiny, u_max, band, hard);
        rf = hn::DemoteTo(df, r);
        gf = hn::DemoteTo(df, g);
        bf = hn::DemoteTo(df, b);
        if (HWY_LIKELY(hn::AllFalse(d, hard))) {
            hn::StoreInterleaved3(rf, gf, bf, df, out + 3 * i);
            continue;
        }
        alignas(64) float result[3 * max_float_lanes];
        alignas(64) float flag[max_float_lanes];
        hn::StoreInterleaved3(rf, gf, bf, df, result);
        hn::Store(hn::DemoteTo(df, hn::IfThenElseZero(hard, hn::Set(d, 1.0))), df, flag);
        Patch(clipper, in + 3 * i, out + 3 * i, result, flag, n);
    }
    return i;
}

}  // namespace

std::size_t ClipAcesRgc(const GamutClipper& clipper, const float* in, float* out,
                        std::size_t colours) {
    return clipper.inverse() ? Inverse(clipper, in, out, colours)
                             : Forward(clipper, in, out, colours);
}

}  // namespace HWY_NAMESPACE
}  // namespace irid
HWY_AFTER_NAMESPACE();

#if HWY_ONCE

namespace irid {

HWY_EXPORT(ClipAcesRgc);

namespace detail {

std::size_t clip_aces_rgc_simd(const GamutClipper& clipper, const float* in, float* out,
                               std::size_t colours) noexcept {
    return HWY_DYNAMIC_DISPATCH(ClipAcesRgc)(clipper, in, out, colours);
}

}  // namespace detail
}  // namespace irid

#endif  // HWY_ONCE
