#pragma once
#include "debrisflow/dem/dem_solver.hpp"

namespace debrisflow::gpu {

// One evaluation of every grain-grain contact slot on the host and on the GPU.
struct ContactComparison {
    long slots = 0, candidates = 0, touching = 0;
    double host_ms = 0, kernel_ms = 0; // host: one thread; device: median of the repeats
    // max |device - host| / max |host| of the contact force, the torques and the updated
    // tangential spring and rolling moment (the history)
    double force = 0, torque = 0, history = 0;
};

// Evaluates the contact law (dem::grain_pair_force) of every slot of `in` on the host and on
// the first CUDA device, from the same state and history, and compares them. Leaves the
// solver's state unchanged.
ContactComparison compare_grain_contacts(const dem::GrainContactInputs& in, int repeats);

} // namespace debrisflow::gpu
