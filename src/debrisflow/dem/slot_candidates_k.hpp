#pragma once
// Who may touch whom before the next neighbour rebuild, grain by grain, written once for the
// host (DemSolver::rebuild through ContactSlots::build) and a device: candidates(i, emit) calls
// emit(partner, key) for each partner of grain i within reach (radii + skin).
#include "debrisflow/dem/obstacles.hpp"
#include "debrisflow/dem/wall_bins_k.hpp"
#include "debrisflow/dem/wall_geometry_k.hpp"
#include "debrisflow/neighbors/grid_view_k.hpp"
#include <cstddef>
#include <cstdint>
#include <type_traits>

namespace debrisflow::dem {

// Grain-grain candidates from the cell grid, each pair once, in the row of the smaller grain
// (equal radii: of the lower id), members of one clump never paired; the key is the partner's
// persistent id. A boulder's row holds only the grains at least as large as itself, not the
// hundreds of fines around it: the slots' capacity per grain is the longest row's, so one
// boulder's row would otherwise size every grain's (a boulder block listed before the fines
// multiplied the memory of cases/papers/slit_dam_dem/typeB.toml by 4.5).
struct GrainCandidates {
    neighbors::GridView grid;
    const Vec3* pos;
    const Real* radius;
    const std::uint32_t* id;
    const std::int32_t* clump_of; // clump of each grain id (< 0: none), or null
    Real skin;
    template <class Emit> DF_HD void operator()(Index i, Emit&& emit) const {
        const Real ri = radius[i];
        const std::uint32_t idi = id[i];
        const std::int32_t ci = clump_of ? clump_of[idi] : -1;
        const Real* p = &pos[0].x;
        grid.for_each_neighbor(
            i, pos[i], p, p + 1, p + 2,
            [&](Index j, Vec3, Real r2) {
                if (radius[j] < ri || (radius[j] == ri && id[j] < idi)) return;
                if (ci >= 0 && clump_of[id[j]] == ci) return; // members of one clump
                const Real reach = ri + radius[j] + skin;
                if (r2 < reach * reach) emit(j, id[j]);
            },
            3);
    }
};
static_assert(std::is_trivially_copyable_v<GrainCandidates>);

// Grain-wall candidates among the active primitives (`active`: their indices, `bounds`: their
// boxes, which reject most faces of a flume's structures before the closest-point search; `bins`:
// those of the grain's cell and the unbinned ones when there are many, in the same ascending
// order); the key is the primitive's index.
struct WallCandidatesOf {
    const WallPrimitive* prims;
    const Index* active;
    const PrimitiveBounds* bounds;
    Index count;
    const Vec3* pos;
    const Real* radius;
    Real skin;
    WallBinsView bins;
    template <class Emit> DF_HD void operator()(Index i, Emit&& emit) const {
        const Vec3 p = pos[i];
        const Real reach = radius[i] + skin;
        bins.for_each_candidate(p, count, [&](Index a) {
            if (!bounds[a].may_reach(p, reach)) return;
            const WallPrimitive& w = prims[active[a]];
            const Vec3 q = closest_point(w, p);
            if (wall_distance(w, p, q) < reach) emit(active[a], std::uint32_t(active[a]));
        });
    }
};
static_assert(std::is_trivially_copyable_v<WallCandidatesOf>);

// Grain-obstacle candidates: the rigid bodies' contact spheres within reach, found on a cell
// grid of the spheres (cells of one reach: largest grain + largest sphere + skin; built by
// DemSolver::configure_obstacle_grid and a sort of the spheres by cell); the key is the
// sphere's index.
struct ObstacleCandidates {
    neighbors::GridView grid;
    const ObstacleSphere* spheres;
    Index count; // spheres
    const Vec3* pos;
    const Real* radius;
    Real skin;
    // The spheres' centres as strided coordinates for the grid (a sphere is 15 reals).
    static constexpr int stride = int(sizeof(ObstacleSphere) / sizeof(Real));
    template <class Emit> DF_HD void operator()(Index i, Emit&& emit) const {
        if (count == 0) return;
        const Real ri = radius[i];
        const Real* c = &spheres[0].x.x;
        grid.for_each_neighbor(
            -1, pos[i], c, c + 1, c + 2,
            [&](Index s, Vec3, Real r2) {
                const Real reach = ri + spheres[s].r + skin;
                if (r2 < reach * reach) emit(s, std::uint32_t(s));
            },
            stride);
    }
};
static_assert(std::is_trivially_copyable_v<ObstacleCandidates>);
static_assert(sizeof(ObstacleSphere) % sizeof(Real) == 0 && offsetof(ObstacleSphere, x) == 0);

} // namespace debrisflow::dem
