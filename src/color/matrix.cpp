#include <irid/color/matrix.h>
#include <irid/error.h>

#include <cmath>
#include <string>

namespace irid {

Mat3 inverse(const Mat3& a, const char* what) {
    const double det = a.determinant();
    if (!std::isfinite(det) || std::abs(det) < 1e-300) {
        throw Error(std::string(what) + " is singular (determinant " + std::to_string(det) +
                    "); it has no inverse");
    }
    const double s = 1.0 / det;
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

}  // namespace irid
