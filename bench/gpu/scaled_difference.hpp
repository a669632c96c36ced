#pragma once
#include "debrisflow/core/real.hpp"
#include <algorithm>
#include <cmath>
#include <vector>

namespace debrisflow::gpu {

// max |a - b| / max |b| over components [first, first + width) of records of `stride` reals:
// the difference relative to the field's scale (sums that cancel make per-entry relative
// differences meaningless). Infinite when the sizes differ.
inline double scaled_difference(const std::vector<Real>& a, const std::vector<Real>& b,
                                int stride = 1, int first = 0, int width = 1) {
    if (a.size() != b.size()) return INFINITY;
    double diff = 0, scale = 0;
    for (std::size_t s = 0; s + std::size_t(stride) <= a.size(); s += std::size_t(stride))
        for (int c = first; c < first + width; ++c) {
            diff = std::max(diff, double(std::abs(a[s + c] - b[s + c])));
            scale = std::max(scale, double(std::abs(b[s + c])));
        }
    return scale > 0 ? diff / scale : diff;
}

} // namespace debrisflow::gpu
