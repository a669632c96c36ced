#pragma once
#include "debrisflow/models/rheology_k.hpp"
#include <cmath>

namespace debrisflow::models {

// Carreau-Yasuda shear-thinning (or thickening) fluid (Yasuda, Armstrong & Cohen 1981):
// mu_app = mu_inf + (mu_0 - mu_inf) [1 + (lambda gdot)^a]^((n - 1) / a) (+ the base rho0 nu),
// capped at mu_max. Keys: viscosity_zero (mu_0) and viscosity_infinity (mu_inf) [Pa s],
// relaxation_time (lambda) [s], flow_index (n), yasuda_a (a, default 2: Carreau's fluid).
struct CarreauYasudaViscosity : GeneralisedNewtonian {
    static constexpr const char* name = "carreau_yasuda";
    Real mu_zero = 0, mu_inf = 0, lambda = 0, flow_index = 1, yasuda_a = 2;

    DF_HD Real apparent_viscosity(Real gdot, Real /*p*/) const {
        const Real x = lambda * gdot;
        const Real thinning = std::pow(1 + std::pow(x, yasuda_a), (flow_index - 1) / yasuda_a);
        return capped(mu_base + mu_inf + (mu_zero - mu_inf) * thinning);
    }

    template <class Table>
    static CarreauYasudaViscosity from_config(const Table& t, const ViscosityContext& c) {
        CarreauYasudaViscosity v;
        v.set_base(c);
        v.mu_zero = t.positive("viscosity_zero");
        v.mu_inf = t.real("viscosity_infinity", 0);
        if (v.mu_inf < 0 || v.mu_inf > v.mu_zero)
            t.fail("viscosity_infinity", "must be within [0, viscosity_zero] [Pa s]");
        v.lambda = t.positive("relaxation_time");
        v.flow_index = t.positive("flow_index");
        v.yasuda_a = t.positive("yasuda_a", 2);
        // Shear-thinning (n <= 1): largest at rest, mu_0; shear-thickening: unbounded.
        v.read_cap(t, v.flow_index <= 1 ? v.mu_base + v.mu_zero : 0);
        return v;
    }
};

} // namespace debrisflow::models
