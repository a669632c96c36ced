#pragma once
// What the grain probes read of the grains (issue #34), written once for the host's DemSolver
// (probes/host_grain_reader.cpp) and a resident DEM phase (dem/resident_grain_reader.hpp),
// where a probe evaluated beside the grain arrays brings back its few numbers, or the few rows
// it selects, instead of the arrays (exec/cuda_instantiations.cu compiles these with nvcc).
#include "debrisflow/core/hd.hpp"
#include "debrisflow/dem/wall_geometry_k.hpp"
#include "debrisflow/rigid/free_rotation_k.hpp"
#include <cstdint>
#include <type_traits>

namespace debrisflow::probes {

// The grains as a probe reads them: read-only views of the grain and clump arrays, and
// clump_of[id] (< 0: a free grain; null: no clumps).
struct GrainsRead {
    const Vec3 *pos, *vel, *spin;
    const Real *radius, *mass, *inv_inertia;
    const std::uint8_t* material;
    const std::uint32_t* id;
    const std::int32_t* clump_of;
    Index n;
    DF_HD bool free(Index i) const { return !clump_of || clump_of[id[i]] < 0; }
};
static_assert(std::is_trivially_copyable_v<GrainsRead>);

struct ClumpsRead {
    const Vec3 *pos, *vel, *ang_mom, *inv_inertia;
    const rigid::Quat* orient;
    const Real* mass;
    Index n;
};
static_assert(std::is_trivially_copyable_v<ClumpsRead>);

// A closed box (every coordinate, y included: 2D grains lie at y = 0 inside any box that
// holds y = 0).
struct GrainBox {
    Vec3 lo, hi;
    DF_HD bool holds(Vec3 p) const {
        return p.x >= lo.x && p.x <= hi.x && p.y >= lo.y && p.y <= hi.y && p.z >= lo.z &&
               p.z <= hi.z;
    }
};

// Sums over the grains in a box (a fold's item type: T{} is the identity, combine adds).
// Kinetic energy: translational 1/2 m v^2 and rotational 1/2 I w^2 of a free grain, 1/2 M V^2
// and 1/2 w . L of a clump by its centre of mass; mass and solid volume m / rho_s of the free
// grains and clump members whose centres are inside (the deposit).
struct GrainSums {
    Real translational = 0, rotational = 0, count = 0;
    Real mass = 0, volume = 0;
    DF_HD static void combine(GrainSums& a, const GrainSums& b) {
        a.translational += b.translational, a.rotational += b.rotational, a.count += b.count;
        a.mass += b.mass, a.volume += b.volume;
    }
};

// Grain i, when its centre is inside: its mass and solid volume m / rho_s (density[material]),
// and its kinetic energy when it is free (a clump's members count through their clump).
struct GrainSumsIn {
    GrainsRead g;
    const Real* density;
    GrainBox box;
    DF_HD void operator()(Index i, GrainSums& s) const {
        if (!box.holds(g.pos[i])) return;
        s.mass += g.mass[i];
        s.volume += g.mass[i] / density[g.material[i]];
        if (!g.free(i)) return;
        s.translational += Real(0.5) * g.mass[i] * dot(g.vel[i], g.vel[i]);
        s.rotational += Real(0.5) / g.inv_inertia[i] * dot(g.spin[i], g.spin[i]);
        s.count += 1;
    }
};

// Clump c's kinetic energy by its centre of mass: 1/2 M V^2 and 1/2 w . L.
struct ClumpEnergy {
    ClumpsRead cl;
    GrainBox box;
    DF_HD void operator()(Index c, GrainSums& s) const {
        if (!box.holds(cl.pos[c])) return;
        const Vec3 w = rigid::angular_velocity(cl.orient[c], cl.ang_mom[c], cl.inv_inertia[c]);
        s.translational += Real(0.5) * cl.mass[c] * dot(cl.vel[c], cl.vel[c]);
        s.rotational += Real(0.5) * dot(w, cl.ang_mom[c]);
        s.count += 1;
    }
};

// Grain i's top z + r above `bed` when it touches one of the wall's primitives (within 5 % of
// its radius of it), else `none`: the run-up is the largest.
struct GrainTopOnWall {
    GrainsRead g;
    const dem::WallPrimitive* faces; // the wall's primitives
    Index count;
    Real bed, none;
    DF_HD Real operator()(Index i) const {
        const Vec3 p = g.pos[i];
        const Real reach = Real(1.05) * g.radius[i];
        for (Index k = 0; k < count; ++k)
            if (dem::wall_distance(faces[k], p, dem::closest_point(faces[k], p)) < reach)
                return p.z + g.radius[i] - bed;
        return none;
    }
};

// A plane that grains cross (point, unit normal); a jump across it by more than `wrap` is a
// periodic wrap, not a crossing.
struct CrossingPlane {
    Vec3 point, normal;
    Real wrap = 0;
};

// A grain id's distance before it was first counted.
constexpr Real unseen_distance = Real(1e300);

// Grain i against a plane: its signed distance s now and last[id] at the previous count; a
// change of side (not a wrap) adds ±m and ±m / rho_s (+ towards the normal) to the net
// crossing; last[id] = s. (Each grain is visited once per count: the write is its own.)
struct GrainCrossing {
    GrainsRead g;
    const Real* density;
    CrossingPlane plane;
    Real* last; // by grain id
    DF_HD void operator()(Index i, GrainSums& s) const {
        const Real d = dot(g.pos[i] - plane.point, plane.normal);
        Real& prev = last[g.id[i]];
        const Real jump = d - prev;
        if (prev != unseen_distance && (jump < 0 ? -jump : jump) <= plane.wrap &&
            (prev < 0) != (d < 0)) {
            const Real sign = d >= 0 ? 1 : -1;
            s.mass += sign * g.mass[i];
            s.volume += sign * (g.mass[i] / density[g.material[i]]);
        }
        prev = d;
    }
};

// Grain i's id, for the largest id held.
struct GrainIdOf {
    const std::uint32_t* id;
    DF_HD Real operator()(Index i) const { return Real(id[i]); }
};

// A grain that a probe reads on the host (GrainReader::rows): the few it selects.
struct GrainRow {
    std::uint32_t id = 0;
    std::int32_t clump = -1; // its clump, or -1
    Vec3 pos, vel;
    Real radius = 0, mass = 0;
    Real volume = 0; // m / rho_s
};

// Flags the grains whose centres lie in the box (1) and the others (0).
struct FlagGrainsIn {
    GrainsRead g;
    GrainBox box;
    Index* flag;
    DF_HD void operator()(Index i) const { flag[i] = box.holds(g.pos[i]) ? 1 : 0; }
};

// Row at[i] of the flagged grains.
struct GatherGrainRows {
    GrainsRead g;
    const Real* density;
    const Index *flag, *at;
    GrainRow* out;
    DF_HD void operator()(Index i) const {
        if (!flag[i]) return;
        GrainRow& r = out[at[i]];
        r.id = g.id[i], r.pos = g.pos[i], r.vel = g.vel[i];
        r.clump = g.clump_of ? g.clump_of[g.id[i]] : -1;
        r.radius = g.radius[i], r.mass = g.mass[i];
        r.volume = g.mass[i] / density[g.material[i]];
    }
};

} // namespace debrisflow::probes
