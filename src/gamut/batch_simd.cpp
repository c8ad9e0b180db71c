// The SIMD kernels of the gamut batches (Google Highway, dynamic dispatch).
//
// foreach_target.h includes this file once per instruction set (with g++ 12 and Highway 1.0.3 on
// x86-64: AVX3 = AVX-512, AVX2, SSE4, SSSE3 and the baseline SCALAR); HWY_DYNAMIC_DISPATCH picks
// the best one the CPU supports on the first call and caches it.
//
// No floating-point contraction here: g++ fuses a * b + c into an FMA on the AVX2 and AVX-512
// targets by default (-ffp-contract=fast), which would round differently from the scalar
// specification compiled for baseline x86-64. With contraction off, every lane performs the same
// IEEE operations in the same order as smits_clip_rgb<float>, so the results are the same bits.
// The pragma comes before every #include so that all inline functions of this file share the
// same options (no inlining mismatch). (Clang's default, -ffp-contract=on, only fuses within one
// source expression, which Highway's separate Mul and Add calls never are.)
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC optimize("fp-contract=off")
#endif

#undef HWY_TARGET_INCLUDE
// __BASE_FILE__ is this file's path as given to the compiler, absolute under CMake (unlike
// __FILE__, which would name foreach_target.h where the macro is expanded).
#define HWY_TARGET_INCLUDE __BASE_FILE__
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include <irid/gamut/batch.h>

#include <cstddef>
#include <cstdint>

HWY_BEFORE_NAMESPACE();
namespace irid {
namespace HWY_NAMESPACE {
namespace {

namespace hn = hwy::HWY_NAMESPACE;
using D = hn::ScalableTag<float>;
using V = hn::Vec<D>;

/// The non-finite rule of clip.h: NaN → 0, ±Inf → ±1e30.
HWY_INLINE V finite_or_default(D d, V v) {
    v = hn::IfThenZeroElse(hn::IsNaN(v), v);
    return hn::IfThenElse(hn::IsInf(v), hn::CopySign(hn::Set(d, 1e30f), v), v);
}

/// The rule on three channels, skipped (a few comparisons) when they are all finite.
HWY_INLINE void finite_or_default(D d, V& r, V& g, V& b) {
    if (HWY_LIKELY(
            hn::AllTrue(d, hn::And(hn::And(hn::IsFinite(r), hn::IsFinite(g)), hn::IsFinite(b))))) {
        return;
    }
    r = finite_or_default(d, r);
    g = finite_or_default(d, g);
    b = finite_or_default(d, b);
}

/// std::clamp(v, 0, max) for non-NaN v (-0 stays -0, as in the scalar code).
HWY_INLINE V clamp_to_cube(V v, V zero, V max) {
    v = hn::IfThenElse(hn::Lt(v, zero), zero, v);
    return hn::IfThenElse(hn::Gt(v, max), max, v);
}

/// The same for a clipped channel c + t (w − c), which is never NaN nor -0 (c = -0 is not below
/// 0, so it only moves by +t w): Min and Max give the same bits in fewer instructions.
HWY_INLINE V clamp_clipped(V v, V zero, V max) {
    return hn::Min(hn::Max(v, zero), max);
}

/// One channel's plane crossing in smits_clip_rgb: t_i = (c − bound)/(c − w) where the channel is
/// below 0 (bound 0, numerator c itself) or above max, kept when larger than t.
/// `face` records which channel gave the largest t so far (the first on ties, as the scalar loop).
HWY_INLINE V crossing(V c, V w, V max, hn::Mask<D> low, hn::Mask<D> high, V t, V index, V& face) {
    const V num = hn::IfThenElse(low, c, hn::Sub(c, max));
    const V ti = hn::Div(num, hn::Sub(c, w));
    const auto larger = hn::And(hn::Or(low, high), hn::Gt(ti, t));
    face = hn::IfThenElse(larger, index, face);
    return hn::IfThenElse(larger, ti, t);
}

/// The channel of the face the colour was moved onto is exactly that face's bound.
HWY_INLINE V on_face(V v, V face, V index, hn::Mask<D> low, V zero, V max) {
    return hn::IfThenElse(hn::Eq(face, index), hn::IfThenElse(low, zero, max), v);
}

}  // namespace

std::size_t ClipSmits(const float* in, float* out, std::size_t colours,
                      const detail::BatchFloatParams& p) {
    const D d;
    const std::size_t n = hn::Lanes(d);
    const V zero = hn::Zero(d);
    const V max = hn::Set(d, p.max);
    const V l0 = hn::Set(d, p.lum0), l1 = hn::Set(d, p.lum1), l2 = hn::Set(d, p.lum2);
    const V inv = hn::Set(d, p.inv_lum_sum);
    std::size_t i = 0;
    for (; i + n <= colours; i += n) {
        V r, g, b;
        hn::LoadInterleaved3(d, in + 3 * i, r, g, b);
        finite_or_default(d, r, g, b);
        // Outcodes.
        const auto low_r = hn::Lt(r, zero), low_g = hn::Lt(g, zero), low_b = hn::Lt(b, zero);
        const auto high_r = hn::Gt(r, max), high_g = hn::Gt(g, max), high_b = hn::Gt(b, max);
        const auto outside =
            hn::Or(hn::Or(hn::Or(low_r, high_r), hn::Or(low_g, high_g)), hn::Or(low_b, high_b));
        if (hn::AllFalse(d, outside)) {  // in-gamut colours cost only the comparisons
            hn::StoreInterleaved3(r, g, b, d, out + 3 * i);
            continue;
        }
        // The grey of equal luminance, in the scalar code's order: (A r + B g) + C b.
        const V y = hn::Add(hn::Add(hn::Mul(l0, r), hn::Mul(l1, g)), hn::Mul(l2, b));
        const V w = hn::Mul(y, inv);
        V t = zero;
        V face = hn::Set(d, -1.0f);
        const V i0 = zero, i1 = hn::Set(d, 1.0f), i2 = hn::Set(d, 2.0f);
        t = crossing(r, w, max, low_r, high_r, t, i0, face);
        t = crossing(g, w, max, low_g, high_g, t, i1, face);
        t = crossing(b, w, max, low_b, high_b, t, i2, face);
        V rr = on_face(hn::Add(r, hn::Mul(t, hn::Sub(w, r))), face, i0, low_r, zero, max);
        V gg = on_face(hn::Add(g, hn::Mul(t, hn::Sub(w, g))), face, i1, low_g, zero, max);
        V bb = on_face(hn::Add(b, hn::Mul(t, hn::Sub(w, b))), face, i2, low_b, zero, max);
        // w >= max → white; Y <= 0 (or NaN) → black, tested first in the scalar code so it wins.
        const auto white = hn::Not(hn::Lt(w, max));
        const auto black = hn::Not(hn::Gt(y, zero));
        rr = hn::IfThenZeroElse(black, hn::IfThenElse(white, max, rr));
        gg = hn::IfThenZeroElse(black, hn::IfThenElse(white, max, gg));
        bb = hn::IfThenZeroElse(black, hn::IfThenElse(white, max, bb));
        // In-gamut lanes unchanged, the others kept inside [0, max]³.
        rr = hn::IfThenElse(outside, clamp_clipped(rr, zero, max), r);
        gg = hn::IfThenElse(outside, clamp_clipped(gg, zero, max), g);
        bb = hn::IfThenElse(outside, clamp_clipped(bb, zero, max), b);
        hn::StoreInterleaved3(rr, gg, bb, d, out + 3 * i);
    }
    return i;
}

std::size_t ClipClamp(const float* in, float* out, std::size_t colours,
                      const detail::BatchFloatParams& p) {
    const D d;
    const std::size_t n = hn::Lanes(d);
    const V zero = hn::Zero(d);
    const V max = hn::Set(d, p.max);
    std::size_t i = 0;
    for (; i + n <= colours; i += n) {
        V r, g, b;
        hn::LoadInterleaved3(d, in + 3 * i, r, g, b);
        finite_or_default(d, r, g, b);
        r = clamp_to_cube(r, zero, max);
        g = clamp_to_cube(g, zero, max);
        b = clamp_to_cube(b, zero, max);
        hn::StoreInterleaved3(r, g, b, d, out + 3 * i);
    }
    return i;
}

std::int64_t Target() {
    return HWY_TARGET;
}

}  // namespace HWY_NAMESPACE
}  // namespace irid
HWY_AFTER_NAMESPACE();

#if HWY_ONCE

namespace irid {

HWY_EXPORT(ClipSmits);
HWY_EXPORT(ClipClamp);
HWY_EXPORT(Target);

namespace detail {

std::size_t clip_smits_simd(const float* in, float* out, std::size_t colours,
                            const BatchFloatParams& p) noexcept {
    return HWY_DYNAMIC_DISPATCH(ClipSmits)(in, out, colours, p);
}

std::size_t clip_clamp_simd(const float* in, float* out, std::size_t colours,
                            const BatchFloatParams& p) noexcept {
    return HWY_DYNAMIC_DISPATCH(ClipClamp)(in, out, colours, p);
}

}  // namespace detail

std::string_view simd_target_name() {
    return hwy::TargetName(HWY_DYNAMIC_DISPATCH(Target)());
}

}  // namespace irid

#endif  // HWY_ONCE
