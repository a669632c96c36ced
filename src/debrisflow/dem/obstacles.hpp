#pragma once
#include "debrisflow/core/vec3_k.hpp"
#include <cstdint>
#include <type_traits>
#include <vector>

namespace debrisflow::dem {

// A sphere attached to a rigid body that grains collide with: centre, velocity of the body
// point at the centre, the body's angular velocity, radius, body mass (m* of the contact),
// material and owning body.
struct ObstacleSphere {
    Vec3 x, v, w;
    Real r, m;
    int material, body;
    // The body's compliance at this sphere, for the DEM's stable step (0: an immovable body):
    // normal 1/M + |c|^2/I_min, tangential 1/M + (|c| + r)^2/I_min, rotational 1/I_min, with
    // c the sphere's offset from the body's centre of mass.
    Real normal_compliance = 0, tangential_compliance = 0, rotational_compliance = 0;
};
static_assert(std::is_trivially_copyable_v<ObstacleSphere>);

// The link between the DEM and the rigid bodies: the bodies write their contact spheres
// (and bump `version` when they move); the DEM adds each grain-sphere contact with the grain
// pair laws and accumulates the reaction impulse on every body (force and torque about its
// centre of mass) until the bodies collect it.
struct ObstacleSet {
    std::vector<ObstacleSphere> spheres;
    std::vector<Vec3> body_com;
    std::vector<Vec3> impulse, angular_impulse; // per body, since the last collection [N s]
    Real time = 0;                              // time those impulses cover [s]
    std::uint64_t version = 0;
};

} // namespace debrisflow::dem
