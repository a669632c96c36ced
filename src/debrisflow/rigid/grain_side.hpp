#pragma once
#include "debrisflow/rigid/body_model.hpp"
#include "debrisflow/rigid/body_state.hpp"
#include <vector>

namespace debrisflow::rigid {

// The grains a body solver is coupled to, as the bodies see it (coupling::DemBodyCoupling is
// the implementation): the grains' reaction on each body, and the bodies' contact spheres
// the grains collide with.
class GrainSide {
public:
    virtual ~GrainSide() = default;
    // Adds the grains' contact force and moment on every body (averaged over the DEM steps
    // since the last call; the last average while none was taken) to loads[b].contact_force
    // and contact_torque.
    virtual void add_loads(std::vector<BodyLoads>& loads) = 0;
    // The contact spheres follow the bodies (after every update of the bodies, and when one
    // is added or removed).
    virtual void follow(const std::vector<BodyState>& bodies,
                        const std::vector<BodyModel>& models) = 0;
};

} // namespace debrisflow::rigid
