#pragma once
#include "debrisflow/sph/sph_solver.hpp"
#include "device_info.hpp"
#include <string>

namespace debrisflow::gpu {

// Wall times of one offloaded force evaluation [ms]: copying the state in, the kernel (median
// of the repeats) and copying the results back.
struct DeviceTimes {
    std::string device;
    double upload_ms = 0, kernel_ms = 0, download_ms = 0;
};

// Runs the solver's gather force evaluation (SphSolver::with_gather) on the first CUDA device,
// `repeats` times, and leaves its results in the particle set as compute_forces_gather does.
// Throws NoDevice, or std::runtime_error naming the CUDA call that failed.
DeviceTimes gather_on_device(sph::SphSolver& solver, int repeats);

} // namespace debrisflow::gpu
