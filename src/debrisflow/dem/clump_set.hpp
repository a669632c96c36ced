#pragma once
#include "debrisflow/core/vec3_k.hpp"
#include "debrisflow/rigid/quaternion_k.hpp"
#include <cstdint>
#include <vector>

namespace debrisflow::dem {

// Rigid clumps of grains (the multi-sphere method, Favier et al. 1999): each clump is a rigid
// body whose member spheres (discs in 2D) are ordinary grains of the GrainSet for the contact
// search and the contact laws. Members of one clump never touch each other; the forces and
// torques on the members are summed on the clump, which moves as a rigid body (velocity
// Verlet for the centre of mass, the angular momentum kicked by the torque and the rotation
// split as in rigid::free_rotation), and the members are placed and moved with it.
// Members are referred to by their persistent grain id, so reordering the grains keeps them.
struct ClumpSet {
    // per clump (structure of arrays)
    std::vector<Vec3> pos, vel;      // centre of mass [m], velocity [m/s]
    std::vector<Vec3> ang_mom;       // angular momentum about the centre of mass, world [kg m2/s]
    std::vector<Vec3> force, torque; // last evaluation, gravity included [N], [N m]
    std::vector<rigid::Quat> orient; // principal (body) frame -> world
    std::vector<Real> mass;          // [kg]
    std::vector<Vec3> inv_inertia;   // inverse principal moments [1/(kg m2)]
    // members, clump by clump: first[c] .. first[c + 1] - 1
    std::vector<std::uint32_t> first{0};
    std::vector<std::uint32_t> member_id; // the members' grain ids
    std::vector<Vec3> offset;             // member centre - centre of mass, body frame [m]

    Index size() const { return Index(mass.size()); }
    bool empty() const { return mass.empty(); }
    // Adds a clump; the members (ids, body-frame offsets) must already be grains.
    Index add(Vec3 com, Vec3 v, Vec3 w, rigid::Quat q, Real m, Vec3 inv_inertia,
              const std::vector<std::uint32_t>& ids, const std::vector<Vec3>& offsets);
    // World angular velocity of clump c.
    Vec3 spin(Index c) const;
    // Keeps the clumps with keep[c] != 0.
    void select(const std::vector<std::uint8_t>& keep);
    // The largest inverse principal moment of clump c (the most compliant axis).
    Real max_inv_inertia(Index c) const;
    Real total_mass() const;
};

} // namespace debrisflow::dem
