#pragma once
#include "debrisflow/core/real.hpp"
#include <cstdint>
#include <omp.h>
#include <vector>

namespace debrisflow::exec {

// The only place that knows how loops run on the host (OpenMP). A CUDA backend will provide
// the same calls launching the same functors. Nothing outside exec/ writes a `#pragma omp`.

// How a loop is split over the threads.
struct Loop {
    int chunk = 0;          // 0: one contiguous block per thread (static); > 0: dynamic chunks
    Index serial_below = 0; // loops of fewer iterations run on the calling thread alone
};

// A loop that balances uneven work (neighbour searches): dynamic chunks of `chunk`.
inline Loop dynamic(int chunk, Index serial_below = 0) {
    return {chunk, serial_below};
}
// Contiguous blocks, on the calling thread alone below `n` iterations.
inline Loop serial_below(Index n) {
    return {0, n};
}

int max_threads();
void set_threads(int n);

// f(i) for i in [0, n).
template <class F> void for_each(Index n, const F& f, Loop loop = {}) {
    const bool parallel = n >= loop.serial_below;
    if (loop.chunk > 0) {
        const int chunk = loop.chunk;
#pragma omp parallel for schedule(dynamic, chunk) if (parallel)
        for (Index i = 0; i < n; ++i) f(i);
    } else {
#pragma omp parallel for schedule(static) if (parallel)
        for (Index i = 0; i < n; ++i) f(i);
    }
}

// Folds [0, n) into one value: each thread starts from `identity` and calls f(i, acc) on its
// iterations; the threads' values are then combined, combine(total, part), in thread order, so
// a run repeats bitwise for a given thread count (and at one thread equals the serial loop).
template <class Acc, class F, class Combine>
Acc reduce(Index n, const Acc& identity, const F& f, const Combine& combine, Loop loop = {}) {
    Acc total = identity;
    if (n < loop.serial_below || omp_get_max_threads() == 1) {
        for (Index i = 0; i < n; ++i) f(i, total);
        return total;
    }
    const int chunk = loop.chunk;
#pragma omp parallel
    {
        Acc part = identity;
        if (chunk > 0) {
#pragma omp for schedule(dynamic, chunk) nowait
            for (Index i = 0; i < n; ++i) f(i, part);
        } else {
#pragma omp for schedule(static) nowait
            for (Index i = 0; i < n; ++i) f(i, part);
        }
        // schedule(static, 1) hands iteration t to thread t; `ordered` runs them in turn.
        const int nt = omp_get_num_threads();
#pragma omp for ordered schedule(static, 1)
        for (int t = 0; t < nt; ++t) {
#pragma omp ordered
            combine(total, part);
        }
    }
    return total;
}

// max over i of f(i), or `floor` when every f(i) is below it (and for n = 0).
template <class T, class F> T max_of(Index n, T floor, const F& f, Loop loop = {}) {
    return reduce(
        n, floor,
        [&](Index i, T& m) {
            const T v = f(i);
            m = v > m ? v : m;
        },
        [](T& m, const T& v) { m = v > m ? v : m; }, loop);
}

// max over i of f(i) for f returning Real >= 0 (0 for n = 0).
template <class F> Real max_of(Index n, const F& f, Loop loop = {}) {
    return max_of(n, Real(0), f, loop);
}

// sum over i of f(i).
template <class T, class F> T sum_of(Index n, const F& f, Loop loop = {}) {
    return reduce(
        n, T(0), [&](Index i, T& s) { s += f(i); }, [](T& s, const T& v) { s += v; }, loop);
}

// out[i] = value(0) + ... + value(i - 1) for i in [0, n) (an exclusive prefix sum, the step
// that turns per-item counts into positions: stream compaction, counting sorts); returns the
// total. In two passes over contiguous blocks, one per thread: each block's sum, then each
// block's prefix from the sums of the blocks before it. Integer sums repeat exactly.
template <class T, class F> T exclusive_scan(Index n, const F& value, T* out, Loop loop = {}) {
    const int nt = n < loop.serial_below ? 1 : omp_get_max_threads();
    if (nt == 1) {
        T sum = 0;
        for (Index i = 0; i < n; ++i) {
            out[i] = sum;
            sum += value(i);
        }
        return sum;
    }
    T total = 0;
    std::vector<T> block(std::size_t(nt) + 1, T(0));
#pragma omp parallel num_threads(nt)
    {
        const int t = omp_get_thread_num(), m = omp_get_num_threads();
        const Index lo = Index(std::int64_t(n) * t / m), hi = Index(std::int64_t(n) * (t + 1) / m);
        T sum = 0;
        for (Index i = lo; i < hi; ++i) sum += value(i);
        block[std::size_t(t) + 1] = sum;
#pragma omp barrier
#pragma omp single
        {
            for (int b = 0; b < m; ++b) block[std::size_t(b) + 1] += block[std::size_t(b)];
            total = block[std::size_t(m)];
        }
        T run = block[std::size_t(t)];
        for (Index i = lo; i < hi; ++i) {
            out[i] = run;
            run += value(i);
        }
    }
    return total;
}

// A team of threads running one body together: its thread number, its size, and a barrier
// all of them wait at.
struct Team {
    int thread = 0;
    int size = 1;
    void barrier() const {
#pragma omp barrier
    }
};

// body(team) on `threads` threads at once (1: on the calling thread).
template <class F> void team(int threads, const F& body) {
    if (threads <= 1) {
        body(Team{0, 1});
        return;
    }
#pragma omp parallel num_threads(threads)
    body(Team{omp_get_thread_num(), omp_get_num_threads()});
}

// x += v where several threads may add to x at once.
inline void atomic_add(Real& x, Real v) {
#pragma omp atomic
    x += v;
}

} // namespace debrisflow::exec
