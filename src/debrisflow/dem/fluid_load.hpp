#pragma once
#include "debrisflow/core/vec3_k.hpp"
#include <vector>

namespace debrisflow::dem {

// What a surrounding fluid does to each grain (filled by coupling::SphDemCoupling): a force
// held over the fluid step (the pressure gradient) and a linear drag beta (u - v) toward the
// local fluid velocity u, which the DEM evaluates at every sub-step with the grain's own
// velocity v. The DEM sums the impulse the fluid gave each grain until the coupling collects
// it for the reaction on the fluid. Arrays are per grain and follow reordering and removal.
struct FluidLoad {
    std::vector<Vec3> force;    // [N], held over the fluid step
    std::vector<Vec3> u;        // local fluid velocity [m/s]
    std::vector<Real> beta;     // drag coefficient [kg/s]
    std::vector<Vec3> impulse;  // fluid impulse on the grain since the last collection [N s]
    std::vector<Vec3> felt;     // fluid force of the last DEM force evaluation [N]
    std::vector<Vec3> handover; // impulse of the last DEM advance, for the next fluid step [N s]
    Real time = 0;              // time the impulses cover [s]
    Real max_rate = 0;          // largest beta / m [1/s]: explicit drag needs h < 0.5 m / beta

    void resize(std::size_t n);
    // Element i becomes old element perm[i].
    void permute(const std::vector<Index>& perm);
    // Keeps the listed old indices, in order.
    void select(const std::vector<Index>& kept);
};

} // namespace debrisflow::dem
