#pragma once
// Small CUDA helpers of the GPU checks: error checking, a device arena, a kernel that runs a
// functor over 0 .. n-1, and an event timer.
#include "debrisflow/core/real.hpp"
#include <algorithm>
#include <cuda_runtime.h>
#include <stdexcept>
#include <string>
#include <vector>

namespace debrisflow::gpu {

inline void check(cudaError_t e, const char* what) {
    if (e != cudaSuccess)
        throw std::runtime_error(std::string(what) + ": " + cudaGetErrorString(e));
}

// Device allocations of one evaluation, freed together.
class DeviceArena {
public:
    DeviceArena() = default;
    DeviceArena(const DeviceArena&) = delete;
    DeviceArena& operator=(const DeviceArena&) = delete;
    ~DeviceArena() {
        for (void* p : blocks_) cudaFree(p);
    }
    template <class T> T* alloc(std::size_t n) {
        if (n == 0) return nullptr;
        void* p = nullptr;
        check(cudaMalloc(&p, n * sizeof(T)), "cudaMalloc");
        blocks_.push_back(p);
        return static_cast<T*>(p);
    }
    // A device copy of host[0 .. n), or null for a null host array.
    template <class T> T* copy_in(const T* host, std::size_t n) {
        if (host == nullptr) return nullptr;
        T* d = alloc<T>(n);
        check(cudaMemcpy(d, host, n * sizeof(T), cudaMemcpyHostToDevice), "cudaMemcpy in");
        return d;
    }

private:
    std::vector<void*> blocks_;
};

template <class T> void copy_out(T* host, const T* dev, std::size_t n) {
    if (host && dev)
        check(cudaMemcpy(host, dev, n * sizeof(T), cudaMemcpyDeviceToHost), "cudaMemcpy out");
}

template <class F> __global__ void for_each_kernel(Index n, F f) {
    const Index i = Index(blockIdx.x) * Index(blockDim.x) + Index(threadIdx.x);
    if (i < n) f(i);
}

// f(i) for i = 0 .. n-1 on the device, 128 threads a block.
template <class F> void launch(Index n, const F& f) {
    const int block = 128;
    for_each_kernel<<<unsigned((std::size_t(n) + block - 1) / block), block>>>(n, f);
    check(cudaGetLastError(), "kernel launch");
}

class EventTimer {
public:
    EventTimer() {
        check(cudaEventCreate(&a_), "cudaEventCreate");
        check(cudaEventCreate(&b_), "cudaEventCreate");
    }
    ~EventTimer() {
        cudaEventDestroy(a_);
        cudaEventDestroy(b_);
    }
    EventTimer(const EventTimer&) = delete;
    EventTimer& operator=(const EventTimer&) = delete;
    void start() { check(cudaEventRecord(a_), "cudaEventRecord"); }
    double stop_ms() {
        check(cudaEventRecord(b_), "cudaEventRecord");
        check(cudaEventSynchronize(b_), "cudaEventSynchronize");
        float ms = 0;
        check(cudaEventElapsedTime(&ms, a_, b_), "cudaEventElapsedTime");
        return ms;
    }

private:
    cudaEvent_t a_{}, b_{};
};

// Median of the samples (sorted in place).
inline double median(std::vector<double>& v) {
    std::sort(v.begin(), v.end());
    return v.empty() ? 0 : v[v.size() / 2];
}

} // namespace debrisflow::gpu
