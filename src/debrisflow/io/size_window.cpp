#include "debrisflow/io/size_window.hpp"

#include <algorithm>
#include <cmath>

namespace debrisflow::io {

Real normal_lower_tail(Real x) {
    return Real(0.5) * std::erfc(-x / std::sqrt(Real(2)));
}
Real normal_upper_tail(Real x) {
    return Real(0.5) * std::erfc(x / std::sqrt(Real(2)));
}

void lognormal_window(const SizeSpec& s, Real& a, Real& b) {
    a = std::clamp(std::log(s.min / s.d50) / s.sigma, Real(-40), Real(40));
    b = std::clamp(std::log(s.max / s.d50) / s.sigma, Real(-40), Real(40));
}

Real lognormal_window_probability(const SizeSpec& s) {
    Real a, b;
    lognormal_window(s, a, b);
    if (a >= 0) return normal_upper_tail(a) - normal_upper_tail(b);
    if (b <= 0) return normal_lower_tail(b) - normal_lower_tail(a);
    return 1 - normal_lower_tail(a) - normal_upper_tail(b);
}

Real sieve_window_mass_fraction(const SizeSpec& s) {
    const auto& d = s.sieve_sizes;
    const auto& p = s.sieve_passing;
    const Real total = p.back() - p.front();
    if (!(total > 0)) return 0;
    Real kept = 0;
    for (std::size_t k = 1; k < d.size(); ++k) {
        const Real lo = std::max(d[k - 1], s.min), hi = std::min(d[k], s.max);
        if (hi > lo) kept += (p[k] - p[k - 1]) * (hi - lo) / (d[k] - d[k - 1]);
    }
    return kept / total;
}

} // namespace debrisflow::io
