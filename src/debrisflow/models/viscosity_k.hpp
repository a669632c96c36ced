#pragma once
#include "debrisflow/core/hd.hpp"
#include "debrisflow/models/pair_state_k.hpp"
#include "debrisflow/models/viscosity_context.hpp"

namespace debrisflow::models {

// Every model returns G_ij with a_i += m_j G_ij and a_j -= m_i G_ij (momentum-conserving),
// and builds itself from the [sph] table with from_config(table, ViscosityContext): its own
// keys, defaults and checks (`requires_nu`: the case must give the fluid's nu).

// Artificial viscosity (Monaghan 1992, eq. 4.1): Pi_ij = -alpha cbar mu_ij / rhobar for
// v_ij.r_ij < 0, mu_ij = h v_ij.r_ij / (r^2 + 0.01 h^2); a_i -= sum m_j Pi_ij grad W.
// alpha is multiplied by `boundary_factor` for fluid-boundary pairs.
struct ArtificialViscosity {
    static constexpr const char* name = "artificial";
    static constexpr bool needs_velocity_gradient = false;
    static constexpr bool needs_apparent_viscosity = false;
    static constexpr bool no_slip_walls = false; // uses v_ij as is
    static constexpr bool requires_nu = false;
    Real alpha = 0.01, boundary_factor = 1, h = 0;

    template <class Table>
    static ArtificialViscosity from_config(const Table&, const ViscosityContext& c) {
        return {c.alpha, c.boundary_factor, c.h};
    }

    DF_HD DF_HOT_INLINE Vec3 acceleration(const PairState& s) const {
        const Real vr = dot(s.v, s.r);
        if (vr >= 0) return {};
        const Real a = s.boundary_j ? alpha * boundary_factor : alpha;
        const Real mu = h * vr * s.inv_r2_eta2;
        const Real pi = -a * Real(0.5) * (s.c_i + s.c_j) * mu / (Real(0.5) * (s.rho_i + s.rho_j));
        return (-pi) * s.grad_w;
    }
    // Largest kinematic viscosity for the viscous time-step limit (none for this model).
    Real kinematic_viscosity() const { return 0; }
};

// Laminar viscosity (Morris, Fox & Zhu 1997, eq. 8):
// a_i += sum m_j (mu_i + mu_j) r_ij.grad W / (rho_i rho_j (r^2 + eta^2)) v_ij, mu = rho0 nu.
struct LaminarViscosity {
    static constexpr const char* name = "laminar";
    static constexpr bool needs_velocity_gradient = false;
    static constexpr bool needs_apparent_viscosity = false;
    static constexpr bool no_slip_walls = true; // uses v_visc (Morris wall extrapolation)
    static constexpr bool requires_nu = true;
    Real nu = 1e-6, rho0 = 1000, eta2 = 0;

    template <class Table>
    static LaminarViscosity from_config(const Table&, const ViscosityContext& c) {
        return {c.nu, c.rho0, c.morris_eta2()};
    }

    DF_HD DF_HOT_INLINE Vec3 acceleration(const PairState& s) const {
        const Real mu2 = 2 * rho0 * nu;
        const Real k = mu2 * s.r2 * s.f / (s.rho_i * s.rho_j * (s.r2 + eta2));
        return k * s.v_visc;
    }
    Real kinematic_viscosity() const { return nu; }
};

// Laminar + sub-particle-scale turbulence (Dalrymple & Rogers 2006, eqs. 9-12): Morris laminar
// term plus sum m_j (tau_i/rho_i^2 + tau_j/rho_j^2) . grad W with the Smagorinsky SPS stress
// tau/rho = 2 nu_t S - 2/3 nu_t S_kk I - 2/3 C_I dp^2 |S|^2 I, nu_t = (C_s dp)^2 |S|.
// The stress term itself is added by the interaction from the per-particle tau field.
struct LaminarSpsViscosity {
    static constexpr const char* name = "laminar_sps";
    static constexpr bool needs_velocity_gradient = true;
    static constexpr bool needs_apparent_viscosity = false;
    static constexpr bool no_slip_walls = true;
    static constexpr bool requires_nu = true;
    Real nu = 1e-6, rho0 = 1000, eta2 = 0;
    Real smagorinsky = 0.12, blin = 0.0066; // C_s and C_I of Dalrymple & Rogers

    template <class Table>
    static LaminarSpsViscosity from_config(const Table&, const ViscosityContext& c) {
        LaminarSpsViscosity v;
        v.nu = c.nu;
        v.rho0 = c.rho0;
        v.eta2 = c.morris_eta2();
        return v;
    }

    DF_HD DF_HOT_INLINE Vec3 acceleration(const PairState& s) const {
        return LaminarViscosity{nu, rho0, eta2}.acceleration(s);
    }
    Real kinematic_viscosity() const { return nu; }
};

} // namespace debrisflow::models
