// The SIMD batch kernel of aces-rgc (Google Highway, dynamic dispatch), forward and inverse.
//
// Per vector of colours, in float, the scalar reference's steps (aces_rgc.cpp): the non-finite
// rule, ach = max(r, g, b), per channel d = (ach − c)·(1/|ach|), and beyond the threshold the
// curve, through ln nd (Highway's Exp, Log and Log1p, hwy/contrib/math/math-inl.h):
//   forward  D = thr + s·exp(min(L, 0) − log1p(exp(−p|L|))/p),  L = ln nd
//            (= thr + s·nd/(1 + nd^p)^(1/p), with the exponent never positive: no overflow);
//   inverse  D = thr + s·exp(L − log1p(−u)/p), u = exp(p L) = nd^p, for d below the asymptote
//            thr + s (unchanged from there on);
// then ach − D·|ach|, capped at ±1e30 (a compressed channel, as the reference), and clamped into [0, max] when the clipper confines.
// A channel whose lanes are all below the threshold skips the curve.
//
// Lanes sent to the double reference (GamutClipper::clip, written over the vector's result),
// where float cannot stay within the contract (tests/gamut/aces_rgc_test.cpp):
// - |ach| < 1e-30 (not 0, which gives 0 here as in the reference): 1/|ach| may overflow;
// - |ach| > 1e30, or, when confined, ach > 16·max: the output is ach − D·|ach|, whose float
//   rounding (a few 1e-7 of |ach|) must stay below 1e-5·max when it lands inside the cube;
// - inverse, u = nd^p > 0.9 on a channel below the asymptote: the curve's slope
//   (1 − u)^(−(1+p)/p) amplifies float's rounding of d beyond 1e-5 near the asymptote; and d
//   within 1e-5 (relative) above the asymptote, where the inverse jumps from +inf back to the
//   identity and float's rounding of d may fall on the other side.
// On the benchmark's input (uniform in [-0.5, 1.5]^3 outside the sRGB cube, as ACEScg) the
// forward sends none; the inverse sends the colours with a channel in that band (measured by
// aces_rgc_test, about 2 %).

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE __BASE_FILE__
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>
#include <hwy/contrib/math/math-inl.h>

#include "kernels.h"
#include "simd_common-inl.h"

#include <cstddef>
#include <cstdint>

HWY_BEFORE_NAMESPACE();
namespace irid {
namespace HWY_NAMESPACE {
namespace {

namespace hn = hwy::HWY_NAMESPACE;
using simd::Df;
using simd::Mf;
using simd::Vf;

/// The float parameters of one channel's curve.
struct ChannelV {
    Vf thr, scale, inv_scale, asymptote;
};

/// The float parameters of a call, broadcast once.
struct AcesV {
    ChannelV ch[3];
    Vf power, inv_power, max;
    Vf large;  // |ach| above this goes to the double reference
    bool inverse, confined;
};

/// Compresses (or, inverse, uncompresses) one channel c against ach; flags lanes for the double
/// reference in `hard` (inverse near its asymptote).
HWY_INLINE Vf Channel(Df d, const AcesV& P, const ChannelV& C, Vf c, Vf ach, Vf abs_ach,
                      Vf inv_abs, Mf& hard) {
    const Vf dist = hn::Mul(hn::Sub(ach, c), inv_abs);
    Mf active = hn::Ge(dist, C.thr);
    if (P.inverse) {
        // The inverse jumps from +inf to the identity at the asymptote: a lane within float's
        // rounding of d above it may belong below it.
        const Vf above = hn::Mul(C.asymptote, hn::Set(d, 1.0f + 1e-5f));
        hard = hn::Or(hard, hn::And(hn::Ge(dist, C.asymptote), hn::Lt(dist, above)));
        active = hn::And(active, hn::Lt(dist, C.asymptote));
    }
    if (hn::AllFalse(d, active)) return c;
    // nd in [FLT_MIN, 1e30]: Log is finite; the clamped ends change nothing that shows (nd below
    // 1.2e-38 compresses to thr, beyond 1e30 to thr + s, both to float precision).
    const Vf nd = hn::Min(hn::Max(hn::Mul(hn::Sub(dist, C.thr), C.inv_scale),
                                  hn::Set(d, 1.17549435e-38f)),
                          hn::Set(d, 1e30f));
    const Vf L = hn::Log(d, nd);
    Vf f;
    if (!P.inverse) {
        const Vf e = hn::Exp(d, hn::Neg(hn::Mul(P.power, hn::Abs(L))));
        f = hn::Exp(d, hn::NegMulAdd(hn::Log1p(d, e), P.inv_power, hn::Min(L, hn::Zero(d))));
    } else {
        const Vf u = hn::Exp(d, hn::Mul(P.power, L));
        hard = hn::Or(hard, hn::And(active, hn::Gt(u, hn::Set(d, 0.9f))));
        const Vf safe_u = hn::Min(u, hn::Set(d, 0.9f));
        f = hn::Exp(d, hn::NegMulAdd(hn::Log1p(d, hn::Neg(safe_u)), P.inv_power, L));
    }
    const Vf D = hn::MulAdd(C.scale, f, C.thr);
    // Capped at ±1e30 as the reference caps a compressed channel (aces_rgc.cpp).
    const Vf cap = hn::Set(d, 1e30f);
    const Vf out = hn::Min(hn::Max(hn::NegMulAdd(D, abs_ach, ach), hn::Neg(cap)), cap);
    return hn::IfThenElse(active, out, c);
}

}  // namespace

std::size_t ClipAcesRgc(const GamutClipper& clipper, const float* in, float* out,
                        std::size_t colours) {
    const Df d;
    const std::size_t n = hn::Lanes(d);
    const auto& x = clipper.derived();
    AcesV P;
    for (std::size_t k = 0; k < 3; ++k) {
        P.ch[k].thr = hn::Set(d, static_cast<float>(x[k]));
        P.ch[k].scale = hn::Set(d, static_cast<float>(x[3 + k]));
        P.ch[k].inv_scale = hn::Set(d, static_cast<float>(1.0 / x[3 + k]));
        P.ch[k].asymptote = hn::Set(d, static_cast<float>(x[8 + k]));
    }
    P.power = hn::Set(d, static_cast<float>(x[6]));
    P.inv_power = hn::Set(d, static_cast<float>(x[7]));
    const double max = clipper.gamut().max();
    P.max = hn::Set(d, static_cast<float>(max));
    P.inverse = clipper.inverse();
    P.confined = clipper.confines_to_cube();
    P.large = hn::Set(d, P.confined ? static_cast<float>(16.0 * max) : 1e30f);
    const Vf zero = hn::Zero(d);
    const Vf tiny = hn::Set(d, 1e-30f);

    std::size_t i = 0;
    for (; i + n <= colours; i += n) {
        Vf r, g, b;
        hn::LoadInterleaved3(d, in + 3 * i, r, g, b);
        simd::FiniteOrDefault(d, r, g, b);
        const Vf ach = hn::Max(r, hn::Max(g, b));
        const Vf abs_ach = hn::Abs(ach);
        const Mf is_zero = hn::Eq(ach, zero);
        Mf hard = hn::AndNot(is_zero, hn::Or(hn::Lt(abs_ach, tiny), hn::Gt(abs_ach, P.large)));
        // Zero and hard lanes divide by 1 here; their results are replaced below.
        const Vf inv_abs =
            hn::Div(hn::Set(d, 1.0f), hn::IfThenElse(hn::Or(is_zero, hard), hn::Set(d, 1.0f), abs_ach));
        Vf ro = Channel(d, P, P.ch[0], r, ach, abs_ach, inv_abs, hard);
        Vf go = Channel(d, P, P.ch[1], g, ach, abs_ach, inv_abs, hard);
        Vf bo = Channel(d, P, P.ch[2], b, ach, abs_ach, inv_abs, hard);
        ro = hn::IfThenZeroElse(is_zero, ro);
        go = hn::IfThenZeroElse(is_zero, go);
        bo = hn::IfThenZeroElse(is_zero, bo);
        if (P.confined) {
            ro = hn::Min(hn::Max(ro, zero), P.max);
            go = hn::Min(hn::Max(go, zero), P.max);
            bo = hn::Min(hn::Max(bo, zero), P.max);
        }
        if (HWY_LIKELY(hn::AllFalse(d, hard))) {
            hn::StoreInterleaved3(ro, go, bo, d, out + 3 * i);
            continue;
        }
        // The rare hard lanes: the double reference, from the input (read before `out`, which
        // may be the same memory, is written).
        constexpr std::size_t max_lanes = HWY_MAX_BYTES / sizeof(float);
        alignas(64) float result[3 * max_lanes];
        alignas(64) float flag[max_lanes];
        hn::StoreInterleaved3(ro, go, bo, d, result);
        hn::Store(hn::IfThenElseZero(hard, hn::Set(d, 1.0f)), d, flag);
        for (std::size_t k = 0; k < n; ++k) {
            if (flag[k] == 0.0f) continue;
            const float* c = in + 3 * (i + k);
            const Rgb o = clipper.clip({c[0], c[1], c[2]});
            result[3 * k] = static_cast<float>(o.r);
            result[3 * k + 1] = static_cast<float>(o.g);
            result[3 * k + 2] = static_cast<float>(o.b);
        }
        for (std::size_t k = 0; k < 3 * n; ++k) out[3 * i + k] = result[k];
    }
    return i;
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
