#pragma once

#include <array>

namespace irid {

/// A column vector of three doubles, the arithmetic type behind every tristimulus value.
using Vec3 = std::array<double, 3>;

/// A 3x3 matrix stored by rows: m[row][column].
struct Mat3 {
    std::array<Vec3, 3> m{};

    [[nodiscard]] static constexpr Mat3 identity() noexcept {
        return Mat3{{{{1.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, {0.0, 0.0, 1.0}}}};
    }
    [[nodiscard]] static constexpr Mat3 diagonal(const Vec3& d) noexcept {
        return Mat3{{{{d[0], 0.0, 0.0}, {0.0, d[1], 0.0}, {0.0, 0.0, d[2]}}}};
    }
    /// A matrix whose columns are a, b and c.
    [[nodiscard]] static constexpr Mat3 from_columns(const Vec3& a, const Vec3& b,
                                                      const Vec3& c) noexcept {
        return Mat3{{{{a[0], b[0], c[0]}, {a[1], b[1], c[1]}, {a[2], b[2], c[2]}}}};
    }

    [[nodiscard]] constexpr const Vec3& operator[](int row) const noexcept { return m[row]; }
    [[nodiscard]] constexpr Vec3& operator[](int row) noexcept { return m[row]; }

    [[nodiscard]] constexpr Vec3 operator*(const Vec3& v) const noexcept {
        return {m[0][0] * v[0] + m[0][1] * v[1] + m[0][2] * v[2],
                m[1][0] * v[0] + m[1][1] * v[1] + m[1][2] * v[2],
                m[2][0] * v[0] + m[2][1] * v[1] + m[2][2] * v[2]};
    }

    [[nodiscard]] constexpr Mat3 operator*(const Mat3& o) const noexcept {
        Mat3 r;
        for (int i = 0; i < 3; ++i) {
            for (int j = 0; j < 3; ++j) {
                r.m[i][j] = m[i][0] * o.m[0][j] + m[i][1] * o.m[1][j] + m[i][2] * o.m[2][j];
            }
        }
        return r;
    }

    [[nodiscard]] constexpr double determinant() const noexcept {
        return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
               m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
               m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
    }
};

/// The inverse by the adjugate, unchecked: for matrices known to be regular (constants), usable
/// in constant expressions.
[[nodiscard]] constexpr Mat3 inverse_unchecked(const Mat3& a) noexcept {
    const double s = 1.0 / a.determinant();
    Mat3 r;
    r[0][0] = (a[1][1] * a[2][2] - a[1][2] * a[2][1]) * s;
    r[0][1] = (a[0][2] * a[2][1] - a[0][1] * a[2][2]) * s;
    r[0][2] = (a[0][1] * a[1][2] - a[0][2] * a[1][1]) * s;
    r[1][0] = (a[1][2] * a[2][0] - a[1][0] * a[2][2]) * s;
    r[1][1] = (a[0][0] * a[2][2] - a[0][2] * a[2][0]) * s;
    r[1][2] = (a[0][2] * a[1][0] - a[0][0] * a[1][2]) * s;
    r[2][0] = (a[1][0] * a[2][1] - a[1][1] * a[2][0]) * s;
    r[2][1] = (a[0][1] * a[2][0] - a[0][0] * a[2][1]) * s;
    r[2][2] = (a[0][0] * a[1][1] - a[0][1] * a[1][0]) * s;
    return r;
}

/// The inverse by the adjugate. Throws irid::Error when the matrix is singular (|det| below
/// 1e-300 or not finite), naming `what`.
[[nodiscard]] Mat3 inverse(const Mat3& a, const char* what = "matrix");

}  // namespace irid
