#pragma once
#include "debrisflow/core/hd.hpp"
#include "debrisflow/models/diffusion_context.hpp"
#include "debrisflow/models/pair_state_k.hpp"
#include <cmath>

namespace debrisflow::models {

// Each model gives both sides of a fluid-fluid pair: drho_i += d.first, drho_j += d.second.
// Each also says how its parameters follow from the fluid (static configure(context), host
// only) and whether its pair term reads the particles' renormalised density gradients
// (needs_density_gradient: PairState::grad_rho_i/j, sph/density_gradient_k.hpp);
// sph/sph_models.hpp lists the models.
struct DensityRates {
    Real i, j;
};

// No density diffusion: plain continuity equation.
struct NoDiffusion {
    static constexpr const char* name = "none";
    static constexpr bool needs_density_gradient = false;
    static NoDiffusion configure(const DiffusionContext&) { return {}; }
    DF_HD DF_HOT_INLINE DensityRates pair(const PairState&) const { return {0, 0}; }
};

// delta-SPH density diffusion (Molteni & Colagrossi 2009; Antuono et al. 2010 eq. 6):
// D_i = delta h c0 sum 2 (rho_j - rho_i) (x_j - x_i).grad_i W / |x_ij|^2 m_j / rho_j.
struct MolteniColagrossi {
    static constexpr const char* name = "molteni";
    static constexpr bool needs_density_gradient = false;
    Real delta = 0.1, h = 0, c0 = 0;

    static MolteniColagrossi configure(const DiffusionContext& c) {
        MolteniColagrossi d;
        d.delta = c.delta, d.h = c.h, d.c0 = c.c0;
        return d;
    }

    DF_HD DF_HOT_INLINE DensityRates pair(const PairState& s) const {
        // (x_j - x_i).grad_i W = -r^2 f
        const Real k = 2 * delta * h * c0 * (-s.r2 * s.f) * s.inv_r2_eta2 * (s.rho_j - s.rho_i);
        return {k * s.vol_j, -k * s.vol_i};
    }
};

// Density diffusion with the hydrostatic part removed (Fourtakas et al. 2019, eqs. 7-8):
// as Molteni-Colagrossi with (rho_j - rho_i) replaced by (rho_j - rho_i) - (rho^H_j - rho^H_i),
// rho^H_j - rho^H_i = rho0 [(1 + rho0 g.(x_j - x_i) / B)^(1/gamma) - 1], B = c0^2 rho0 / gamma.
struct Fourtakas {
    static constexpr const char* name = "fourtakas";
    static constexpr bool needs_density_gradient = false;
    Real delta = 0.1, h = 0, c0 = 0;
    Real rho0 = 1000, inv_gamma = 1.0 / 7, g_over_b[3] = {0, 0, 0}; // rho0 g / B

    static Fourtakas configure(const DiffusionContext& c) {
        Fourtakas d;
        d.delta = c.delta, d.h = c.h, d.c0 = c.c0;
        const Real b = c.c0 * c.c0 * c.rho0 / c.gamma;
        d.rho0 = c.rho0;
        d.inv_gamma = 1 / c.gamma;
        for (int k = 0; k < 3; ++k) d.g_over_b[k] = c.rho0 * c.gravity[k] / b;
        return d;
    }

    DF_HD DF_HOT_INLINE DensityRates pair(const PairState& s) const {
        // g.(x_j - x_i) = -g.r, scaled by rho0 / B
        const Real gr = -(g_over_b[0] * s.r.x + g_over_b[1] * s.r.y + g_over_b[2] * s.r.z);
        const Real k = 2 * delta * h * c0 * (-s.r2 * s.f) * s.inv_r2_eta2;
        return {k * (s.rho_j - s.rho_i - hydrostatic(gr)) * s.vol_j,
                k * (s.rho_i - s.rho_j - hydrostatic(-gr)) * s.vol_i};
    }
    // rho^H_b - rho^H_a for rho0 g.(x_b - x_a) / B = x
    DF_HD DF_HOT_INLINE Real hydrostatic(Real x) const {
        // (1 + x)^a - 1 by its Taylor series to third order: |x| <= 2 h gamma g / c0^2 << 1 for
        // a pair, so the truncation (a (a-1)(a-2)(a-3)/24 x^4) is below 1e-9 relative.
        const Real a = inv_gamma;
        return rho0 * a * x * (1 + Real(0.5) * (a - 1) * x * (1 + (a - 2) / 3 * x));
    }
};

// delta-SPH density diffusion with renormalised gradients (Antuono, Colagrossi, Marrone &
// Molteni 2010, eqs. 5-6): D_i = delta h c0 sum_j psi_ji . grad_i W_ij m_j / rho_j,
// psi_ji = 2 (rho_j - rho_i) (x_j - x_i) / |x_ij|^2 - (<grad rho>^L_i + <grad rho>^L_j).
// The second term removes what the first gives for a linear density field, hydrostatic or
// not, so the term is of order h^2 (Molteni's and Fourtakas's are of order h where the
// pressure field is not hydrostatic, as behind an impact).
struct Antuono {
    static constexpr const char* name = "antuono";
    static constexpr bool needs_density_gradient = true;
    Real delta = 0.1, h = 0, c0 = 0;

    static Antuono configure(const DiffusionContext& c) {
        Antuono d;
        d.delta = c.delta, d.h = c.h, d.c0 = c.c0;
        return d;
    }

    DF_HD DF_HOT_INLINE DensityRates pair(const PairState& s) const {
        // 2 (rho_j - rho_i) (x_j - x_i).grad_i W / |x_ij|^2 = -2 f (rho_j - rho_i), exactly
        const Vec3 g = s.grad_rho_i + s.grad_rho_j;
        const Real k = delta * h * c0 * (-2 * s.f * (s.rho_j - s.rho_i) - dot(g, s.grad_w));
        return {k * s.vol_j, -k * s.vol_i};
    }
};

} // namespace debrisflow::models
