// Highway helpers shared by the SIMD kernels (included once per target by each batch_simd*.cpp
// after hwy/highway.h; the include guard toggles with HWY_TARGET_TOGGLE, as Highway's own -inl.h
// headers do).
//
// - FiniteOrDefault: the non-finite rule of clip.h (NaN → 0, ±Inf → ±1e30).
// - RunKernel: the loop every per-vector kernel shares (load, the rule, the body, store, the hard
//   lanes redone in double), and RedoHardLanes.
// - Mul3: a float 3×3 matrix (kernels.h, row-major) times a vector of colours.
// The cube root is the one of src/color/simd_math-inl.h (simd_math::Cbrt).
// - ToOklab / FromOklab: linear RGB of a gamut ↔ Oklab, through the clipper's LMS matrices and
//   Ottosson's M2 (in float).

#if defined(IRID_GAMUT_SIMD_COMMON_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef IRID_GAMUT_SIMD_COMMON_INL_H_
#undef IRID_GAMUT_SIMD_COMMON_INL_H_
#else
#define IRID_GAMUT_SIMD_COMMON_INL_H_
#endif

#include <hwy/highway.h>
#include <irid/color/spaces.h>

#include "../color/simd_math-inl.h"

#include "kernels.h"

#include <cstddef>

HWY_BEFORE_NAMESPACE();
namespace irid {
namespace HWY_NAMESPACE {
namespace simd {

namespace hn = hwy::HWY_NAMESPACE;
using Df = hn::ScalableTag<float>;
using Vf = hn::Vec<Df>;
using Mf = hn::Mask<Df>;

/// The non-finite rule of clip.h (finite_or_default: NaN → 0, ±Inf → ±1e30), in float or double.
template <class D, class V = hn::Vec<D>>
HWY_INLINE V FiniteOrDefault(D d, V v) {
    using T = hn::TFromD<D>;
    v = hn::IfThenZeroElse(hn::IsNaN(v), v);
    return hn::IfThenElse(hn::IsInf(v), hn::CopySign(hn::Set(d, static_cast<T>(1e30)), v), v);
}

/// The rule on three channels, skipped when they are all finite: v − v is 0 for a finite v and
/// NaN for NaN and ±Inf, and a sum with a NaN is NaN, so one comparison of
/// (r − r) + (g − g) + (b − b) with 0 tests the three channels (5 arithmetic operations, fewer
/// than three IsFinite on AVX2, where each is a few integer operations).
/// (One overload per precision rather than a template: the smits kernel measured 1.8 ns per
/// colour with the template against 1.1 ns with a plain function, g++ 12 -O3, AVX-512.)
HWY_INLINE void FiniteOrDefault(Df d, Vf& r, Vf& g, Vf& b) {
    const Vf sum = hn::Add(hn::Add(hn::Sub(r, r), hn::Sub(g, g)), hn::Sub(b, b));
    if (HWY_LIKELY(hn::AllTrue(d, hn::Eq(sum, hn::Zero(d))))) return;
    r = FiniteOrDefault(d, r);
    g = FiniteOrDefault(d, g);
    b = FiniteOrDefault(d, b);
}
using Dd = hn::ScalableTag<double>;
using Vd = hn::Vec<Dd>;
HWY_INLINE void FiniteOrDefault(Dd d, Vd& r, Vd& g, Vd& b) {
    const Vd sum = hn::Add(hn::Add(hn::Sub(r, r), hn::Sub(g, g)), hn::Sub(b, b));
    if (HWY_LIKELY(hn::AllTrue(d, hn::Eq(sum, hn::Zero(d))))) return;
    r = FiniteOrDefault(d, r);
    g = FiniteOrDefault(d, g);
    b = FiniteOrDefault(d, b);
}

/// The hard lanes of one vector of colours redone by the double reference: GamutClipper::clip of
/// each lane of the input (raw_r, raw_g, raw_b as loaded, before any rule) whose `hard` is set,
/// written over out + 3 (i + lane).
template <class D, class V = hn::Vec<D>, class M = hn::Mask<D>>
HWY_NOINLINE void RedoHardLanes(D d, M hard, const GamutClipper& clipper, V raw_r, V raw_g, V raw_b,
                                float* out, std::size_t i) {
    using T = hn::TFromD<D>;
    constexpr std::size_t max_lanes = HWY_MAX_BYTES / sizeof(T);
    HWY_ALIGN T cr[max_lanes], cg[max_lanes], cb[max_lanes], flag[max_lanes];
    hn::Store(raw_r, d, cr);
    hn::Store(raw_g, d, cg);
    hn::Store(raw_b, d, cb);
    hn::Store(hn::IfThenElseZero(hard, hn::Set(d, T(1))), d, flag);
    for (std::size_t k = 0; k < hn::Lanes(d); ++k) {
        if (flag[k] == T(0)) continue;
        const Rgb o = clipper.clip({static_cast<double>(cr[k]), static_cast<double>(cg[k]),
                                    static_cast<double>(cb[k])});
        out[3 * (i + k)] = static_cast<float>(o.r);
        out[3 * (i + k) + 1] = static_cast<float>(o.g);
        out[3 * (i + k) + 2] = static_cast<float>(o.b);
    }
}

/// The loop every per-vector kernel shares: load a vector of interleaved float colours (promoted
/// to double when D is double), the non-finite rule, `body(r, g, b, rr, gg, bb)` returning the
/// hard lanes, store rr, gg, bb (demoted to float), then the hard lanes redone by the double
/// reference. The input is kept in registers, so `in` may equal `out`. Returns how many colours
/// it did: the largest multiple of the vector length (kernels.h). aces-rgc's forward kernel is
/// the one that does not use it: it works on blocks of vectors, packing each channel's lanes
/// that need the curve, and redoes its hard lanes after the block (batch_simd_aces.cpp).
template <class D, class Body>
HWY_INLINE std::size_t RunKernel(D d, const GamutClipper& clipper, const float* in, float* out,
                                 std::size_t colours, const Body& body) {
    using V = hn::Vec<D>;
    const std::size_t n = hn::Lanes(d);
    std::size_t i = 0;
    for (; i + n <= colours; i += n) {
        V r0, g0, b0;
        if constexpr (sizeof(hn::TFromD<D>) == sizeof(float)) {
            hn::LoadInterleaved3(d, in + 3 * i, r0, g0, b0);
        } else {
            const hn::Rebind<float, D> df;
            hn::Vec<decltype(df)> rf, gf, bf;
            hn::LoadInterleaved3(df, in + 3 * i, rf, gf, bf);
            r0 = hn::PromoteTo(d, rf);
            g0 = hn::PromoteTo(d, gf);
            b0 = hn::PromoteTo(d, bf);
        }
        V r = r0, g = g0, b = b0;
        FiniteOrDefault(d, r, g, b);
        V rr, gg, bb;
        const auto hard = body(r, g, b, rr, gg, bb);
        if constexpr (sizeof(hn::TFromD<D>) == sizeof(float)) {
            hn::StoreInterleaved3(rr, gg, bb, d, out + 3 * i);
        } else {
            const hn::Rebind<float, D> df;
            hn::StoreInterleaved3(hn::DemoteTo(df, rr), hn::DemoteTo(df, gg), hn::DemoteTo(df, bb), df,
                                  out + 3 * i);
        }
        if (HWY_UNLIKELY(!hn::AllFalse(d, hard))) RedoHardLanes(d, hard, clipper, r0, g0, b0, out, i);
    }
    return i;
}

/// A float matrix broadcast into vectors once per kernel call.
struct MatV {
    Vf m[9];
};
HWY_INLINE MatV Broadcast(Df d, const detail::Mat3f& a) {
    MatV v;
    for (int k = 0; k < 9; ++k) v.m[k] = hn::Set(d, a.m[static_cast<std::size_t>(k)]);
    return v;
}

/// (o0, o1, o2) = M (x0, x1, x2).
HWY_INLINE void Mul3(const MatV& M, Vf x0, Vf x1, Vf x2, Vf& o0, Vf& o1, Vf& o2) {
    o0 = hn::MulAdd(M.m[2], x2, hn::MulAdd(M.m[1], x1, hn::Mul(M.m[0], x0)));
    o1 = hn::MulAdd(M.m[5], x2, hn::MulAdd(M.m[4], x1, hn::Mul(M.m[3], x0)));
    o2 = hn::MulAdd(M.m[8], x2, hn::MulAdd(M.m[7], x1, hn::Mul(M.m[6], x0)));
}

/// Oklab of linear RGB: LMS = rgb_to_lms · rgb, cube roots, then Ottosson's M2.
struct OklabMatrices {
    MatV to_lms, from_lms, m2, m2_inverse;
};
HWY_INLINE OklabMatrices LoadOklabMatrices(Df d, const GamutClipper& clipper) {
    return {Broadcast(d, detail::to_float(clipper.rgb_to_lms())),
            Broadcast(d, detail::to_float(clipper.lms_to_rgb())),
            Broadcast(d, detail::to_float(oklab_m2)),
            Broadcast(d, detail::to_float(oklab_m2_inverse))};
}
HWY_INLINE void ToOklab(Df d, const OklabMatrices& M, Vf r, Vf g, Vf b, Vf& L, Vf& A, Vf& B) {
    Vf l, m, s;
    Mul3(M.to_lms, r, g, b, l, m, s);
    Mul3(M.m2, simd_math::Cbrt(d, l), simd_math::Cbrt(d, m), simd_math::Cbrt(d, s), L, A, B);
}
HWY_INLINE void FromOklab(const OklabMatrices& M, Vf L, Vf A, Vf B, Vf& r, Vf& g, Vf& b) {
    Vf l, m, s;
    Mul3(M.m2_inverse, L, A, B, l, m, s);
    Mul3(M.from_lms, hn::Mul(hn::Mul(l, l), l), hn::Mul(hn::Mul(m, m), m), hn::Mul(hn::Mul(s, s), s),
         r, g, b);
}

}  // namespace simd
}  // namespace HWY_NAMESPACE
}  // namespace irid
HWY_AFTER_NAMESPACE();

#endif  // include guard
