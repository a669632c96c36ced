#pragma once
// The unresolved SPH-DEM coupling's per-grain and per-particle work (coupling/sph_dem.hpp),
// written once as host/device functors: the host's SphDemCoupling and the resident loop's
// (coupling/resident_sph_dem.hpp) launch the same code.
#include "debrisflow/core/hd.hpp"
#include "debrisflow/core/vec3_k.hpp"
#include "debrisflow/coupling/drag_laws_k.hpp"
#include "debrisflow/neighbors/grid_view_k.hpp"
#include "debrisflow/particles/particle_set.hpp"
#include <cmath>

namespace debrisflow::coupling {

// Below this fluid share a grain is taken as out of the fluid.
constexpr Real sph_dem_dry_share = Real(1e-3);

// Solves L g = b (Cramer's rule); returns b itself when L is close to singular (a grain
// with few neighbours), where the plain kernel gradient is the better estimate.
DF_HD inline Vec3 solve3(const Real L[3][3], Vec3 b) {
    const Real det = L[0][0] * (L[1][1] * L[2][2] - L[1][2] * L[2][1]) -
                     L[0][1] * (L[1][0] * L[2][2] - L[1][2] * L[2][0]) +
                     L[0][2] * (L[1][0] * L[2][1] - L[1][1] * L[2][0]);
    if (!((det < 0 ? -det : det) > Real(0.05))) return b;
    Vec3 g;
    for (int c = 0; c < 3; ++c) {
        Real m[3][3];
        for (int r = 0; r < 3; ++r)
            for (int k = 0; k < 3; ++k) m[r][k] = k == c ? b[r] : L[r][k];
        g[c] = (m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
                m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0])) /
               det;
    }
    return g;
}

// What the coupling reads of the grains and writes of their fluid loads (dem::FluidLoad).
struct GrainsInFluid {
    const Vec3 *pos, *vel;
    const Real *radius, *inv_mass;
    Index n;
    Vec3 *force, *u; // held force [N], local fluid velocity [m/s]
    Real* beta;      // drag coefficient [kg/s]
    Real* share;     // S_f per grain: the reaction's weights
    Vec3* handover;  // the DEM's impulse over its last advance, for the reaction
};

// Per grain i, the fluid load of this evaluation (Robinson, Ramaioli & Luding 2014 fields):
//   S_f = sum_fluid V_j W_ij, S_b = sum_boundary V_j W_ij, phi = min(1, S_f / (1 - min(S_b, 0.9)))
//   u = sum_fluid V_j v_j W_ij / S_f, rho_f = sum_fluid m_j W_ij / S_f
//   grad p = L^-1 sum_all V_j (p_j - p_i) grad W_ij (Bonet & Lok 1999), eps = 1 - sum_k V_k W_ik
//   F = -phi V_i grad p held, beta = phi beta_drag(d, rho_f, mu_f, |u - v_i|, eps)
// Returns beta / m_i (the largest bounds the DEM step: explicit drag needs h < 0.5 m / beta).
template <class Kernel, class Drag> struct GrainFluidSample {
    particles::ParticleView pv;
    neighbors::GridView fluid_grid; // cells of the kernel support over the particles
    neighbors::GridView grain_grid; // the same cells over the grains
    GrainsInFluid g;
    Kernel kernel;
    Real nu;     // the fluid's kinematic viscosity where no particle carries its own mu
    bool has_mu; // the particles carry an apparent viscosity

    DF_HD Real operator()(Index i) const {
        constexpr Real pi = Real(3.14159265358979323846);
        const Vec3 xi = g.pos[i];
        // One pass gathers the kernel sums and, for the renormalised pressure gradient,
        // A = sum_j V_j p_j grad W_ij, B = sum_j V_j grad W_ij and
        // L = sum_j V_j (x_j - x_i) (x) grad W_ij; then grad p = L^-1 (A - p_i B) with p_i
        // the Shepard pressure: exact for a linear (hydrostatic) field, where the plain sum A
        // errs by p_i B on a compressed lattice.
        Real sf = 0, sb = 0, mass = 0, mu = 0, sp = 0;
        Vec3 mom{}, ga{}, gb{};
        Real L[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
        const particles::ParticleView& v = pv;
        fluid_grid.for_each_neighbor(-1, xi, v.x, v.y, v.z, [&](Index j, Vec3 r, Real r2) {
            const Real d = std::sqrt(r2);
            const Real w = kernel.w(d);
            const Real vj = v.mass[j] / v.rho[j];
            const Vec3 gw = (vj * kernel.grad_over_r(d)) * r; // V_j grad_i W(x_i - x_j)
            ga += v.p[j] * gw;
            gb += gw;
            for (int a = 0; a < 3; ++a)
                for (int b = 0; b < 3; ++b) L[a][b] -= gw[a] * r[b];
            sp += vj * v.p[j] * w;
            if (!v.is_fluid(j)) {
                sb += vj * w;
                return;
            }
            sf += vj * w;
            mass += v.mass[j] * w;
            mom += (vj * w) * v.vel(j);
            if (has_mu) mu += vj * w * v.mu[j];
        });
        if (sf < sph_dem_dry_share) {
            g.force[i] = {}, g.u[i] = {}, g.beta[i] = 0, g.share[i] = 0;
            return 0;
        }
        g.share[i] = sf;
        const Real p_i = sp / (sf + sb);
        const Vec3 gradp = solve3(L, ga - p_i * gb);
        Real solid = 0;
        const Real* gp = &g.pos[0].x;
        grain_grid.for_each_neighbor(
            -1, xi, gp, gp + 1, gp + 2,
            [&](Index k, Vec3, Real r2) {
                const Real rk = g.radius[k];
                solid += Real(4) / 3 * pi * rk * rk * rk * kernel.w(std::sqrt(r2));
            },
            3);
        const Real eps1 = 1 - solid;
        const Real eps = eps1 < Real(0.2) ? Real(0.2) : (eps1 > 1 ? Real(1) : eps1);
        const Real rho_f = mass / sf;
        const Vec3 u = (1 / sf) * mom;
        const Real mu_f = has_mu && mu > 0 ? mu / sf : rho_f * nu;
        const Real wall = sb < Real(0.9) ? sb : Real(0.9);
        const Real phi_raw = sf / (1 - wall);
        const Real phi = phi_raw < 1 ? phi_raw : Real(1);
        const Real r = g.radius[i];
        const Real vol = Real(4) / 3 * pi * r * r * r;
        const Real slip = norm(u - g.vel[i]);
        const Real beta = phi * Drag::beta({2 * r, rho_f, mu_f, slip, eps});
        g.force[i] = (-phi * vol) * gradp;
        g.u[i] = u;
        g.beta[i] = beta;
        return beta * g.inv_mass[i];
    }
};

// The impulse the DEM recorded over its last advance becomes the handover for the fluid step
// that follows; the record starts again.
struct FluidImpulseHandOver {
    Vec3 *impulse, *handover;
    DF_HD void operator()(Index i) const {
        handover[i] = impulse[i];
        impulse[i] = {};
    }
};

// The reaction per unit weight, c_i = -F_i / S_f with F_i = handover / dt the mean fluid
// force on grain i over the fluid step (zero for a grain out of the fluid).
struct ReactionPerWeight {
    const Vec3* handover;
    const Real* share;
    Real inv_dt;
    Vec3* reaction;
    DF_HD void operator()(Index i) const {
        reaction[i] = share[i] > 0 ? (-inv_dt / share[i]) * handover[i] : Vec3{};
    }
};

// Grain i hands fluid particle j the force c_i V_j W_ij (the weights V_j W_ij / S_f sum to
// one over j): per unit mass W_ij c_i / rho_j, gathered per fluid particle over the grains
// around it, so there are no write conflicts and the sums do not depend on the thread count.
template <class Kernel> struct FluidReactionGather {
    particles::ParticleView pv;
    neighbors::GridView grain_grid;
    const Vec3* grain_pos;
    const Vec3* reaction;
    Kernel kernel;
    DF_HD void operator()(Index j) const {
        if (!pv.is_fluid(j)) return;
        Vec3 a{};
        const Real* gp = &grain_pos[0].x;
        grain_grid.for_each_neighbor(
            -1, pv.pos(j), gp, gp + 1, gp + 2,
            [&](Index i, Vec3, Real r2) { a += kernel.w(std::sqrt(r2)) * reaction[i]; }, 3);
        if (a.x == 0 && a.y == 0 && a.z == 0) return;
        const Real inv_rho = 1 / pv.rho[j];
        pv.ax[j] += inv_rho * a.x;
        pv.ay[j] += inv_rho * a.y;
        pv.az[j] += inv_rho * a.z;
    }
};

} // namespace debrisflow::coupling
