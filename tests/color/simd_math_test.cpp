// The shared SIMD maths (src/color/simd_math-inl.h) on every instruction set Highway compiled
// and this CPU runs, against the scalar library: the cube root in float and in double.

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE __BASE_FILE__
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "../../src/color/simd_math-inl.h"

#include <cstddef>

HWY_BEFORE_NAMESPACE();
namespace irid {
namespace HWY_NAMESPACE {
namespace {

namespace hn = hwy::HWY_NAMESPACE;

/// simd_math::Cbrt over n values (n a multiple of every vector length).
template <class T>
void CbrtAll(const T* in, T* out, std::size_t n) {
    const hn::ScalableTag<T> d;
    for (std::size_t i = 0; i < n; i += hn::Lanes(d)) {
        hn::StoreU(simd_math::Cbrt(d, hn::LoadU(d, in + i)), d, out + i);
    }
}

}  // namespace

void CbrtFloat(const float* in, float* out, std::size_t n) { CbrtAll(in, out, n); }
void CbrtDouble(const double* in, double* out, std::size_t n) { CbrtAll(in, out, n); }

}  // namespace HWY_NAMESPACE
}  // namespace irid
HWY_AFTER_NAMESPACE();

#if HWY_ONCE

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

namespace irid {
namespace {

HWY_EXPORT(CbrtFloat);
HWY_EXPORT(CbrtDouble);

/// Values over the range each precision must handle: both signs, zero, decades from the
/// smallest normal float to 1e37, and random mantissas.
template <class T>
std::vector<T> samples() {
    std::vector<T> v{T(0), T(-0.0), T(1), T(-1), T(8), T(-27), T(1e-38), T(1.2e-38), T(1e37), T(-1e37)};
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> exponent(-37.9, 37.0), unit(0.0, 1.0);
    while (v.size() < 4096) {
        const double x = std::pow(10.0, exponent(rng)) * (unit(rng) < 0.5 ? -1.0 : 1.0);
        v.push_back(static_cast<T>(x));
    }
    return v;
}

/// The largest error of the SIMD cube root, in ulps of the exact one (std::cbrt in long double),
/// over samples() on the current target.
template <class T, class F>
double worst_ulps(F run) {
    const std::vector<T> in = samples<T>();
    std::vector<T> out(in.size());
    run(in.data(), out.data(), in.size());
    double worst = 0.0;
    for (std::size_t i = 0; i < in.size(); ++i) {
        const long double exact = std::cbrt(static_cast<long double>(in[i]));
        if (std::abs(in[i]) < T(1.17549435e-38)) {
            EXPECT_EQ(out[i], T(0)) << in[i];  // below the smallest normal float: 0
            continue;
        }
        const long double ulp = std::nextafter(static_cast<T>(std::abs(exact)), std::numeric_limits<T>::infinity()) -
                                static_cast<T>(std::abs(exact));
        worst = std::max(worst, static_cast<double>(std::abs(out[i] - exact) / ulp));
        EXPECT_EQ(std::signbit(out[i]), std::signbit(in[i])) << in[i];
    }
    return worst;
}

TEST(SimdMath, CubeRootOnEveryCompiledTarget) {
    int targets = 0;
    for (const std::int64_t target : hwy::SupportedAndGeneratedTargets()) {
        hwy::SetSupportedTargetsForTest(target);
        const double f = worst_ulps<float>(HWY_DYNAMIC_DISPATCH(CbrtFloat));
        const double d = worst_ulps<double>(HWY_DYNAMIC_DISPATCH(CbrtDouble));
        EXPECT_LE(f, 3.0) << hwy::TargetName(target);  // measured 2.82 on every x86 target
        EXPECT_LE(d, 3.0) << hwy::TargetName(target);  // measured 2.55
        std::printf("simd_math::Cbrt on %s: within %.2f ulp in float, %.2f ulp in double\n",
                    hwy::TargetName(target), f, d);
        ++targets;
    }
    hwy::SetSupportedTargetsForTest(0);
    EXPECT_GE(targets, 2);
}

}  // namespace
}  // namespace irid

#endif  // HWY_ONCE
