#pragma once
#include "debrisflow/neighbors/grid_view_k.hpp"
#include "debrisflow/particles/particle_set.hpp"
#include <cmath>

namespace debrisflow::sph {

// Modified dynamic boundary conditions (mDBC; English et al. 2022, Comp. Part. Mech. 9, eqs.
// 8-11): a boundary particle b with wall normal n (into the fluid) at depth d behind the wall
// surface takes the density of the fluid at its ghost node x_g = x_b + 2 d n, mirrored across
// the surface, extrapolated back linearly:
//   rho_b = rho_g + (x_b - x_g) . grad rho_g,
// with rho_g and grad rho_g from the first-order consistent interpolation over the fluid
// neighbours j of x_g (V_j = m_j / rho_j, r_j = x_j - x_g, G_j = grad_j W):
//   [ sum V W      sum V W r^T   ] [ rho_g      ]   [ sum rho V W ]
//   [ sum V G      sum V G (x) r ] [ grad rho_g ] = [ sum rho V G ].
// Where the matrix is near singular (few fluid neighbours: a free surface, a corner) the
// Shepard mean sum rho V W / sum V W is used while the ghost is inside the fluid (kernel sum
// sum V W >= 1/2, the free-surface criterion). A ghost at or above a free surface, or with no
// fluid near, carries no information about the wall's pressure; there the boundary particle
// keeps the density that the continuity equation integrates for it, as DBC (Crespo et al.
// 2007), so that a sheet thinner than the kernel running along or against the wall is still
// repelled instead of seeing p = 0. Boundary particles without wall geometry (d = 0) are left
// to DBC. Densities never fall below rho_min (the density of boundary_min_pressure).
template <class Kernel> struct MdbcDensity {
    particles::ParticleView pv;
    neighbors::GridView grid;
    Kernel kernel;
    Real h;       // smoothing length: the matrix is assembled in units of h
    Real rho_min; // floor of the boundary density
    int dim;

    // Threshold on the determinant of the h-scaled matrix (DualSPHysics's default for mDBC).
    static constexpr Real det_min = Real(1e-3);

    DF_HD void operator()(Index b) const {
        if (pv.is_fluid(b) || !(pv.wd[b] > 0)) return;
        const Vec3 n{pv.wnx[b], pv.wny[b], pv.wnz[b]};
        const Real two_d = 2 * pv.wd[b];
        const Vec3 xg = pv.pos(b) + two_d * n;
        // a[r][c]: row 0 the kernel moment, rows 1..3 the gradient moments; columns likewise
        // (0: rho_g, 1..3: h grad rho_g). Lengths are in units of h.
        Real a[4][4] = {}, rhs[4] = {};
        const Real inv_h = 1 / h;
        grid.for_each_class0_neighbor(-1, xg, pv.x, pv.y, pv.z, [&](Index j, Vec3 r, Real r2) {
            if (!pv.is_fluid(j)) return;
            const Real dist = std::sqrt(r2);
            const Real w = kernel.w(dist);
            if (w <= 0) return;
            const Real vol = pv.mass[j] / pv.rho[j];
            const Vec3 rj = (-inv_h) * r;                        // (x_j - x_g) / h
            const Vec3 gj = (-kernel.grad_over_r(dist) * h) * r; // h grad_j W
            const Real row[4] = {w, gj.x, gj.y, gj.z};
            const Real col[4] = {1, rj.x, rj.y, rj.z};
            for (int p = 0; p < 4; ++p) {
                rhs[p] += pv.rho[j] * vol * row[p];
                for (int q = 0; q < 4; ++q) a[p][q] += vol * row[p] * col[q];
            }
        });
        Real rho = pv.rho[b]; // DBC's, unless the ghost node sees the fluid
        Real sol[4];
        if (a[0][0] > 0 && solve(a, rhs, sol)) {
            // rho_b = rho_g + (x_b - x_g) . grad rho_g, x_b - x_g = -2 d n
            const Real grad_n = sol[1] * n.x + sol[2] * n.y + sol[3] * n.z; // h grad . n
            rho = sol[0] - two_d * inv_h * grad_n;
        } else if (a[0][0] >= Real(0.5)) {
            rho = rhs[0] / a[0][0]; // Shepard, for a ghost inside the fluid
        }
        // else the ghost is at or above a free surface (kernel sum < 1/2): the Shepard mean
        // of the fluid below would push the fluid from a wall standing in air.
        pv.rho[b] = rho > rho_min ? rho : rho_min;
    }

private:
    // Gaussian elimination with partial pivoting on the 3 x 3 (2D: x, z) or 4 x 4 system;
    // false when |det| < det_min.
    DF_HD bool solve(Real (&a)[4][4], Real (&rhs)[4], Real (&sol)[4]) const {
        int idx[4] = {0, 1, 2, 3};
        int m = 4;
        if (dim == 2) idx[2] = 3, m = 3; // drop the y row and column
        Real s[4][5];
        for (int p = 0; p < m; ++p) {
            for (int q = 0; q < m; ++q) s[p][q] = a[idx[p]][idx[q]];
            s[p][m] = rhs[idx[p]];
        }
        Real det = 1;
        for (int c = 0; c < m; ++c) {
            int piv = c;
            for (int r = c + 1; r < m; ++r)
                if (std::abs(s[r][c]) > std::abs(s[piv][c])) piv = r;
            if (piv != c) {
                for (int q = 0; q <= m; ++q) {
                    const Real t = s[c][q];
                    s[c][q] = s[piv][q];
                    s[piv][q] = t;
                }
                det = -det;
            }
            det *= s[c][c];
            if (s[c][c] == 0) return false;
            for (int r = c + 1; r < m; ++r) {
                const Real f = s[r][c] / s[c][c];
                for (int q = c; q <= m; ++q) s[r][q] -= f * s[c][q];
            }
        }
        if (!(std::abs(det) >= det_min)) return false;
        Real x[4] = {0, 0, 0, 0};
        for (int r = m - 1; r >= 0; --r) {
            Real v = s[r][m];
            for (int q = r + 1; q < m; ++q) v -= s[r][q] * x[q];
            x[r] = v / s[r][r];
        }
        sol[0] = sol[1] = sol[2] = sol[3] = 0;
        for (int p = 0; p < m; ++p) sol[idx[p]] = x[p];
        return true;
    }
};

} // namespace debrisflow::sph
