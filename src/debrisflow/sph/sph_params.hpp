#pragma once
#include "debrisflow/core/vec3_k.hpp"
#include <array>
#include <string>

namespace debrisflow::sph {

// Everything the WCSPH solver needs, already validated and in SI units.
struct SphParams {
    int dim = 2;
    Real dp = 0.01;
    Real h = 0.013;
    std::string kernel = "wendland_c2";
    Real rho0 = 1000;
    Real c0 = 0;
    Real gamma = 7;
    std::string viscosity = "artificial";
    Real alpha = 0.01;
    Real boundary_factor = 1;
    Real nu = 1e-6;
    std::string diffusion = "fourtakas";
    Real delta = 0.1;
    Vec3 gravity{0, 0, -9.81};
    Real cfl = 0.2;
    int reorder_every = 1;
};

} // namespace debrisflow::sph
