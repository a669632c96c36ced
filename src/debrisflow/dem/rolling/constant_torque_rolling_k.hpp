#pragma once
#include "debrisflow/dem/contact_params.hpp"
#include "debrisflow/dem/rolling/rolling_types_k.hpp"

namespace debrisflow::dem {

// Constant directional torque (Zhou et al. 1999, model A of Ai et al. 2011):
// M_r = -mu_r R* F_n w_r / |w_r|, with w_r the rolling part of w_i - w_j.
struct ConstantTorqueRolling {
    static constexpr const char* name = "constant_torque";
    static constexpr bool keeps_moment = false;
    DF_HD static Vec3 moment(const PairParams& p, const RollingInput& in, Vec3*) {
        const Vec3 wr = rolling_velocity(in);
        const Real mmax = p.mu_roll * in.r_eff * in.fn;
        const Real w = norm(wr);
        return w > 0 ? (-mmax / w) * wr : Vec3{};
    }
    // no spring: no mode of its own
    static Real mode_ratio(const PairParams&, Real, Real, Real) { return 0; }
};

} // namespace debrisflow::dem
