#pragma once
#include "debrisflow/core/hd.hpp"
#include "debrisflow/dem/contact_params.hpp"
#include "debrisflow/models/registry.hpp"
#include <cmath>

namespace debrisflow::dem {

// Normal force of a contact and the tangential spring and dashpot that go with it.
struct NormalResponse {
    Real fn;         // normal force on grain i along n (may be < 0 only for the linear law)
    Real kt, gt;     // tangential stiffness [N/m] and damping [N s/m]
    Real friction;   // Coulomb bound on |F_t| before the law's velocity factor
    Real kn_tangent; // dF_n/d(delta), for the elastic-plastic rolling spring
};

// Inputs shared by the laws: overlap delta > 0, approach rate ddelta = -v_rel . n,
// effective radius R* = r_i r_j/(r_i + r_j), mass m* = m_i m_j/(m_i + m_j) and sqrt(m*).
struct ContactInput {
    Real delta, ddelta, r_eff, m_eff, sqrt_m_eff;
};

// Linear spring-dashpot (Cundall & Strack 1979): F_n = k_n delta + 2 zeta sqrt(m* k_n) ddelta,
// zeta = -ln e / sqrt(pi^2 + ln^2 e), exact restitution of the linear oscillator; no tension
// cut-off, so contact time pi / (w0 sqrt(1 - zeta^2)) and restitution are exact.
struct LinearLaw {
    static constexpr const char* name = "linear";
    DF_HD static NormalResponse normal(const PairParams& p, const ContactInput& c) {
        const Real gn = p.linear_gn * c.sqrt_m_eff; // 2 zeta sqrt(k_n) sqrt(m*)
        const Real gt = p.linear_gt * c.sqrt_m_eff; // 2 zeta sqrt(k_t) sqrt(m*)
        const Real fn = p.kn * c.delta + gn * c.ddelta;
        return {fn, p.kt, gt, p.mu * (fn > 0 ? fn : Real(0)), p.kn};
    }
    DF_HD static Real friction_factor(Real) { return 1; }
};

// Hertz-Mindlin no-slip (Johnson 1985; Tsuji et al. 1992 damping):
// F_n = (4/3) E* sqrt(R*) delta^1.5 + alpha sqrt(m* k_h) delta^0.25 ddelta, clamped >= 0;
// k_t = 8 G* sqrt(R* delta), g_t = alpha sqrt(2/3) sqrt(m* k_t); alpha(e) from the exact
// restitution of the Tsuji oscillator (tsuji_alpha, Antypov & Elliott 2011).
struct HertzMindlinLaw {
    static constexpr const char* name = "hertz_mindlin";
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
};

// Distributed-contact DEM of Canelas et al. 2017 (Lemieux et al. 2008 normal law):
// F_n = k_n delta^1.5 - g_n delta^0.25 v_n, k_n = (4/3) E* sqrt(R*),
// g_n = C_n sqrt(6 m* E* sqrt(R*)); F_t = min(mu F_n tanh(8 |v_t|), |k_t xi + g_t v_t|) with
// k_t = 2/7 k_n sqrt(delta) and g_t = 2/7 g_n delta^0.25 (the paper's k_t = 2/7 k_n, taken on
// the secant Hertz stiffness so that k_t is in N/m).
struct DcdemLaw {
    static constexpr const char* name = "dcdem";
    DF_HD static NormalResponse normal(const PairParams& p, const ContactInput& c) {
        const Real kn = Real(4) / 3 * p.e_star * std::sqrt(c.r_eff);
        const Real gn = p.damping * c.sqrt_m_eff * std::sqrt(6 * p.e_star * std::sqrt(c.r_eff));
        const Real root_d = std::sqrt(c.delta), quarter = std::sqrt(root_d);
        Real fn = kn * c.delta * root_d + gn * quarter * c.ddelta;
        fn = fn > 0 ? fn : Real(0);
        return {fn, Real(2) / 7 * kn * root_d, Real(2) / 7 * gn * quarter, p.mu * fn,
                Real(1.5) * kn * root_d};
    }
    DF_HD static Real friction_factor(Real vt) { return std::tanh(8 * vt); }
};

using ContactLawRegistry = models::Registry<LinearLaw, HertzMindlinLaw, DcdemLaw>;

// Dispatches on the pair's law (a switch, so the same code runs on a GPU); vt2 = |v_t|^2.
DF_HD DF_HOT_INLINE NormalResponse normal_response(const PairParams& p, const ContactInput& c,
                                                   Real vt2, Real& friction_factor) {
    switch (p.law) {
    case LawId::hertz_mindlin:
        friction_factor = 1;
        return HertzMindlinLaw::normal(p, c);
    case LawId::dcdem:
        friction_factor = DcdemLaw::friction_factor(std::sqrt(vt2));
        return DcdemLaw::normal(p, c);
    default:
        friction_factor = 1;
        return LinearLaw::normal(p, c);
    }
}

} // namespace debrisflow::dem
