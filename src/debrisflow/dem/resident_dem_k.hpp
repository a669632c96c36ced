#pragma once
// The small per-grain steps of the resident DEM loop (dem/resident_dem.hpp) that the host
// solver does with its own containers: the contact pass's copy of the grain state, the grains'
// bounding box (dem/grain_bounds_k.hpp), the keys of the reverse index, and the flags of the
// grains that leave (outlets, the domain exit) or that a feed's new grains must keep clear of,
// and the wall contacts brought to the host (on a FEM solid's surface, whose impulse goes to its
// nodes; on a wall a pressure map reads). Host/device functors.
#include "debrisflow/core/domain.hpp"
#include "debrisflow/dem/grain_bounds_k.hpp"
#include "debrisflow/dem/grain_contact_k.hpp"
#include "debrisflow/dem/grain_own_pass_k.hpp"
#include "debrisflow/dem/wall_geometry_k.hpp"
#include "debrisflow/flow/exit_faces_k.hpp"
#include "debrisflow/flow/feed_reach_k.hpp"
#include "debrisflow/flow/outlet_box_k.hpp"
#include <cmath>
#include <cstdint>
#include <type_traits>

namespace debrisflow::dem {

// hot[i] = grain i's state as the contact pass reads it (DemSolver::refresh_hot).
struct LoadHot {
    GrainView g;
    GrainState* hot;
    DF_HD void operator()(Index i) const { hot[i] = GrainState::load(g, i); }
};

// The reverse index's sort key of slot s = i * capacity + k: the partner it names, or n (after
// every grain) for an empty slot. Sorted stably, the slots naming grain j come in slot order,
// as DemSolver::slot_contacts's counting sort leaves them.
struct SlotPartnerKey {
    Index capacity;
    const Index *count, *partner;
    Index n;
    Index* key;
    DF_HD void operator()(Index s) const {
        const Index i = s / capacity, k = s % capacity;
        key[s] = k < count[i] ? partner[s] : n;
    }
};

// a[i] = value.
template <class T> struct FillWith {
    T* a;
    T value;
    DF_HD void operator()(Index i) const { a[i] = value; }
};

// keep[i] = 0 for the grains whose centre is inside an outlet's box, 1 otherwise.
struct GrainKeepOutsideBox {
    const Vec3* pos;
    flow::OutletBox box;
    Index* keep;
    DF_HD void operator()(Index i) const { keep[i] = !box.contains(pos[i]); }
};

// keep[i] = 0 for the grains whose (finite) centre left the domain, 1 for the others (a grain
// that is not finite stays for the health check to name).
struct GrainKeepInsideDomain {
    const Vec3* pos;
    flow::ExitFaces faces;
    Index* keep;
    DF_HD void operator()(Index i) const { keep[i] = faces.of_finite(pos[i]) < 0; }
};

// out[at[i]] = the face leaver i crossed, for the grains with leave[i] (`at` the exclusive
// scan of leave).
struct GrainLeaverFaces {
    const Vec3* pos;
    flow::ExitFaces faces;
    const Index* leave;
    const Index* at;
    int* out;
    DF_HD void operator()(Index i) const {
        if (leave[i]) out[at[i]] = faces.of_finite(pos[i]);
    }
};

// Whether grain i is not finite or its centre is outside a closed side of the domain (y does
// not count in 2D): what the health check stops at (DemSolver::escaped).
struct GrainEscaped {
    const Vec3 *pos, *vel;
    Domain dom;
    bool plane;
    DF_HD bool operator()(Index i) const {
        const Vec3 p = pos[i], v = vel[i];
        bool bad = !(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z) &&
                     std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z));
        for (int d = 0; d < 3; ++d)
            if (!(plane && d == 1) && !dom.periodic[d])
                bad = bad || !(p[d] >= dom.lo[d] && p[d] <= dom.hi[d]);
        return bad;
    }
};

// flag[i] = 1 for the grains near a feed's region (FeedReach::near), 0 otherwise.
struct GrainNearFeed {
    const Vec3* pos;
    const Real* radius;
    flow::FeedReach region;
    Index* flag;
    DF_HD void operator()(Index i) const { flag[i] = region.near(pos[i], radius[i]); }
};

// The mass of grain i (the sum over the grains: the mass the set holds).
struct GrainMass {
    const Real* mass;
    DF_HD Real operator()(Index i) const { return mass[i]; }
};

// A grain's contact with a wall's primitive, brought to the host: the primitive, the force on
// the grain and the contact point. Of a triangle on moving nodes (a FEM solid's surface,
// DEM-FEM) the host turns it into the corners' impulse with the barycentric weights; of a wall
// that records its contacts (a pressure map reads them) it keeps it (DemSolver's slot pass, in
// slot order).
struct WallContactRow {
    Index prim;
    Vec3 f, q;
};

// flag[s] = 1 for wall slot s (grain s / cap, row s % cap) in use and touching, on a triangle on
// moving nodes (nodal) or on a wall that records its contacts (not nodal).
struct FlagWallContacts {
    const Index *count, *partner;
    const std::uint8_t* touching;
    const WallPrimitive* prims;
    const WallState* walls;
    Index cap;
    bool nodal;
    Index* flag;
    DF_HD void operator()(Index s) const {
        bool pick = s % cap < count[s / cap] && touching[s];
        if (pick) {
            const WallPrimitive& pr = prims[partner[s]];
            pick = nodal ? pr.corners >= 0 : walls[pr.wall].record;
        }
        flag[s] = pick ? 1 : 0;
    }
};

// Row at[s] of the flagged slots from the per-grain pass's output (force 0-2, point 3-5).
struct GatherWallContacts {
    const Index* partner;
    const Real* out; // 9 per slot
    const Index *flag, *at;
    WallContactRow* rows;
    DF_HD void operator()(Index s) const {
        if (!flag[s]) return;
        const Real* o = out + 9 * s;
        rows[at[s]] = {partner[s], {o[0], o[1], o[2]}, {o[3], o[4], o[5]}};
    }
};

static_assert(std::is_trivially_copyable_v<WallContactRow>);
static_assert(std::is_trivially_copyable_v<FlagWallContacts>);
static_assert(std::is_trivially_copyable_v<GatherWallContacts>);
static_assert(std::is_trivially_copyable_v<LoadHot>);
static_assert(std::is_trivially_copyable_v<GrainKeepOutsideBox>);
static_assert(std::is_trivially_copyable_v<GrainKeepInsideDomain>);
static_assert(std::is_trivially_copyable_v<GrainLeaverFaces>);
static_assert(std::is_trivially_copyable_v<GrainEscaped>);
static_assert(std::is_trivially_copyable_v<GrainNearFeed>);
static_assert(std::is_trivially_copyable_v<SlotPartnerKey>);

} // namespace debrisflow::dem
