// The ACES 2.0 kernel's inverse (include/irid/gamut/aces2_kernel.h): the display's CIE XYZ back
// to ACES2065-1 on vectors of colours, in double throughout (docs/KERNELS.md), following
// Aces2Output::inverse; what it shares with the forward is aces2_simd-inl.h.

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

}  // namespace aces2_simd

namespace hn = hwy::HWY_NAMESPACE;

std::size_t Aces2InverseRun(const Aces2Kernel& kernel, const detail::Aces2KernelData& data,
                            const float* in, float* out, std::size_t colours) {
    const hn::ScalableTag<double> dd;
    return aces2_simd::Run(dd, kernel, data.d, in, out, colours,
                           [](auto d, const auto& p, auto& x0, auto& x1, auto& x2) {
                               return aces2_simd::Inverse(d, p, x0, x1, x2);
                           });
}

}  // namespace HWY_NAMESPACE
}  // namespace irid
HWY_AFTER_NAMESPACE();

#if HWY_ONCE

namespace irid {

HWY_EXPORT(Aces2InverseRun);

std::size_t detail::aces2_inverse_run(const Aces2Kernel& kernel, const Aces2KernelData& data,
                                      const float* in, float* out, std::size_t colours) noexcept {
    return HWY_DYNAMIC_DISPATCH(Aces2InverseRun)(kernel, data, in, out, colours);
}

}  // namespace irid

#endif  // HWY_ONCE
