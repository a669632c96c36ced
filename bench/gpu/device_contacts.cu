// The DEM grain-grain contact law (dem::grain_pair_force, as DemSolver::forces calls it) run
// on a GPU, one thread per contact slot, against the same functor on the host.
#include "cuda_support.cuh"
#include "device_contacts.hpp"
#include "scaled_difference.hpp"
#include <algorithm>
#include <chrono>
#include <cmath>

namespace debrisflow::gpu {

namespace {

std::vector<Real> as_reals(const std::vector<dem::ContactHistory>& h) {
    std::vector<Real> r;
    r.reserve(6 * h.size());
    for (const auto& x : h)
        r.insert(r.end(), {x.xi.x, x.xi.y, x.xi.z, x.mroll.x, x.mroll.y, x.mroll.z});
    return r;
}

} // namespace

ContactComparison compare_grain_contacts(const dem::GrainContactInputs& in, int repeats) {
    ContactComparison cmp;
    const std::size_t n = std::size_t(in.n), slots = n * std::size_t(in.capacity);
    cmp.slots = long(slots);
    for (std::size_t i = 0; i < n; ++i) cmp.candidates += in.count[i];

    // host: the same functor, one thread
    std::vector<Real> host_out(9 * slots);
    std::vector<dem::ContactHistory> host_hist(slots);
    const std::vector<dem::ContactHistory> history = dem::slot_histories(in);
    const dem::GrainSlotContact host{in, history.data(), host_out.data(), host_hist.data()};
    const auto t0 = std::chrono::steady_clock::now();
    for (std::size_t s = 0; s < slots; ++s) host(Index(s));
    cmp.host_ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    for (std::size_t s = 0; s < slots; ++s)
        if (host_out[9 * s] != 0 || host_out[9 * s + 1] != 0 || host_out[9 * s + 2] != 0)
            ++cmp.touching;

    // device: the state, the slots, the history and the pair table copied over
    DeviceArena a;
    dem::GrainSlotContact dev = host;
    dev.in.grains = a.copy_in(in.grains, n);
    dev.in.partner = a.copy_in(in.partner, slots);
    dev.in.count = a.copy_in(in.count, n);
    dev.in.xi = dev.in.mroll = nullptr;              // read through history_in
    dev.in.grid.start = dev.in.grid.order = nullptr; // only separation() is used
    dev.in.table.params = a.copy_in(in.table.params, std::size_t(in.table.count * in.table.count));
    dev.history_in = a.copy_in(history.data(), slots);
    dev.out = a.alloc<Real>(9 * slots);
    dev.history_out = a.alloc<dem::ContactHistory>(slots);
    EventTimer timer;
    std::vector<double> ms;
    for (int r = 0; r < std::max(repeats, 1); ++r) {
        timer.start();
        launch(Index(slots), dev);
        ms.push_back(timer.stop_ms());
    }
    cmp.kernel_ms = median(ms);
    std::vector<Real> dev_out(9 * slots);
    std::vector<dem::ContactHistory> dev_hist(slots);
    copy_out(dev_out.data(), dev.out, dev_out.size());
    copy_out(dev_hist.data(), dev.history_out, slots);

    cmp.force = scaled_difference(dev_out, host_out, 9, 0, 3);
    cmp.torque = scaled_difference(dev_out, host_out, 9, 3, 6);
    const auto hd = as_reals(dev_hist), hh = as_reals(host_hist);
    cmp.history = std::max(scaled_difference(hd, hh, 6, 0, 3), scaled_difference(hd, hh, 6, 3, 3));
    return cmp;
}

} // namespace debrisflow::gpu
