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
// sum V W >= 1/2, the free-surface criterion). Where the kernel sum is below 1/2 as well the
// ghost carries no usable mirror image, and where it stands decides:
// - inside a sheet thinner than the kernel (a fluid particle within dp sqrt(dim) / 2 of it,
//   the farthest any point of a filled lattice is from its nearest particle): the boundary
//   particle keeps the density that the continuity equation integrates for it, as DBC
//   (Crespo et al. 2007), so that a sheet running along or against the wall is repelled;
// - in air (fluid within the support, but none that near: above a free surface, beside a wall
//   standing out of the water, ahead of a surge): the wall carries the air's pressure, p = 0,
//   at most, so that a density DBC's continuity equation left there does not push the fluid
//   from a dry wall;
// - with no fluid in the support at all, the particle keeps its density.
// Boundary particles without wall geometry (d = 0) are left to DBC. Densities never fall
// below rho_min (the density of boundary_min_pressure).
// With `ghost` (sph.no_slip = "mdbc", English et al. 2022's no-slip variant) the same
// interpolation also gives the fluid's velocity at the ghost node, v_g (its value there: the
// mirror image needs no gradient), and ghost[4 b ..] = (v_g - v_b, 1); (0, 0, 0, 0) where the
// ghost sees no fluid (NoSlipWall then falls back to Morris's rule). Fluid particles and
// particles without wall geometry get zeros.
template <class Kernel> struct MdbcDensity {
    particles::ParticleView pv;
    neighbors::GridView grid;
    Kernel kernel;
    Real h;       // smoothing length: the matrix is assembled in units of h
    Real rho_min; // floor of the boundary density
    Real rho_air; // density at p = 0
    Real dp;      // particle spacing
    int dim;
    Real* ghost = nullptr; // 4 per particle, or nullptr: density only

    // Threshold on the determinant of the h-scaled matrix (DualSPHysics's default for mDBC).
    static constexpr Real det_min = Real(1e-3);

    DF_HD void operator()(Index b) const {
        if (ghost) ghost[4 * b] = ghost[4 * b + 1] = ghost[4 * b + 2] = ghost[4 * b + 3] = 0;
        if (pv.is_fluid(b) || !(pv.wd[b] > 0)) return;
        const Vec3 n{pv.wnx[b], pv.wny[b], pv.wnz[b]};
        const Real two_d = 2 * pv.wd[b];
        const Vec3 xg = pv.pos(b) + two_d * n;
        // a[r][c]: row 0 the kernel moment, rows 1..3 the gradient moments; columns likewise
        // (0: the value at x_g, 1..3: h times its gradient). Lengths are in units of h.
        // Right-hand sides: rhs[0] the density's, rhs[1..3] the velocity components'.
        const int fields = ghost ? 4 : 1;
        Real a[4][4] = {}, rhs[4][4] = {};
        const Real inv_h = 1 / h;
        Real nearest2 = -1; // squared distance of the nearest fluid particle in the support
        grid.for_each_class0_neighbor(-1, xg, pv.x, pv.y, pv.z, [&](Index j, Vec3 r, Real r2) {
            if (!pv.is_fluid(j)) return;
            const Real dist = std::sqrt(r2);
            const Real w = kernel.w(dist);
            if (w <= 0) return;
            nearest2 = nearest2 < 0 || r2 < nearest2 ? r2 : nearest2;
            const Real vol = pv.mass[j] / pv.rho[j];
            const Vec3 rj = (-inv_h) * r;                        // (x_j - x_g) / h
            const Vec3 gj = (-kernel.grad_over_r(dist) * h) * r; // h grad_j W
            const Real row[4] = {w, gj.x, gj.y, gj.z};
            const Real col[4] = {1, rj.x, rj.y, rj.z};
            const Real field[4] = {pv.rho[j], pv.vx[j], pv.vy[j], pv.vz[j]};
            for (int p = 0; p < 4; ++p) {
                for (int k = 0; k < fields; ++k) rhs[k][p] += field[k] * vol * row[p];
                for (int q = 0; q < 4; ++q) a[p][q] += vol * row[p] * col[q];
            }
        });
        Real rho = pv.rho[b]; // DBC's, unless the ghost node sees the fluid
        Real sol[4][4];
        Vec3 vg;
        bool seen = true;
        if (a[0][0] > 0 && solve(a, rhs, fields, sol)) {
            // rho_b = rho_g + (x_b - x_g) . grad rho_g, x_b - x_g = -2 d n
            const Real grad_n = sol[0][1] * n.x + sol[0][2] * n.y + sol[0][3] * n.z; // h grad.n
            rho = sol[0][0] - two_d * inv_h * grad_n;
            vg = {sol[1][0], sol[2][0], sol[3][0]};
        } else if (a[0][0] >= Real(0.5)) {
            // Shepard, for a ghost inside the fluid
            rho = rhs[0][0] / a[0][0];
            vg = (1 / a[0][0]) * Vec3{rhs[1][0], rhs[2][0], rhs[3][0]};
        } else {
            // the ghost is at or above a free surface (kernel sum < 1/2): the Shepard mean
            // of the fluid below would push the fluid from a wall standing in air.
            seen = false;
            // in air: fluid within the support, none within half a lattice cell's diagonal
            const bool in_air = nearest2 > Real(0.25) * dim * dp * dp;
            if (in_air && rho > rho_air) rho = rho_air;
        }
        pv.rho[b] = rho > rho_min ? rho : rho_min;
        if (ghost && seen) {
            const Vec3 u = vg - pv.vel(b);
            ghost[4 * b] = u.x;
            ghost[4 * b + 1] = dim == 2 ? Real(0) : u.y;
            ghost[4 * b + 2] = u.z;
            ghost[4 * b + 3] = 1;
        }
    }

private:
    // Gaussian elimination with partial pivoting on the 3 x 3 (2D: x, z) or 4 x 4 system,
    // for `fields` right-hand sides rhs[k]; false when |det| < det_min.
    DF_HD bool solve(Real (&a)[4][4], Real (&rhs)[4][4], int fields, Real (&sol)[4][4]) const {
        int idx[4] = {0, 1, 2, 3};
        int m = 4;
        if (dim == 2) idx[2] = 3, m = 3; // drop the y row and column
        const int cols = m + fields;
        Real s[4][8];
        for (int p = 0; p < m; ++p) {
            for (int q = 0; q < m; ++q) s[p][q] = a[idx[p]][idx[q]];
            for (int k = 0; k < fields; ++k) s[p][m + k] = rhs[k][idx[p]];
        }
        Real det = 1;
        for (int c = 0; c < m; ++c) {
            int piv = c;
            for (int r = c + 1; r < m; ++r)
                if (std::abs(s[r][c]) > std::abs(s[piv][c])) piv = r;
            if (piv != c) {
                for (int q = 0; q < cols; ++q) {
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
                for (int q = c; q < cols; ++q) s[r][q] -= f * s[c][q];
            }
        }
        if (!(std::abs(det) >= det_min)) return false;
        for (int k = 0; k < fields; ++k) {
            Real x[4] = {0, 0, 0, 0};
            for (int r = m - 1; r >= 0; --r) {
                Real v = s[r][m + k];
                for (int q = r + 1; q < m; ++q) v -= s[r][q] * x[q];
                x[r] = v / s[r][r];
            }
            sol[k][0] = sol[k][1] = sol[k][2] = sol[k][3] = 0;
            for (int p = 0; p < m; ++p) sol[k][idx[p]] = x[p];
        }
        return true;
    }
};

} // namespace debrisflow::sph
