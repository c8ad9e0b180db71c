// The vector maths the ACES 2.0 kernel's forward (aces2_simd_forward.cpp) and inverse
// (aces2_simd_inverse.cpp) share: the model's response and hue, the tables' lookups, the chroma
// and gamut compression, and the loop that runs a body over a buffer and hands the lanes it
// cannot follow to the double chain. Included once per Highway target by each (the include
// guard toggles with HWY_TARGET_TOGGLE, as Highway's own -inl.h headers do). Their arithmetic
// is in docs/KERNELS.md.

#if defined(IRID_GAMUT_ACES2_SIMD_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef IRID_GAMUT_ACES2_SIMD_INL_H_
#undef IRID_GAMUT_ACES2_SIMD_INL_H_
#else
#define IRID_GAMUT_ACES2_SIMD_INL_H_
#endif

#include <hwy/contrib/math/math-inl.h>
#include <hwy/highway.h>

#include "aces2_constants.h"
#include "aces2_kernel_data.h"

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstring>
#include <limits>
#include <numbers>

HWY_BEFORE_NAMESPACE();
namespace irid {
namespace HWY_NAMESPACE {
namespace aces2_simd {

namespace hn = hwy::HWY_NAMESPACE;

using aces2::response_exponent;
using aces2::response_offset;
using aces2::response_scale;

/// An inverse response beyond this (of response_scale, where it diverges) goes to the double
/// path: the float inverse's conditioning there, and the reference's NaN from 400 on.
constexpr double response_inverse_limit = 380.0;
/// Where ResponseDifference takes its series: |c0 / c1 − 1| up to this.
constexpr double response_series_reach = 0.125;
/// Input channels beyond this magnitude go to the double path: the input matrix's float rounding
/// of large terms that cancel.
constexpr double large_input = 1e6;
/// The half width of the band around proportion = 1 where the gamut compression switches off
/// (aces2.cpp, remap_m) and a lane goes to the double path: the switch is a jump.
constexpr double proportion_band = 1e-4;

template <class D>
using Params = detail::Aces2Params<hn::TFromD<D>>;

/// The constant x in the precision of D.
template <class D, class V = hn::Vec<D>>
HWY_INLINE V C(D d, double x) {
    return hn::Set(d, static_cast<hn::TFromD<D>>(x));
}

/// (o0, o1, o2) = m (x0, x1, x2), m row-major.
template <class D, class V = hn::Vec<D>, class T = hn::TFromD<D>>
HWY_INLINE void Mul3(D d, const std::array<T, 9>& m, V x0, V x1, V x2, V& o0, V& o1, V& o2) {
    o0 = hn::MulAdd(hn::Set(d, m[2]), x2,
                    hn::MulAdd(hn::Set(d, m[1]), x1, hn::Mul(hn::Set(d, m[0]), x0)));
    o1 = hn::MulAdd(hn::Set(d, m[5]), x2,
                    hn::MulAdd(hn::Set(d, m[4]), x1, hn::Mul(hn::Set(d, m[3]), x0)));
    o2 = hn::MulAdd(hn::Set(d, m[8]), x2,
                    hn::MulAdd(hn::Set(d, m[7]), x1, hn::Mul(hn::Set(d, m[6]), x0)));
}

/// x^e for x >= 0 (x below the smallest normal taken as it: the result is then far below anything
/// that shows); NaN for NaN x, which the floor would otherwise turn into a tiny number.
template <class D, class V = hn::Vec<D>>
HWY_INLINE V Pow(D d, V x, V e) {
    using T = hn::TFromD<D>;
    const V p =
        hn::Exp(d, hn::Mul(e, hn::Log(d, hn::Max(x, hn::Set(d, std::numeric_limits<T>::min())))));
    return hn::IfThenElse(hn::IsNaN(x), x, p);
}

/// The lanes where any of the values is not finite: they go to the double path before a clamp
/// or a floor can hide them.
template <class D, class V = hn::Vec<D>, class... Vs>
HWY_INLINE hn::Mask<D> NotFinite(D d, V v, Vs... vs) {
    hn::Mask<D> all = hn::IsFinite(v);
    ((all = hn::And(all, hn::IsFinite(vs))), ...);
    (void)d;
    return hn::Not(all);
}

/// (F_L |c|)^0.42, the power inside the response; 0 for c = 0 (Pow would give the power of the
/// smallest normal, which leaves a black colour's A above 0).
template <class D, class V = hn::Vec<D>>
HWY_INLINE V ResponsePower(D d, const Params<D>& p, V c) {
    return hn::IfThenZeroElse(
        hn::Eq(c, hn::Zero(d)),
        Pow(d, hn::Mul(hn::Abs(c), hn::Set(d, p.fl_n)), C(d, response_exponent)));
}

/// The response of c from its ResponsePower f (Response).
template <class D, class V = hn::Vec<D>>
HWY_INLINE V ResponseOfPower(D d, V c, V f) {
    return hn::CopySign(
        hn::Div(hn::Mul(C(d, response_scale), f), hn::Add(C(d, response_offset), f)), c);
}

/// The compressive response, mirrored for negatives (Aces2JmhModel: mirrored_response).
template <class D, class V = hn::Vec<D>>
HWY_INLINE V Response(D d, const Params<D>& p, V c) {
    return ResponseOfPower(d, c, ResponsePower(d, p, c));
}

/// Its inverse; |r| beyond response_inverse_limit is added to `hard`.
template <class D, class V = hn::Vec<D>, class M = hn::Mask<D>>
HWY_INLINE V ResponseInverse(D d, const Params<D>& p, V r, M& hard) {
    const V limit = C(d, response_inverse_limit);
    const V a = hn::Abs(r);
    hard = hn::Or(hard, hn::Gt(a, limit));
    const V s = hn::Min(a, limit);
    const V f = hn::Div(hn::Mul(C(d, response_offset), s), hn::Sub(C(d, response_scale), s));
    return hn::CopySign(hn::Div(Pow(d, f, C(d, 1.0 / response_exponent)), hn::Set(d, p.fl_n)), r);
}

/// The hue atan2(b, a) in degrees, in [0, 360) (Aces2JmhModel::aab_to_jmh).
template <class D, class V = hn::Vec<D>>
HWY_INLINE V HueDegrees(D d, V a, V b) {
    const V ax = hn::Abs(a), ay = hn::Abs(b);
    const V big = hn::Max(ax, ay), small = hn::Min(ax, ay);
    const V ratio = hn::IfThenZeroElse(
        hn::Eq(big, hn::Zero(d)),
        hn::Div(small, hn::Max(big, hn::Set(d, std::numeric_limits<hn::TFromD<D>>::min()))));
    V r = hn::Atan(d, ratio);
    r = hn::IfThenElse(hn::Gt(ay, ax), hn::Sub(C(d, std::numbers::pi / 2), r), r);
    r = hn::IfThenElse(hn::Lt(a, hn::Zero(d)), hn::Sub(C(d, std::numbers::pi), r), r);
    V h = hn::Mul(hn::CopySign(r, b), C(d, 180.0 / std::numbers::pi));
    h = hn::IfThenElse(hn::Lt(h, hn::Zero(d)), hn::Add(h, C(d, 360.0)), h);
    return hn::IfThenElse(hn::Ge(h, C(d, 360.0)), hn::Sub(h, C(d, 360.0)), h);
}

template <class V>
struct Polar {
    V m, h, cos_h, sin_h;
};

/// M, h in degrees, cos h and sin h of the opponent a, b (Aces2JmhModel::aab_to_jmh); where M
/// is 0, h is 0 and (cos h, sin h) = (1, 0).
template <class D, class V = hn::Vec<D>>
HWY_INLINE Polar<V> ToPolar(D d, V a, V b) {
    const V m = hn::Sqrt(hn::MulAdd(a, a, hn::Mul(b, b)));
    const auto no_hue = hn::Eq(m, hn::Zero(d));
    const V inv_m = hn::Div(C(d, 1.0), hn::IfThenElse(no_hue, C(d, 1.0), m));
    return {m, HueDegrees(d, a, b), hn::IfThenElse(no_hue, C(d, 1.0), hn::Mul(a, inv_m)),
            hn::Mul(b, inv_m)};
}

/// The hue-dependent normalisation of M from cos h and sin h (Aces2Rendering::m_norm).
template <class D, class V = hn::Vec<D>>
HWY_INLINE V Norm(D d, const Params<D>& p, V c, V s) {
    const V cos2 = hn::NegMulAdd(s, s, hn::Mul(c, c)), sin2 = hn::Mul(C(d, 2.0), hn::Mul(c, s));
    const V cos3 = hn::Mul(c, hn::MulAdd(C(d, 4.0), hn::Mul(c, c), C(d, -3.0)));
    const V sin3 = hn::Mul(s, hn::NegMulAdd(C(d, 4.0), hn::Mul(s, s), C(d, 3.0)));
    const auto& k = aces2::m_norm_coefficients;
    V m = C(d, k[0]);
    m = hn::MulAdd(C(d, k[1]), c, m);
    m = hn::MulAdd(C(d, k[2]), cos2, m);
    m = hn::MulAdd(C(d, k[3]), cos3, m);
    m = hn::MulAdd(C(d, k[4]), s, m);
    m = hn::MulAdd(C(d, k[5]), sin2, m);
    m = hn::MulAdd(C(d, k[6]), sin3, m);
    return hn::Mul(m, hn::Set(d, p.chroma_scale));
}

/// The per-hue values read from the tables: the reach's M and the cusp (Aces2Rendering::reach_m,
/// cusp_at).
template <class V>
struct HueValues {
    V reach, cusp_j, cusp_m, gamma_top_inv, focus_j, threshold;
};

template <class D, class V = hn::Vec<D>>
HWY_INLINE V Lerp(V a, V b, V t) {
    return hn::MulAdd(t, hn::Sub(b, a), a);
}

template <class D, class V = hn::Vec<D>>
HWY_INLINE HueValues<V> AtHue(D d, const Params<D>& p, V h) {
    const hn::RebindToSigned<D> di;
    using VI = hn::Vec<decltype(di)>;
    HueValues<V> v;
    // The reach: per whole degree.
    const VI deg = hn::Min(hn::Max(hn::ConvertTo(di, h), hn::Zero(di)), hn::Set(di, 359));
    const V t_reach = hn::Sub(h, hn::ConvertTo(d, deg));
    v.reach = Lerp<D>(hn::GatherIndex(d, p.reach.data(), deg),
                      hn::GatherIndex(d, p.reach.data(), hn::Add(deg, hn::Set(di, 1))), t_reach);
    // The cusp: the last entry below h, from its bucket's first and stepping on.
    const VI bucket =
        hn::Min(hn::Max(hn::ConvertTo(di, hn::Mul(h, C(d, detail::aces2_buckets_per_degree))),
                        hn::Zero(di)),
                hn::Set(di, static_cast<int>(detail::aces2_buckets) - 1));
    VI lo = hn::GatherIndex(di, p.bucket_lo.data(), bucket);
    for (int s = 0; s < p.bucket_steps; ++s) {
        const VI next = hn::Add(lo, hn::Set(di, 1));
        const V next_hue = hn::GatherIndex(d, p.hue.data(), next);
        lo = hn::IfThenElse(hn::RebindMask(di, hn::Lt(next_hue, h)), next, lo);
    }
    // lo + 1 is the first entry at or above h. OpenColorIO's search (Aces2Rendering::hue_interval)
    // takes it only within its window around the entry n of h's whole degree: if h is above
    // entry n, at most n + window[1]; else at least n + window[0] + 1 and at most n (the
    // bisection's two halves, each a clamp of the first entry at or above h).
    const VI one = hn::Set(di, 1);
    const VI n = hn::Add(
        hn::Min(hn::Max(hn::ConvertTo(di, h), hn::Zero(di)), hn::Set(di, aces2::table_hues)), one);
    const VI first = hn::Add(lo, one);
    const VI window_lo = hn::Max(hn::Zero(di), hn::Add(n, hn::Set(di, p.hue_search[0])));
    const VI window_hi =
        hn::Min(hn::Set(di, aces2::table_hues + 1), hn::Add(n, hn::Set(di, p.hue_search[1])));
    const auto above_n = hn::RebindMask(di, hn::Gt(h, hn::GatherIndex(d, p.hue.data(), n)));
    VI hi = hn::IfThenElse(above_n, hn::Min(first, window_hi),
                           hn::Min(hn::Max(first, hn::Add(window_lo, one)), n));
    hi = hn::Max(hi, one);
    lo = hn::Sub(hi, one);
    const V h0 = hn::GatherIndex(d, p.hue.data(), lo), h1 = hn::GatherIndex(d, p.hue.data(), hi);
    const V t = hn::Div(hn::Sub(h, h0), hn::Sub(h1, h0));
    v.cusp_j = Lerp<D>(hn::GatherIndex(d, p.cusp_j.data(), lo),
                       hn::GatherIndex(d, p.cusp_j.data(), hi), t);
    v.cusp_m = Lerp<D>(hn::GatherIndex(d, p.cusp_m.data(), lo),
                       hn::GatherIndex(d, p.cusp_m.data(), hi), t);
    v.gamma_top_inv = Lerp<D>(hn::GatherIndex(d, p.gamma_top_inv.data(), lo),
                              hn::GatherIndex(d, p.gamma_top_inv.data(), hi), t);
    const V limit_j = hn::Set(d, p.limit_j);
    // focus_j_of and the analytical threshold (aces2.cpp).
    const V blend =
        hn::Min(C(d, 1.0), hn::Sub(C(d, aces2::cusp_mid_blend), hn::Div(v.cusp_j, limit_j)));
    v.focus_j = Lerp<D>(v.cusp_j, hn::Set(d, p.mid_j), blend);
    v.threshold = Lerp<D>(v.cusp_j, limit_j, C(d, aces2::focus_gain_blend));
    return v;
}

/// The chroma compression's toe (aces2.cpp, toe_forward and toe_inverse). The forward's root
/// is taken in the form without cancellation on either sign of −b.
template <class D, class V = hn::Vec<D>>
HWY_INLINE V Toe(D d, V x, V limit, V k1_in, V k2_in, bool inverse) {
    const V k2 = hn::Max(k2_in, C(d, 0.001));
    const V k1 = hn::Sqrt(hn::MulAdd(k1_in, k1_in, hn::Mul(k2, k2)));
    const V k3 = hn::Div(hn::Add(limit, k1), hn::Add(limit, k2));
    V t;
    if (!inverse) {
        const V minus_b = hn::MulSub(k3, x, k1);
        const V minus_ac = hn::Mul(hn::Mul(k2, k3), x);
        const V root = hn::Sqrt(hn::MulAdd(minus_b, minus_b, hn::Mul(C(d, 4.0), minus_ac)));
        const V plain = hn::Mul(C(d, 0.5), hn::Add(minus_b, root));
        const V stable = hn::Div(hn::Mul(C(d, 2.0), minus_ac), hn::Sub(root, minus_b));
        t = hn::IfThenElse(hn::Lt(minus_b, hn::Zero(d)), stable, plain);
    } else {
        t = hn::Div(hn::MulAdd(x, x, hn::Mul(k1, x)), hn::Mul(k3, hn::Add(x, k2)));
    }
    return hn::IfThenElse(hn::Gt(x, limit), x, t);
}

/// Tonescale-scaled chroma compression of M (Aces2Rendering::tonescale_and_chroma_forward and
/// _inverse): nj = J/limit_j of the tonescaled J, a_ratio = nj^(1/cz) (the A of that J over the
/// peak's), `scale` = (J_tonescaled/J)^(1/cz) forward, its inverse's factor inverse.
template <class D, class V = hn::Vec<D>>
HWY_INLINE V ChromaCompress(D d, const Params<D>& p, V m, V nj, V a_ratio, V scale, V norm, V reach,
                            bool inverse) {
    const V snj = hn::Max(hn::Zero(d), hn::Sub(C(d, 1.0), nj));
    const V limit = hn::Div(hn::Mul(a_ratio, reach), norm);
    const V k_sat = hn::Mul(snj, hn::Set(d, p.sat));
    const V k_thr = hn::Sqrt(hn::MulAdd(nj, nj, hn::Set(d, p.sat_thr)));
    const V k_compr = hn::Mul(nj, hn::Set(d, p.compr));
    const V limit_toe = hn::Sub(limit, C(d, 0.001));
    if (!inverse) {
        m = hn::Div(hn::Mul(m, scale), norm);
        m = hn::Sub(limit, Toe(d, hn::Sub(limit, m), limit_toe, k_sat, k_thr, false));
        m = Toe(d, m, limit, k_compr, snj, false);
        return hn::Mul(m, norm);
    }
    m = hn::Div(m, norm);
    m = Toe(d, m, limit, k_compr, snj, true);
    m = hn::Sub(limit, Toe(d, hn::Sub(limit, m), limit_toe, k_sat, k_thr, true));
    return hn::Mul(hn::Mul(m, norm), scale);
}

/// Where the compression line through (J, M) meets the J axis (aces2.cpp, solve_j_intersect).
template <class D, class V = hn::Vec<D>>
HWY_INLINE V SolveJIntersect(D d, V j, V m, V focus_j, V max_j, V slope_gain) {
    const V m_gain = hn::Div(m, slope_gain);
    const V a = hn::Div(m_gain, focus_j);
    const V four_a = hn::Mul(C(d, 4.0), a);
    // Below the focus: b = 1 − M/g, c = −J.
    const V b1 = hn::Sub(C(d, 1.0), m_gain);
    const V below = hn::Div(hn::Mul(C(d, -2.0), j),
                            hn::Sub(hn::Neg(b1), hn::Sqrt(hn::MulAdd(b1, b1, hn::Mul(four_a, j)))));
    // Above: b = −(1 + M/g + max_j M/(focus_j g)), c = max_j M/g + J.
    const V minus_b2 = hn::Add(hn::Add(C(d, 1.0), m_gain), hn::Mul(max_j, a));
    const V c2 = hn::MulAdd(max_j, m_gain, j);
    const V above = hn::Div(
        hn::Mul(C(d, 2.0), c2),
        hn::Add(minus_b2, hn::Sqrt(hn::NegMulAdd(four_a, c2, hn::Mul(minus_b2, minus_b2)))));
    return hn::IfThenElse(hn::Lt(j, focus_j), below, above);
}

template <class D, class V = hn::Vec<D>>
HWY_INLINE V CompressionSlope(V j_intersect, V focus_j, V limit_j, V slope_gain) {
    const V scaler =
        hn::IfThenElse(hn::Lt(j_intersect, focus_j), j_intersect, hn::Sub(limit_j, j_intersect));
    return hn::Div(hn::Mul(scaler, hn::Sub(j_intersect, focus_j)), hn::Mul(focus_j, slope_gain));
}

/// aces2_geometry.h, line_boundary_m: 0 where the line meets the axis at or beyond the apex.
template <class D, class V = hn::Vec<D>>
HWY_INLINE V LineBoundaryM(D d, V j_axis, V slope, V inv_gamma, V j_max, V m_max, V j_reference) {
    const V shifted =
        hn::IfThenZeroElse(hn::Le(j_axis, hn::Zero(d)),
                           hn::Mul(j_reference, Pow(d, hn::Div(j_axis, j_reference), inv_gamma)));
    return hn::Div(hn::Mul(shifted, m_max), hn::NegMulAdd(slope, m_max, j_max));
}

/// Gamut compression (Aces2Rendering::compress): (J, M) to (j_out, m_out), the focus gain from
/// jx; lanes near the switch of remap_m are added to `hard`.
template <class D, class V = hn::Vec<D>, class M = hn::Mask<D>>
HWY_INLINE void Compress(D d, const Params<D>& p, const HueValues<V>& hv, V j, V m, V jx,
                         bool inverse, V& j_out, V& m_out, M& hard) {
    const V zero = hn::Zero(d), one = C(d, 1.0);
    const V limit_j = hn::Set(d, p.limit_j);
    // focus_gain (aces2.cpp): beyond the threshold, 1 + log10(r)² (r > 1 there).
    const V gain_ratio =
        hn::Div(hn::Sub(limit_j, hv.threshold),
                hn::Max(C(d, aces2::focus_gain_min_distance), hn::Sub(limit_j, jx)));
    const V log_ratio = hn::Log10(d, hn::Max(gain_ratio, one));
    const V above = hn::MulAdd(log_ratio, log_ratio, one);
    const V gain = hn::IfThenElse(hn::Gt(jx, hv.threshold), above, one);
    const V slope_gain = hn::Mul(hn::Mul(limit_j, hn::Set(d, p.focus_dist)), gain);
    const V j_source = SolveJIntersect(d, j, m, hv.focus_j, limit_j, slope_gain);
    const V slope = CompressionSlope<D>(j_source, hv.focus_j, limit_j, slope_gain);
    const V j_cusp = SolveJIntersect(d, hv.cusp_j, hv.cusp_m, hv.focus_j, limit_j, slope_gain);
    const V lower = LineBoundaryM(d, j_source, slope, hn::Set(d, p.lower_gamma_inv), hv.cusp_j,
                                  hv.cusp_m, j_cusp);
    const V upper = LineBoundaryM(d, hn::Sub(limit_j, j_source), hn::Neg(slope), hv.gamma_top_inv,
                                  hn::Sub(limit_j, hv.cusp_j), hv.cusp_m, hn::Sub(limit_j, j_cusp));
    // smooth_min (aces2.cpp).
    const V s = hn::Mul(C(d, aces2::smooth_cusps), hv.cusp_m);
    const V hs = hn::Div(hn::Max(hn::Sub(s, hn::Abs(hn::Sub(lower, upper))), zero), s);
    const V gamut_m = hn::NegMulAdd(hn::Mul(hn::Mul(hs, hs), hs), hn::Mul(s, C(d, 1.0 / 6.0)),
                                    hn::Min(lower, upper));
    const V reach_m =
        LineBoundaryM(d, j_source, slope, hn::Set(d, p.cz_inv), limit_j, hv.reach, limit_j);
    // remap_m (aces2.cpp).
    const V proportion = hn::Max(hn::Div(gamut_m, reach_m), C(d, aces2::compression_threshold));
    const V threshold = hn::Mul(proportion, gamut_m);
    const V m_offset = hn::Sub(m, threshold);
    const V gamut_offset = hn::Sub(gamut_m, threshold);
    const V reach_offset = hn::Sub(reach_m, threshold);
    // Reinhard's curve without the ratio m_offset / scale, which overflows where gamut_m is next
    // to 0 at the peak's J (aces2.cpp, remap_m).
    const V scale =
        hn::Div(hn::Mul(reach_offset, gamut_offset), hn::Sub(reach_offset, gamut_offset));
    V remapped;
    if (!inverse) {
        remapped = hn::MulAdd(scale, hn::Div(m_offset, hn::Add(scale, m_offset)), threshold);
    } else {
        const V tail = hn::Mul(scale, hn::Div(m_offset, hn::Sub(scale, m_offset)));
        remapped = hn::Add(threshold, hn::IfThenElse(hn::Ge(m_offset, scale), scale, tail));
        hard = hn::Or(hard, hn::And(hn::And(hn::Gt(m, threshold), hn::Lt(proportion, one)),
                                    hn::Gt(m_offset, hn::Mul(scale, C(d, 1.0 - proportion_band)))));
    }
    const M keep = hn::Or(hn::Ge(proportion, one), hn::Le(m, threshold));
    const M near_switch = hn::And(hn::Gt(m, threshold),
                                  hn::Lt(hn::Abs(hn::Sub(proportion, one)), C(d, proportion_band)));
    const M no_m = hn::Or(hn::Or(hn::Le(m, zero), hn::Gt(j, limit_j)), hn::Le(gamut_m, zero));
    const M black = hn::Le(j, zero);
    hard = hn::Or(hard, hn::AndNot(hn::Or(no_m, black), near_switch));
    const V m_new = hn::IfThenElse(keep, m, remapped);
    j_out = hn::IfThenZeroElse(black, hn::IfThenElse(no_m, j, hn::MulAdd(m_new, slope, j_source)));
    m_out = hn::IfThenZeroElse(hn::Or(black, no_m), m_new);
    // The minimum and maximum above can turn a NaN into a number on some targets.
    hard = hn::Or(hard, hn::AndNot(black, NotFinite(d, j_source, slope, lower, upper, reach_m,
                                                    j_out, m_out)));
}

/// The input matrix and the clamp to [0, in_max].
template <class D, class V = hn::Vec<D>>
HWY_INLINE void InClamped(D d, const Params<D>& p, V x0, V x1, V x2, V& r, V& g, V& b) {
    Mul3(d, p.in, x0, x1, x2, r, g, b);
    const V zero = hn::Zero(d), in_max = hn::Set(d, p.in_max);
    r = hn::Min(hn::Max(r, zero), in_max);
    g = hn::Min(hn::Max(g, zero), in_max);
    b = hn::Min(hn::Max(b, zero), in_max);
}

/// The input (InClamped) to the model's achromatic A and opponent a, b (the cone responses and
/// the opponent matrix).
template <class D, class V = hn::Vec<D>>
HWY_INLINE void Aab(D d, const Params<D>& p, V x0, V x1, V x2, V& A, V& a, V& b) {
    V r, g, bl, c0, c1, c2;
    InClamped(d, p, x0, x1, x2, r, g, bl);
    Mul3(d, p.to_cone, r, g, bl, c0, c1, c2);
    Mul3(d, p.to_aab, Response(d, p, c0), Response(d, p, c1), Response(d, p, c2), A, a, b);
}

/// Every vector of `colours` triples, and the tail through the same code padded to a whole
/// vector; lanes the body returns, and lanes whose result is not finite, are redone by
/// kernel.reference() from the input as loaded (so `in` may be `out`).
template <class D, class Body>
HWY_INLINE std::size_t Run(D d, const Aces2Kernel& kernel, const Params<D>& p, const float* in,
                           float* out, std::size_t colours, const Body& body) {
    using T = hn::TFromD<D>;
    using V = hn::Vec<D>;
    const hn::Rebind<float, D> df;
    const std::size_t n = hn::Lanes(d);
    constexpr std::size_t max_lanes = HWY_MAX_BYTES / sizeof(T);
    std::size_t handed = 0;
    const auto vector = [&](const float* src, float* dst, std::size_t valid) {
        V x0, x1, x2;
        if constexpr (sizeof(T) == sizeof(float)) {
            hn::LoadInterleaved3(d, src, x0, x1, x2);
        } else {
            hn::Vec<decltype(df)> f0, f1, f2;
            hn::LoadInterleaved3(df, src, f0, f1, f2);
            x0 = hn::PromoteTo(d, f0);
            x1 = hn::PromoteTo(d, f1);
            x2 = hn::PromoteTo(d, f2);
        }
        const V raw0 = x0, raw1 = x1, raw2 = x2;
        // A non-finite channel as aces2_finite_input takes it: +Inf as 65504, -Inf and NaN as 0.
        const V inf_as = hn::Set(d, static_cast<T>(aces2_positive_infinity_as));
        x0 = hn::IfThenElse(hn::IsFinite(x0), x0, hn::IfThenElseZero(hn::Gt(x0, hn::Zero(d)), inf_as));
        x1 = hn::IfThenElse(hn::IsFinite(x1), x1, hn::IfThenElseZero(hn::Gt(x1, hn::Zero(d)), inf_as));
        x2 = hn::IfThenElse(hn::IsFinite(x2), x2, hn::IfThenElseZero(hn::Gt(x2, hn::Zero(d)), inf_as));
        auto hard = body(d, p, x0, x1, x2);
        hard = hn::Or(
            hard, hn::Not(hn::And(hn::And(hn::IsFinite(x0), hn::IsFinite(x1)), hn::IsFinite(x2))));
        if constexpr (sizeof(T) == sizeof(float)) {
            hn::StoreInterleaved3(x0, x1, x2, d, dst);
        } else {
            hn::StoreInterleaved3(hn::DemoteTo(df, x0), hn::DemoteTo(df, x1), hn::DemoteTo(df, x2),
                                  df, dst);
        }
        if (HWY_LIKELY(hn::AllFalse(d, hard))) return;
        HWY_ALIGN T c0[max_lanes] = {}, c1[max_lanes] = {}, c2[max_lanes] = {},
                    flag[max_lanes] = {};
        hn::Store(raw0, d, c0);
        hn::Store(raw1, d, c1);
        hn::Store(raw2, d, c2);
        hn::Store(hn::IfThenElseZero(hard, hn::Set(d, T(1))), d, flag);
        for (std::size_t k = 0; k < valid; ++k) {
            if (flag[k] == T(0)) continue;
            const Vec3 o = kernel.reference({static_cast<double>(c0[k]), static_cast<double>(c1[k]),
                                             static_cast<double>(c2[k])});
            for (std::size_t c = 0; c < 3; ++c) dst[3 * k + c] = static_cast<float>(o[c]);
            ++handed;
        }
    };
    std::size_t i = 0;
    for (; i + n <= colours; i += n) vector(in + 3 * i, out + 3 * i, n);
    if (i < colours) {
        HWY_ALIGN float buffer[3 * max_lanes] = {};
        const std::size_t rest = colours - i;
        std::memcpy(buffer, in + 3 * i, 3 * rest * sizeof(float));
        vector(buffer, buffer, rest);
        std::memcpy(out + 3 * i, buffer, 3 * rest * sizeof(float));
    }
    return handed;
}

}  // namespace aces2_simd
}  // namespace HWY_NAMESPACE
}  // namespace irid
HWY_AFTER_NAMESPACE();

#endif  // IRID_GAMUT_ACES2_SIMD_INL_H_
