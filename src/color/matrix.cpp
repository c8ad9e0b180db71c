#include <irid/color/matrix.h>
#include <irid/color/numeric_table.h>
#include <irid/error.h>

#include <cmath>
#include <string>

namespace irid {

Mat3 inverse(const Mat3& a, const char* what) {
    const double det = a.determinant();
    if (!std::isfinite(det) || std::abs(det) < 1e-300) {
        throw Error(std::string(what) + " is singular (determinant " + format_shortest(det) +
                    "); it has no inverse");
    }
    return inverse_unchecked(a);
}

}  // namespace irid
