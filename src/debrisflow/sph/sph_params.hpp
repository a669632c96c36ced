#pragma once
#include "debrisflow/core/vec3_k.hpp"
#include "debrisflow/sph/viscosity_registry.hpp"
#include <array>
#include <cmath>
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
    std::string viscosity = "artificial"; // the model's name
    Viscosity viscosity_model;            // the model, built by its from_config
    Real nu = 1e-6; // the fluid's kinematic viscosity (slurries: of the base; drag laws)
    std::string diffusion = "fourtakas";
    Real delta = 0.1;
    Vec3 gravity{0, 0, -9.81};
    Real cfl = 0.2;
    int reorder_every = 1;
    // DBC boundary particles never fall below the density of this pressure (Crespo et al.
    // 2007 clamp at p = 0 by default); negative values let fully immersed bodies feel the
    // suction behind them when the fluid has no hydrostatic background.
    Real boundary_min_pressure = 0;
    // Boundary particles' density: "dbc" (continuity, Crespo et al. 2007) or "mdbc" (mirrored
    // from the fluid at a ghost node, English et al. 2022; particles with wall geometry).
    std::string boundary = "dbc";
    // The wall velocity of the viscous terms (models with no-slip walls): "morris" (per pair,
    // Morris et al. 1997) or "mdbc" (the mirrored ghost-node velocity, English et al. 2022;
    // needs boundary = "mdbc").
    std::string no_slip = "morris";
    // How the force evaluation visits pairs: "list" (half pair list with a Verlet skin,
    // scattered to both particles; the host's way) or "cells" (each particle gathers its
    // neighbours from the cell grid, every pair evaluated from both sides; the GPU's way,
    // run on the host to check it).
    std::string pair_loop = "list";
    bool gathers() const { return pair_loop == "cells"; }
};

// How `check` and the log name the pair loop; every phase runs on the host (OpenMP) so far.
inline const char* pair_loop_words(const SphParams& p) {
    return p.gathers() ? "gathered over cells (the GPU's loop, run on the host)"
                       : "from a half list (host)";
}

// How `check` and the log name the wall treatment.
inline std::string wall_words(const SphParams& p) {
    return p.no_slip == "mdbc" ? p.boundary + " (no-slip velocity mirrored at the ghost nodes)"
                               : p.boundary;
}

// Volume a particle of the lattice stands for, dp^dim (2D: per metre of thickness); a
// particle's mass is a density times it.
inline Real lattice_volume(Real dp, int dim) {
    return std::pow(dp, Real(dim));
}

// Layers of boundary particles that cover the kernel support 2h of a fluid at spacing dp
// (the default of every wall, structure, body shell and FEM surface); 1 without a fluid.
inline int kernel_layers(Real h, Real dp) {
    return dp > 0 ? int(std::ceil(2 * h / dp - Real(1e-9))) : 1;
}

} // namespace debrisflow::sph
