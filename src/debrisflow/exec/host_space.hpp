#pragma once
// The host's memory space and the data-parallel primitives a resident time loop is written
// against (sph/resident_sph.hpp): the same calls as CudaSpace (exec/cuda_space.cuh), run on
// the host's threads through exec/parallel.hpp. A loop written against a Space runs on either;
// the host one is what CI exercises of the device's code path.
#include "debrisflow/core/real.hpp"
#include "debrisflow/exec/counting_sort.hpp"
#include "debrisflow/exec/parallel.hpp"
#include <algorithm>
#include <cstddef>
#include <vector>

namespace debrisflow::exec {

struct HostSpace {
    // An array in this space. Copies to and from the host are explicit (upload, download).
    template <class T> class Buffer {
    public:
        T* data() { return v_.data(); }
        const T* data() const { return v_.data(); }
        Index size() const { return Index(v_.size()); }
        // Grows with an eighth to spare (appends come in layers), contents kept; the first
        // allocation is exact.
        void resize(Index n) {
            const std::size_t m = std::size_t(n);
            if (m > v_.capacity()) v_.reserve(v_.empty() ? m : m + m / 8);
            v_.resize(m);
        }
        void clear() { std::vector<T>().swap(v_); }
        void upload(const T* src, Index n) { v_.assign(src, src + n); }
        // Copies n values from the host to [offset, offset + n) (inside the size).
        void upload_at(Index offset, const T* src, Index n) {
            std::copy(src, src + n, v_.begin() + offset);
        }
        void download(T* dst) const { std::copy(v_.begin(), v_.end(), dst); }
        void swap(Buffer& o) { v_.swap(o.v_); }
        T at(Index i) const { return v_[std::size_t(i)]; } // one element, copied to the host
        std::size_t bytes() const { return v_.capacity() * sizeof(T); }

    private:
        std::vector<T> v_;
    };

    // f(i) for i in [0, n).
    template <class F> static void for_each(Index n, const F& f) { exec::for_each(n, f); }

    // max over i of f(i) for f >= 0 (0 for n = 0).
    template <class F> static Real max_of(Index n, const F& f) { return exec::max_of(n, f); }

    // max over i of f(i) and init.
    template <class F> static Real max_from(Index n, const F& f, Real init) {
        return exec::max_of(n, init, f);
    }

    // sum over i of f(i) (0 for n = 0).
    template <class F> static Real sum_of(Index n, const F& f) { return exec::sum_of<Real>(n, f); }

    // out[i] = in[0] + ... + in[i-1]; returns the total (stream compaction's positions).
    static Index exclusive_scan(Index n, const Index* in, Index* out) {
        return exec::exclusive_scan<Index>(
            n, [=](Index i) { return in[i]; }, out);
    }

    // out[s] = in[start[s]] + ... + in[start[s+1]-1] for each segment s in [0, segments),
    // summed in order from T{} (each segment on one thread: the host's order of a serial sum).
    template <class T>
    static void segmented_sum(Index segments, const Index* start, const T* in, T* out) {
        exec::for_each(segments, [=](Index s) {
            T sum{};
            for (Index k = start[s]; k < start[s + 1]; ++k) sum = sum + in[k];
            out[s] = sum;
        });
    }

    // The fold of f over [0, n): f(i, T&) adds item i into a T; the partial Ts are combined
    // with T::combine, from T{} (a T's default value is the fold's identity). Partial sums are
    // combined in thread order (a run repeats bitwise for a thread count).
    template <class T, class F> static T fold(Index n, const F& f) {
        return exec::reduce(n, T{}, f, [](T& a, const T& b) { T::combine(a, b); });
    }
    // The same on one thread below `serial_below` items, as the host solver's loop of that
    // threshold: a load that moves a body then repeats the host's bitwise (a device ignores
    // the threshold).
    template <class T, class F> static T fold(Index n, const F& f, Index serial_below) {
        return exec::reduce(
            n, T{}, f, [](T& a, const T& b) { T::combine(a, b); },
            exec::serial_below(serial_below));
    }

    // The smallest i with bad(i), or n when there is none.
    template <class F> static Index first_where(Index n, const F& bad) {
        return exec::reduce(
            n, n, [&](Index i, Index& b) { b = (i < b && bad(i)) ? i : b; },
            [](Index& b, Index v) { b = v < b ? v : b; });
    }

    // Sorts the indices 0 .. n-1 stably by their key (keys in [0, key_count)) into order:
    // the cell grid's counting sort. The keys are left as they were.
    class Sorter {
    public:
        void sort(const Index* keys, Index n, Index key_count, Index* order) {
            counting_sort(keys, n, key_count, order, start_, cursor_);
        }
        std::size_t bytes() const {
            return (start_.capacity() + cursor_.capacity()) * sizeof(Index);
        }

    private:
        std::vector<Index> start_, cursor_;
    };

    // Waits until every launched loop has finished (the host's loops return finished).
    static void synchronize() {}
};

} // namespace debrisflow::exec
