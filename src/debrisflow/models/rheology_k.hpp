#pragma once
#include "debrisflow/core/hd.hpp"
#include "debrisflow/models/pair_state_k.hpp"
#include "debrisflow/models/viscosity_context.hpp"
#include <cmath>

namespace debrisflow::models {

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
    static constexpr bool requires_nu = false; // nu, if given, is the base's
    Real rho0 = 1000, eta2 = 0;
    Real mu_base = 0; // Newtonian part [Pa s] (rho0 nu), e.g. the interstitial water
    Real mu_max = 0;  // cap of the apparent viscosity [Pa s]

    // The fields every slurry takes from the context.
    void set_base(const ViscosityContext& c) {
        rho0 = c.rho0;
        eta2 = c.morris_eta2();
        mu_base = c.rho0 * c.nu;
    }
    // mu_max: given, or by default `at_rest` where the apparent viscosity is bounded there
    // (at_rest > 0); required otherwise.
    template <class Table> void read_cap(const Table& t, Real at_rest) {
        mu_max = at_rest > 0 ? t.positive("mu_max", at_rest) : t.positive("mu_max");
    }

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

    template <class Table>
    static HerschelBulkleyViscosity from_config(const Table& t, const ViscosityContext& c) {
        HerschelBulkleyViscosity v;
        v.read_plastic(t, c, t.positive("flow_index"));
        return v;
    }

protected:
    // Keys yield_stress, consistency, regularization and mu_max, with n = flow_index.
    template <class Table> void read_plastic(const Table& t, const ViscosityContext& c, Real n) {
        set_base(c);
        flow_index = n;
        yield_stress = t.real("yield_stress");
        if (yield_stress < 0) t.fail("yield_stress", "must be >= 0 [Pa]");
        consistency = t.positive("consistency");
        regularization = t.positive("regularization");
        // With n >= 1 the apparent viscosity is largest at rest: mu_p + tau_y m (+ the base);
        // with n < 1, K gdot^(n-1) is unbounded at rest.
        read_cap(t, n >= 1 ? mu_base + consistency + yield_stress * regularization : 0);
    }

public:
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

    template <class Table>
    static BinghamViscosity from_config(const Table& t, const ViscosityContext& c) {
        if (t.has("flow_index"))
            t.fail("flow_index", "a Bingham fluid has n = 1; use viscosity = \"herschel_bulkley\"");
        BinghamViscosity v;
        v.read_plastic(t, c, 1);
        return v;
    }
};

// mu(I) frictional rheology for dense granular slurries (Jop, Forterre & Pouliquen 2006, eq. 2;
// Drucker-Prager-type yield p mu_s): mu(I) = mu_s + (mu_2 - mu_s) / (I0 / I + 1),
// I = gdot d / sqrt(p / rho_s), mu_app = mu_base + mu(I) max(p, 0) / gdot, capped at mu_max.
struct MuIViscosity : GeneralisedNewtonian {
    static constexpr const char* name = "mu_i";
    Real mu_s = Real(0.38), mu_2 = Real(0.64), i0 = Real(0.279);
    Real grain_diameter = Real(0.001), grain_density = 2500;

    template <class Table>
    static MuIViscosity from_config(const Table& t, const ViscosityContext& c) {
        MuIViscosity v;
        v.set_base(c);
        v.mu_s = t.positive("mu_s", 0.38);
        v.mu_2 = t.positive("mu_2", 0.64);
        if (v.mu_2 < v.mu_s) t.fail("mu_2", "must be >= mu_s");
        v.i0 = t.positive("I0", 0.279);
        v.grain_diameter = t.positive("grain_diameter");
        v.grain_density = t.positive("grain_density");
        v.read_cap(t, 0); // mu(I) p / gdot is unbounded at rest
        return v;
    }

    DF_HD Real apparent_viscosity(Real gdot, Real p) const {
        if (!(p > 0)) return capped(mu_base);
        const Real g = gdot > Real(1e-12) ? gdot : Real(1e-12);
        const Real inertial = g * grain_diameter / std::sqrt(p / grain_density);
        const Real mu = mu_s + (mu_2 - mu_s) * inertial / (i0 + inertial);
        return capped(mu_base + mu * p / g);
    }
};

} // namespace debrisflow::models
