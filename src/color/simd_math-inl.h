// The SIMD maths irid's Highway kernels share (the colour conversions of convert_simd.cpp and the
// gamut kernels of src/gamut): one cube root, in float and in double. Included once per target
// after hwy/highway.h, by files compiled through foreach_target.h (the include guard toggles with
// HWY_TARGET_TOGGLE, as Highway's own -inl.h headers do). tests/color/simd_math_test.cpp checks
// it on every target this machine has against std::cbrt.
//
// The cube root: a start within 7 % from the bits of the float nearest |x| (the bits of a
// positive float are nearly a scaled log2: a third of them plus 0x2A5137A0, which is 127 · 2^23 ·
// 2/3 shifted to split the error around 0), then Halley steps y ← y (y³ + 2a)/(2y³ + a), whose
// relative error goes 7 % → 3e-4 → 3e-11 → rounding (cubic convergence): two steps in float,
// three in double.

#if defined(IRID_COLOR_SIMD_MATH_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef IRID_COLOR_SIMD_MATH_INL_H_
#undef IRID_COLOR_SIMD_MATH_INL_H_
#else
#define IRID_COLOR_SIMD_MATH_INL_H_
#endif

#include <hwy/highway.h>

HWY_BEFORE_NAMESPACE();
namespace irid {
namespace HWY_NAMESPACE {
namespace simd_math {

namespace hn = hwy::HWY_NAMESPACE;

/// The smallest normal float: below it the start from float bits is meaningless.
inline constexpr float smallest_normal_float = 1.17549435e-38f;

/// The start of the cube root of a = |x| (a float vector), within 7 % for a in float's normal
/// range.
template <class DF, class VF = hn::Vec<DF>>
HWY_INLINE VF CbrtStart(DF df, VF a) {
    const hn::RebindToSigned<DF> di;
    const auto third =
        hn::ConvertTo(di, hn::Mul(hn::ConvertTo(df, hn::BitCast(di, a)), hn::Set(df, 1.0f / 3.0f)));
    return hn::BitCast(df, hn::Add(third, hn::Set(di, 709921077)));
}

/// The real cube root with the sign of x, 0 for |x| below the smallest normal float (whose cube
/// root, 2.3e-13, matters to no colour). Float: within 3 ulp for |x| up to 1e37 (above about
/// 1.1e38 the step's 2y³ + |x| overflows). Double: within 3 ulp for |x| in float's normal
/// range (the start comes from the nearest float).
template <class D, class V = hn::Vec<D>>
HWY_INLINE V Cbrt(D d, V x) {
    using T = hn::TFromD<D>;
    const V a = hn::Abs(x);
    V y;
    if constexpr (sizeof(T) == sizeof(float)) {
        y = CbrtStart(d, a);
    } else {
        const hn::Rebind<float, D> df;
        y = hn::PromoteTo(d, CbrtStart(df, hn::DemoteTo(df, a)));
    }
    constexpr int steps = sizeof(T) == sizeof(float) ? 2 : 3;
    const V two = hn::Set(d, T(2));
    for (int it = 0; it < steps; ++it) {
        const V y3 = hn::Mul(hn::Mul(y, y), y);
        y = hn::Mul(y, hn::Div(hn::MulAdd(two, a, y3), hn::MulAdd(two, y3, a)));
    }
    y = hn::IfThenZeroElse(hn::Lt(a, hn::Set(d, static_cast<T>(smallest_normal_float))), y);
    return hn::CopySign(y, x);
}

}  // namespace simd_math
}  // namespace HWY_NAMESPACE
}  // namespace irid
HWY_AFTER_NAMESPACE();

#endif  // include guard
