#pragma once
#include "debrisflow/core/hd.hpp"
#include "debrisflow/sph/pair_state_k.hpp"
#include <cmath>

namespace debrisflow::models {

using sph::PairState;

// Generalised-Newtonian slurries: each fluid particle carries an apparent dynamic viscosity
// mu_app(gamma_dot, p) computed before the force loop from its SPH strain rate
// gamma_dot = sqrt(2 D:D); the pair term is Morris et al. (1997, eq. 8) with the particles'
// own viscosities: a_i += sum m_j (mu_i + mu_j) r_ij.grad W / (rho_i rho_j (r^2 + eta^2)) v_ij.
// Boundary particles take the fluid partner's viscosity. mu_app is capped at mu_max, which
// also sets the viscous time-step bound (0.125 h^2 rho / mu_max is never exceeded).
struct GeneralisedNewtonian {
    static constexpr bool needs_velocity_gradient = false;
    static constexpr bool needs_apparent_viscosity = true;
    static constexpr bool no_slip_walls = true;
    Real rho0 = 1000, eta2 = 0;
    Real mu_base = 0; // Newtonian part [Pa s] (rho0 nu), e.g. the interstitial water
    Real mu_max = 0;  // cap of the apparent viscosity [Pa s]

    DF_HD Vec3 acceleration(const PairState& s) const {
        const Real mu_sum = s.boundary_j ? 2 * s.mu_i : s.mu_i + s.mu_j;
        const Real k = mu_sum * s.r2 * s.f / (s.rho_i * s.rho_j * (s.r2 + eta2));
        return k * s.v_visc;
    }
    DF_HD Real capped(Real mu) const { return mu < mu_max ? mu : mu_max; }
    // Upper bound of the kinematic viscosity (initial time-step estimate).
    Real kinematic_viscosity() const { return mu_max / rho0; }
};

// (1 - exp(-m gdot)) / gdot without cancellation at small gdot (limit m).
DF_HD inline Real papanastasiou_factor(Real m, Real gdot) {
    const Real x = m * gdot;
    return x < Real(1e-8) ? m * (1 - Real(0.5) * x) : -std::expm1(-x) / gdot;
}

// Herschel-Bulkley with Papanastasiou (1987) regularisation:
// mu_app = K gdot^(n-1) + tau_y (1 - exp(-m gdot)) / gdot, capped at mu_max.
struct HerschelBulkleyViscosity : GeneralisedNewtonian {
    static constexpr const char* name = "herschel_bulkley";
    Real yield_stress = 0, consistency = 0, flow_index = 1, regularization = 1000;

    DF_HD Real apparent_viscosity(Real gdot, Real /*p*/) const {
        const Real g = gdot > Real(1e-12) ? gdot : Real(1e-12);
        const Real power =
            flow_index == 1 ? consistency : consistency * std::pow(g, flow_index - 1);
        return capped(mu_base + power + yield_stress * papanastasiou_factor(regularization, gdot));
    }
};

// Bingham plastic with Papanastasiou (1987) regularisation: Herschel-Bulkley with n = 1,
// mu_app = mu_p + tau_y (1 - exp(-m gdot)) / gdot; `consistency` is the plastic viscosity mu_p.
struct BinghamViscosity : HerschelBulkleyViscosity {
    static constexpr const char* name = "bingham";
};

// mu(I) frictional rheology for dense granular slurries (Jop, Forterre & Pouliquen 2006, eq. 2;
// Drucker-Prager-type yield p mu_s): mu(I) = mu_s + (mu_2 - mu_s) / (I0 / I + 1),
// I = gdot d / sqrt(p / rho_s), mu_app = mu_base + mu(I) max(p, 0) / gdot, capped at mu_max.
struct MuIViscosity : GeneralisedNewtonian {
    static constexpr const char* name = "mu_i";
    Real mu_s = Real(0.38), mu_2 = Real(0.64), i0 = Real(0.279);
    Real grain_diameter = Real(0.001), grain_density = 2500;

    DF_HD Real apparent_viscosity(Real gdot, Real p) const {
        if (!(p > 0)) return capped(mu_base);
        const Real g = gdot > Real(1e-12) ? gdot : Real(1e-12);
        const Real inertial = g * grain_diameter / std::sqrt(p / grain_density);
        const Real mu = mu_s + (mu_2 - mu_s) * inertial / (i0 + inertial);
        return capped(mu_base + mu * p / g);
    }
};

} // namespace debrisflow::models
