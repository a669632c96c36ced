#pragma once
#include "debrisflow/core/vec3_k.hpp"
#include "debrisflow/neighbors/pair_list.hpp"
#include <algorithm>
#include <omp.h>
#include <vector>

namespace debrisflow::exec {

// Per-thread accumulation buffers for symmetric pair loops: (x, y, z, scalar) per particle.
struct ScatterBuffers {
    std::vector<std::vector<Real>> per_thread;
};

// Runs pair(load(i), i, j, vec_i, s_i, out_j) over every pair of a half list, each pair once:
// the pair adds particle i's contribution to (vec_i, s_i) and particle j's to out_j[0..3].
// out(i, vec, s) then receives each particle's totals. Threads write their own buffers (no
// atomics), which are summed at the end; load(i) fetches particle i's data once.
template <class Load, class Pair, class Out>
void for_each_pair(const neighbors::PairList& list, Index n, ScatterBuffers& buf, const Load& load,
                   const Pair& pair, const Out& out) {
    const int nt = omp_get_max_threads();
    buf.per_thread.resize(std::size_t(nt));
    for (auto& b : buf.per_thread) b.resize(4 * std::size_t(n));
    const Index* nb = list.neighbors();
#pragma omp parallel
    {
        Real* b = buf.per_thread[std::size_t(omp_get_thread_num())].data();
        std::fill(b, b + 4 * std::size_t(n), Real(0)); // each thread clears its own buffer
#pragma omp for schedule(static, 64) // round-robin chunks: balanced and deterministic
        for (Index i = 0; i < n; ++i) {
            Vec3 vi{};
            Real si = 0;
            const Index* js = nb + list.begin(i);
            const Index c = list.count(i);
            const auto data_i = load(i);
            for (Index k = 0; k < c; ++k) {
                const Index j = js[k];
                pair(data_i, i, j, vi, si, b + 4 * j);
            }
            b[4 * i] += vi.x;
            b[4 * i + 1] += vi.y;
            b[4 * i + 2] += vi.z;
            b[4 * i + 3] += si;
        }
#pragma omp for schedule(static)
        for (Index i = 0; i < n; ++i) {
            Vec3 v{};
            Real s = 0;
            for (int t = 0; t < nt; ++t) {
                const Real* bt = buf.per_thread[std::size_t(t)].data() + 4 * i;
                v += Vec3{bt[0], bt[1], bt[2]};
                s += bt[3];
            }
            out(i, v, s);
        }
    }
}

// The same loop with W values per particle: pair(load(i), i, j, acc_i, out_j) adds to
// acc_i[0..W) and out_j[0..W); out(i, totals) receives each particle's W totals.
template <int W, class Load, class Pair, class Out>
void for_each_pair_w(const neighbors::PairList& list, Index n, ScatterBuffers& buf,
                     const Load& load, const Pair& pair, const Out& out) {
    const int nt = omp_get_max_threads();
    buf.per_thread.resize(std::size_t(nt));
    for (auto& b : buf.per_thread) b.resize(W * std::size_t(n));
    const Index* nb = list.neighbors();
#pragma omp parallel
    {
        Real* b = buf.per_thread[std::size_t(omp_get_thread_num())].data();
        std::fill(b, b + W * std::size_t(n), Real(0));
#pragma omp for schedule(static, 64)
        for (Index i = 0; i < n; ++i) {
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
            for (int t = 0; t < nt; ++t) {
                const Real* bt = buf.per_thread[std::size_t(t)].data() + W * i;
                for (int w = 0; w < W; ++w) total[w] += bt[w];
            }
            out(i, total);
        }
    }
}

} // namespace debrisflow::exec
