#pragma once
#include "debrisflow/core/vec3_k.hpp"

namespace debrisflow::dem {

// What a rolling-resistance model sees of one compressive contact: the relative angular
// velocity w_i - w_j, the normal n (from j to i), the normal force F_n > 0 and its tangent
// stiffness dF_n/d(delta), the effective radius R* and the step.
struct RollingInput {
    Vec3 wrel, n;
    Real fn, kn_tangent, r_eff, dt;
};

// The rolling part of w_rel: its component in the contact plane.
DF_HD inline Vec3 rolling_velocity(const RollingInput& in) {
    return in.wrel - dot(in.wrel, in.n) * in.n;
}

} // namespace debrisflow::dem
