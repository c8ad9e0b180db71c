// The ACES 2.0 kernel's forward (include/irid/gamut/aces2_kernel.h): the display chain from
// ACES2065-1 to the display's CIE XYZ on vectors of colours, following the double reference
// (aces2_display.cpp, aces2.cpp, aces2_model.cpp) stage by stage, and its stages one at a time
// for OpenColorIO's stage vectors. Its arithmetic and the lanes it hands to the double path are
// in docs/KERNELS.md; what it shares with the inverse is aces2_simd-inl.h.

// clang-format off
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE __BASE_FILE__
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>
// clang-format on

#include "aces2_simd-inl.h"

HWY_BEFORE_NAMESPACE();
namespace irid {
namespace HWY_NAMESPACE {
namespace aces2_simd {

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

}  // namespace aces2_simd

namespace hn = hwy::HWY_NAMESPACE;

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
        aces2_simd::Stage(d, data.f, data.d, stage, in_float, x0, x1, x2);
        hn::StoreInterleaved3(x0, x1, x2, d, buffer);
        std::memcpy(out + 3 * i, buffer, 3 * count * sizeof(float));
    }
}

std::size_t Aces2ForwardRun(const Aces2Kernel& kernel, const detail::Aces2KernelData& data,
                            const float* in, float* out, std::size_t colours) {
    const hn::ScalableTag<float> df;
    return aces2_simd::Run(df, kernel, data.f, in, out, colours,
                           [&](auto d, const auto& p, auto& x0, auto& x1, auto& x2) {
                               return aces2_simd::Forward(d, p, data.d, x0, x1, x2);
                           });
}

}  // namespace HWY_NAMESPACE
}  // namespace irid
HWY_AFTER_NAMESPACE();

#if HWY_ONCE

namespace irid {

HWY_EXPORT(Aces2ForwardRun);
HWY_EXPORT(Aces2StageRun);

std::size_t detail::aces2_forward_run(const Aces2Kernel& kernel, const Aces2KernelData& data,
                                      const float* in, float* out, std::size_t colours) noexcept {
    return HWY_DYNAMIC_DISPATCH(Aces2ForwardRun)(kernel, data, in, out, colours);
}

void detail::aces2_stage_run(const Aces2KernelData& data, Aces2Kernel::Stage stage, bool in_float,
                             const float* in, float* out, std::size_t colours) noexcept {
    HWY_DYNAMIC_DISPATCH(Aces2StageRun)(data, stage, in_float, in, out, colours);
}

}  // namespace irid

#endif  // HWY_ONCE
