// Linear RGB <-> Oklab in float to about an ulp of each result, for the css and css-raytrace
// kernels (batch_simd_css.cpp; docs/KERNELS.md says why): compensated products and sums, the
// cube root and the cubes as float pairs, and on targets with double vectors the same
// transforms in double. Included once per target after simd_common-inl.h, and only where
// floating-point contraction is off (the compensated arithmetic needs every product and sum
// rounded on its own); the include guard toggles with HWY_TARGET_TOGGLE.

#if defined(IRID_GAMUT_OKLAB_PAIRS_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef IRID_GAMUT_OKLAB_PAIRS_INL_H_
#undef IRID_GAMUT_OKLAB_PAIRS_INL_H_
#else
#define IRID_GAMUT_OKLAB_PAIRS_INL_H_
#endif

#ifndef IRID_FP_CONTRACT_OFF
#error "oklab_pairs-inl.h needs floating-point contraction off: define IRID_FP_CONTRACT_OFF after the pragma"
#endif

#include <hwy/highway.h>
#include <irid/color/matrix.h>

#include "simd_common-inl.h"

HWY_BEFORE_NAMESPACE();
namespace irid {
namespace HWY_NAMESPACE {
namespace oklab_pairs {

namespace hn = hwy::HWY_NAMESPACE;
using simd::Df;
using simd::Mf;
using simd::Vf;

/// A double 3×3 matrix (row-major) as float pairs, m = hi + lo to about 2^-48 |m|.
struct PairMatrix {
    Vf hi[9], lo[9];
};

/// The pairs of a double matrix, broadcast.
HWY_INLINE PairMatrix LoadPairMatrix(Df d, const Mat3& m) {
    PairMatrix p;
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            const auto hi = static_cast<float>(m[i][j]);
            const auto lo = static_cast<float>(m[i][j] - static_cast<double>(hi));
            p.hi[3 * i + j] = hn::Set(d, hi);
            p.lo[3 * i + j] = hn::Set(d, lo);
        }
    }
    return p;
}

/// Knuth's TwoSum: s + err = a + b exactly.
HWY_INLINE Vf TwoSum(Vf a, Vf b, Vf& err) {
    const Vf s = hn::Add(a, b);
    const Vf bb = hn::Sub(s, a);
    err = hn::Add(hn::Sub(a, hn::Sub(s, bb)), hn::Sub(b, bb));
    return s;
}

/// p + e = a b exactly (barring overflow and underflow): the fused a b − p on the x86 targets
/// with FMA (AVX2, AVX-512), Dekker's split product (1971) on the others, which needs
/// |a|, |b| below about 1e34 (4097 x must not overflow).
HWY_INLINE Vf TwoProd(Df d, Vf a, Vf b, Vf& e) {
    const Vf p = hn::Mul(a, b);
#if HWY_ARCH_X86 && HWY_TARGET <= HWY_AVX2
    (void)d;
    e = hn::MulSub(a, b, p);
#else
    const Vf split = hn::Set(d, 4097.0f);
    const Vf ta = hn::Mul(split, a), tb = hn::Mul(split, b);
    const Vf ah = hn::Sub(ta, hn::Sub(ta, a)), bh = hn::Sub(tb, hn::Sub(tb, b));
    const Vf al = hn::Sub(a, ah), bl = hn::Sub(b, bh);
    e = hn::Add(hn::Add(hn::Add(hn::Sub(hn::Mul(ah, bh), p), hn::Mul(ah, bl)), hn::Mul(al, bh)),
                hn::Mul(al, bl));
#endif
    return p;
}

/// Row i of M times (x + xe) (x, xe: a vector as float pairs), as a pair s + se: compensated
/// products and sums, so that the result is within about an ulp of itself however much its
/// terms cancel (a plain float dot product loses up to 1e-7 of the terms' size).
HWY_INLINE Vf Dot3(Df d, const PairMatrix& M, int i, const Vf (&x)[3], const Vf (&xe)[3], Vf& se) {
    Vf p[3];
    Vf small = hn::Zero(d);
    for (int j = 0; j < 3; ++j) {
        const int k = 3 * i + j;
        Vf e;
        p[j] = TwoProd(d, M.hi[k], x[j], e);
        small = hn::Add(small, hn::Add(e, hn::Add(hn::Mul(M.hi[k], xe[j]), hn::Mul(M.lo[k], x[j]))));
    }
    Vf r1, r2;
    const Vf s1 = TwoSum(p[0], p[1], r1);
    const Vf s2 = TwoSum(s1, p[2], r2);
    const Vf tail = hn::Add(hn::Add(r1, r2), small);
    const Vf s = hn::Add(s2, tail);
    se = hn::Sub(tail, hn::Sub(s, s2));
    return s;
}

/// The real cube root of x, sign kept, to about 3e-7 relative over float's normal range (0
/// below it), without a division: simd_math::Cbrt's start from the exponent bits (within 7 %), then
/// two Halley steps written as corrections, y <- y (1 + (a - y^3)/(2 y^3 + a)), whose
/// quotient needs only a 12-bit reciprocal (its error scales the correction, not y). The start
/// of CbrtPair, whose exact Newton step squares this error.
HWY_INLINE Vf CbrtStart(Df d, Vf x) {
    const Vf a = hn::Abs(x);
    Vf y = simd_math::CbrtStart(d, a);  // src/color/simd_math-inl.h
    for (int it = 0; it < 2; ++it) {
        const Vf y3 = hn::Mul(hn::Mul(y, y), y);
        const Vf c = hn::Mul(hn::Sub(a, y3),
                             hn::ApproximateReciprocal(hn::MulAdd(hn::Set(d, 2.0f), y3, a)));
        y = hn::MulAdd(y, c, y);
    }
    y = hn::IfThenZeroElse(hn::Lt(a, hn::Set(d, simd_math::smallest_normal_float)), y);
    return hn::CopySign(y, x);
}

/// The real cube root of x as a pair y + dy, to about 2^-33 relative (2^-37 with AVX-512's
/// 14-bit reciprocal): CbrtStart, then one Newton step on the exact residual x - y^3
/// (dy = (x - y^3)/(3y^2); a 12-bit reciprocal is ample for a correction of a few ulp). 0
/// stays 0.
HWY_INLINE Vf CbrtPair(Df d, Vf x, Vf& dy) {
    const Vf y = CbrtStart(d, x);
    Vf pe, ce;
    const Vf p = TwoProd(d, y, y, pe);
    const Vf c = TwoProd(d, p, y, ce);
    const Vf residual = hn::Sub(hn::Sub(x, c), hn::MulAdd(pe, y, ce));
    const Vf inv = hn::ApproximateReciprocal(hn::Mul(hn::Set(d, 3.0f), p));
    dy = hn::IfThenZeroElse(hn::Eq(y, hn::Zero(d)), hn::Mul(residual, inv));
    return y;
}

/// The transforms of the kernels, as float pairs (accurate versions of simd::ToOklab and
/// simd::FromOklab): the float rounding of plain products, which a cube root near an LMS of 0
/// and the rays' grazing intersections amplify, would otherwise move results by more than 1e-5.
struct Transforms {
    PairMatrix to_lms, from_lms, m2, m2_inverse;
};

/// Oklab of linear RGB given as float pairs (r + re, ...), each component within about an ulp
/// of itself.
HWY_INLINE void ToOklabPair(Df d, const Transforms& T, Vf r, Vf g, Vf b, Vf re, Vf ge, Vf be,
                            Vf& L, Vf& A, Vf& B) {
    const Vf c[3] = {r, g, b}, ce[3] = {re, ge, be};
    Vf y[3], dy[3], unused;
    for (int i = 0; i < 3; ++i) y[i] = CbrtPair(d, Dot3(d, T.to_lms, i, c, ce, unused), dy[i]);
    L = Dot3(d, T.m2, 0, y, dy, unused);
    A = Dot3(d, T.m2, 1, y, dy, unused);
    B = Dot3(d, T.m2, 2, y, dy, unused);
}

/// Oklab of linear RGB, each component within about an ulp of itself.
HWY_INLINE void ToOklabAccurate(Df d, const Transforms& T, Vf r, Vf g, Vf b, Vf& L, Vf& A, Vf& B) {
    const Vf zero = hn::Zero(d);
    ToOklabPair(d, T, r, g, b, zero, zero, zero, L, A, B);
}

/// The Oklab chroma sqrt(a² + b²) of linear RGB, as ToOklabAccurate's a and b (L unused). For
/// a colour in the cube (non-negative channels) of a gamut whose rgb_to_lms has no negative
/// entry (`positive_lms`), the LMS sum has no cancellation and the plain float product is
/// within a few ulp of each component already.
HWY_INLINE Vf ChromaAccurate(Df d, const Transforms& T, bool positive_lms, Vf r, Vf g, Vf b) {
    const Vf zero = hn::Zero(d);
    const Vf c[3] = {r, g, b}, ce[3] = {zero, zero, zero};
    Vf y[3], dy[3], unused;
    if (positive_lms) {
        Vf lms[3];
        for (int i = 0; i < 3; ++i) {
            const int k = 3 * i;
            lms[i] = hn::MulAdd(T.to_lms.hi[k + 2], b,
                                hn::MulAdd(T.to_lms.hi[k + 1], g, hn::Mul(T.to_lms.hi[k], r)));
        }
        for (int i = 0; i < 3; ++i) y[i] = CbrtPair(d, lms[i], dy[i]);
    } else {
        for (int i = 0; i < 3; ++i) y[i] = CbrtPair(d, Dot3(d, T.to_lms, i, c, ce, unused), dy[i]);
    }
    const Vf A = Dot3(d, T.m2, 1, y, dy, unused);
    const Vf B = Dot3(d, T.m2, 2, y, dy, unused);
    return hn::Sqrt(hn::MulAdd(A, A, hn::Mul(B, B)));
}

/// Linear RGB of Oklab as float pairs r + re, ... (the cubes as pairs too), to about 2^-40 of
/// each channel.
HWY_INLINE void FromOklabPair(Df d, const Transforms& T, Vf L, Vf A, Vf B, Vf& r, Vf& g, Vf& b,
                              Vf& re, Vf& ge, Vf& be) {
    const Vf zero = hn::Zero(d);
    const Vf lab[3] = {L, A, B}, labe[3] = {zero, zero, zero};
    Vf cube[3], cube_e[3];
    for (int i = 0; i < 3; ++i) {
        Vf se, pe, ce;
        const Vf s = Dot3(d, T.m2_inverse, i, lab, labe, se);
        const Vf p = TwoProd(d, s, s, pe);
        pe = hn::MulAdd(hn::Add(s, s), se, pe);  // (s + se)² = p + pe to second order
        cube[i] = TwoProd(d, p, s, ce);
        cube_e[i] = hn::MulAdd(p, se, hn::MulAdd(pe, s, ce));
    }
    r = Dot3(d, T.from_lms, 0, cube, cube_e, re);
    g = Dot3(d, T.from_lms, 1, cube, cube_e, ge);
    b = Dot3(d, T.from_lms, 2, cube, cube_e, be);
}

/// The same, each channel rounded to float.
HWY_INLINE void FromOklabAccurate(Df d, const Transforms& T, Vf L, Vf A, Vf B, Vf& r, Vf& g, Vf& b) {
    Vf re, ge, be;
    FromOklabPair(d, T, L, A, B, r, g, b, re, ge, be);
}

#if HWY_TARGET != HWY_SCALAR && HWY_HAVE_FLOAT64
/// css-raytrace's restore step in double, on the targets with double vectors (all but SCALAR,
/// which keeps the float pairs): double has the pairs' accuracy at a fraction of their work.
using Dd = hn::Repartition<double, Df>;  // half as many lanes as Df
using Vd = hn::Vec<Dd>;

/// The lower and upper halves of a float vector, in double.
HWY_INLINE void SplitToDouble(Vf v, Vd (&out)[2]) {
    const Dd dd;
    const hn::Half<Df> dh;
    out[0] = hn::PromoteTo(dd, hn::LowerHalf(dh, v));
    out[1] = hn::PromoteTo(dd, hn::UpperHalf(dh, v));
}

/// The float vector of two double halves (rounded to nearest).
HWY_INLINE Vf JoinToFloat(Df d, const Vd (&v)[2]) {
    const hn::Half<Df> dh;
    return hn::Combine(d, hn::DemoteTo(dh, v[1]), hn::DemoteTo(dh, v[0]));
}

/// A double 3×3 matrix (row-major), broadcast.
struct DoubleMatrix {
    Vd m[9];
};

HWY_INLINE DoubleMatrix LoadDoubleMatrix(const Mat3& m) {
    const Dd dd;
    DoubleMatrix p;
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) p.m[3 * i + j] = hn::Set(dd, m[i][j]);
    }
    return p;
}

/// Row i of M times x, in double.
HWY_INLINE Vd DotD(const DoubleMatrix& M, int i, const Vd (&x)[3]) {
    return hn::MulAdd(M.m[3 * i + 2], x[2], hn::MulAdd(M.m[3 * i + 1], x[1], hn::Mul(M.m[3 * i], x[0])));
}

/// The transforms in double.
struct DoubleTransforms {
    DoubleMatrix to_lms, from_lms, m2, m2_inverse;
};

/// The cube roots of the LMS of linear RGB c (double halves) in y, lane by lane: the LMS in
/// double, the cube roots' start in float (CbrtStart, 3e-7), then one Newton step in double
/// (with a float reciprocal, 2^-12 of a correction of 3e-7), to about 1e-12 relative; an LMS
/// below float's normal range has the cube root 0, as CbrtPair.
HWY_INLINE void LmsRootsDouble(Df d, const DoubleTransforms& T, const Vd (&c)[3][2], Vd (&y)[2][3]) {
    for (int i = 0; i < 3; ++i) {
        Vd lms[2];
        for (int h = 0; h < 2; ++h) lms[h] = DotD(T.to_lms, i, {c[0][h], c[1][h], c[2][h]});
        const Vf yf = CbrtStart(d, JoinToFloat(d, lms));
        const Vf inv = hn::IfThenZeroElse(
            hn::Eq(yf, hn::Zero(d)), hn::ApproximateReciprocal(hn::Mul(hn::Set(d, 3.0f), hn::Mul(yf, yf))));
        Vd y0[2], inv_d[2];
        SplitToDouble(yf, y0);
        SplitToDouble(inv, inv_d);
        for (int h = 0; h < 2; ++h) {
            const Vd cube = hn::Mul(hn::Mul(y0[h], y0[h]), y0[h]);
            y[h][i] = hn::MulAdd(hn::Sub(lms[h], cube), inv_d[h], y0[h]);
        }
    }
}

/// Oklab of linear RGB through double (LmsRootsDouble, then M2), each component rounded to
/// float: the accuracy of ToOklabAccurate for less work. For |channels| up to split_limit.
HWY_INLINE void ToOklabDouble(Df d, const DoubleTransforms& T, Vf r, Vf g, Vf b, Vf& L, Vf& A, Vf& B) {
    Vd c[3][2];
    SplitToDouble(r, c[0]);
    SplitToDouble(g, c[1]);
    SplitToDouble(b, c[2]);
    Vd y[2][3];
    LmsRootsDouble(d, T, c, y);
    Vd lab[3][2];
    for (int h = 0; h < 2; ++h) {
        for (int i = 0; i < 3; ++i) lab[i][h] = DotD(T.m2, i, y[h]);
    }
    L = JoinToFloat(d, lab[0]);
    A = JoinToFloat(d, lab[1]);
    B = JoinToFloat(d, lab[2]);
}

/// The restore of css_raytrace.cpp's passes i > 0, lane by lane: the Oklab chroma of (r, g, b)
/// and then linear RGB of Oklab (L, C cos h, C sin h) (cos h = ua, sin h = ub; L, ua, ub given
/// in double halves), written to (nr, ng, nb) rounded to float; in double but for the cube
/// roots' start (LmsRootsDouble).
HWY_INLINE void RestoreDouble(Df d, const DoubleTransforms& T, Vf r, Vf g, Vf b, const Vd (&L)[2],
                              const Vd (&ua)[2], const Vd (&ub)[2], Vf& nr, Vf& ng, Vf& nb) {
    Vd c[3][2];
    SplitToDouble(r, c[0]);
    SplitToDouble(g, c[1]);
    SplitToDouble(b, c[2]);
    Vd y[2][3];
    LmsRootsDouble(d, T, c, y);
    Vd out[3][2];
    for (int h = 0; h < 2; ++h) {
        const Vd a = DotD(T.m2, 1, y[h]), bb = DotD(T.m2, 2, y[h]);
        const Vd chroma = hn::Sqrt(hn::MulAdd(a, a, hn::Mul(bb, bb)));
        const Vd lab[3] = {L[h], hn::Mul(chroma, ua[h]), hn::Mul(chroma, ub[h])};
        Vd cube[3];
        for (int i = 0; i < 3; ++i) {
            const Vd s = DotD(T.m2_inverse, i, lab);
            cube[i] = hn::Mul(hn::Mul(s, s), s);
        }
        for (int i = 0; i < 3; ++i) out[i][h] = DotD(T.from_lms, i, cube);
    }
    nr = JoinToFloat(d, out[0]);
    ng = JoinToFloat(d, out[1]);
    nb = JoinToFloat(d, out[2]);
}
#endif

}  // namespace oklab_pairs
}  // namespace HWY_NAMESPACE
}  // namespace irid
HWY_AFTER_NAMESPACE();

#endif  // IRID_GAMUT_OKLAB_PAIRS_INL_H_
