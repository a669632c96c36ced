#pragma once
#include "debrisflow/core/vec3_k.hpp"

namespace debrisflow::models {

// What a density diffusion model's configure(context) may use: the [sph] table's `delta`
// (read for every model so that a sweep can switch models with --set) and the fluid's
// properties its terms follow from.
struct DiffusionContext {
    Real delta = Real(0.1); // diffusion coefficient
    Real h = 0;             // smoothing length [m]
    Real c0 = 0;            // artificial sound speed [m/s]
    Real rho0 = 1000;       // reference density [kg/m^3]
    Real gamma = 7;         // Tait exponent
    Vec3 gravity;           // [m/s^2]
};

} // namespace debrisflow::models
