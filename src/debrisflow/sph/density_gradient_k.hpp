#pragma once
#include "debrisflow/neighbors/grid_view_k.hpp"
#include "debrisflow/particles/particle_set.hpp"
#include <cmath>

namespace debrisflow::sph {

// Renormalised density gradient of fluid particle i over its fluid neighbours (Randles &
// Libersky 1996; as delta-SPH uses it, Antuono et al. 2010 eq. 6):
//   <grad rho>^L_i = L_i sum_j (rho_j - rho_i) grad_i W_ij V_j,
//   L_i = [sum_j (x_j - x_i) (x) grad_i W_ij V_j]^-1,   V_j = m_j / rho_j,
// exact for a linear density field however the kernel is truncated (free surface, walls,
// whose particles are left out: their density is the wall treatment's, not the fluid's).
// Where the matrix is nearly singular (a particle with few fluid neighbours: spray, a sheet
// one particle thick) the plain sum is kept.

// det(L^-1) below which the plain sum is kept: a flat free surface gives about 0.5^dim.
inline constexpr Real renormalisation_min_det = Real(0.01);

// The sums per particle: 2D (the x-z plane) s.x, s.z, a_xx, a_zz, a_xz; 3D s.x, s.y, s.z,
// a_xx, a_yy, a_zz, a_xy, a_xz, a_yz.
template <int Dim> inline constexpr int density_gradient_sums = Dim == 2 ? 5 : 9;

// Adds pair (i, j)'s terms to particle i's sums: s += (rho_j - rho_i) grad_i W_ij V_j and
// a += (x_j - x_i) (x) grad_i W_ij V_j = -f r (x) r V_j (symmetric), with r = x_i - x_j,
// f = (dW/dr) / r, vf = V_j f.
template <int Dim>
DF_HD DF_HOT_INLINE void add_density_gradient_pair(Real* acc, Real drho, Real vf, Vec3 r) {
    const Real g = drho * vf;
    if constexpr (Dim == 2) {
        acc[0] += g * r.x;
        acc[1] += g * r.z;
        acc[2] -= vf * r.x * r.x;
        acc[3] -= vf * r.z * r.z;
        acc[4] -= vf * r.x * r.z;
    } else {
        acc[0] += g * r.x;
        acc[1] += g * r.y;
        acc[2] += g * r.z;
        acc[3] -= vf * r.x * r.x;
        acc[4] -= vf * r.y * r.y;
        acc[5] -= vf * r.z * r.z;
        acc[6] -= vf * r.x * r.y;
        acc[7] -= vf * r.x * r.z;
        acc[8] -= vf * r.y * r.z;
    }
}

// L s from the sums of add_density_gradient_pair, or s where L^-1 is nearly singular.
template <int Dim> DF_HD inline Vec3 renormalised_gradient(const Real* acc) {
    if constexpr (Dim == 2) {
        const Real sx = acc[0], sz = acc[1], xx = acc[2], zz = acc[3], xz = acc[4];
        const Real det = xx * zz - xz * xz;
        if (det <= renormalisation_min_det) return {sx, 0, sz};
        return {(zz * sx - xz * sz) / det, 0, (xx * sz - xz * sx) / det};
    } else {
        const Vec3 s{acc[0], acc[1], acc[2]};
        const Real* a = acc + 3;
        // inverse of the symmetric 3 x 3 by cofactors
        const Real c00 = a[1] * a[2] - a[5] * a[5], c01 = a[4] * a[5] - a[3] * a[2],
                   c02 = a[3] * a[5] - a[1] * a[4], c11 = a[0] * a[2] - a[4] * a[4],
                   c12 = a[3] * a[4] - a[0] * a[5], c22 = a[0] * a[1] - a[3] * a[3];
        const Real det = a[0] * c00 + a[3] * c01 + a[4] * c02;
        if (det <= renormalisation_min_det) return s;
        return {(c00 * s.x + c01 * s.y + c02 * s.z) / det,
                (c01 * s.x + c11 * s.y + c12 * s.z) / det,
                (c02 * s.x + c12 * s.y + c22 * s.z) / det};
    }
}

// Gather form (one particle, its cell neighbours): the gather and resident paths. The host's
// half-list path sums the same pairs (SphSolver::update_density_gradient). Writes 3 reals per
// particle (0 for walls).
template <class Kernel> struct RenormalisedDensityGradient {
    particles::ParticleView pv;
    neighbors::GridView grid;
    Kernel kernel;
    Real* out; // 3 per particle
    int dim;

    DF_HD void operator()(Index i) const {
        const Vec3 v = pv.is_fluid(i) ? (dim == 2 ? gather<2>(i) : gather<3>(i)) : Vec3{};
        Real* g = out + 3 * i;
        g[0] = v.x;
        g[1] = v.y;
        g[2] = v.z;
    }

    template <int Dim> DF_HD Vec3 gather(Index i) const {
        const Real rho_i = pv.rho[i];
        Real acc[density_gradient_sums<Dim>] = {};
        grid.for_each_neighbor(i, pv.pos(i), pv.x, pv.y, pv.z, [&](Index j, Vec3 r, Real r2) {
            if (!pv.is_fluid(j)) return;
            add_density_gradient_pair<Dim>(
                acc, pv.rho[j] - rho_i, pv.mass[j] / pv.rho[j] * kernel.grad_over_r(std::sqrt(r2)),
                r);
        });
        return renormalised_gradient<Dim>(acc);
    }
};

} // namespace debrisflow::sph
