#pragma once
// The small per-item steps of the resident SPH loop (sph/resident_sph.hpp) that the host
// solver does with its own containers: the grid's cell starts, reordering, the constant
// viscosity, and the predicates its reductions look for. Host/device functors.
#include "debrisflow/particles/particle_set.hpp"
#include "debrisflow/sph/time_schemes_k.hpp"
#include <type_traits>

namespace debrisflow::sph {

// start[c] = the first sorted position whose key is >= c (a binary search over the keys in
// sorted order), for c in [0, key_count]: with keys sorted stably, cell c's particles are
// order[start[c]] .. order[start[c+1]-1], as CellGrid's counting sort leaves them.
struct CellStarts {
    const Index* key;   // per particle
    const Index* order; // sorted position -> particle
    Index n;
    Index* start;
    DF_HD void operator()(Index c) const {
        Index lo = 0, hi = n;
        while (lo < hi) {
            const Index mid = lo + (hi - lo) / 2;
            if (key[order[mid]] < c)
                lo = mid + 1;
            else
                hi = mid;
        }
        start[c] = lo;
    }
};

// out[i] = in[order[i]] for `width` values per item (a permutation applied by gathering).
template <class T> struct GatherByOrder {
    const T* in;
    const Index* order;
    T* out;
    int width;
    DF_HD void operator()(Index i) const {
        const std::size_t to = std::size_t(i) * width, from = std::size_t(order[i]) * width;
        for (int k = 0; k < width; ++k) out[to + k] = in[from + k];
    }
};

// Whether sorted position i holds another particle than i (the particles are not in order).
struct OutOfOrder {
    const Index* order;
    DF_HD bool operator()(Index i) const { return order[i] != i; }
};

// A constant dynamic viscosity mu for fluid particles, 0 for walls (the pair term uses the
// fluid partner's).
struct FluidViscosity {
    particles::ParticleView pv;
    Real mu;
    DF_HD void operator()(Index i) const { pv.mu[i] = pv.is_fluid(i) ? mu : Real(0); }
};

// mu_i / rho_i of a fluid particle (the viscous step limit of a generalised-Newtonian fluid).
struct FluidKinematicViscosity {
    particles::ParticleView pv;
    DF_HD Real operator()(Index i) const { return pv.is_fluid(i) ? pv.mu[i] / pv.rho[i] : Real(0); }
};

// f(i) >= value (the particle that attains a reduction's maximum).
template <class F> struct AtLeast {
    F f;
    Real value;
    DF_HD bool operator()(Index i) const { return f(i) >= value; }
};

// The particles the health check stops at.
struct Unhealthy {
    ParticleHealthy healthy;
    DF_HD bool operator()(Index i) const { return !healthy(i); }
};

static_assert(std::is_trivially_copyable_v<CellStarts>);
static_assert(std::is_trivially_copyable_v<Unhealthy>);

} // namespace debrisflow::sph
