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

#include "simd_common-inl.h"

#include <cstddef>
#include <cstdint>

HWY_BEFORE_NAMESPACE();
namespace irid {
namespace HWY_NAMESPACE {
namespace {

namespace hn = hwy::HWY_NAMESPACE;
using D = hn::ScalableTag<float>;
using V = hn::Vec<D>;

/// std::clamp(v, 0, max) for non-NaN v (-0 stays -0, as in the scalar code).
HWY_INLINE V clamp_to_cube(V v, V zero, V max) {
    v = hn::IfThenElse(hn::Lt(v, zero), zero, v);
    return hn::IfThenElse(hn::Gt(v, max), max, v);
}

/// The same for a clipped channel w + s (c − w), which is never NaN nor -0 (w > 0, and a sum that
/// is exactly 0 rounds to +0): Min and Max give the same bits in fewer instructions.
HWY_INLINE V clamp_clipped(V v, V zero, V max) {
    return hn::Min(hn::Max(v, zero), max);
}

/// One channel's plane crossing in smits_clip_rgb: the fraction s_i = n/d with n = w or
/// room = max − w and d = |c − w| (= w − c below 0, c − w above max: the same IEEE values as the
/// scalar code's), taken when n D < N d (cross-multiplication). The kept N/D starts as 1/0
/// (s = ∞), which every crossed channel beats (d > 0): the scalar code's "first crossed channel
/// as it is". A channel not crossed gets d = 0 and never beats anything (n D >= 0 = N d).
/// Returns whether it was taken.
HWY_INLINE hn::Mask<D> crossing(V e, V w, V room, hn::Mask<D> low, hn::Mask<D> crossed, V& num,
                                V& den) {
    const V n = hn::IfThenElse(low, w, room);
    const V d = hn::IfThenElseZero(crossed, hn::Abs(e));
    const auto take = hn::Lt(hn::Mul(n, den), hn::Mul(num, d));
    num = hn::IfThenElse(take, n, num);
    den = hn::IfThenElse(take, d, den);
    return take;
}

/// The channel of the face the colour was moved onto is exactly that face's bound.
HWY_INLINE V on_face(V v, hn::Mask<D> face, hn::Mask<D> low, V zero, V max) {
    return hn::IfThenElse(face, hn::IfThenElse(low, zero, max), v);
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
    const V one = hn::Set(d, 1.0f);
    std::size_t i = 0;
    for (; i + n <= colours; i += n) {
        V r, g, b;
        hn::LoadInterleaved3(d, in + 3 * i, r, g, b);
        simd::FiniteOrDefault(d, r, g, b);
        // Outcodes.
        const auto low_r = hn::Lt(r, zero), low_g = hn::Lt(g, zero), low_b = hn::Lt(b, zero);
        const auto high_r = hn::Gt(r, max), high_g = hn::Gt(g, max), high_b = hn::Gt(b, max);
        const auto cross_r = hn::Or(low_r, high_r), cross_g = hn::Or(low_g, high_g),
                   cross_b = hn::Or(low_b, high_b);
        const auto outside = hn::Or(hn::Or(cross_r, cross_g), cross_b);
        if (hn::AllFalse(d, outside)) {  // in-gamut colours cost only the comparisons
            hn::StoreInterleaved3(r, g, b, d, out + 3 * i);
            continue;
        }
        // The grey of equal luminance, in the scalar code's order: (A r + B g) + C b.
        const V y = hn::Add(hn::Add(hn::Mul(l0, r), hn::Mul(l1, g)), hn::Mul(l2, b));
        const V w = hn::Mul(y, inv);
        // Y <= 0 (black) and w >= max (white) give the grey w itself, which the final clamp
        // turns into 0 or max: the scalar code's black and white (+0, as its clamp gives).
        // (y and w are never NaN: the channels are finite and the weights sum to about 1, so
        // Le and Ge are the scalar code's !(y > 0) and !(w < max).)
        const auto grey = hn::Or(hn::Le(y, zero), hn::Ge(w, max));
        const V er = hn::Sub(r, w), eg = hn::Sub(g, w), eb = hn::Sub(b, w);
        const V room = hn::Sub(max, w);
        // Red against the initial 1/0 is taken exactly where it is crossed (d > 0), so its
        // fraction is set without the products.
        V num = hn::IfThenElse(cross_r, hn::IfThenElse(low_r, w, room), one);
        V den = hn::IfThenElseZero(cross_r, hn::Abs(er));
        const auto take_g = crossing(eg, w, room, low_g, cross_g, num, den);
        const auto take_b = crossing(eb, w, room, low_b, cross_b, num, den);
        const V s = hn::Div(num, den);  // the one division
        // The face of the kept fraction: the last channel taken.
        const auto face_b = take_b;
        const auto face_g = hn::AndNot(take_b, take_g);
        const auto face_r = hn::AndNot(hn::Or(take_g, take_b), cross_r);
        V rr = on_face(hn::Add(w, hn::Mul(s, er)), face_r, low_r, zero, max);
        V gg = on_face(hn::Add(w, hn::Mul(s, eg)), face_g, low_g, zero, max);
        V bb = on_face(hn::Add(w, hn::Mul(s, eb)), face_b, low_b, zero, max);
        rr = hn::IfThenElse(grey, w, rr);
        gg = hn::IfThenElse(grey, w, gg);
        bb = hn::IfThenElse(grey, w, bb);
        // The lanes kept inside [0, max]³, and in-gamut lanes (if any) unchanged.
        rr = clamp_clipped(rr, zero, max);
        gg = clamp_clipped(gg, zero, max);
        bb = clamp_clipped(bb, zero, max);
        if (!hn::AllTrue(d, outside)) {
            rr = hn::IfThenElse(outside, rr, r);
            gg = hn::IfThenElse(outside, gg, g);
            bb = hn::IfThenElse(outside, bb, b);
        }
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
        simd::FiniteOrDefault(d, r, g, b);
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
