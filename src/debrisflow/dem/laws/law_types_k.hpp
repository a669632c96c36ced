#pragma once
#include "debrisflow/core/hd.hpp"
#include "debrisflow/core/real.hpp"

namespace debrisflow::dem {

// What a contact law returns for one contact: its normal force and the tangential spring and
// dashpot that go with it.
struct NormalResponse {
    Real fn;         // normal force on grain i along n (< 0: attraction, or the linear dashpot)
    Real kt, gt;     // tangential stiffness [N/m] and damping [N s/m]
    Real friction;   // Coulomb bound on |F_t| before the law's velocity factor
    Real kn_tangent; // dF_n/d(delta), for the elastic-plastic rolling spring
};

// Inputs shared by the laws: overlap delta (> 0, or down to -reach for an adhesive law),
// approach rate ddelta = -v_rel . n, effective radius R* = r_i r_j/(r_i + r_j), mass
// m* = m_i m_j/(m_i + m_j) and sqrt(m*).
struct ContactInput {
    Real delta, ddelta, r_eff, m_eff, sqrt_m_eff;
};

// Which stiffness parameters a law reads from its materials: linear springs k_n, k_t [N/m],
// or elastic moduli E, nu (from which E* and G* of a pair follow).
enum class Stiffness { springs, moduli };

// Damping ratios of a law's dashpots against its tangent stiffnesses, on the normal effective
// mass m*: zeta = g / (2 sqrt(k m*)) of the normal and of the tangential dashpot (for the
// explicit step's dashpot limit, dem/critical_dt.cpp).
struct DampingRatios {
    Real normal, tangential;
};

} // namespace debrisflow::dem
