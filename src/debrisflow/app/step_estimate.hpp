#pragma once
#include "debrisflow/app/simulation.hpp"
#include <limits>
#include <string>

namespace debrisflow::app {

// The global step a run starts with and what limits it (as `check` prints it): the SPH
// criteria, the DEM contact time unless sub-cycled, a rigid-only dt, or the FEM element CFL.
struct StepEstimate {
    Real dt = std::numeric_limits<Real>::max();
    std::string limiter;
};

StepEstimate estimate_step(Simulation& sim);

// A run of more than 1e10 steps cannot end on any machine (days at a microsecond a step), and
// a step that is zero or not finite cannot advance: both are refused with InputError naming
// time.end, the step and what limits it. `check` and `run` call it alike.
void require_feasible_steps(Simulation& sim);

} // namespace debrisflow::app
