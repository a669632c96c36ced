// The SPH gather loop body (sph::FluidInteraction, the functor the host runs in
// compute_forces_gather) launched on a GPU over a device copy of the state it reads.
#include "cuda_support.cuh"
#include "debrisflow/sph/sph_solver_gather.hpp"
#include "device_gather.hpp"
#include <algorithm>
#include <cuda_runtime.h>
#include <stdexcept>
#include <vector>

namespace debrisflow::gpu {

namespace {

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
    if (f.terms.grad_rho) f.terms.grad_rho = a.copy_in(f.terms.grad_rho, 3 * n);
    f.grid.start = a.copy_in(f.grid.start, cells * std::size_t(f.grid.classes) + 1);
    f.grid.order = a.copy_in(f.grid.order, n);
    f.tau_next = V::needs_velocity_gradient ? a.alloc<Real>(6 * n) : nullptr;
    return f;
}

} // namespace

DeviceTimes gather_on_device(sph::SphSolver& solver, int repeats) {
    DeviceTimes t;
    t.device = first_device();
    const std::size_t cells = std::size_t(solver.grid().cell_count());
    solver.with_gather([&](const auto& host) {
        const std::size_t n = std::size_t(host.terms.pv.n);
        DeviceArena arena;
        EventTimer timer;
        timer.start();
        const auto f = to_device(host, cells, arena);
        t.upload_ms = timer.stop_ms();
        std::vector<double> ms;
        for (int r = 0; r < std::max(repeats, 1); ++r) {
            timer.start();
            launch(Index(n), f);
            ms.push_back(timer.stop_ms());
        }
        t.kernel_ms = median(ms);
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
