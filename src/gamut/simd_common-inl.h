// Highway helpers shared by the SIMD kernels (included once per target by each batch_simd*.cpp
// after hwy/highway.h; the include guard toggles with HWY_TARGET_TOGGLE, as Highway's own -inl.h
// headers do).
//
// - finite_or_default: the non-finite rule of clip.h (NaN → 0, ±Inf → ±1e30).
// - Mul3: a float 3×3 matrix (kernels.h, row-major) times a vector of colours.
// - Cbrt: the real cube root, sign kept, to within 2 ulp of float over the normal range (an
//   initial guess from the exponent bits, refined by two Halley steps; tests/gamut/kernel_test).
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

#include "kernels.h"

HWY_BEFORE_NAMESPACE();
namespace irid {
namespace HWY_NAMESPACE {
namespace simd {

namespace hn = hwy::HWY_NAMESPACE;
using Df = hn::ScalableTag<float>;
using Vf = hn::Vec<Df>;
using Mf = hn::Mask<Df>;

HWY_INLINE Vf FiniteOrDefault(Df d, Vf v) {
    v = hn::IfThenZeroElse(hn::IsNaN(v), v);
    return hn::IfThenElse(hn::IsInf(v), hn::CopySign(hn::Set(d, 1e30f), v), v);
}

/// The rule on three channels, skipped (a few comparisons) when they are all finite.
HWY_INLINE void FiniteOrDefault(Df d, Vf& r, Vf& g, Vf& b) {
    if (HWY_LIKELY(
            hn::AllTrue(d, hn::And(hn::And(hn::IsFinite(r), hn::IsFinite(g)), hn::IsFinite(b))))) {
        return;
    }
    r = FiniteOrDefault(d, r);
    g = FiniteOrDefault(d, g);
    b = FiniteOrDefault(d, b);
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

/// The real cube root with the sign of x; 0 for ±0 (and for subnormal x, below 1.2e-38, whose
/// cube root 2.3e-13 matters to no colour). For |x| up to 1e37: above about 1.1e38 the Halley
/// step's 2y³ + |x| overflows and the result is wrong (callers send such lanes to the double
/// reference; inputs are at most 1e30 after the non-finite rule).
HWY_INLINE Vf Cbrt(Df d, Vf x) {
    const hn::RebindToSigned<Df> di;
    const Vf a = hn::Abs(x);
    // The bits of a float are nearly a scaled log2: a third of them, plus the bias times 2/3
    // (127 · 2^23 · 2/3 = 0x2A2AAAAB; 0x2A51_37A0 splits the error around 0), is within 7 % of
    // the root.
    const auto bits = hn::BitCast(di, a);
    const auto third = hn::ConvertTo(
        di, hn::Mul(hn::ConvertTo(d, bits), hn::Set(d, 1.0f / 3.0f)));
    Vf y = hn::BitCast(d, hn::Add(third, hn::Set(di, 709921077)));
    // Halley: y ← y (y³ + 2a)/(2y³ + a), cubic convergence (7 % → 1e-4 → float rounding).
    const Vf two = hn::Set(d, 2.0f);
    for (int it = 0; it < 2; ++it) {
        const Vf y3 = hn::Mul(hn::Mul(y, y), y);
        y = hn::Mul(y, hn::Div(hn::MulAdd(two, a, y3), hn::MulAdd(two, y3, a)));
    }
    y = hn::IfThenZeroElse(hn::Lt(a, hn::Set(d, 1.17549435e-38f)), y);
    return hn::CopySign(y, x);
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
    Mul3(M.m2, Cbrt(d, l), Cbrt(d, m), Cbrt(d, s), L, A, B);
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
