#pragma once
#include "debrisflow/core/real.hpp"

namespace debrisflow::models {

// What a viscosity model's from_config(table, context) may use besides its own keys: the
// fluid's properties and the keys the [sph] table reads for every model (so that a sweep can
// switch models with --set).
struct ViscosityContext {
    Real rho0 = 1000;         // reference density [kg/m^3]
    Real h = 0;               // smoothing length [m]
    Real nu = 0;              // kinematic viscosity of the fluid (slurries: of the base) [m^2/s]
    Real alpha = 0.01;        // artificial viscosity coefficient
    Real boundary_factor = 1; // its factor on fluid-boundary pairs

    // Regulariser eta^2 of the Morris term: 0.01 h^2 (Morris 1997) biases the Laplacian by
    // -1.5 % on a lattice at h = 1.5 dp; 0.001 h^2 keeps the bias below 0.4 %.
    Real morris_eta2() const { return Real(0.001) * h * h; }
};

} // namespace debrisflow::models
