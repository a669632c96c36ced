#pragma once
// A CUDA device's memory space and the data-parallel primitives of a resident time loop: the
// same calls as HostSpace (exec/host_space.hpp), on the device. Arrays are device memory;
// loops are kernels launching the same host/device functors; reductions and the stable sort
// are CUB's (shipped with the CUDA toolkit). Compiled by nvcc only (exec/cuda_instantiations.cu).
#include "debrisflow/core/real.hpp"
#include <cstddef>
#include <cub/device/device_radix_sort.cuh>
#include <cub/device/device_reduce.cuh>
#include <cub/device/device_scan.cuh>
#include <cub/device/device_segmented_reduce.cuh>
#include <cuda_runtime.h>
#include <stdexcept>
#include <string>
#include <utility>

namespace debrisflow::exec {

inline void cuda_check(cudaError_t e, const char* what) {
    if (e != cudaSuccess)
        throw std::runtime_error(std::string("CUDA: ") + what + ": " + cudaGetErrorString(e));
}

namespace cuda_detail {

template <class F> __global__ void for_each_kernel(Index n, F f) {
    const Index i = Index(blockIdx.x) * Index(blockDim.x) + Index(threadIdx.x);
    if (i < n) f(i);
}

// out[i] = f(i): what a reduction reduces.
template <class F, class T> struct EvaluateInto {
    F f;
    T* out;
    __device__ void operator()(Index i) const { out[i] = T(f(i)); }
};

// i where bad(i), n otherwise (the minimum is the first bad index).
template <class F> struct IndexWhere {
    F bad;
    Index n;
    __device__ Index operator()(Index i) const { return bad(i) ? i : n; }
};

// The reductions' operators.
struct Larger {
    template <class T> __device__ T operator()(T a, T b) const { return a > b ? a : b; }
};
struct Smaller {
    template <class T> __device__ T operator()(T a, T b) const { return a < b ? a : b; }
};
struct Plus {
    template <class T> __device__ T operator()(T a, T b) const { return a + b; }
};

// out[i] = T{} with item i folded in (f(i, T&)): what a fold reduces.
template <class F, class T> struct FoldInto {
    F f;
    T* out;
    __device__ void operator()(Index i) const {
        T t{};
        f(i, t);
        out[i] = t;
    }
};

// T::combine as a binary operator for CUB.
template <class T> struct Combine {
    __device__ T operator()(T a, const T& b) const {
        T::combine(a, b);
        return a;
    }
};

struct Iota {
    Index* out;
    __device__ void operator()(Index i) const { out[i] = i; }
};

} // namespace cuda_detail

struct CudaSpace {
    // An array in device memory. Grows by reallocation with an eighth to spare (appends come
    // in layers), contents kept; copies to and from the host are explicit.
    template <class T> class Buffer {
    public:
        Buffer() = default;
        Buffer(const Buffer&) = delete;
        Buffer& operator=(const Buffer&) = delete;
        ~Buffer() { cudaFree(p_); }
        T* data() { return p_; }
        const T* data() const { return p_; }
        Index size() const { return n_; }
        void resize(Index n) {
            if (n > cap_) {
                const Index cap = n_ > 0 ? n + n / 8 : n;
                T* q = nullptr;
                cuda_check(cudaMalloc(&q, std::size_t(cap) * sizeof(T)), "cudaMalloc");
                if (n_ > 0)
                    cuda_check(
                        cudaMemcpy(q, p_, std::size_t(n_) * sizeof(T), cudaMemcpyDeviceToDevice),
                        "cudaMemcpy (grow)");
                cudaFree(p_);
                p_ = q;
                cap_ = cap;
            }
            n_ = n;
        }
        void clear() {
            cudaFree(p_);
            p_ = nullptr;
            n_ = cap_ = 0;
        }
        void upload(const T* src, Index n) {
            resize(n);
            if (n > 0)
                cuda_check(cudaMemcpy(p_, src, std::size_t(n) * sizeof(T), cudaMemcpyHostToDevice),
                           "cudaMemcpy (upload)");
        }
        // Copies n values from the host to [offset, offset + n) (inside the size).
        void upload_at(Index offset, const T* src, Index n) {
            if (n > 0)
                cuda_check(cudaMemcpy(p_ + offset, src, std::size_t(n) * sizeof(T),
                                      cudaMemcpyHostToDevice),
                           "cudaMemcpy (upload_at)");
        }
        void download(T* dst) const {
            if (n_ > 0)
                cuda_check(cudaMemcpy(dst, p_, std::size_t(n_) * sizeof(T), cudaMemcpyDeviceToHost),
                           "cudaMemcpy (download)");
        }
        void swap(Buffer& o) {
            std::swap(p_, o.p_);
            std::swap(n_, o.n_);
            std::swap(cap_, o.cap_);
        }
        T at(Index i) const {
            T v{};
            cuda_check(cudaMemcpy(&v, p_ + i, sizeof(T), cudaMemcpyDeviceToHost),
                       "cudaMemcpy (at)");
            return v;
        }
        std::size_t bytes() const { return std::size_t(cap_) * sizeof(T); }

    private:
        T* p_ = nullptr;
        Index n_ = 0, cap_ = 0;
    };

    template <class F> static void for_each(Index n, const F& f) {
        if (n <= 0) return;
        const int block = 128;
        cuda_detail::for_each_kernel<<<(n + block - 1) / block, block>>>(n, f);
        cuda_check(cudaGetLastError(), "kernel launch");
    }

    // max over i of f(i) for f >= 0 (0 for n = 0).
    template <class F> static Real max_of(Index n, const F& f) {
        const Real m = reduce<Real>(n, f, cuda_detail::Larger{}, Real(0));
        return m > 0 ? m : Real(0);
    }

    // max over i of f(i) and init.
    template <class F> static Real max_from(Index n, const F& f, Real init) {
        return reduce<Real>(n, f, cuda_detail::Larger{}, init);
    }

    // sum over i of f(i) (0 for n = 0).
    template <class F> static Real sum_of(Index n, const F& f) {
        return reduce<Real>(n, f, cuda_detail::Plus{}, Real(0));
    }

    // out[i] = in[0] + ... + in[i-1]; returns the total (CUB's scan).
    static Index exclusive_scan(Index n, const Index* in, Index* out) {
        if (n <= 0) return 0;
        auto& s = scratch();
        std::size_t bytes = 0;
        cuda_check(cub::DeviceScan::ExclusiveSum(nullptr, bytes, in, out, n),
                   "cub::DeviceScan::ExclusiveSum (size)");
        s.temp.resize(Index(bytes));
        cuda_check(cub::DeviceScan::ExclusiveSum(s.temp.data(), bytes, in, out, n),
                   "cub::DeviceScan::ExclusiveSum");
        Index last_in = 0, last_out = 0;
        cuda_check(cudaMemcpy(&last_in, in + n - 1, sizeof(Index), cudaMemcpyDeviceToHost),
                   "cudaMemcpy (scan)");
        cuda_check(cudaMemcpy(&last_out, out + n - 1, sizeof(Index), cudaMemcpyDeviceToHost),
                   "cudaMemcpy (scan)");
        return last_out + last_in;
    }

    // out[s] = in[start[s]] + ... + in[start[s+1]-1] for each segment s in [0, segments)
    // (CUB's segmented reduction; its order of summation is CUB's).
    template <class T>
    static void segmented_sum(Index segments, const Index* start, const T* in, T* out) {
        if (segments <= 0) return;
        auto& s = scratch();
        std::size_t bytes = 0;
        cuda_check(cub::DeviceSegmentedReduce::Reduce(nullptr, bytes, in, out, segments, start,
                                                      start + 1, cuda_detail::Plus{}, T{}),
                   "cub::DeviceSegmentedReduce::Reduce (size)");
        s.temp.resize(Index(bytes));
        cuda_check(cub::DeviceSegmentedReduce::Reduce(s.temp.data(), bytes, in, out, segments,
                                                      start, start + 1, cuda_detail::Plus{}, T{}),
                   "cub::DeviceSegmentedReduce::Reduce");
    }

    // The fold of f over [0, n): f(i, T&) adds item i into a T; the items' Ts are combined
    // with T::combine from T{} by CUB's reduction (its order of combination is CUB's).
    template <class T, class F> static T fold(Index n, const F& f) {
        if (n <= 0) return T{};
        static Buffer<T> values, out; // one pair per folded type, kept between calls
        auto& s = scratch();
        values.resize(n);
        out.resize(1);
        for_each(n, cuda_detail::FoldInto<F, T>{f, values.data()});
        std::size_t bytes = 0;
        cuda_check(cub::DeviceReduce::Reduce(nullptr, bytes, values.data(), out.data(), n,
                                             cuda_detail::Combine<T>{}, T{}),
                   "cub::DeviceReduce::Reduce (size)");
        s.temp.resize(Index(bytes));
        cuda_check(cub::DeviceReduce::Reduce(s.temp.data(), bytes, values.data(), out.data(), n,
                                             cuda_detail::Combine<T>{}, T{}),
                   "cub::DeviceReduce::Reduce");
        return out.at(0);
    }

    // The host space's threshold for folding on one thread has no meaning on a device.
    template <class T, class F> static T fold(Index n, const F& f, Index) { return fold<T>(n, f); }

    // The smallest i with bad(i), or n when there is none.
    template <class F> static Index first_where(Index n, const F& bad) {
        return reduce<Index>(n, cuda_detail::IndexWhere<F>{bad, n}, cuda_detail::Smaller{}, n);
    }

    // Sorts the indices 0 .. n-1 stably by their key (keys in [0, key_count)) into order:
    // CUB's radix sort of (key, index) pairs over the key's significant bits.
    class Sorter {
    public:
        void sort(const Index* keys, Index n, Index key_count, Index* order) {
            if (n <= 0) return;
            int bits = 1;
            while (bits < 31 && (Index(1) << bits) < key_count) ++bits;
            iota_.resize(n);
            keys_out_.resize(n);
            for_each(n, cuda_detail::Iota{iota_.data()});
            std::size_t bytes = 0;
            cuda_check(cub::DeviceRadixSort::SortPairs(nullptr, bytes, keys, keys_out_.data(),
                                                       iota_.data(), order, n, 0, bits),
                       "cub::DeviceRadixSort::SortPairs (size)");
            temp_.resize(Index(bytes));
            cuda_check(cub::DeviceRadixSort::SortPairs(temp_.data(), bytes, keys, keys_out_.data(),
                                                       iota_.data(), order, n, 0, bits),
                       "cub::DeviceRadixSort::SortPairs");
        }
        std::size_t bytes() const { return iota_.bytes() + keys_out_.bytes() + temp_.bytes(); }

    private:
        Buffer<Index> iota_, keys_out_;
        Buffer<unsigned char> temp_;
    };

    static void synchronize() { cuda_check(cudaDeviceSynchronize(), "cudaDeviceSynchronize"); }

private:
    // op over f(0) .. f(n-1) from init: f into a work array, then CUB's reduction.
    template <class T, class F, class Op> static T reduce(Index n, const F& f, Op op, T init) {
        if (n <= 0) return init;
        auto& s = scratch();
        auto& values = s.values(T{});
        auto& out = s.out(T{});
        values.resize(n);
        out.resize(1);
        for_each(n, cuda_detail::EvaluateInto<F, T>{f, values.data()});
        std::size_t bytes = 0;
        cuda_check(
            cub::DeviceReduce::Reduce(nullptr, bytes, values.data(), out.data(), n, op, init),
            "cub::DeviceReduce::Reduce (size)");
        s.temp.resize(Index(bytes));
        cuda_check(
            cub::DeviceReduce::Reduce(s.temp.data(), bytes, values.data(), out.data(), n, op, init),
            "cub::DeviceReduce::Reduce");
        return out.at(0);
    }

    // The reductions' work arrays, kept between calls.
    struct Scratch {
        Buffer<Real> real_values, real_out;
        Buffer<Index> index_values, index_out;
        Buffer<unsigned char> temp;
        Buffer<Real>& values(Real) { return real_values; }
        Buffer<Index>& values(Index) { return index_values; }
        Buffer<Real>& out(Real) { return real_out; }
        Buffer<Index>& out(Index) { return index_out; }
    };
    static Scratch& scratch() {
        static Scratch s;
        return s;
    }
};

} // namespace debrisflow::exec
