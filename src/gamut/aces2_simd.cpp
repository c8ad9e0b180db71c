// The Highway kernel of Aces2Kernel (include/irid/gamut/aces2_kernel.h): the ACES 2.0 display
// chain on vectors of colours, following the double reference (aces2_display.cpp, aces2.cpp,
// aces2_model.cpp) stage by stage. Its arithmetic and the lanes it hands to the double path
// are in docs/KERNELS.md.

// clang-format off
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE __BASE_FILE__
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>
#include <hwy/contrib/math/math-inl.h>
// clang-format on

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
namespace {

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

/// The tonescale (Aces2Rendering::tonescale_forward) of the achromatic response A > 0, as the
/// tonescaled A and J; `flag` is 1 where the inverse response was beyond its limit.
template <class D, class V = hn::Vec<D>>
HWY_INLINE void Tonescale(D d, const Params<D>& p, V A, V& a_ts, V& j_ts, V& flag) {
    hn::Mask<D> hard = hn::FirstN(d, 0);
    const V y =
        ResponseInverse(d, p,
                        hn::Mul(hn::Max(A, hn::Set(d, std::numeric_limits<hn::TFromD<D>>::min())),
                                hn::Set(d, p.a_w_j)),
                        hard);
    const V f = hn::Mul(hn::Set(d, p.m_2),
                        Pow(d, hn::Div(y, hn::Add(y, hn::Set(d, p.s_2))), hn::Set(d, p.g)));
    const V y_ts =
        hn::Mul(hn::Max(hn::Zero(d), hn::Div(hn::Mul(f, f), hn::Add(f, hn::Set(d, p.t_1)))),
                C(d, aces2::reference_luminance));
    a_ts = hn::Div(Response(d, p, y_ts), hn::Set(d, p.a_w_j));
    j_ts = hn::Mul(C(d, aces2::j_scale), Pow(d, a_ts, hn::Set(d, p.cz)));
    flag = hn::IfThenElseZero(hard, C(d, 1.0));
}

/// fn computed in double on float vectors: the lanes of `in` promoted in pieces of a double
/// vector, fn(dd, inputs) giving N outputs, each demoted back. Through memory, so the same on
/// every target (Highway's halves and Combine do not exist on its scalar one).
template <std::size_t N, class D, std::size_t K, class Fn, class V = hn::Vec<D>>
HWY_INLINE std::array<V, N> InDouble(D d, const std::array<V, K>& in, const Fn& fn) {
    const hn::ScalableTag<double> dd;
    const hn::Rebind<float, decltype(dd)> df;
    constexpr std::size_t lanes = HWY_MAX_BYTES / sizeof(float);
    HWY_ALIGN float buf[K + N][lanes];
    for (std::size_t k = 0; k < K; ++k) hn::Store(in[k], d, buf[k]);
    for (std::size_t i = 0; i < hn::Lanes(d); i += hn::Lanes(dd)) {
        std::array<hn::Vec<decltype(dd)>, K> x;
        for (std::size_t k = 0; k < K; ++k) x[k] = hn::PromoteTo(dd, hn::LoadU(df, buf[k] + i));
        const auto y = fn(dd, x);
        for (std::size_t n = 0; n < N; ++n) hn::StoreU(hn::DemoteTo(df, y[n]), df, buf[K + n] + i);
    }
    std::array<V, N> out;
    for (std::size_t n = 0; n < N; ++n) out[n] = hn::Load(d, buf[K + n]);
    return out;
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

/// (1 + t)^0.42 − 1 for |t| <= response_series_reach: its binomial series to degree 7, whose
/// first dropped term is below 2e-8 of the sum there.
constexpr std::array<double, 8> response_binomials() {
    std::array<double, 8> b{};  // binomial(0.42, n), n = 0..7
    b[0] = 1.0;
    for (std::size_t n = 1; n < b.size(); ++n)
        b[n] = b[n - 1] * (response_exponent - static_cast<double>(n - 1)) / static_cast<double>(n);
    return b;
}

template <class D, class V = hn::Vec<D>>
HWY_INLINE V ResponseSeries(D d, V t) {
    constexpr auto binomial = response_binomials();
    V c = C(d, binomial[7]);
    for (std::size_t n = 6; n >= 1; --n) c = hn::MulAdd(c, t, C(d, binomial[n]));
    return hn::Mul(c, t);
}

/// Response(c0) − Response(c1) from c, their ResponsePower f and responses r, without the
/// cancellation of r0 − r1: where c0 and c1 are positive and |c0 / c1 − 1| <=
/// response_series_reach, S O (f0 − f1) / ((O + f0)(O + f1)) with f0 − f1 = f1 ((c0 / c1)^0.42 −
/// 1) by ResponseSeries, exact to the rounding of c0 − c1; elsewhere r0 − r1 loses at most a
/// factor of about 20 of the responses' rounding.
template <class D, class V = hn::Vec<D>>
HWY_INLINE V ResponseDifference(D d, V c0, V c1, V f0, V f1, V r0, V r1) {
    const V zero = hn::Zero(d);
    const V t = hn::Div(hn::Sub(c0, c1), hn::IfThenElse(hn::Gt(c1, zero), c1, C(d, 1.0)));
    const auto near = hn::And(hn::And(hn::Gt(c0, zero), hn::Gt(c1, zero)),
                              hn::Le(hn::Abs(t), C(d, response_series_reach)));
    const V df = hn::Mul(f1, ResponseSeries(d, hn::IfThenElseZero(near, t)));
    const V offset = C(d, response_offset);
    const V exact = hn::Div(hn::Mul(C(d, response_scale * response_offset), df),
                            hn::Mul(hn::Add(offset, f0), hn::Add(offset, f1)));
    return hn::IfThenElse(near, exact, hn::Sub(r0, r1));
}

/// The model's A, a, b of cone signals c in float: A from the responses, and a and b from their
/// differences (the opponent matrix's a and b rows sum to 0, Aces2JmhModel), each by
/// ResponseDifference. a and b cancel for all but the most saturated colours: subtracting the
/// float responses put M off by up to 7e-4 and its hue by 0.02°, which moved outputs by up to
/// 2.6e-5.
template <class D, class V = hn::Vec<D>>
HWY_INLINE void AabOfCones(D d, const Params<D>& p, V c0, V c1, V c2, V& A, V& a, V& b) {
    const V f0 = ResponsePower(d, p, c0), f1 = ResponsePower(d, p, c1),
            f2 = ResponsePower(d, p, c2);
    const V r0 = ResponseOfPower(d, c0, f0), r1 = ResponseOfPower(d, c1, f1),
            r2 = ResponseOfPower(d, c2, f2);
    const auto& m = p.to_aab;
    A = hn::MulAdd(hn::Set(d, m[2]), r2,
                   hn::MulAdd(hn::Set(d, m[1]), r1, hn::Mul(hn::Set(d, m[0]), r0)));
    const V d01 = ResponseDifference(d, c0, c1, f0, f1, r0, r1);
    const V d21 = ResponseDifference(d, c2, c1, f2, f1, r2, r1);
    a = hn::MulAdd(hn::Set(d, m[5]), d21, hn::Mul(hn::Set(d, m[3]), d01));
    b = hn::MulAdd(hn::Set(d, m[8]), d21, hn::Mul(hn::Set(d, m[6]), d01));
}

/// AabOfCones of the input (InClamped).
template <class D, class V = hn::Vec<D>>
HWY_INLINE void AabFloat(D d, const Params<D>& p, V x0, V x1, V x2, V& A, V& a, V& b) {
    V r, g, bl, c0, c1, c2;
    InClamped(d, p, x0, x1, x2, r, g, bl);
    Mul3(d, p.to_cone, r, g, bl, c0, c1, c2);
    AabOfCones(d, p, c0, c1, c2, A, a, b);
}

/// Aab and the Tonescale of A: when D is float and not precise, AabFloat; when precise, both in
/// double.
template <class D, class V = hn::Vec<D>>
HWY_INLINE void ToAab(D d, const Params<D>& p, const detail::Aces2Params<double>& pd, V x0, V x1,
                      V x2, V& A, V& a, V& bb, V& a_ts, V& j_ts, V& flag) {
    if constexpr (sizeof(hn::TFromD<D>) == 8) {
        (void)pd;
        Aab(d, p, x0, x1, x2, A, a, bb);
        Tonescale(d, p, A, a_ts, j_ts, flag);
    } else if (!p.precise) {
        AabFloat(d, p, x0, x1, x2, A, a, bb);
        Tonescale(d, p, A, a_ts, j_ts, flag);
    } else {
        const auto o = InDouble<6>(d, std::array<V, 3>{x0, x1, x2}, [&](auto dd, const auto& x) {
            std::array<hn::Vec<decltype(dd)>, 6> y;
            Aab(dd, pd, x[0], x[1], x[2], y[0], y[1], y[2]);
            Tonescale(dd, pd, y[0], y[3], y[4], y[5]);
            return y;
        });
        A = o[0], a = o[1], bb = o[2];
        a_ts = o[3], j_ts = o[4], flag = o[5];
    }
}

/// JMh (cos h, sin h) to RGB through the `to` model, clamped to [0, out_max], then the output
/// matrix; returns the lanes whose inverse response was beyond its limit.
template <class D, class V = hn::Vec<D>>
HWY_INLINE hn::Mask<D> OutputStage(D d, const Params<D>& p, V j, V m, V cos_h, V sin_h, V& x0,
                                   V& x1, V& x2) {
    hn::Mask<D> hard = hn::FirstN(d, 0);
    const V a_out = Pow(d, hn::Mul(j, C(d, 1.0 / aces2::j_scale)), hn::Set(d, p.cz_inv));
    V r0, r1, r2, r, g, b;
    Mul3(d, p.from_aab, a_out, hn::Mul(m, cos_h), hn::Mul(m, sin_h), r0, r1, r2);
    Mul3(d, p.from_cone, ResponseInverse(d, p, r0, hard), ResponseInverse(d, p, r1, hard),
         ResponseInverse(d, p, r2, hard), r, g, b);
    hard = hn::Or(hard, NotFinite(d, r, g, b));  // before the clamp, which would hide a NaN
    const V zero = hn::Zero(d), out_max = hn::Set(d, p.out_max);
    Mul3(d, p.out, hn::Min(hn::Max(r, zero), out_max), hn::Min(hn::Max(g, zero), out_max),
         hn::Min(hn::Max(b, zero), out_max), x0, x1, x2);
    return hard;
}

/// The forward from the model's JMh on: chroma compression, gamut compression and OutputStage;
/// returns the lanes for the double path.
template <class D, class V = hn::Vec<D>>
HWY_INLINE hn::Mask<D> ForwardFromJmh(D d, const Params<D>& p, V A, V M_, V h, V cos_h, V sin_h,
                                      V a_ts, V j_ts, V& x0, V& x1, V& x2) {
    hn::Mask<D> hard = hn::FirstN(d, 0);
    const HueValues<V> hv = AtHue(d, p, h);
    const V norm = Norm(d, p, cos_h, sin_h);
    const V nj = hn::Div(j_ts, hn::Set(d, p.limit_j));
    const V m = ChromaCompress(d, p, M_, nj, hn::Div(a_ts, hn::Set(d, p.limit_a)), hn::Div(a_ts, A),
                               norm, hv.reach, false);
    hard = hn::Or(hard, NotFinite(d, m));
    V j_out, m_out;
    Compress(d, p, hv, j_ts, hn::IfThenZeroElse(hn::Eq(M_, hn::Zero(d)), m), j_ts, false, j_out,
             m_out, hard);
    return hn::Or(hard, OutputStage(d, p, j_out, m_out, cos_h, sin_h, x0, x1, x2));
}

/// One vector of the forward chain, in place on (x0, x1, x2) (finite); returns the lanes for the
/// double path.
template <class D, class V = hn::Vec<D>, class M = hn::Mask<D>>
HWY_INLINE M Forward(D d, const Params<D>& p, const detail::Aces2Params<double>& pd, V& x0, V& x1,
                     V& x2) {
    using T = hn::TFromD<D>;
    const V zero = hn::Zero(d), tiny = hn::Set(d, std::numeric_limits<T>::min());
    M hard = hn::Gt(hn::Max(hn::Max(hn::Abs(x0), hn::Abs(x1)), hn::Abs(x2)), C(d, large_input));
    // ACES2065-1 to AP1, clamped, and to the cone responses of the input (AP0) model.
    V A, a, bb, a_ts, j_ts, flag;
    ToAab(d, p, pd, x0, x1, x2, A, a, bb, a_ts, j_ts, flag);
    hard = hn::Or(hard, hn::Or(hn::Gt(flag, zero), NotFinite(d, A, a, bb, a_ts, j_ts)));
    const M black = hn::Le(A, zero);
    A = hn::Max(A, tiny);
    const auto [M_, h, cos_h, sin_h] = ToPolar(d, a, bb);
    // The rest, in double when precise: near the peak's J the gamut compression subtracts J from
    // limit_j (the focus gain, the upper hull), and the output's luminance grows as J^2.7 through
    // matrices that cancel, which turned float's rounding into errors of 1.3e-5 at 1000 cd/m².
    if (sizeof(T) == 8 || !p.precise) {
        hard = hn::Or(hard, ForwardFromJmh(d, p, A, M_, h, cos_h, sin_h, a_ts, j_ts, x0, x1, x2));
    } else {
        const auto o = InDouble<4>(
            d, std::array<V, 7>{A, M_, h, cos_h, sin_h, a_ts, j_ts}, [&](auto dd, const auto& x) {
                std::array<hn::Vec<decltype(dd)>, 4> y;
                const auto hard_d = ForwardFromJmh(dd, pd, x[0], x[1], x[2], x[3], x[4], x[5], x[6],
                                                   y[0], y[1], y[2]);
                y[3] = hn::IfThenElseZero(hard_d, C(dd, 1.0));
                return y;
            });
        x0 = o[0], x1 = o[1], x2 = o[2];
        hard = hn::Or(hard, hn::Gt(o[3], zero));
    }
    x0 = hn::IfThenZeroElse(black, x0);
    x1 = hn::IfThenZeroElse(black, x1);
    x2 = hn::IfThenZeroElse(black, x2);
    return hard;
}

/// One vector of the inverse chain (Aces2Output::inverse), as Forward.
template <class D, class V = hn::Vec<D>, class M = hn::Mask<D>>
HWY_INLINE M Inverse(D d, const Params<D>& p, V& x0, V& x1, V& x2) {
    using T = hn::TFromD<D>;
    const V zero = hn::Zero(d), tiny = hn::Set(d, std::numeric_limits<T>::min());
    M hard = hn::Gt(hn::Max(hn::Max(hn::Abs(x0), hn::Abs(x1)), hn::Abs(x2)), C(d, large_input));
    V r, g, b, A, a, bb;
    Aab(d, p, x0, x1, x2, A, a, bb);
    const M black = hn::Le(A, zero);
    A = hn::Max(A, tiny);
    const V j = hn::Mul(C(d, aces2::j_scale), Pow(d, A, hn::Set(d, p.cz)));
    const auto [M_, h, cos_h, sin_h] = ToPolar(d, a, bb);
    // Gamut compression inverse: the focus gain's J solved by the reference's fixed point
    // (Aces2Rendering::gamut_compress_inverse), each lane frozen at its own convergence so that
    // its result does not depend on its neighbours.
    const HueValues<V> hv = AtHue(d, p, h);
    V jx = j, j_c, m_c;
    M done = hn::Not(hn::Eq(zero, zero));
    for (int k = 0; k < aces2_inverse_focus_iterations; ++k) {
        Compress(d, p, hv, j, M_, jx, true, j_c, m_c, hard);
        const V tol = hn::Mul(C(d, 1e-13), hn::Max(C(d, 1.0), hn::Abs(jx)));
        const M small = hn::Le(hn::Abs(hn::Sub(j_c, jx)), tol);
        jx = hn::IfThenElse(done, jx, j_c);
        done = hn::Or(done, small);
        if (hn::AllTrue(d, done)) break;
    }
    Compress(d, p, hv, j, M_, jx, true, j_c, m_c, hard);
    // Tonescale inverse (Aces2Rendering::tonescale_inverse).
    const V a_c =
        hn::Max(Pow(d, hn::Mul(j_c, C(d, 1.0 / aces2::j_scale)), hn::Set(d, p.cz_inv)), tiny);
    const V y_ts = ResponseInverse(d, p, hn::Mul(a_c, hn::Set(d, p.a_w_j)), hard);
    const V z = hn::Min(hn::Max(hn::Mul(y_ts, C(d, 1.0 / aces2::reference_luminance)), zero),
                        hn::Set(d, p.inverse_limit));
    const V f = hn::Mul(
        C(d, 0.5), hn::Add(z, hn::Sqrt(hn::Mul(z, hn::MulAdd(C(d, 4.0), hn::Set(d, p.t_1), z)))));
    const V den = hn::Sub(Pow(d, hn::Div(hn::Set(d, p.m_2), hn::Max(f, tiny)), hn::Set(d, p.g_inv)),
                          C(d, 1.0));
    const V y = hn::Div(hn::Set(d, p.s_2), den);
    const V a_src = hn::Div(Response(d, p, y), hn::Set(d, p.a_w_j));
    // Chroma compression inverse.
    const V norm = Norm(d, p, cos_h, sin_h);
    const V nj = hn::Div(j_c, hn::Set(d, p.limit_j));
    V m = ChromaCompress(d, p, m_c, nj, hn::Div(a_c, hn::Set(d, p.limit_a)), hn::Div(a_src, a_c),
                         norm, hv.reach, true);
    m = hn::IfThenZeroElse(hn::Or(hn::Eq(M_, zero), hn::Eq(m_c, zero)), m);
    // To AP0 through the input model, to AP1, clamped, and to the output.
    V r0, r1, r2;
    Mul3(d, p.from_aab, a_src, hn::Mul(m, cos_h), hn::Mul(m, sin_h), r0, r1, r2);
    Mul3(d, p.from_cone, ResponseInverse(d, p, r0, hard), ResponseInverse(d, p, r1, hard),
         ResponseInverse(d, p, r2, hard), r, g, b);
    hard = hn::Or(hard, hn::AndNot(black, NotFinite(d, r, g, b)));
    const V out_max = hn::Set(d, p.out_max);
    r = hn::IfThenZeroElse(black, hn::Min(hn::Max(r, zero), out_max));
    g = hn::IfThenZeroElse(black, hn::Min(hn::Max(g, zero), out_max));
    b = hn::IfThenZeroElse(black, hn::Min(hn::Max(b, zero), out_max));
    Mul3(d, p.out, r, g, b, x0, x1, x2);
    return hard;
}

/// The forward's stage `stage` (Aces2Kernel::run_stage) on one vector, in place on
/// (x0, x1, x2), in the precision of D; for rgb_to_jmh, only A, a and b.
template <class D, class V = hn::Vec<D>>
HWY_INLINE void StageIn(D d, const Params<D>& p, Aces2Kernel::Stage stage, V& x0, V& x1, V& x2) {
    using T = hn::TFromD<D>;
    const V zero = hn::Zero(d);
    switch (stage) {
        case Aces2Kernel::Stage::rgb_to_jmh: {
            // As Aab and AabFloat, without InClamped's clamp: the stage is the model alone.
            V r, g, b, c0, c1, c2;
            Mul3(d, p.in, x0, x1, x2, r, g, b);
            Mul3(d, p.to_cone, r, g, b, c0, c1, c2);
            if constexpr (sizeof(T) == 4) {
                AabOfCones(d, p, c0, c1, c2, x0, x1, x2);
            } else {
                Mul3(d, p.to_aab, Response(d, p, c0), Response(d, p, c1), Response(d, p, c2), x0,
                     x1, x2);
            }
            return;
        }
        case Aces2Kernel::Stage::tonescale_and_chroma: {
            const V j = x0, m_in = x1, h = x2;
            const V A = Pow(d,
                            hn::Max(hn::Mul(j, C(d, 1.0 / aces2::j_scale)),
                                    hn::Set(d, std::numeric_limits<T>::min())),
                            hn::Set(d, p.cz_inv));
            V a_ts, j_ts, flag;
            Tonescale(d, p, A, a_ts, j_ts, flag);
            const V radians = hn::Mul(h, C(d, std::numbers::pi / 180.0));
            const V norm = Norm(d, p, hn::Cos(d, radians), hn::Sin(d, radians));
            const V m = ChromaCompress(d, p, m_in, hn::Div(j_ts, hn::Set(d, p.limit_j)),
                                       hn::Div(a_ts, hn::Set(d, p.limit_a)), hn::Div(a_ts, A), norm,
                                       AtHue(d, p, h).reach, false);
            x0 = j_ts;
            x1 = hn::IfThenZeroElse(hn::Eq(m_in, zero), m);
            return;
        }
        case Aces2Kernel::Stage::gamut_compression: {
            hn::Mask<D> hard = hn::FirstN(d, 0);
            V j_out, m_out;
            Compress(d, p, AtHue(d, p, x2), x0, x1, x0, false, j_out, m_out, hard);
            x0 = j_out;
            x1 = m_out;
            return;
        }
    }
}

/// One vector of a stage as Forward computes it: in double what Forward takes in double (every
/// stage when precise), unless in_float.
template <class D, class V = hn::Vec<D>>
HWY_INLINE void Stage(D d, const Params<D>& p, const detail::Aces2Params<double>& pd,
                      Aces2Kernel::Stage stage, bool in_float, V& x0, V& x1, V& x2) {
    const bool rgb = stage == Aces2Kernel::Stage::rgb_to_jmh;
    if (in_float || !p.precise) {
        StageIn(d, p, stage, x0, x1, x2);
    } else {
        const auto o = InDouble<3>(d, std::array<V, 3>{x0, x1, x2}, [&](auto dd, const auto& x) {
            auto y = x;
            StageIn(dd, pd, stage, y[0], y[1], y[2]);
            return y;
        });
        x0 = o[0], x1 = o[1], x2 = o[2];
    }
    if (!rgb) return;
    // A, a, b to J, M, h as Forward takes them (Aces2JmhModel::aab_to_jmh: 0 where A <= 0).
    const auto [m, h, cos_h, sin_h] = ToPolar(d, x1, x2);
    const auto black = hn::Le(x0, hn::Zero(d));
    x0 = hn::IfThenZeroElse(black, hn::Mul(C(d, aces2::j_scale), Pow(d, x0, hn::Set(d, p.cz))));
    x1 = hn::IfThenZeroElse(black, m);
    x2 = hn::IfThenZeroElse(black, h);
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

}  // namespace

void Aces2StageRun(const detail::Aces2KernelData& data, Aces2Kernel::Stage stage, bool in_float,
                   const float* in, float* out, std::size_t colours) {
    const hn::ScalableTag<float> d;
    const std::size_t n = hn::Lanes(d);
    HWY_ALIGN float buffer[3 * HWY_MAX_BYTES / sizeof(float)] = {};
    for (std::size_t i = 0; i < colours; i += n) {
        const std::size_t count = std::min(n, colours - i);
        std::memcpy(buffer, in + 3 * i, 3 * count * sizeof(float));
        hn::Vec<decltype(d)> x0, x1, x2;
        hn::LoadInterleaved3(d, buffer, x0, x1, x2);
        Stage(d, data.f, data.d, stage, in_float, x0, x1, x2);
        hn::StoreInterleaved3(x0, x1, x2, d, buffer);
        std::memcpy(out + 3 * i, buffer, 3 * count * sizeof(float));
    }
}

std::size_t Aces2Run(const Aces2Kernel& kernel, const detail::Aces2KernelData& data,
                     const float* in, float* out, std::size_t colours) {
    const hn::ScalableTag<float> df;
    const hn::ScalableTag<double> dd;
    if (!kernel.inverse()) {
        return Run(df, kernel, data.f, in, out, colours,
                   [&](auto d, const auto& p, auto& x0, auto& x1, auto& x2) {
                       return Forward(d, p, data.d, x0, x1, x2);
                   });
    }
    return Run(dd, kernel, data.d, in, out, colours,
               [](auto d, const auto& p, auto& x0, auto& x1, auto& x2) {
                   return Inverse(d, p, x0, x1, x2);
               });
}

}  // namespace HWY_NAMESPACE
}  // namespace irid
HWY_AFTER_NAMESPACE();

#if HWY_ONCE

namespace irid {

HWY_EXPORT(Aces2Run);
HWY_EXPORT(Aces2StageRun);

std::size_t detail::aces2_run(const Aces2Kernel& kernel, const Aces2KernelData& data,
                              const float* in, float* out, std::size_t colours) noexcept {
    return HWY_DYNAMIC_DISPATCH(Aces2Run)(kernel, data, in, out, colours);
}

void detail::aces2_stage_run(const Aces2KernelData& data, Aces2Kernel::Stage stage, bool in_float,
                             const float* in, float* out, std::size_t colours) noexcept {
    HWY_DYNAMIC_DISPATCH(Aces2StageRun)(data, stage, in_float, in, out, colours);
}

}  // namespace irid

#endif  // HWY_ONCE
