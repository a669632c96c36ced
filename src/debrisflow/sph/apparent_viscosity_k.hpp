#pragma once
#include "debrisflow/neighbors/grid_view_k.hpp"
#include "debrisflow/particles/particle_set.hpp"
#include "debrisflow/sph/no_slip_wall_k.hpp"
#include <cmath>

namespace debrisflow::sph {

// Apparent viscosity of fluid particle i for a generalised-Newtonian model: the SPH velocity
// gradient grad v_i = sum_j m_j / rho_j (v_j - v_i) (x) grad W_ij (Monaghan 1992, eq. 2.6 form),
// the strain rate gamma_dot = sqrt(2 D:D) with D = (grad v + grad v^T) / 2, then
// mu_i = model.apparent_viscosity(gamma_dot, p_i). Wall particles carry the no-slip wall
// velocity of the viscous pair term (NoSlipWall: Morris's or mDBC's), so the wall shear is not
// halved. Boundary particles get mu = 0 (the pair term uses the fluid partner's viscosity).
// v_j - v_i as the velocity-gradient sum of fluid particle i sees it.
DF_HD inline Vec3 gradient_velocity_difference(const particles::ParticleView& pv,
                                               const NoSlipWall& wall, Index j, Vec3 xi, Vec3 vi) {
    const Vec3 dv = pv.vel(j) - vi;
    return pv.is_fluid(j) ? dv : -1 * wall.difference(pv, j, xi, -1 * dv);
}

// gamma_dot = sqrt(2 D:D) from the symmetric gradient D = (xx, yy, zz, xy, xz, yz).
DF_HD inline Real strain_rate_of(const Real d[6]) {
    return std::sqrt(2 * (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]) +
                     4 * (d[3] * d[3] + d[4] * d[4] + d[5] * d[5]));
}

// Adds vol (dv (x) gw) symmetrised to D = (xx, yy, zz, xy, xz, yz).
DF_HD inline void add_symmetric_gradient(Real d[6], Real vol, Vec3 dv, Vec3 gw) {
    d[0] += vol * dv.x * gw.x;
    d[1] += vol * dv.y * gw.y;
    d[2] += vol * dv.z * gw.z;
    d[3] += Real(0.5) * vol * (dv.x * gw.y + dv.y * gw.x);
    d[4] += Real(0.5) * vol * (dv.x * gw.z + dv.z * gw.x);
    d[5] += Real(0.5) * vol * (dv.y * gw.z + dv.z * gw.y);
}

// Gather form (one particle, its cell neighbours): device and gather paths. The host path
// sums the same terms over the half pair list (SphSolver::update_viscosity).
template <class Kernel, class Model> struct ApparentViscosity {
    particles::ParticleView pv;
    neighbors::GridView grid;
    Kernel kernel;
    Model model;
    NoSlipWall wall;

    DF_HD Real strain_rate(Index i) const {
        const Vec3 xi = pv.pos(i), vi = pv.vel(i);
        Real d[6] = {0, 0, 0, 0, 0, 0};
        grid.for_each_neighbor(i, xi, pv.x, pv.y, pv.z, [&](Index j, Vec3 r, Real r2) {
            const Vec3 gw = kernel.grad_over_r(std::sqrt(r2)) * r;
            add_symmetric_gradient(d, pv.mass[j] / pv.rho[j],
                                   gradient_velocity_difference(pv, wall, j, xi, vi), gw);
        });
        return strain_rate_of(d);
    }

    DF_HD void operator()(Index i) const {
        pv.mu[i] = pv.is_fluid(i) ? model.apparent_viscosity(strain_rate(i), pv.p[i]) : Real(0);
    }
};

// A constant dynamic viscosity mu for fluid particles, 0 for walls (the pair term uses the
// fluid partner's).
struct FluidViscosity {
    particles::ParticleView pv;
    Real mu;
    DF_HD void operator()(Index i) const { pv.mu[i] = pv.is_fluid(i) ? mu : Real(0); }
};

// mu_i / rho_i of a fluid particle (the viscous step limit of a generalised-Newtonian fluid).
struct FluidKinematicViscosity {
    particles::ParticleView pv;
    DF_HD Real operator()(Index i) const { return pv.is_fluid(i) ? pv.mu[i] / pv.rho[i] : Real(0); }
};

} // namespace debrisflow::sph
