#pragma once
#include "debrisflow/core/real.hpp"

namespace debrisflow::exec {

// The only place that knows how particle loops run on the host (OpenMP). A CUDA backend
// will provide the same calls launching the same functors.
template <class F> void for_each(Index n, const F& f) {
#pragma omp parallel for schedule(static)
    for (Index i = 0; i < n; ++i) f(i);
}

// max over i of f(i) (f returns Real >= 0).
template <class F> Real max_of(Index n, const F& f) {
    Real m = 0;
#pragma omp parallel for schedule(static) reduction(max : m)
    for (Index i = 0; i < n; ++i) {
        const Real v = f(i);
        m = v > m ? v : m;
    }
    return m;
}

int max_threads();
void set_threads(int n);

} // namespace debrisflow::exec
