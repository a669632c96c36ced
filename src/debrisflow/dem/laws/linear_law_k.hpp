#pragma once
#include "debrisflow/dem/contact_params.hpp"
#include "debrisflow/dem/laws/law_types_k.hpp"
#include "debrisflow/dem/tsuji_damping.hpp"
#include <cmath>

namespace debrisflow::dem {

// Linear spring-dashpot (Cundall & Strack 1979): F_n = k_n delta + 2 zeta sqrt(m* k_n) ddelta,
// zeta = -ln e / sqrt(pi^2 + ln^2 e), exact restitution of the linear oscillator; no tension
// cut-off, so contact time pi / (w0 sqrt(1 - zeta^2)) and restitution are exact.
struct LinearLaw {
    static constexpr const char* name = "linear";
    static constexpr Stiffness stiffness = Stiffness::springs;
    static constexpr Real min_restitution = 0;
    static constexpr bool uses_restitution = true;

    DF_HD static NormalResponse normal(const PairParams& p, const ContactInput& c) {
        const Real gn = p.linear_gn * c.sqrt_m_eff; // 2 zeta sqrt(k_n) sqrt(m*)
        const Real gt = p.linear_gt * c.sqrt_m_eff; // 2 zeta sqrt(k_t) sqrt(m*)
        const Real fn = p.kn * c.delta + gn * c.ddelta;
        return {fn, p.kt, gt, p.mu * (fn > 0 ? fn : Real(0)), p.kn};
    }
    DF_HD static Real friction_factor(Real) { return 1; }
    DF_HD static Real reach(const PairParams&, Real) { return 0; }

    static void configure(PairParams& p) {
        p.set_linear_damping(linear_damping_ratio(p.restitution));
    }

    // Undamped duration pi sqrt(m*/k_n); the damped oscillator lasts pi / (w0 sqrt(1 - zeta^2)).
    static constexpr bool speed_dependent_time = false;
    static Real undamped_contact_time(const PairParams& p, Real m_eff, Real, Real) {
        return Real(3.14159265358979323846) * std::sqrt(m_eff / p.kn);
    }
    static Real contact_time(const PairParams& p, Real m_eff, Real r_eff, Real v) {
        return undamped_contact_time(p, m_eff, r_eff, v) / std::sqrt(1 - p.damping * p.damping);
    }
    // k_t against the normal stiffness (frequency ratio of the tangential mode, squared).
    static Real tangential_ratio(const PairParams& p) { return p.kt / p.kn; }
    // g_n = 2 zeta sqrt(k_n m*), g_t = 2 zeta sqrt(k_t m*)
    static DampingRatios damping_ratios(const PairParams& p) { return {p.damping, p.damping}; }
};

} // namespace debrisflow::dem
