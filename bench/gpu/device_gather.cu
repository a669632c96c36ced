// The SPH gather loop body (sph::FluidInteraction, the functor the host runs in
// compute_forces_gather) launched on a GPU over a device copy of the state it reads.
#include "debrisflow/sph/sph_solver_gather.hpp"
#include "device_gather.hpp"
#include <algorithm>
#include <cuda_runtime.h>
#include <stdexcept>
#include <vector>

namespace debrisflow::gpu {

namespace {

void check(cudaError_t e, const char* what) {
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

template <class F> __global__ void for_each_kernel(Index n, F f) {
    const Index i = Index(blockIdx.x) * Index(blockDim.x) + Index(threadIdx.x);
    if (i < n) f(i);
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

// The functor with every array it reads or writes replaced by a device copy (outputs are
// allocated, not copied). n particles, `cells` grid cells.
template <class K, class V, class D>
sph::FluidInteraction<K, V, D> to_device(sph::FluidInteraction<K, V, D> f, std::size_t cells,
                                         DeviceArena& a) {
    auto& pv = f.terms.pv;
    const std::size_t n = std::size_t(pv.n);
    for (Real** p : {&pv.x, &pv.y, &pv.z, &pv.vx, &pv.vy, &pv.vz, &pv.rho, &pv.p, &pv.mass, &pv.wnx,
                     &pv.wny, &pv.wnz, &pv.wd, &pv.mu})
        *p = a.copy_in(*p, n);
    pv.kind = a.copy_in(pv.kind, n);
    pv.group = a.copy_in(pv.group, n);
    for (Real** p : {&pv.ax, &pv.ay, &pv.az, &pv.drho}) *p = a.alloc<Real>(n);
    f.terms.prho = a.copy_in(f.terms.prho, n);
    f.terms.cs = a.copy_in(f.terms.cs, n);
    f.terms.vol = a.copy_in(f.terms.vol, n);
    f.terms.tau = a.copy_in(f.terms.tau, 6 * n);
    f.grid.start = a.copy_in(f.grid.start, cells + 1);
    f.grid.order = a.copy_in(f.grid.order, n);
    f.tau_next = V::needs_velocity_gradient ? a.alloc<Real>(6 * n) : nullptr;
    return f;
}

template <class T> void copy_out(T* host, const T* dev, std::size_t n) {
    if (host && dev)
        check(cudaMemcpy(host, dev, n * sizeof(T), cudaMemcpyDeviceToHost), "cudaMemcpy out");
}

} // namespace

std::string first_device() {
    int count = 0;
    if (const cudaError_t e = cudaGetDeviceCount(&count); e != cudaSuccess || count == 0)
        throw NoDevice(e != cudaSuccess ? cudaGetErrorString(e) : "no CUDA device");
    cudaDeviceProp prop{};
    check(cudaGetDeviceProperties(&prop, 0), "cudaGetDeviceProperties");
    return prop.name;
}

DeviceTimes gather_on_device(sph::SphSolver& solver, int repeats) {
    DeviceTimes t;
    t.device = first_device();
    check(cudaSetDevice(0), "cudaSetDevice");
    const std::size_t cells = std::size_t(solver.grid().cell_count());
    solver.with_gather([&](const auto& host) {
        const std::size_t n = std::size_t(host.terms.pv.n);
        DeviceArena arena;
        EventTimer timer;
        check(cudaFree(nullptr), "CUDA context"); // create the context outside the timings
        timer.start();
        const auto f = to_device(host, cells, arena);
        t.upload_ms = timer.stop_ms();
        const int block = 128;
        const unsigned grid = unsigned((n + block - 1) / block);
        std::vector<double> ms;
        for (int r = 0; r < std::max(repeats, 1); ++r) {
            timer.start();
            for_each_kernel<<<grid, block>>>(Index(n), f);
            check(cudaGetLastError(), "kernel launch");
            ms.push_back(timer.stop_ms());
        }
        std::sort(ms.begin(), ms.end());
        t.kernel_ms = ms[ms.size() / 2];
        timer.start();
        const auto& pv = host.terms.pv;
        copy_out(pv.ax, f.terms.pv.ax, n);
        copy_out(pv.ay, f.terms.pv.ay, n);
        copy_out(pv.az, f.terms.pv.az, n);
        copy_out(pv.drho, f.terms.pv.drho, n);
        copy_out(host.tau_next, f.tau_next, 6 * n);
        t.download_ms = timer.stop_ms();
    });
    return t;
}

} // namespace debrisflow::gpu
