// The float SIMD kernel of aces-rgc (Google Highway, dynamic dispatch), forward and inverse,
// following the scalar reference (aces_rgc.cpp) step by step. Its arithmetic (the forward
// curve in float with a fitted tail polynomial, the inverse in double) and the lanes it sends
// to the reference are in docs/KERNELS.md.

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE __BASE_FILE__
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>
#include <hwy/contrib/math/math-inl.h>

#include "kernels.h"
#include "simd_common-inl.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <numbers>

#ifndef IRID_GAMUT_BATCH_SIMD_ACES_ONCE
#define IRID_GAMUT_BATCH_SIMD_ACES_ONCE
namespace irid {
namespace {

/// For each mask m of up to 8 lanes, the lane indices of Compress packed in nibbles (nibble j =
/// the index of the j-th set bit of m; the nibbles past the count are 0). At namespace scope:
/// Highway 1.0.3's own table for 8 × 32-bit lanes is a local constexpr array inside
/// IndicesFromBits (hwy/ops/x86_256-inl.h), which g++ 12 copies onto the stack (1 KiB, `rep movs`)
/// at every Compress; that made this kernel 4× slower on AVX2 (33 ns per colour, against 5 on
/// AVX-512).
struct CompressTable {
    std::uint32_t nibbles[256];
};

constexpr CompressTable make_compress_table() noexcept {
    CompressTable t{};
    for (std::uint32_t m = 0; m < 256; ++m) {
        std::uint32_t packed = 0, j = 0;
        for (std::uint32_t lane = 0; lane < 8; ++lane) {
            if ((m >> lane) & 1u) packed |= lane << (4 * j++);
        }
        t.nibbles[m] = packed;
    }
    return t;
}

inline constexpr CompressTable compress_table = make_compress_table();

/// For each mask m of up to 8 lanes, the lane indices of Expand packed in nibbles (nibble j =
/// the number of set bits of m below bit j: where lane j takes its value from).
constexpr CompressTable make_expand_table() noexcept {
    CompressTable t{};
    for (std::uint32_t m = 0; m < 256; ++m) {
        std::uint32_t packed = 0, below = 0;
        for (std::uint32_t lane = 0; lane < 8; ++lane) {
            packed |= below << (4 * lane);
            below += (m >> lane) & 1u;
        }
        t.nibbles[m] = packed;
    }
    return t;
}

inline constexpr CompressTable expand_table = make_expand_table();

/// Terms of the polynomial that gives the forward curve's (1 + v)^(−1/p) (degree 9).
constexpr std::size_t tail_terms = 10;

/// The monomial coefficients, in t = 2v − 1, of the Chebyshev interpolant (at the 10 Chebyshev
/// nodes of [−1, 1]) of q(v) = (1 + v)^(−a) over v in [0, 1], rounded to float. q is analytic
/// save at v = −1, so the interpolation error falls as (3 + √8)^(−10): below 5e-8 relative for
/// every a in (0, 1] (a = 1, the largest, is the pole 1/(1 + v)); the coefficients are below 1
/// in magnitude, so float's Horner evaluation adds only about 1e-7. 20 calls of libm per call of
/// the kernel (16384 colours).
void tail_polynomial(double a, float (&coeffs)[tail_terms]) noexcept {
    constexpr std::size_t n = tail_terms;
    double cheb[n] = {};
    for (std::size_t k = 0; k < n; ++k) {
        const double t = std::cos(std::numbers::pi * (static_cast<double>(k) + 0.5) / n);
        const double q = std::pow(1.5 + 0.5 * t, -a);
        double t0 = 1.0, t1 = t;  // T_j(t) by T_{j+1} = 2t T_j − T_{j−1}
        for (std::size_t j = 0; j < n; ++j) {
            cheb[j] += q * t0;
            const double t2 = 2.0 * t * t1 - t0;
            t0 = t1;
            t1 = t2;
        }
    }
    // Σ cheb_j T_j(t) → Σ mono_i t^i, the monomials of T_j by the same recurrence.
    double mono[n] = {}, prev[n] = {}, cur[n] = {}, next[n] = {};
    prev[0] = 1.0;
    cur[1] = 1.0;
    for (std::size_t j = 0; j < n; ++j) {
        const double c = cheb[j] * (j == 0 ? 1.0 : 2.0) / n;
        const double* tj = j == 0 ? prev : cur;
        for (std::size_t i = 0; i < n; ++i) mono[i] += c * tj[i];
        if (j == 0) continue;
        for (std::size_t i = 0; i < n; ++i) next[i] = (i > 0 ? 2.0 * cur[i - 1] : 0.0) - prev[i];
        for (std::size_t i = 0; i < n; ++i) {
            prev[i] = cur[i];
            cur[i] = next[i];
        }
    }
    for (std::size_t i = 0; i < n; ++i) coeffs[i] = static_cast<float>(mono[i]);
}

}  // namespace
}  // namespace irid
#endif  // IRID_GAMUT_BATCH_SIMD_ACES_ONCE

HWY_BEFORE_NAMESPACE();
namespace irid {
namespace HWY_NAMESPACE {
namespace {

namespace hn = hwy::HWY_NAMESPACE;

/// Compress(v, m) of hwy (the lanes of m in order first, the rest unspecified). AVX-512 has an
/// instruction (register form); the other x86 targets (at most 8 lanes of float) look the lane
/// indices up in compress_table and permute; other architectures use Highway's.
template <class D, class V = hn::Vec<D>, class M = hn::Mask<D>>
HWY_INLINE V CompressLanes(D d, V v, M m) {
#if HWY_ARCH_X86 && HWY_TARGET != HWY_AVX3 && HWY_TARGET != HWY_AVX3_DL && HWY_TARGET != HWY_SCALAR
    static_assert(hn::MaxLanes(D()) <= 8, "the table covers up to 8 lanes");
    const hn::RebindToUnsigned<D> du;
    std::uint8_t bits[8] = {};
    hn::StoreMaskBits(d, m, bits);
    const auto shifts = hn::ShiftLeft<2>(hn::Iota(du, 0));
    const auto idx = hn::And(hn::Shr(hn::Set(du, compress_table.nibbles[bits[0]]), shifts),
                             hn::Set(du, static_cast<std::uint32_t>(hn::MaxLanes(D()) - 1)));
    return hn::TableLookupLanes(v, hn::IndicesFromVec(d, idx));
#else
    (void)d;
    return hn::Compress(v, m);
#endif
}

/// The float (forward) or double (inverse) parameters of one channel's curve.
template <class V>
struct ChannelV {
    V thr, scale, inv_scale, asymptote;
};

/// The parameters of a call, broadcast once, in the kernel's precision.
template <class D>
struct AcesV {
    using V = hn::Vec<D>;
    ChannelV<V> ch[3];
    V power, inv_power, max, large;  // |ach| above `large` goes to the double reference
    bool inverse, confined;

    /// From the clipper's prepared values (aces_rgc.cpp); `large` is large_confined × max when
    /// the clipper confines, else large_free.
    AcesV(D d, const GamutClipper& clipper, double large_confined, double large_free) {
        using T = hn::TFromD<D>;
        const AcesRgcPrepared& x = clipper.aces_rgc_prepared();
        for (std::size_t k = 0; k < 3; ++k) {
            ch[k].thr = hn::Set(d, static_cast<T>(x.threshold[k]));
            ch[k].scale = hn::Set(d, static_cast<T>(x.scale[k]));
            ch[k].inv_scale = hn::Set(d, static_cast<T>(1.0 / x.scale[k]));
            ch[k].asymptote = hn::Set(d, static_cast<T>(x.asymptote[k]));
        }
        power = hn::Set(d, static_cast<T>(x.power));
        inv_power = hn::Set(d, static_cast<T>(x.inverse_power));
        const double m = clipper.gamut().max();
        max = hn::Set(d, static_cast<T>(m));
        inverse = clipper.inverse();
        confined = clipper.confines_to_cube();
        large = hn::Set(d, static_cast<T>(confined ? large_confined * m : large_free));
    }
};

/// Compresses (or, inverse, uncompresses) one channel c against ach (inv_abs = 1/|ach|); adds to
/// `hard` the lanes for the double reference: inverse with u = nd^p above u_max, or d at or above
/// the asymptote by less than the factor `band`. Channels below the threshold return c.
template <class D, class V = hn::Vec<D>, class M = hn::Mask<D>>
HWY_INLINE V Channel(D d, const AcesV<D>& P, const ChannelV<V>& C, V c, V ach, V abs_ach,
                     V inv_abs, V u_max, V band, M& hard) {
    using T = hn::TFromD<D>;
    const V dist = hn::Mul(hn::Sub(ach, c), inv_abs);
    M active = hn::Ge(dist, C.thr);
    if (P.inverse) {
        // The inverse jumps from +inf back to the identity at the asymptote: a lane within
        // rounding of d above it may belong below it.
        hard = hn::Or(hard, hn::And(hn::Ge(dist, C.asymptote), hn::Lt(dist, hn::Mul(C.asymptote, band))));
        active = hn::And(active, hn::Lt(dist, C.asymptote));
    }
    if (hn::AllFalse(d, active)) return c;
    // nd clamped into [smallest normal, 1e30]: Log is finite; the clamped ends change nothing
    // that shows (below, nd compresses to thr; beyond 1e30, to thr + s, to float precision).
    const V nd = hn::Min(hn::Max(hn::Mul(hn::Sub(dist, C.thr), C.inv_scale),
                                 hn::Set(d, std::numeric_limits<T>::min())),
                         hn::Set(d, static_cast<T>(1e30)));
    const V L = hn::Log(d, nd);
    V f;
    if (!P.inverse) {
        const V e = hn::Exp(d, hn::Neg(hn::Mul(P.power, hn::Abs(L))));
        f = hn::Exp(d, hn::NegMulAdd(hn::Log1p(d, e), P.inv_power, hn::Min(L, hn::Zero(d))));
    } else {
        const V u = hn::Exp(d, hn::Mul(P.power, L));
        hard = hn::Or(hard, hn::And(active, hn::Gt(u, u_max)));
        const V safe_u = hn::Min(u, u_max);
        f = hn::Exp(d, hn::NegMulAdd(hn::Log1p(d, hn::Neg(safe_u)), P.inv_power, L));
    }
    const V D_ = hn::MulAdd(C.scale, f, C.thr);
    // Capped at ±1e30 as the reference caps a compressed channel (aces_rgc.cpp).
    const V cap = hn::Set(d, static_cast<T>(1e30));
    const V out = hn::Min(hn::Max(hn::NegMulAdd(D_, abs_ach, ach), hn::Neg(cap)), cap);
    return hn::IfThenElse(active, out, c);
}

/// One vector of colours (r, g, b in and out, the non-finite rule applied) in the precision of D: ach,
/// the three channels, 0 where ach = 0, the cube when confined. `hard` receives the lanes whose
/// results must come from the double reference (|ach| below `tiny` or above P.large, and those
/// of Channel); their r, g, b here are meaningless.
template <class D, class V = hn::Vec<D>, class M = hn::Mask<D>>
HWY_INLINE void Colours(D d, const AcesV<D>& P, V& r, V& g, V& b, V tiny, V u_max, V band,
                        M& hard) {
    using T = hn::TFromD<D>;
    const V zero = hn::Zero(d), one = hn::Set(d, static_cast<T>(1.0));
    const V ach = hn::Max(r, hn::Max(g, b));
    const V abs_ach = hn::Abs(ach);
    const M is_zero = hn::Eq(ach, zero);
    hard = hn::AndNot(is_zero, hn::Or(hn::Lt(abs_ach, tiny), hn::Gt(abs_ach, P.large)));
    // Zero and hard lanes divide by 1 here; their results are replaced.
    const V inv_abs = hn::Div(one, hn::IfThenElse(hn::Or(is_zero, hard), one, abs_ach));
    V ro = Channel(d, P, P.ch[0], r, ach, abs_ach, inv_abs, u_max, band, hard);
    V go = Channel(d, P, P.ch[1], g, ach, abs_ach, inv_abs, u_max, band, hard);
    V bo = Channel(d, P, P.ch[2], b, ach, abs_ach, inv_abs, u_max, band, hard);
    r = hn::IfThenZeroElse(is_zero, ro);
    g = hn::IfThenZeroElse(is_zero, go);
    b = hn::IfThenZeroElse(is_zero, bo);
    if (P.confined) {
        r = hn::Min(hn::Max(r, zero), P.max);
        g = hn::Min(hn::Max(g, zero), P.max);
        b = hn::Min(hn::Max(b, zero), P.max);
    }
}

constexpr std::size_t max_float_lanes = HWY_MAX_BYTES / sizeof(float);

/// log2 x for positive normal float x, without a division: x = 2^e m with m in [√½, √2),
/// log2 m = (2/ln 2) atanh(t), t = (m − 1)/(m + 1) in [−0.172, 0.172], by its series
/// (2/ln 2) t (1 + t²/3 + t⁴/5 + t⁶/7) (truncation below 5e-8), 1/(m + 1) by the approximate
/// reciprocal and one Newton step. Within about 1e-7 of log2 x, absolutely, over the normal range
/// (what the curve needs: it uses log2 only through v = 2^(−p|log2 nd|), see ForwardCurve).
template <class D, class V = hn::Vec<D>>
HWY_INLINE V FastLog2(D d, V x) {
    const hn::RebindToSigned<D> di;
    // Offset so that the exponent field counts from √½ (0x3F3504F3 = the bits of √½).
    const auto bits = hn::Sub(hn::BitCast(di, x), hn::Set(di, 0x3F3504F3));
    const V e = hn::ConvertTo(d, hn::ShiftRight<23>(bits));
    const V m = hn::BitCast(d, hn::Add(hn::And(bits, hn::Set(di, 0x007FFFFF)), hn::Set(di, 0x3F3504F3)));
    const V one = hn::Set(d, 1.0f), two = hn::Set(d, 2.0f);
    const V den = hn::Add(m, one);
    V inv = hn::ApproximateReciprocal(den);
    inv = hn::Mul(inv, hn::NegMulAdd(den, inv, two));  // Newton: y (2 − a y)
    const V t = hn::Mul(hn::Sub(m, one), inv);
    const V t2 = hn::Mul(t, t);
    V series = hn::MulAdd(t2, hn::Set(d, 1.0f / 7.0f), hn::Set(d, 1.0f / 5.0f));
    series = hn::MulAdd(series, t2, hn::Set(d, 1.0f / 3.0f));
    series = hn::Mul(series, t2);
    const V u = hn::Mul(t, hn::Set(d, static_cast<float>(2.0 / std::numbers::ln2)));
    return hn::Add(e, hn::MulAdd(u, series, u));
}

/// 2^y for y in [−127, 0] in float (0 at −127, where 2^y is no longer a normal float and
/// matters to no colour): y = k + r, k = round(y) by adding and subtracting 1.5·2^23, |r| <= ½,
/// 2^r = e^(r ln 2) by its Taylor series to degree 6 (truncation below 1.2e-7 relative), times
/// 2^k from the exponent bits (k + 127 sits in the low bits of y + 1.5·2^23).
template <class D, class V = hn::Vec<D>>
HWY_INLINE V FastExp2(D d, V y) {
    const hn::RebindToSigned<D> di;
    const V magic = hn::Set(d, 12582912.0f);  // 1.5·2^23
    const V shifted = hn::Add(y, magic);
    const V r = hn::Sub(y, hn::Sub(shifted, magic));
    constexpr double l = std::numbers::ln2;
    V p = hn::MulAdd(r, hn::Set(d, static_cast<float>(l * l * l * l * l * l / 720.0)),
                     hn::Set(d, static_cast<float>(l * l * l * l * l / 120.0)));
    p = hn::MulAdd(p, r, hn::Set(d, static_cast<float>(l * l * l * l / 24.0)));
    p = hn::MulAdd(p, r, hn::Set(d, static_cast<float>(l * l * l / 6.0)));
    p = hn::MulAdd(p, r, hn::Set(d, static_cast<float>(l * l / 2.0)));
    p = hn::MulAdd(p, r, hn::Set(d, static_cast<float>(l)));
    p = hn::MulAdd(p, r, hn::Set(d, 1.0f));
    const V scale = hn::BitCast(d, hn::ShiftLeft<23>(hn::Add(hn::BitCast(di, shifted), hn::Set(di, 127))));
    return hn::Mul(p, scale);
}

/// The forward curve f(nd) = nd / (1 + nd^p)^(1/p) in float (nd >= 0, also +inf), written as
/// min(nd, 1) q(v) with v = min(nd, 1/nd)^p = 2^(−p |log2 nd|) in [0, 1] and
/// q(v) = (1 + v)^(−1/p) (for nd > 1, nd (1 + nd^p)^(−1/p) = (1 + nd^(−p))^(−1/p)); q is the
/// polynomial of tail_polynomial in t = 2v − 1 (coefficients `tail`). Nothing overflows, and
/// the error of log2 moves q by at most ln 2 · v/(1 + v) of it, that of 2^r by 1/(2p): f is
/// within about 2e-7 of itself, relatively.
template <class D, class V = hn::Vec<D>>
HWY_INLINE V ForwardCurve(D d, V nd, V neg_power, const V (&tail)[tail_terms]) {
    using T = hn::TFromD<D>;
    const V one = hn::Set(d, static_cast<T>(1.0));
    const V y = hn::Max(hn::Mul(neg_power, hn::Abs(FastLog2(d, nd))), hn::Set(d, static_cast<T>(-127.0)));
    const V t = hn::MulAdd(FastExp2(d, y), hn::Set(d, static_cast<T>(2.0)), hn::Neg(one));
    V q = tail[tail_terms - 1];
    for (std::size_t k = tail_terms - 1; k-- > 0;) q = hn::MulAdd(q, t, tail[k]);
    return hn::Mul(hn::Min(nd, one), q);
}

/// Expand, the inverse of Compress: the lanes set in the mask whose StoreMaskBits are `bits` take,
/// in order, the first lanes of `packed`; the others keep `fallback`. AVX-512 has an instruction
/// (register form); the other x86 targets look the lane indices up in expand_table, permute and
/// blend; other architectures go lane by lane.
template <class D, class V = hn::Vec<D>>
HWY_INLINE V ExpandLanes(D d, V packed, const std::uint8_t* bits, V fallback) {
#if HWY_TARGET == HWY_AVX3 || HWY_TARGET == HWY_AVX3_DL
    return V{_mm512_mask_expand_ps(fallback.raw, hn::LoadMaskBits(d, bits).raw, packed.raw)};
#elif HWY_ARCH_X86 && HWY_TARGET != HWY_SCALAR
    static_assert(hn::MaxLanes(D()) <= 8, "the table covers up to 8 lanes");
    const hn::RebindToUnsigned<D> du;
    const auto shifts = hn::ShiftLeft<2>(hn::Iota(du, 0));
    const auto idx = hn::And(hn::Shr(hn::Set(du, expand_table.nibbles[bits[0]]), shifts),
                             hn::Set(du, static_cast<std::uint32_t>(hn::MaxLanes(D()) - 1)));
    return hn::IfThenElse(hn::LoadMaskBits(d, bits),
                          hn::TableLookupLanes(packed, hn::IndicesFromVec(d, idx)), fallback);
#else
    using T = hn::TFromD<D>;
    constexpr std::size_t lanes = HWY_MAX_BYTES / sizeof(T);
    alignas(64) T p[lanes], f[lanes];
    hn::Store(packed, d, p);
    hn::Store(fallback, d, f);
    for (std::size_t k = 0, j = 0; k < hn::Lanes(d); ++k) {
        if ((bits[k / 8] >> (k % 8)) & 1u) f[k] = p[j++];
    }
    return hn::Load(d, f);
#endif
}

/// Colours per block of the forward (its buffers, about 16 KiB, stay in L1).
constexpr std::size_t block_colours = 256;

/// The forward in float, in blocks of block_colours, in three passes:
/// (1) per vector: the non-finite rule, ach, and per channel d = (ach − c)·(1/|ach|) (one
///     division per vector); the lanes at or beyond the threshold are packed (Compress) as d and
///     ach into that channel's list, their mask and count kept; the channel as it is (0 where
///     ach = 0, clamped into the cube when confined) is stored in a planar buffer;
/// (2) per channel, the curve on full vectors of its list only (a third of the channels on the
///     benchmark's input, where nearly every vector has some): nd = (d − thr)/s and
///     out = ach − (thr + s f(nd))·|ach|;
/// (3) per vector: each channel's results expanded (Expand) over its planar values by the kept
///     mask, stored interleaved; then the hard lanes by the double reference.
/// `out` may be `in`: a block is read whole before it is written.
template <bool kConfined>
std::size_t ForwardBlocks(const GamutClipper& clipper, const float* in, float* out,
                          std::size_t colours) {
    using D = hn::ScalableTag<float>;
    const D d;
    using V = hn::Vec<D>;
    const std::size_t n = hn::Lanes(d);
    const AcesV<D> P(d, clipper, 16.0, 1e30);
    const V zero = hn::Zero(d), one = hn::Set(d, 1.0f), tiny = hn::Set(d, 1e-30f);
    const V cap = hn::Set(d, 1e30f), nan = hn::Set(d, std::numeric_limits<float>::quiet_NaN());
    const V neg_power = hn::Neg(P.power);
    V tail[tail_terms];
    {
        float coeffs[tail_terms];
        tail_polynomial(clipper.aces_rgc_prepared().inverse_power, coeffs);
        for (std::size_t k = 0; k < tail_terms; ++k) tail[k] = hn::Set(d, coeffs[k]);
    }
    constexpr std::size_t capacity = block_colours + max_float_lanes;
    constexpr std::size_t mask_bytes = (max_float_lanes + 7) / 8;
    alignas(64) float planar[3][block_colours];
    // Zeroed once per call: the last vector of a list reads past its packed values.
    alignas(64) float nd_buf[3][capacity]{}, ach_buf[3][capacity]{};
    alignas(8) std::uint8_t mask_buf[3][block_colours * mask_bytes];
    std::uint8_t count_buf[3][block_colours];
    alignas(64) float hard_buf[3 * block_colours];
    std::size_t hard_at[block_colours];
    alignas(64) float flag[max_float_lanes];

    const std::size_t whole = colours / n * n;
    for (std::size_t begin = 0; begin < whole; begin += block_colours) {
        const std::size_t end = std::min(whole, begin + block_colours);
        std::size_t count[3] = {0, 0, 0}, hard_count = 0;
        // (1)
        for (std::size_t i = begin, vi = 0; i < end; i += n, ++vi) {
            V c[3];
            hn::LoadInterleaved3(d, in + 3 * i, c[0], c[1], c[2]);
            if (HWY_UNLIKELY(!hn::AllTrue(d, hn::And(hn::And(hn::IsFinite(c[0]), hn::IsFinite(c[1])),
                                                   hn::IsFinite(c[2]))))) {
                for (V& v : c) v = simd::FiniteOrDefault(d, v);
            }
            const V ach = hn::Max(c[0], hn::Max(c[1], c[2]));
            const V abs_ach = hn::Abs(ach);
            const auto is_zero = hn::Eq(ach, zero);
            const auto hard =
                hn::AndNot(is_zero, hn::Or(hn::Lt(abs_ach, tiny), hn::Gt(abs_ach, P.large)));
            V inv_abs = hn::Div(one, abs_ach);
            if (HWY_UNLIKELY(!hn::AllFalse(d, hn::Or(is_zero, hard)))) {
                // NaN: d compares false with every threshold, so nothing is packed.
                inv_abs = hn::IfThenElse(hn::Or(is_zero, hard), nan, inv_abs);
                for (V& v : c) v = hn::IfThenZeroElse(is_zero, v);
                if (!hn::AllFalse(d, hard)) {
                    hn::Store(hn::IfThenElseZero(hard, one), d, flag);
                    for (std::size_t k = 0; k < n; ++k) {
                        if (flag[k] == 0.0f) continue;
                        for (std::size_t m = 0; m < 3; ++m) {
                            hard_buf[3 * hard_count + m] = in[3 * (i + k) + m];
                        }
                        hard_at[hard_count++] = i + k;
                    }
                }
            }
            for (std::size_t k = 0; k < 3; ++k) {
                const ChannelV<V>& C = P.ch[k];
                const V dist = hn::Mul(hn::Sub(ach, c[k]), inv_abs);
                const auto active = hn::Ge(dist, C.thr);
                hn::StoreMaskBits(d, active, mask_buf[k] + vi * mask_bytes);
                // Compress in registers, then a full store (the lists have a vector of slack):
                // a compressing store to memory is microcoded and slow on x86.
                hn::StoreU(CompressLanes(d, dist, active), d, nd_buf[k] + count[k]);
                hn::StoreU(CompressLanes(d, ach, active), d, ach_buf[k] + count[k]);
                const std::size_t added = hn::CountTrue(d, active);
                count_buf[k][vi] = static_cast<std::uint8_t>(added);
                count[k] += added;
                V v = c[k];
                if (kConfined) v = hn::Min(hn::Max(v, zero), P.max);
                hn::Store(v, d, planar[k] + (i - begin));
            }
        }
        // (2) Two vectors at a time: the curve is one long dependent chain, and two independent
        // chains keep the pipeline fuller. The last vector's unused lanes are left-over values,
        // computed and never read.
        for (std::size_t k = 0; k < 3; ++k) {
            const ChannelV<V>& C = P.ch[k];
            float* nd_k = nd_buf[k];
            const float* ach_k = ach_buf[k];
            const auto finish = [&](std::size_t j, V f) {
                const V a = hn::Load(d, ach_k + j);
                V o = hn::NegMulAdd(hn::MulAdd(C.scale, f, C.thr), hn::Abs(a), a);
                o = kConfined ? hn::Min(hn::Max(o, zero), P.max)
                              : hn::Min(hn::Max(o, hn::Neg(cap)), cap);
                hn::Store(o, d, nd_k + j);
            };
            const auto curve = [&](std::size_t j) {
                const V nd = hn::Mul(hn::Sub(hn::Load(d, nd_k + j), C.thr), C.inv_scale);
                return ForwardCurve(d, nd, neg_power, tail);
            };
            std::size_t j = 0;
            for (; j + n < count[k]; j += 2 * n) {
                const V f0 = curve(j), f1 = curve(j + n);
                finish(j, f0);
                finish(j + n, f1);
            }
            for (; j < count[k]; j += n) finish(j, curve(j));
        }
        // (3)
        std::size_t at[3] = {0, 0, 0};
        for (std::size_t i = begin, vi = 0; i < end; i += n, ++vi) {
            V o[3];
            for (std::size_t k = 0; k < 3; ++k) {
                o[k] = ExpandLanes(d, hn::LoadU(d, nd_buf[k] + at[k]), mask_buf[k] + vi * mask_bytes,
                                   hn::Load(d, planar[k] + (i - begin)));
                at[k] += count_buf[k][vi];
            }
            hn::StoreInterleaved3(o[0], o[1], o[2], d, out + 3 * i);
        }
        for (std::size_t h = 0; h < hard_count; ++h) {
            const float* c = hard_buf + 3 * h;
            const Rgb o = clipper.clip({c[0], c[1], c[2]});
            float* dst = out + 3 * hard_at[h];
            dst[0] = static_cast<float>(o.r);
            dst[1] = static_cast<float>(o.g);
            dst[2] = static_cast<float>(o.b);
        }
    }
    return whole;
}

/// The forward: ForwardBlocks with or without the cube.
std::size_t Forward(const GamutClipper& clipper, const float* in, float* out, std::size_t colours) {
    return clipper.confines_to_cube() ? ForwardBlocks<true>(clipper, in, out, colours)
                                      : ForwardBlocks<false>(clipper, in, out, colours);
}

/// The inverse in double (its slope grows without bound toward the asymptote and would amplify
/// float's rounding beyond 1e-5), colours loaded and stored as float.
std::size_t Inverse(const GamutClipper& clipper, const float* in, float* out, std::size_t colours) {
    using D = hn::ScalableTag<double>;
    const D d;
    using V = hn::Vec<D>;
    // In double the rounding of ach − D |ach| stays far below 1e-5 of max for any ach up to 1e30.
    const AcesV<D> P(d, clipper, 1e30, 1e30);
    const V tiny = hn::Set(d, 1e-300), u_max = hn::Set(d, 1.0 - 1e-4),
            band = hn::Set(d, 1.0 + 1e-9);
    return simd::RunKernel(d, clipper, in, out, colours, [&](V r, V g, V b, V& out_r, V& out_g, V& out_b) {
        hn::Mask<D> hard;
        Colours(d, P, r, g, b, tiny, u_max, band, hard);
        out_r = r, out_g = g, out_b = b;
        return hard;
    });
}

}  // namespace

/// The kernel of kernels.h: the largest multiple of the vector length of `colours`, forward
/// (float) or inverse (double) as the clipper says; returns how many colours it did.
std::size_t ClipAcesRgc(const GamutClipper& clipper, const float* in, float* out,
                        std::size_t colours) {
    return clipper.inverse() ? Inverse(clipper, in, out, colours)
                             : Forward(clipper, in, out, colours);
}

}  // namespace HWY_NAMESPACE
}  // namespace irid
HWY_AFTER_NAMESPACE();

#if HWY_ONCE

namespace irid {
namespace {

IRID_EXPORT_KERNEL(ClipAcesRgc)

}  // namespace

detail::Kernel detail::aces_rgc_kernel(ClipMethod method) noexcept {
    if (method == ClipMethod::aces_rgc) return {ClipAcesRgcDispatch, nullptr};
    return {};
}

}  // namespace irid

#endif  // HWY_ONCE
