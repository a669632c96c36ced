#pragma once
#include "debrisflow/core/hd.hpp"
#include "debrisflow/core/real.hpp"
#include "debrisflow/core/vec3_k.hpp"
#include <type_traits>

namespace debrisflow::neighbors {

// Trivially copyable view of a cell grid built by counting sort. Particles of cell c are
// order[start[c]] .. order[start[c+1]-1]; cells are numbered x fastest, so a run of cells
// along x is one contiguous range. Periodic directions use the minimum-image convention.
// A grid sorted in two classes (fluid 0, boundary 1: CellGrid::build with a class array) keeps
// each cell's class-0 particles first: cell c is order[start[2c]] .. order[start[2c+2]-1], its
// class 0 ends at start[2c+1], so a loop that needs only the fluid skips the walls' particles
// without testing them.
struct GridView {
    const Index* start; // size ncells * classes + 1
    const Index* order; // sorted position -> particle index
    int classes = 1;    // 1, or 2 (each cell split into its class-0 and class-1 particles)
    int nc[3];
    int periodic[3];
    Real lo[3];
    Real length[3]; // domain length per direction (used for periodic images)
    Real inv_cell[3];
    Real radius2; // squared search radius

    DF_HD DF_HOT_INLINE int cell_coord(Real v, int d) const {
        int c = int((v - lo[d]) * inv_cell[d]);
        if (c < 0) c = periodic[d] ? c % nc[d] + nc[d] : 0;
        if (c >= nc[d]) c = periodic[d] ? c % nc[d] : nc[d] - 1;
        return c;
    }

    // The sort key of a point: its cell, numbered x fastest.
    DF_HD Index cell_of(Real x, Real y, Real z) const {
        return cell_coord(x, 0) + nc[0] * (cell_coord(y, 1) + nc[1] * cell_coord(z, 2));
    }

    // Separation xi - xj with periodic images folded in.
    DF_HD DF_HOT_INLINE Vec3 separation(Vec3 xi, Vec3 xj) const {
        Vec3 r = xi - xj;
        for (int d = 0; d < 3; ++d) {
            if (!periodic[d]) continue;
            const Real half = Real(0.5) * length[d];
            if (r[d] > half)
                r[d] -= length[d];
            else if (r[d] < -half)
                r[d] += length[d];
        }
        return r;
    }

    // Calls f(j, r_ij, r2) for every particle j != self with |xi - x_j| < search radius.
    // Coordinates of particle j are px[j * stride] ... (stride 3 for arrays of 3-vectors).
    template <class F>
    DF_HD DF_HOT_INLINE void for_each_neighbor(Index self, Vec3 xi, const Real* px, const Real* py,
                                               const Real* pz, F&& f, int stride = 1) const {
        visit_stencil(self, xi, {px, py, pz, stride}, f, false);
    }

    // The same over class-0 (fluid) particles only where the grid is sorted in two classes;
    // over every particle otherwise (the caller still tells the classes apart).
    template <class F>
    DF_HD DF_HOT_INLINE void for_each_class0_neighbor(Index self, Vec3 xi, const Real* px,
                                                      const Real* py, const Real* pz, F&& f) const {
        visit_stencil(self, xi, {px, py, pz, 1}, f, classes == 2);
    }

private:
    struct Positions {
        const Real *x, *y, *z;
        int stride;
    };
    // Cells of the 3 x 3 (x 3) stencil around xi; class 0 of each cell only with `first`.
    template <class F>
    DF_HD DF_HOT_INLINE void visit_stencil(Index self, Vec3 xi, Positions pos, F& f,
                                           bool first) const {
        const int c0 = cell_coord(xi.x, 0), c1 = cell_coord(xi.y, 1), c2 = cell_coord(xi.z, 2);
        const int r1 = nc[1] > 1 ? 1 : 0, r2 = nc[2] > 1 ? 1 : 0;
        const int k = classes;
        for (int dz = -r2; dz <= r2; ++dz) {
            int cz = c2 + dz;
            if (cz < 0 || cz >= nc[2]) {
                if (!periodic[2]) continue;
                cz = (cz + nc[2]) % nc[2];
            }
            for (int dy = -r1; dy <= r1; ++dy) {
                int cy = c1 + dy;
                if (cy < 0 || cy >= nc[1]) {
                    if (!periodic[1]) continue;
                    cy = (cy + nc[1]) % nc[1];
                }
                const int row = nc[0] * (cy + nc[1] * cz);
                if (!periodic[0] && !first) {
                    const int xa = c0 > 0 ? c0 - 1 : 0;
                    const int xb = c0 + 1 < nc[0] ? c0 + 1 : nc[0] - 1;
                    visit_range(start[k * (row + xa)], start[k * (row + xb + 1)], self, xi, pos, f);
                } else {
                    for (int dx = -1; dx <= 1; ++dx) {
                        int cx = c0 + dx;
                        if (cx < 0 || cx >= nc[0]) {
                            if (!periodic[0]) continue;
                            cx = (cx + nc[0]) % nc[0];
                        }
                        const int c = k * (row + cx);
                        visit_range(start[c], start[first ? c + 1 : c + k], self, xi, pos, f);
                    }
                }
            }
        }
    }
    template <class F>
    DF_HD DF_HOT_INLINE void visit_range(Index a, Index b, Index self, Vec3 xi, Positions p,
                                         F& f) const {
        for (Index k = a; k < b; ++k) {
            const Index j = order[k];
            const std::size_t s = std::size_t(j) * std::size_t(p.stride);
            const Vec3 r = separation(xi, {p.x[s], p.y[s], p.z[s]});
            const Real r2 = dot(r, r);
            if (r2 < radius2 && j != self) f(j, r, r2);
        }
    }
};
static_assert(std::is_trivially_copyable_v<GridView>);

} // namespace debrisflow::neighbors
