#pragma once
#include "debrisflow/dem/contact_frame_k.hpp"
#include "debrisflow/dem/contact_params.hpp"
#include "debrisflow/dem/rolling/rolling_types_k.hpp"
#include <cmath>

namespace debrisflow::dem {

// Elastic-plastic spring-dashpot rolling resistance without its dashpot (Ai et al. 2011,
// model C, eqs. 11-13): M_r += -k_r w_r dt, k_r = 2.25 k_n mu_r^2 R*^2 (k_n the normal tangent
// stiffness), |M_r| <= mu_r R* F_n; the moment is carried from step to step in the contact's
// plane.
struct EpsdRolling {
    static constexpr const char* name = "epsd";
    static constexpr bool keeps_moment = true;
    // memory: the contact's moment from the last step (null: a slot without rolling memory,
    // which starts from zero moment every step).
    DF_HD static Vec3 moment(const PairParams& p, const RollingInput& in, Vec3* memory) {
        const Vec3 wr = rolling_velocity(in);
        const Real mmax = p.mu_roll * in.r_eff * in.fn;
        const Real kr = Real(2.25) * in.kn_tangent * p.mu_roll * p.mu_roll * in.r_eff * in.r_eff;
        Vec3 m = (memory ? rotate_into_plane(*memory, in.n) : Vec3{}) - (kr * in.dt) * wr;
        const Real mag = norm(m);
        if (mag > mmax) m = (mmax / mag) * m;
        if (memory) *memory = m;
        return m;
    }
    // The rolling spring acting on the rotational compliance c_r = sum 1/I of the two sides,
    // relative to the normal mode k_n / m*: sqrt(2.25 mu_r^2 R*^2 c_r m*) (Iwashita & Oda 1998;
    // Ai et al. 2011, eq. 13).
    static Real mode_ratio(const PairParams& p, Real r_eff, Real c_r, Real m_eff) {
        return p.mu_roll > 0
                   ? std::sqrt(Real(2.25) * p.mu_roll * p.mu_roll * r_eff * r_eff * c_r * m_eff)
                   : 0;
    }
};

} // namespace debrisflow::dem
