#pragma once
#include "debrisflow/core/hd.hpp"
#include "debrisflow/core/real.hpp"
#include <cmath>

namespace debrisflow::models {

// Tait equation of state (Batchelor 1967; Monaghan 1994 eq. 3.3):
// p = B [(rho/rho0)^gamma - 1], B = c0^2 rho0 / gamma; c = c0 (rho/rho0)^((gamma-1)/2).
struct TaitEos {
    Real rho0 = 1000, c0 = 10, gamma = 7, b = 0;

    TaitEos() = default;
    TaitEos(Real rho0_, Real c0_, Real gamma_)
        : rho0(rho0_), c0(c0_), gamma(gamma_), b(c0_ * c0_ * rho0_ / gamma_) {}

    DF_HD Real pressure(Real rho) const {
        const Real r = rho / rho0;
        if (gamma == 7) {
            const Real r2 = r * r, r3 = r2 * r;
            return b * (r3 * r3 * r - 1);
        }
        return b * (std::pow(r, gamma) - 1);
    }
    DF_HD Real sound_speed(Real rho) const {
        const Real r = rho / rho0;
        if (gamma == 7) return c0 * r * r * r;
        return c0 * std::pow(r, Real(0.5) * (gamma - 1));
    }
    // Density that gives pressure p (inverse of pressure()).
    DF_HD Real density(Real p) const { return rho0 * std::pow(1 + p / b, 1 / gamma); }
};

} // namespace debrisflow::models
