#pragma once
#include "debrisflow/rigid/free_rotation_k.hpp"
#include <array>
#include <cstdint>
#include <type_traits>

namespace debrisflow::rigid {

// removed: the body left the model through an outlet; it is parked where it left, at rest,
// and no longer moves, touches anything or carries fluid particles.
enum class Motion : std::uint8_t { free = 0, fixed = 1, prescribed = 2, removed = 3 };

// State of one rigid body. The body frame is the principal frame at the centre of mass:
// inertia diag(1 / inv_inertia). Angular momentum is kept in the world frame (conserved
// exactly by the free rotation).
struct BodyState {
    Vec3 pos;          // centre of mass [m]
    Quat q;            // principal frame -> world
    Vec3 vel;          // [m/s]
    Vec3 ang_mom;      // world angular momentum [kg m^2/s]
    Real mass = 0;     // [kg] (2D: per metre of thickness)
    Real inv_mass = 0; // 0 for fixed, prescribed and removed bodies
    Vec3 inv_inertia;  // 1 / principal moments [1/(kg m^2)]
    Quat q_user;       // principal frame in the user's (input) frame: user -> world = q * q_user*
    Motion motion = Motion::free;
    std::array<bool, 3> lock_translation{false, false, false}; // world axes
    std::array<bool, 3> lock_rotation{false, false, false};    // world axes
    std::int32_t material = 0;
    Real contact_radius = 0; // Hertz curvature radius at contact vertices [m]

    DF_HD Vec3 omega() const {
        if (motion != Motion::free) return prescribed_omega;
        return angular_velocity(q, ang_mom, inv_inertia);
    }
    DF_HD Vec3 to_world(Vec3 r_body) const { return pos + rotate(q, r_body); }
    DF_HD Vec3 point_velocity(Vec3 x) const { return vel + cross(omega(), x - pos); }
    // Inverse world inertia tensor applied to a vector.
    DF_HD Vec3 inv_inertia_world(Vec3 v) const {
        if (inv_mass == 0) return {};
        const Vec3 b = rotate_inverse(q, v);
        return rotate(q, {b.x * inv_inertia.x, b.y * inv_inertia.y, b.z * inv_inertia.z});
    }
    Vec3 prescribed_omega; // angular velocity of fixed/prescribed bodies [rad/s]
};
static_assert(std::is_trivially_copyable_v<BodyState>);

// Loads summed on a body over a step, by source, in the world frame (torques about the
// centre of mass).
struct BodyLoads {
    Vec3 fluid_force, fluid_torque;
    Vec3 contact_force, contact_torque;
    Vec3 joint_force, joint_torque; // spring-dampers (constraint impulses are not loads)
};

} // namespace debrisflow::rigid
