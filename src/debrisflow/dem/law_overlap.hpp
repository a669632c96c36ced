#pragma once
#include "debrisflow/dem/contact_laws_k.hpp"

namespace debrisflow::dem {

// A pair's contact law at rest, whatever the law (the registry's own normal response, so
// Hertz, DCDEM and JKR adhesion count as they act; no per-law code): the elastic force at an
// overlap, the overlap that carries a force, and the overlap that takes up a kinetic energy.
// Host-side, for checks of a case before it runs.

// The elastic normal force of pair p at overlap delta (no dashpot).
inline Real elastic_force(const PairParams& p, Real r_eff, Real delta) {
    Real friction_factor = 1;
    const ContactInput in{delta, 0, r_eff, 1, 1};
    return normal_response(p, in, 0, friction_factor).fn;
}

// The smallest x in [0, limit] where the increasing grows(x) reaches target, by bisection to
// `tolerance` x limit; limit when grows(limit) stays below it.
template <class F> Real bisect_increasing(F grows, Real target, Real limit, Real tolerance) {
    if (grows(limit) < target) return limit;
    Real lo = 0, hi = limit;
    for (int it = 0; it < 200 && hi - lo > tolerance * limit; ++it) {
        const Real mid = Real(0.5) * (lo + hi);
        (grows(mid) < target ? lo : hi) = mid;
    }
    return hi;
}

// The overlap at which pair p carries `force`, by bisection on [0, limit] (every law's elastic
// force grows with the overlap); `limit` when even that overlap carries less.
inline Real overlap_carrying(const PairParams& p, Real r_eff, Real force, Real limit) {
    return bisect_increasing([&](Real d) { return elastic_force(p, r_eff, d); }, force, limit,
                             Real(1e-14));
}

// The elastic work int_0^delta F dx (Simpson's rule on 64 intervals: exact for the linear law,
// 1e-5 relative for Hertz's delta^1.5).
inline Real elastic_work(const PairParams& p, Real r_eff, Real delta) {
    constexpr int n = 64;
    const Real step = delta / n;
    Real sum = elastic_force(p, r_eff, 0) + elastic_force(p, r_eff, delta);
    for (int k = 1; k < n; ++k) sum += (k % 2 ? 4 : 2) * elastic_force(p, r_eff, k * step);
    return sum * step / 3;
}

// The largest overlap of an undamped impact that brings kinetic energy `energy` to rest
// (1/2 m* v^2 = the law's elastic work), by bisection on [0, limit]; `limit` when even that
// overlap takes up less. The dashpot only shortens it.
inline Real overlap_absorbing(const PairParams& p, Real r_eff, Real energy, Real limit) {
    return bisect_increasing([&](Real d) { return elastic_work(p, r_eff, d); }, energy, limit,
                             Real(1e-10));
}

} // namespace debrisflow::dem
