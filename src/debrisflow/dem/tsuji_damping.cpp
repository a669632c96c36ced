#include "debrisflow/dem/tsuji_damping.hpp"
#include "debrisflow/core/error.hpp"
#include <cmath>
#include <fmt/format.h>

namespace debrisflow::dem {

Real linear_damping_ratio(Real e) {
    if (e >= 1) return 0;
    const Real l = std::log(e), pi = 3.14159265358979323846;
    return -l / std::sqrt(pi * pi + l * l);
}

Real tsuji_restitution(Real alpha) {
    // X(0) = 0, X'(0) = 1; RK4 on (X, V) until the clamped force vanishes while separating.
    auto acc = [alpha](Real x, Real v) {
        const Real xp = x > 0 ? x : 0;
        const Real f = -xp * std::sqrt(xp) - alpha * std::sqrt(std::sqrt(xp)) * v;
        return f < 0 ? f : Real(0); // no tension
    };
    Real x = 0, v = 1;
    const Real h = 2e-4;
    for (int step = 0; step < 200000; ++step) {
        const Real k1x = v, k1v = acc(x, v);
        const Real k2x = v + 0.5 * h * k1v, k2v = acc(x + 0.5 * h * k1x, v + 0.5 * h * k1v);
        const Real k3x = v + 0.5 * h * k2v, k3v = acc(x + 0.5 * h * k2x, v + 0.5 * h * k2v);
        const Real k4x = v + h * k3v, k4v = acc(x + h * k3x, v + h * k3v);
        x += h / 6 * (k1x + 2 * k2x + 2 * k3x + k4x);
        v += h / 6 * (k1v + 2 * k2v + 2 * k3v + k4v);
        if (v < 0 && (x <= 0 || acc(x, v) == 0)) return -v;
    }
    return 0;
}

Real tsuji_alpha(Real e) {
    if (e >= 1) return 0;
    if (!(e >= hertz_min_restitution))
        throw InputError(fmt::format("restitution {} of a hertz_mindlin pair is below {}: the "
                                     "Tsuji damping is that of an overdamped contact there",
                                     e, hertz_min_restitution));
    // e(alpha) falls monotonically: e(64) = 3e-4 < hertz_min_restitution, so hi stays <= 64.
    Real lo = 0, hi = 1;
    while (tsuji_restitution(hi) > e && hi < 64) hi *= 2;
    for (int it = 0; it < 50; ++it) {
        const Real mid = 0.5 * (lo + hi);
        (tsuji_restitution(mid) > e ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

} // namespace debrisflow::dem
