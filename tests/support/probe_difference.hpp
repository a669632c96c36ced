#pragma once
// Largest difference between the sample histories of two runs' probes, for the tests that run
// one case two ways and compare them to round-off (SphDevicePath, DemDevicePath).
#include "debrisflow/core/real.hpp"
#include <algorithm>
#include <cmath>
#include <vector>

namespace debrisflow::test {

using ProbeHistories = std::vector<std::vector<std::vector<Real>>>; // probe, row, column

// max over probes and columns of max |a - b| / max |a| over the rows (column 0, the time, is
// left out). A column that stays at round-off level (the sideways force on a symmetric body)
// is judged against a thousandth of its probe's largest value instead of its own.
inline double probe_difference(const ProbeHistories& a, const ProbeHistories& b) {
    double out = 0;
    for (std::size_t k = 0; k < a.size(); ++k) {
        const auto &ha = a[k], &hb = b[k];
        if (ha.empty()) continue;
        double floor = 0;
        for (const auto& row : ha)
            for (std::size_t c = 1; c < row.size(); ++c)
                floor = std::max(floor, 1e-3 * std::abs(double(row[c])));
        for (std::size_t c = 1; c < ha[0].size(); ++c) {
            double scale = floor, m = 0;
            for (std::size_t r = 0; r < ha.size(); ++r) {
                scale = std::max(scale, std::abs(double(ha[r][c])));
                m = std::max(m, std::abs(double(ha[r][c] - hb[r][c])));
            }
            if (scale > 0) out = std::max(out, m / scale);
        }
    }
    return out;
}

} // namespace debrisflow::test
