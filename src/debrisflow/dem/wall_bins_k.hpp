#pragma once
// Bins of wall primitives for the grain-wall candidate search (issue #34: "a wall mesh of 10^5
// triangles must not be searched by brute force: bin the triangles"). Each bounded primitive
// is listed in every cell of a uniform grid that its box, widened by the search reach (largest
// grain radius + margin), overlaps; a grain then tests only the primitives of its own cell and
// those kept out of the bins (planes, and faces whose widened box covers many cells). Both
// lists hold positions in the active-primitive list in ascending order, so the candidates come
// out in the order of the search over every active primitive: the binned and the brute-force
// search give the same rows. Built on the host (WallBins, dem/wall_bins.hpp); the view is read
// by a host or device loop.
#include "debrisflow/core/hd.hpp"
#include "debrisflow/core/real.hpp"
#include "debrisflow/core/vec3_k.hpp"
#include <type_traits>

namespace debrisflow::dem {

struct WallBinsView {
    bool binned = false;           // false: every active primitive is a candidate
    const Index* start = nullptr;  // per cell, into items (cells + 1)
    const Index* items = nullptr;  // active positions, ascending within a cell
    const Index* always = nullptr; // active positions outside the bins, ascending
    Index always_count = 0;
    int nc[3] = {1, 1, 1};
    Real lo[3] = {0, 0, 0};
    Real inv_cell[3] = {0, 0, 0}; // 0 in a direction of one cell (2D: y)

    // The cell holding p; a point beyond the grid is placed in its edge cell (no primitive
    // within reach of it is binned: the grid covers every binned primitive's widened box).
    DF_HD int coord(Real v, int d) const {
        const Real x = (v - lo[d]) * inv_cell[d];
        if (!(x > 0)) return 0; // also NaN
        const int c = x < Real(nc[d]) ? int(x) : nc[d] - 1;
        return c;
    }
    DF_HD Index cell_of(Vec3 p) const {
        return coord(p.x, 0) + nc[0] * (coord(p.y, 1) + nc[1] * coord(p.z, 2));
    }

    // Calls f(a) for the active positions a that a grain at p may reach, ascending: with bins,
    // the merge of the unbinned list and p's cell; without, 0 .. count - 1.
    template <class F> DF_HD void for_each_candidate(Vec3 p, Index count, F&& f) const {
        if (!binned) {
            for (Index a = 0; a < count; ++a) f(a);
            return;
        }
        const Index c = cell_of(p);
        Index u = 0, k = start[c];
        const Index end = start[c + 1];
        while (u < always_count || k < end) {
            if (k >= end || (u < always_count && always[u] < items[k]))
                f(always[u++]);
            else
                f(items[k++]);
        }
    }
};
static_assert(std::is_trivially_copyable_v<WallBinsView>);

} // namespace debrisflow::dem
