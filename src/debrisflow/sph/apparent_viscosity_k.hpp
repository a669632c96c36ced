#pragma once
#include "debrisflow/neighbors/grid_view_k.hpp"
#include "debrisflow/particles/particle_set.hpp"
#include <cmath>

namespace debrisflow::sph {

// Apparent viscosity of fluid particle i for a generalised-Newtonian model: the SPH velocity
// gradient grad v_i = sum_j m_j / rho_j (v_j - v_i) (x) grad W_ij (Monaghan 1992, eq. 2.6 form),
// the strain rate gamma_dot = sqrt(2 D:D) with D = (grad v + grad v^T) / 2, then
// mu_i = model.apparent_viscosity(gamma_dot, p_i). Wall particles carry the no-slip
// extrapolated velocity v_B = -(d_B / d_A) v_A (Morris et al. 1997, eq. 30), as in the
// viscous pair term, so the wall shear is not halved. Boundary particles get mu = 0 (the pair
// term uses the fluid partner's viscosity).
template <class Kernel, class Model> struct ApparentViscosity {
    particles::ParticleView pv;
    neighbors::GridView grid;
    Kernel kernel;
    Model model;
    Real half_dp;

    DF_HD Real strain_rate(Index i) const {
        const Vec3 xi = pv.pos(i), vi = pv.vel(i);
        Real g[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
        grid.for_each_neighbor(i, xi, pv.x, pv.y, pv.z, [&](Index j, Vec3 r, Real r2) {
            const Vec3 gw = kernel.grad_over_r(std::sqrt(r2)) * r;
            Vec3 dv = pv.vel(j) - vi;
            if (!pv.is_fluid(j) && pv.wd[j] > 0) {
                const Vec3 n{pv.wnx[j], pv.wny[j], pv.wnz[j]};
                const Real d_fluid = dot(xi - pv.pos(j), n) - pv.wd[j];
                const Real beta = 1 + pv.wd[j] / (d_fluid > half_dp ? d_fluid : half_dp);
                dv = beta * dv; // v_j - v_i with the wall's extrapolated relative velocity
            }
            const Real vol = pv.mass[j] / pv.rho[j];
            for (int a = 0; a < 3; ++a)
                for (int b = 0; b < 3; ++b) g[a][b] += vol * dv[a] * gw[b];
        });
        const Real sxx = g[0][0], syy = g[1][1], szz = g[2][2];
        const Real sxy = Real(0.5) * (g[0][1] + g[1][0]);
        const Real sxz = Real(0.5) * (g[0][2] + g[2][0]);
        const Real syz = Real(0.5) * (g[1][2] + g[2][1]);
        return std::sqrt(2 * (sxx * sxx + syy * syy + szz * szz) +
                         4 * (sxy * sxy + sxz * sxz + syz * syz));
    }

    DF_HD void operator()(Index i) const {
        pv.mu[i] = pv.is_fluid(i) ? model.apparent_viscosity(strain_rate(i), pv.p[i]) : Real(0);
    }
};

} // namespace debrisflow::sph
