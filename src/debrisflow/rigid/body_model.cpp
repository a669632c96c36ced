#include "debrisflow/rigid/body_model.hpp"
#include <algorithm>

namespace debrisflow::rigid {

Vec3 interpolate(const std::vector<Real>& t, const std::vector<Vec3>& v, Real at) {
    if (t.empty()) return {};
    if (at <= t.front()) return v.front();
    if (at >= t.back()) return v.back();
    const auto k = std::size_t(std::upper_bound(t.begin(), t.end(), at) - t.begin());
    const Real w = (at - t[k - 1]) / (t[k] - t[k - 1]);
    return (1 - w) * v[k - 1] + w * v[k];
}

} // namespace debrisflow::rigid
