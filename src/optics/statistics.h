#pragma once

// Statistics the optics' error studies share (private to irid_optics).

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace irid::detail {

/// The value at fraction p of the sorted values (nearest rank, p in [0, 1]); 0 when empty.
inline double percentile(std::vector<double> values, double p) {
    if (values.empty()) return 0.0;
    const auto k = static_cast<std::size_t>(std::round(p * static_cast<double>(values.size() - 1)));
    std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(k), values.end());
    return values[k];
}

}  // namespace irid::detail
