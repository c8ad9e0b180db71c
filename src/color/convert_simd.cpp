// Linear RGB or XYZ → Oklab on every lane (Google Highway, dynamic dispatch as in
// src/gamut/batch_simd.cpp): the cube root is what makes the conversion slow (std::cbrt, about
// 15 ns), and a SIMD one makes it cheap.
//
// The cube root is simd_math::Cbrt (simd_math-inl.h) in double. Its start comes from the nearest
// float, so it needs |x| within float's normal range: a block with any other value (0 aside),
// or a NaN or infinity, takes the scalar path.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE __BASE_FILE__
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "convert_simd.h"
#include "simd_math-inl.h"

#include <cmath>
#include <cstddef>

HWY_BEFORE_NAMESPACE();
namespace irid {
namespace HWY_NAMESPACE {
namespace {

namespace hn = hwy::HWY_NAMESPACE;
using D = hn::ScalableTag<double>;
using V = hn::Vec<D>;
using Df = hn::Rebind<float, D>;

/// Whether every lane is 0 or of magnitude in [1e-30, 1e30] (false for NaN and infinity).
HWY_INLINE bool InRange(D d, V x) {
    const V a = hn::Abs(x);
    const auto ok = hn::Or(hn::And(hn::Ge(a, hn::Set(d, 1e-30)), hn::Le(a, hn::Set(d, 1e30))),
                           hn::Eq(a, hn::Zero(d)));
    return hn::AllTrue(d, ok);
}

HWY_INLINE void Mul3(D d, const double* m, V x, V y, V z, V& a, V& b, V& c) {
    a = hn::MulAdd(hn::Set(d, m[0]), x, hn::MulAdd(hn::Set(d, m[1]), y, hn::Mul(hn::Set(d, m[2]), z)));
    b = hn::MulAdd(hn::Set(d, m[3]), x, hn::MulAdd(hn::Set(d, m[4]), y, hn::Mul(hn::Set(d, m[5]), z)));
    c = hn::MulAdd(hn::Set(d, m[6]), x, hn::MulAdd(hn::Set(d, m[7]), y, hn::Mul(hn::Set(d, m[8]), z)));
}

template <class T>
void Scalar(const T* in, T* out, std::size_t b, std::size_t e, const double* m1, const double* m2) {
    for (std::size_t i = b; i < e; ++i) {
        const double x = static_cast<double>(in[3 * i]), y = static_cast<double>(in[3 * i + 1]),
                     z = static_cast<double>(in[3 * i + 2]);
        const double l = std::cbrt(m1[0] * x + m1[1] * y + m1[2] * z);
        const double m = std::cbrt(m1[3] * x + m1[4] * y + m1[5] * z);
        const double s = std::cbrt(m1[6] * x + m1[7] * y + m1[8] * z);
        out[3 * i] = static_cast<T>(m2[0] * l + m2[1] * m + m2[2] * s);
        out[3 * i + 1] = static_cast<T>(m2[3] * l + m2[4] * m + m2[5] * s);
        out[3 * i + 2] = static_cast<T>(m2[6] * l + m2[7] * m + m2[8] * s);
    }
}

template <class T>
void Kernel(const T* in, T* out, std::size_t n, const double* m1, const double* m2) {
    const D d;
    const std::size_t lanes = hn::Lanes(d);
    std::size_t i = 0;
    for (; i + lanes <= n; i += lanes) {
        V x, y, z;
        if constexpr (sizeof(T) == 8) {
            hn::LoadInterleaved3(d, in + 3 * i, x, y, z);
        } else {
            const Df df;
            hn::Vec<Df> xf, yf, zf;
            hn::LoadInterleaved3(df, in + 3 * i, xf, yf, zf);
            x = hn::PromoteTo(d, xf), y = hn::PromoteTo(d, yf), z = hn::PromoteTo(d, zf);
        }
        V l, m, s;
        Mul3(d, m1, x, y, z, l, m, s);
        if (HWY_UNLIKELY(!(InRange(d, l) && InRange(d, m) && InRange(d, s)))) {
            Scalar(in, out, i, i + lanes, m1, m2);
            continue;
        }
        V L, A, B;
        Mul3(d, m2, simd_math::Cbrt(d, l), simd_math::Cbrt(d, m), simd_math::Cbrt(d, s), L, A, B);
        if constexpr (sizeof(T) == 8) {
            hn::StoreInterleaved3(L, A, B, d, out + 3 * i);
        } else {
            const Df df;
            hn::StoreInterleaved3(hn::DemoteTo(df, L), hn::DemoteTo(df, A), hn::DemoteTo(df, B), df, out + 3 * i);
        }
    }
    Scalar(in, out, i, n, m1, m2);
}

void ToOklabDouble(const double* in, double* out, std::size_t n, const double* m1, const double* m2) {
    Kernel(in, out, n, m1, m2);
}
void ToOklabFloat(const float* in, float* out, std::size_t n, const double* m1, const double* m2) {
    Kernel(in, out, n, m1, m2);
}

}  // namespace
}  // namespace HWY_NAMESPACE
}  // namespace irid
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace irid {
HWY_EXPORT(ToOklabDouble);
HWY_EXPORT(ToOklabFloat);

namespace detail {

void linear_to_oklab_simd(const double* in, double* out, std::size_t n, const double* to_lms,
                          const double* m2) noexcept {
    HWY_DYNAMIC_DISPATCH(ToOklabDouble)(in, out, n, to_lms, m2);
}

void linear_to_oklab_simd(const float* in, float* out, std::size_t n, const double* to_lms,
                          const double* m2) noexcept {
    HWY_DYNAMIC_DISPATCH(ToOklabFloat)(in, out, n, to_lms, m2);
}

}  // namespace detail
}  // namespace irid
#endif
