#pragma once
#include "debrisflow/dem/contact_params.hpp"
#include "debrisflow/dem/laws/hertz_time.hpp"
#include "debrisflow/dem/laws/law_types_k.hpp"
#include "debrisflow/dem/tsuji_damping.hpp"
#include <cmath>

namespace debrisflow::dem {

// Hertz-Mindlin no-slip (Johnson 1985; Tsuji et al. 1992 damping):
// F_n = (4/3) E* sqrt(R*) delta^1.5 + alpha sqrt(m* k_h) delta^0.25 ddelta, clamped >= 0;
// k_t = 8 G* sqrt(R* delta), g_t = alpha sqrt(2/3) sqrt(m* k_t); alpha(e) from the exact
// restitution of the Tsuji oscillator (tsuji_alpha, Antypov & Elliott 2011).
struct HertzMindlinLaw {
    static constexpr const char* name = "hertz_mindlin";
    static constexpr Stiffness stiffness = Stiffness::moduli;
    static constexpr Real min_restitution = hertz_min_restitution;
    static constexpr bool uses_restitution = true;

    DF_HD static NormalResponse normal(const PairParams& p, const ContactInput& c) {
        const Real sq_rd = std::sqrt(c.r_eff * c.delta);
        const Real kh = Real(4) / 3 * p.e_star * std::sqrt(c.r_eff);
        const Real root_d = std::sqrt(c.delta);
        const Real gn = p.damping * c.sqrt_m_eff * std::sqrt(kh * root_d);
        Real fn = kh * c.delta * root_d + gn * c.ddelta;
        fn = fn > 0 ? fn : Real(0);
        const Real kt = 8 * p.g_star * sq_rd;
        const Real gt = p.damping * c.sqrt_m_eff * std::sqrt(Real(2) / 3 * kt);
        return {fn, kt, gt, p.mu * fn, Real(1.5) * kh * root_d};
    }
    DF_HD static Real friction_factor(Real) { return 1; }
    DF_HD static Real reach(const PairParams&, Real) { return 0; }

    static void configure(PairParams& p) { p.damping = tsuji_alpha(p.restitution); }

    static constexpr bool speed_dependent_time = true;
    static Real undamped_contact_time(const PairParams& p, Real m_eff, Real r_eff, Real v) {
        return hertz_contact_time(p, m_eff, r_eff, v);
    }
    static Real contact_time(const PairParams& p, Real m_eff, Real r_eff, Real v) {
        return hertz_contact_time(p, m_eff, r_eff, v);
    }
    // Tsuji: g_n = alpha sqrt(m* k_h sqrt(d)) against the tangent 1.5 k_h sqrt(d), and
    // g_t = alpha sqrt(2/3 k_t m*): both alpha sqrt(2/3) / 2
    static DampingRatios damping_ratios(const PairParams& p) {
        const Real z = p.damping * Real(0.40824829046386301636);
        return {z, z};
    }
    // Mindlin k_t = 8 G* sqrt(R* d) against the normal tangent 2 E* sqrt(R* d).
    static Real tangential_ratio(const PairParams& p) {
        return p.e_star > 0 ? 4 * p.g_star / p.e_star : 0;
    }
};

} // namespace debrisflow::dem
