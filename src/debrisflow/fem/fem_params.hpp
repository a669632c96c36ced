#pragma once
#include "debrisflow/core/vec3_k.hpp"

namespace debrisflow::fem {

// [fem]: the explicit solver's settings.
struct FemParams {
    int dim = 3;
    Vec3 gravity{0, 0, -9.81};
    Real cfl = Real(0.9);  // fraction of the critical central-difference step
    Real alpha = 0;        // Rayleigh mass-proportional damping [1/s]
    Real beta = 0;         // Rayleigh stiffness-proportional damping [s]
    int max_subcycles = 0; // FEM steps per global step at most (0: no limit on the global dt)
    Vec3 domain_min{-1e30, -1e30, -1e30}, domain_max{1e30, 1e30, 1e30};
};

} // namespace debrisflow::fem
