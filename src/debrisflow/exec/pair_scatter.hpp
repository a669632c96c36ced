#pragma once
#include "debrisflow/core/vec3_k.hpp"
#include "debrisflow/neighbors/pair_list.hpp"
#include <cstdint>
#include <omp.h>
#include <stdexcept>
#include <string>
#include <vector>

namespace debrisflow::exec {

// Per-thread accumulation buffers for symmetric pair loops: W values per particle.
struct ScatterBuffers {
    std::vector<std::vector<Real>> per_thread;
};

// Runs pair(load(i), i, j, acc_i, out_j) over every pair of a half list, each pair once: the
// pair adds particle i's contribution to acc_i[0..W) and particle j's to out_j[0..W).
// out(i, totals) then receives each particle's W totals (zeros for particles in no pair).
// Threads write their own buffers (no atomics), summed at the end in thread order, so a run is
// reproducible for a given thread count; load(i) fetches particle i's data once. Only the
// list's non-empty rows are visited and only the particles in some pair are cleared and
// summed: a model made mostly of boundary particles (a long flume) costs what its fluid costs.
template <int W, class Load, class Pair, class Out>
void for_each_pair_w(const neighbors::PairList& list, Index n, ScatterBuffers& buf,
                     const Load& load, const Pair& pair, const Out& out) {
    if (list.particles() != n)
        throw std::logic_error("pair loop over " + std::to_string(n) +
                               " particles with a pair list built for " +
                               std::to_string(list.particles()));
    const int nt = omp_get_max_threads();
    buf.per_thread.resize(std::size_t(nt));
    for (auto& b : buf.per_thread) b.resize(W * std::size_t(n));
    const Index* nb = list.neighbors();
    const Index* rows = list.rows().data();
    const Index nrows = Index(list.rows().size());
    const Index* touched = list.touched().data();
    const Index ntouched = Index(list.touched().size());
    const std::uint8_t* mask = list.touched_mask();
#pragma omp parallel
    {
        Real* b = buf.per_thread[std::size_t(omp_get_thread_num())].data();
        for (Index k = 0; k < ntouched; ++k) // each thread clears its own buffer
            for (int w = 0; w < W; ++w) b[W * touched[k] + w] = 0;
#pragma omp for schedule(static, 64) // round-robin chunks of rows: balanced and deterministic
        for (Index r = 0; r < nrows; ++r) {
            const Index i = rows[r];
            Real acc[W] = {};
            const Index* js = nb + list.begin(i);
            const Index c = list.count(i);
            const auto data_i = load(i);
            for (Index k = 0; k < c; ++k) pair(data_i, i, js[k], acc, b + W * js[k]);
            for (int w = 0; w < W; ++w) b[W * i + w] += acc[w];
        }
#pragma omp for schedule(static)
        for (Index i = 0; i < n; ++i) {
            Real total[W] = {};
            if (mask[i])
                for (int t = 0; t < nt; ++t) {
                    const Real* bt = buf.per_thread[std::size_t(t)].data() + W * i;
                    for (int w = 0; w < W; ++w) total[w] += bt[w];
                }
            out(i, static_cast<const Real*>(total));
        }
    }
}

} // namespace debrisflow::exec
