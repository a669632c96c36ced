#pragma once
// The per-particle rules of the fluid <-> FEM coupling through the boundary particles that the
// elements carry (coupling/sph_fem.hpp), written once for the host's particle set and a
// resident backend's (sph/resident_fem.hpp).
#include "debrisflow/particles/particle_set.hpp"
#include <cstdint>
#include <type_traits>

namespace debrisflow::coupling {

// Where a carried particle sits in its element: the element's nodes (global ids, `nodes` of
// them), the shape-function values N_a(xi) at its natural coordinates, and the boundary facet
// that gives its wall normal.
struct FemCarrier {
    std::int32_t node[10];
    Real n[10];
    std::int32_t nodes, facet;
};

// The element's motion at the particle: x = sum N_a (x_a + ahead v_a), v = sum N_a v_a
// (isoparametric interpolation), n = the facet's outward normal; 2D lies in the x-z plane.
DF_HD inline void place_on_element(const particles::ParticleView& pv, Index i, const FemCarrier& c,
                                   const Vec3* x, const Vec3* v, const Vec3* facet_normal,
                                   Real ahead, bool two_d) {
    Vec3 p{}, u{};
    for (int a = 0; a < c.nodes; ++a) {
        const Vec3 xa = x[c.node[a]], va = v[c.node[a]];
        p = p + c.n[a] * (xa + ahead * va);
        u = u + c.n[a] * va;
    }
    if (two_d) p.y = 0, u.y = 0;
    pv.x[i] = p.x, pv.y[i] = p.y, pv.z[i] = p.z;
    pv.vx[i] = u.x, pv.vy[i] = u.y, pv.vz[i] = u.z;
    const Vec3 n = facet_normal[c.facet];
    pv.wnx[i] = n.x, pv.wny[i] = n.y, pv.wnz[i] = n.z;
}

// The fluid's load on carried particle i: f = m_i a_i (the SPH pair forces are antisymmetric,
// so this is the fluid's reaction on the particle's element).
DF_HD inline Vec3 carried_load(const particles::ParticleView& pv, Index i) {
    return pv.mass[i] * Vec3{pv.ax[i], pv.ay[i], pv.az[i]};
}

// The carried particles' rows as arrays: particle i is carried by row[i] (or -1), placed by
// carrier[row].
struct FemRows {
    const std::int32_t* row; // per particle
    const FemCarrier* carrier;
};

// Every carried particle takes its element's motion (one item per particle).
struct FollowElements {
    particles::ParticleView pv;
    FemRows rows;
    const Vec3 *x, *v, *facet_normal;
    Real ahead;
    bool two_d;
    DF_HD void operator()(Index i) const {
        const std::int32_t r = rows.row[i];
        if (r >= 0) place_on_element(pv, i, rows.carrier[r], x, v, facet_normal, ahead, two_d);
    }
};

// flag[i] = 1 for a carried particle, else 0 (the loads are compacted in index order).
struct CarriedFlags {
    const std::int32_t* row;
    Index* flag;
    DF_HD void operator()(Index i) const { flag[i] = row[i] >= 0 ? 1 : 0; }
};

// A carried particle's row and load, as the host hands the load to the nodes.
struct CarriedLoad {
    std::int32_t row;
    Vec3 force;
};

// load[at[i]] = (row, m a) of each flagged particle.
struct GatherCarriedLoads {
    particles::ParticleView pv;
    const std::int32_t* row;
    const Index *flag, *at;
    CarriedLoad* load;
    DF_HD void operator()(Index i) const {
        if (flag[i]) load[at[i]] = {row[i], carried_load(pv, i)};
    }
};

// keep[i] = 0 for a particle whose row's element eroded (dead[row] = 1), else 1.
struct KeepOffErodedElements {
    const std::int32_t* row;
    const std::uint8_t* dead; // per row
    Index* keep;
    DF_HD void operator()(Index i) const { keep[i] = row[i] >= 0 && dead[row[i]] ? 0 : 1; }
};

// After the surface changed: each carried particle's wall normal (its new facet's) and depth
// under the surface (depth[row]).
struct CarriedSurface {
    particles::ParticleView pv;
    FemRows rows;
    const Vec3* facet_normal;
    const Real* depth; // per row
    DF_HD void operator()(Index i) const {
        const std::int32_t r = rows.row[i];
        if (r < 0) return;
        const Vec3 n = facet_normal[rows.carrier[r].facet];
        pv.wnx[i] = n.x, pv.wny[i] = n.y, pv.wnz[i] = n.z;
        pv.wd[i] = depth[r];
    }
};

static_assert(std::is_trivially_copyable_v<FemCarrier>);
static_assert(std::is_trivially_copyable_v<FollowElements>);
static_assert(std::is_trivially_copyable_v<GatherCarriedLoads>);
static_assert(std::is_trivially_copyable_v<KeepOffErodedElements>);
static_assert(std::is_trivially_copyable_v<CarriedSurface>);

} // namespace debrisflow::coupling
