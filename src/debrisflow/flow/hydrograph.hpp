#pragma once
#include "debrisflow/core/real.hpp"
#include <vector>

namespace debrisflow::flow {

// A discharge as a table of time: piecewise linear between the points, constant beyond them.
struct Hydrograph {
    std::vector<Real> times, values;

    Real at(Real t) const {
        if (times.size() == 1 || t <= times.front()) return values.front();
        if (t >= times.back()) return values.back();
        std::size_t k = 1;
        while (times[k] < t) ++k;
        const Real w = (t - times[k - 1]) / (times[k] - times[k - 1]);
        return values[k - 1] + w * (values[k] - values[k - 1]);
    }
};

} // namespace debrisflow::flow
