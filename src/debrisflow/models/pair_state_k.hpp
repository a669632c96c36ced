#pragma once
#include "debrisflow/core/vec3_k.hpp"

namespace debrisflow::models {

// Everything a per-pair SPH term (viscosity, rheology, density diffusion) needs about particles i
// and j (r = x_i - x_j, v = v_i - v_j).
struct PairState {
    Vec3 r;
    Real r2;
    Vec3 v;
    Vec3 v_visc; // v_ij for viscous terms (no-slip extrapolation at walls, Morris 1997)
    Vec3 grad_w; // grad_i W_ij
    Real f;      // (dW/dr)/r, so grad_w = r * f
    Real mass_i, mass_j;
    Real vol_i, vol_j; // m / rho
    Real inv_r2_eta2;  // 1 / (r^2 + 0.01 h^2), shared by artificial viscosity and diffusion
    Real rho_i, rho_j;
    Real c_i, c_j;
    Real mu_i, mu_j; // apparent dynamic viscosities (generalised-Newtonian models only)
    bool boundary_j; // j is a boundary particle
    // renormalised density gradients <grad rho>^L of i and j (fluid-fluid pairs of diffusion
    // models with needs_density_gradient; unset otherwise)
    Vec3 grad_rho_i, grad_rho_j;
};

} // namespace debrisflow::models
