#pragma once
#include "debrisflow/core/hd.hpp"
#include "debrisflow/core/real.hpp"
#include "debrisflow/models/registry.hpp"
#include <cmath>

namespace debrisflow::coupling {

// What a drag law sees of one grain in the fluid: diameter d [m], fluid density rho [kg/m^3],
// dynamic viscosity mu [Pa s], slip speed |u - v| [m/s] and local fluid fraction eps.
struct DragInput {
    Real d, rho, mu, slip, eps;
};

// Each law returns beta [kg/s] with the drag F = beta (u - v) on the grain.

// Isolated sphere, Schiller & Naumann (1933): F = 3 pi mu d (u - v) (1 + 0.15 Re^0.687),
// Re = rho d |u - v| / mu; C_d = 0.44 above Re = 1000. No fluid-fraction correction.
struct SchillerNaumann {
    static constexpr const char* name = "schiller_naumann";
    DF_HD static Real beta(const DragInput& in) {
        const Real re = in.rho * in.d * in.slip / in.mu;
        const Real pi = Real(3.14159265358979323846);
        const Real f =
            re < 1000 ? 1 + Real(0.15) * std::pow(re, Real(0.687)) : Real(0.44) * re / 24;
        return 3 * pi * in.mu * in.d * f;
    }
};

// Di Felice (1994), as used in CFD-DEM (Zhu et al. 2007, eq. 15):
// F = (pi d^2 / 8) C_d rho eps^2 |u - v| (u - v) eps^-chi, C_d = (0.63 + 4.8 / sqrt(Re))^2,
// Re = eps rho d |u - v| / mu, chi = 3.7 - 0.65 exp(-(1.5 - log10 Re)^2 / 2). Written with
// rho |u - v| = Re mu / (eps d) so that it stays finite as the slip goes to zero.
struct DiFelice {
    static constexpr const char* name = "di_felice";
    DF_HD static Real beta(const DragInput& in) {
        const Real pi = Real(3.14159265358979323846);
        const Real re = in.eps * in.rho * in.d * in.slip / in.mu;
        const Real l = re > 0 ? Real(1.5) - std::log10(re) : Real(1e30);
        const Real chi = Real(3.7) - Real(0.65) * std::exp(-Real(0.5) * l * l);
        const Real sre = std::sqrt(re);
        const Real cd_re = Real(0.3969) * re + Real(6.048) * sre + Real(23.04); // C_d Re
        return pi * in.d * in.d / 8 * std::pow(in.eps, 2 - chi) * in.mu / (in.eps * in.d) * cd_re;
    }
};

// Drag laws of the unresolved SPH-DEM coupling, chosen by name (`[dem] fluid_drag`).
using DragRegistry = models::Registry<DiFelice, SchillerNaumann>;

} // namespace debrisflow::coupling
