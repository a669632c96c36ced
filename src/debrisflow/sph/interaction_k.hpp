#pragma once
#include "debrisflow/models/density_diffusion_k.hpp"
#include "debrisflow/models/eos_tait_k.hpp"
#include "debrisflow/models/pair_state_k.hpp"
#include "debrisflow/neighbors/grid_view_k.hpp"
#include "debrisflow/particles/particle_set.hpp"
#include "debrisflow/sph/apparent_viscosity_k.hpp"
#include "debrisflow/sph/no_slip_wall_k.hpp"

namespace debrisflow::sph {

// The WCSPH terms of one pair (i, j), written once for the gather loop (device) and the
// half-pair-list scatter loop (host):
//   continuity (Monaghan 1992 eq. 2.3): drho_i/dt = sum m_j v_ij . grad W_ij + diffusion
//   momentum (Monaghan 1992 eq. 3.1):   dv_i/dt = -sum m_j (p_i/rho_i^2 + p_j/rho_j^2) grad W_ij
//                                                 + viscous terms + g
// Boundary (DBC, Crespo et al. 2007) particles get drho from fluid neighbours and the
// acceleration the fluid exerts on them (for wall loads); they do not move. Boundary-boundary
// pairs contribute nothing.
template <class Kernel, class Viscosity, class Diffusion> struct PairTerms {
    using viscosity_type = Viscosity;
    particles::ParticleView pv;
    Kernel kernel;
    Viscosity visc;
    Diffusion diff;
    // p / rho^2, sound speed and m / rho per particle, or nullptr: then each is computed from
    // rho, p and m where a side is loaded (the gather path, which keeps no copies of them).
    const Real* prho;
    const Real* cs;
    const Real* vol;
    const Real* tau; // SPS stress / rho^2, 6 per particle (xx, xy, xz, yy, yz, zz), or nullptr:
                     // the stress of the previous force evaluation (see sps_tau below)
    NoSlipWall wall; // the wall velocity the viscous terms see (Morris's or mDBC's no-slip)
    Real eta2;       // 0.01 h^2, regulariser of 1 / r^2 (Monaghan 1992)
    models::TaitEos eos{}; // the sound speed where cs is nullptr
    // renormalised density gradients, 3 per particle (RenormalisedDensityGradient), for
    // diffusion models with needs_density_gradient; nullptr otherwise
    const Real* grad_rho = nullptr;

    // a_i += m_j g, a_j -= m_i g; drho_i += m_j cont + d.i, drho_j += m_i cont + d.j;
    // grad_w = grad_i W_ij (the velocity gradient of the SPS stress sums over it).
    struct Result {
        Vec3 g;
        Real cont;
        models::DensityRates d;
        Vec3 grad_w;
    };

    // Per-particle data of one side of a pair, loaded once per particle in the pair loops.
    struct Side {
        Vec3 x, v;
        Real rho, prho, c, m, vol, mu;
        bool fluid;
    };
    DF_HD DF_HOT_INLINE Side side(Index i) const {
        const Real rho = pv.rho[i], m = pv.mass[i];
        if (prho)
            return {pv.pos(i), pv.vel(i), rho, prho[i], cs[i], m, vol[i], pv.mu[i], pv.is_fluid(i)};
        // the same expressions as SphSolver::update_pressure, so the same numbers
        return {pv.pos(i), pv.vel(i), rho,      pv.p[i] / (rho * rho), eos.sound_speed(rho),
                m,         m / rho,   pv.mu[i], pv.is_fluid(i)};
    }

    DF_HD DF_HOT_INLINE Result operator()(Index i, Index j, Vec3 r, Real r2) const {
        return (*this)(side(i), i, side(j), j, r, r2);
    }

    DF_HD DF_HOT_INLINE Result operator()(const Side& a, Index i, const Side& b, Index j, Vec3 r,
                                          Real r2) const {
        models::PairState s;
        s.r = r;
        s.r2 = r2;
        s.f = kernel.grad_over_r(std::sqrt(r2));
        s.grad_w = s.f * r;
        s.v = a.v - b.v;
        s.mass_i = a.m;
        s.mass_j = b.m;
        s.vol_i = a.vol;
        s.vol_j = b.vol;
        s.inv_r2_eta2 = 1 / (r2 + eta2);
        s.rho_i = a.rho;
        s.rho_j = b.rho;
        s.c_i = a.c;
        s.c_j = b.c;
        s.boundary_j = !(a.fluid && b.fluid);
        // Generalised-Newtonian models: the fluid side's viscosity first when j is a wall.
        s.mu_i = a.fluid ? a.mu : b.mu;
        s.mu_j = a.fluid ? b.mu : a.mu;
        if constexpr (Viscosity::no_slip_walls)
            s.v_visc = s.boundary_j ? (a.fluid ? wall.difference(pv, j, a.x, s.v)
                                               : -1 * wall.difference(pv, i, b.x, -1 * s.v))
                                    : s.v;
        Result out;
        out.cont = dot(s.v, s.grad_w);
        out.g = (-(a.prho + b.prho)) * s.grad_w + visc.acceleration(s);
        if constexpr (Viscosity::needs_velocity_gradient) out.g += tau_dot(i, j, s.grad_w);
        if constexpr (Diffusion::needs_density_gradient)
            if (!s.boundary_j) {
                s.grad_rho_i = {grad_rho[3 * i], grad_rho[3 * i + 1], grad_rho[3 * i + 2]};
                s.grad_rho_j = {grad_rho[3 * j], grad_rho[3 * j + 1], grad_rho[3 * j + 2]};
            }
        out.d = s.boundary_j ? models::DensityRates{0, 0} : diff.pair(s);
        out.grad_w = s.grad_w;
        return out;
    }

    // (tau_i + tau_j) . g
    DF_HD DF_HOT_INLINE Vec3 tau_dot(Index i, Index j, Vec3 g) const {
        const Real* a = tau + 6 * i;
        const Real* b = tau + 6 * j;
        const Real xx = a[0] + b[0], xy = a[1] + b[1], xz = a[2] + b[2];
        const Real yy = a[3] + b[3], yz = a[4] + b[4], zz = a[5] + b[5];
        return {xx * g.x + xy * g.y + xz * g.z, xy * g.x + yy * g.y + yz * g.z,
                xz * g.x + yz * g.y + zz * g.z};
    }
};

// SPS stress tau / rho^2 of a fluid particle (Dalrymple & Rogers 2006, eq. 11) from its
// symmetric velocity gradient S = d[0..6) (xx, yy, zz, xy, xz, yz; add_symmetric_gradient):
// nu_t = (C_s dp)^2 |S|, |S| = sqrt(2 S:S). As in DualSPHysics (Dominguez et al. 2022), the
// velocity gradient is summed in the force loop and the stress it gives is used in the next
// force evaluation (half a step later), which saves a pass over the pairs.
DF_HD inline void sps_tau(const Real d[6], Real smag, Real blin, Real inv_rho, Real t[6]) {
    const Real sxx = d[0], syy = d[1], szz = d[2], sxy = d[3], sxz = d[4], syz = d[5];
    const Real ss =
        2 * (sxx * sxx + syy * syy + szz * szz) + 4 * (sxy * sxy + sxz * sxz + syz * syz);
    const Real nu_t = smag * std::sqrt(ss);
    const Real div = sxx + syy + szz;
    const Real iso = -(Real(2) / 3) * nu_t * div - blin * ss;
    t[0] = inv_rho * (2 * nu_t * sxx + iso);
    t[1] = inv_rho * (2 * nu_t * sxy);
    t[2] = inv_rho * (2 * nu_t * sxz);
    t[3] = inv_rho * (2 * nu_t * syy + iso);
    t[4] = inv_rho * (2 * nu_t * syz);
    t[5] = inv_rho * (2 * nu_t * szz + iso);
}

// Gather form (one thread per particle i, all neighbours from the cell grid): the layout a
// GPU backend uses. Writes a_i (with gravity for fluid) and drho_i, and for Laminar+SPS the
// stress of fluid particle i from this evaluation's velocity gradient into tau_next (6 per
// particle; copied to the particles' stress after the loop, which this loop reads).
template <class Kernel, class Viscosity, class Diffusion> struct FluidInteraction {
    PairTerms<Kernel, Viscosity, Diffusion> terms;
    neighbors::GridView grid;
    Vec3 gravity;
    Real smag = 0; // (C_s dp)^2
    Real blin = 0; // 2/3 C_I dp^2
    Real* tau_next = nullptr;

    DF_HD void operator()(Index i) const {
        const auto& pv = terms.pv;
        const auto a = terms.side(i);
        const bool fluid_i = a.fluid;
        Vec3 acc{};
        Real drho = 0;
        Real strain[6] = {0, 0, 0, 0, 0, 0};
        const auto pair = [&](Index j, Vec3 r, Real r2) {
            const auto b = terms.side(j);
            if (!fluid_i && !b.fluid) return;
            const auto t = terms(a, i, b, j, r, r2);
            acc += b.m * t.g;
            drho += b.m * t.cont + t.d.i;
            if constexpr (Viscosity::needs_velocity_gradient)
                if (fluid_i) add_symmetric_gradient(strain, b.vol, b.v - a.v, t.grad_w);
        };
        // A wall particle takes drho and the fluid's push from fluid partners only.
        if (fluid_i)
            grid.for_each_neighbor(i, a.x, pv.x, pv.y, pv.z, pair);
        else
            grid.for_each_class0_neighbor(i, a.x, pv.x, pv.y, pv.z, pair);
        if (fluid_i) acc += gravity;
        pv.ax[i] = acc.x;
        pv.ay[i] = acc.y;
        pv.az[i] = acc.z;
        pv.drho[i] = drho;
        if constexpr (Viscosity::needs_velocity_gradient) {
            Real* t = tau_next + 6 * i;
            for (int k = 0; k < 6; ++k) t[k] = 0;
            if (fluid_i) sps_tau(strain, smag, blin, 1 / pv.rho[i], t);
        }
    }
};

template <class K, class V, class D>
FluidInteraction<K, V, D> make_gather(const PairTerms<K, V, D>& terms, neighbors::GridView grid,
                                      Vec3 gravity, Real smag, Real blin, Real* tau_next) {
    return {terms, grid, gravity, smag, blin, tau_next};
}

} // namespace debrisflow::sph
