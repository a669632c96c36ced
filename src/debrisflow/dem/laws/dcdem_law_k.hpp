#pragma once
#include "debrisflow/dem/contact_params.hpp"
#include "debrisflow/dem/laws/hertz_time.hpp"
#include "debrisflow/dem/laws/law_types_k.hpp"
#include <cmath>
#include <optional>

namespace debrisflow::dem {

// Distributed-contact DEM of Canelas et al. 2017 (Lemieux et al. 2008 normal law):
// F_n = k_n delta^1.5 - g_n delta^0.25 v_n, k_n = (4/3) E* sqrt(R*),
// g_n = C_n sqrt(6 m* E* sqrt(R*)); F_t = min(mu F_n tanh(8 |v_t|), |k_t xi + g_t v_t|) with
// k_t = 2/7 k_n sqrt(delta) and g_t = 2/7 g_n delta^0.25 (the paper's k_t = 2/7 k_n, taken on
// the secant Hertz stiffness so that k_t is in N/m).
struct DcdemLaw {
    static constexpr const char* name = "dcdem";
    static constexpr Stiffness stiffness = Stiffness::moduli;
    static constexpr Real min_restitution = 0;
    static constexpr bool uses_restitution = false; // damped by C_n

    // Material key: damping_cn, the law's C_n (Canelas et al. 2017 use 1e-5); a pair's C_n is
    // the mean of its two materials' unless a [[contact]] gives it.
    struct MaterialKeys {
        Real damping_cn = 1e-5;
    };
    template <class Table> static MaterialKeys read_keys(const Table& t, bool /*own*/) {
        MaterialKeys k;
        k.damping_cn = t.real("damping_cn", k.damping_cn);
        if (k.damping_cn < 0) t.fail("damping_cn", "must be >= 0");
        return k;
    }
    template <class Table> static std::optional<MaterialKeys> read_override(const Table& t) {
        if (!t.has("damping_cn")) return std::nullopt;
        return read_keys(t, true);
    }
    static void configure(PairParams& p, const MaterialKeys& a, const MaterialKeys& b,
                          const std::optional<MaterialKeys>& pair) {
        p.damping = pair ? pair->damping_cn : Real(0.5) * (a.damping_cn + b.damping_cn);
    }

    DF_HD static NormalResponse normal(const PairParams& p, const ContactInput& c) {
        const Real kn = Real(4) / 3 * p.e_star * std::sqrt(c.r_eff);
        const Real gn = p.damping * c.sqrt_m_eff * std::sqrt(6 * p.e_star * std::sqrt(c.r_eff));
        const Real root_d = std::sqrt(c.delta), quarter = std::sqrt(root_d);
        Real fn = kn * c.delta * root_d + gn * quarter * c.ddelta;
        fn = fn > 0 ? fn : Real(0);
        return {fn, Real(2) / 7 * kn * root_d, Real(2) / 7 * gn * quarter, p.mu * fn,
                Real(1.5) * kn * root_d};
    }
    DF_HD static Real friction_factor(Real vt2) { return std::tanh(8 * std::sqrt(vt2)); }
    DF_HD static Real reach(const PairParams&, Real) { return 0; }

    static constexpr bool speed_dependent_time = true;
    static Real undamped_contact_time(const PairParams& p, Real m_eff, Real r_eff, Real v) {
        return hertz_contact_time(p, m_eff, r_eff, v);
    }
    static Real contact_time(const PairParams& p, Real m_eff, Real r_eff, Real v) {
        return hertz_contact_time(p, m_eff, r_eff, v);
    }
    // k_t = 2/7 (4/3) E* sqrt(R* d): 4/21 of the normal tangent 2 E* sqrt(R* d).
    static Real tangential_ratio(const PairParams&) { return Real(4) / 21; }
    // g_n = C_n sqrt(6 m* E* sqrt(R*)) d^(1/4) against the tangent 2 E* sqrt(R* d): C_n sqrt(3)/2;
    // g_t = 2/7 g_n against k_t = 4/21 of that tangent: (2/7) / sqrt(4/21) of it
    static DampingRatios damping_ratios(const PairParams& p) {
        const Real z = p.damping * Real(0.86602540378443864676);
        return {z, z * Real(2) / 7 / std::sqrt(Real(4) / 21)};
    }
};

} // namespace debrisflow::dem
