#pragma once
// The small per-item steps of the resident SPH loop (sph/resident_sph.hpp) that the host
// solver does with its own containers: the grid's cell starts, reordering, compaction, and the
// predicates its reductions look for (the grid's cell starts and gathering by order are
// exec/reorder_k.hpp's, the compaction's scatter exec/compact_k.hpp's). Host/device functors.
#include "debrisflow/exec/compact_k.hpp"
#include "debrisflow/exec/reorder_k.hpp"
#include "debrisflow/flow/exit_faces_k.hpp"
#include "debrisflow/flow/outlet_box_k.hpp"
#include "debrisflow/particles/particle_set.hpp"
#include "debrisflow/sph/time_schemes_k.hpp"
#include <cstring>
#include <type_traits>

namespace debrisflow::sph {

using exec::CellStarts;
using exec::Complement;
using exec::Dropped;
using exec::GatherByOrder;
using exec::OutOfOrder;
using exec::ScatterKept;

// Gathers and scatters of a narrow array through a wider carrier array (a scratch of another
// type): item i's bytes are copied into the carrier's slot, then back (FromCarrier).
// carrier[i] <- the bytes of in[order[i]].
template <class T, class C> struct GatherIntoCarrier {
    static_assert(sizeof(T) <= sizeof(C));
    const T* in;
    const Index* order;
    C* carrier;
    DF_HD void operator()(Index i) const {
        C c{};
        memcpy(&c, in + order[i], sizeof(T));
        carrier[i] = c;
    }
};
// carrier[at[i]] <- the bytes of in[i] for the items with keep[i] (stream compaction).
template <class T, class C> struct ScatterIntoCarrier {
    static_assert(sizeof(T) <= sizeof(C));
    const T* in;
    const Index* keep;
    const Index* at;
    C* carrier;
    DF_HD void operator()(Index i) const {
        if (!keep[i]) return;
        C c{};
        memcpy(&c, in + i, sizeof(T));
        carrier[at[i]] = c;
    }
};
// out[i] <- the bytes in carrier[i].
template <class T, class C> struct FromCarrier {
    const C* carrier;
    T* out;
    DF_HD void operator()(Index i) const { memcpy(out + i, carrier + i, sizeof(T)); }
};

// keep[i] = 0 for the boundary particles of wall group `group` (a gate lifting), 1 otherwise.
struct KeepOutsideGroup {
    particles::ParticleView pv;
    std::int16_t group;
    Index* keep;
    DF_HD void operator()(Index i) const { keep[i] = pv.is_fluid(i) || pv.group[i] != group; }
};

// keep[i] = 0 for the fluid particles whose centre left the domain, 1 for the others.
struct KeepInsideDomain {
    particles::ParticleView pv;
    flow::ExitFaces faces;
    Index* keep;
    DF_HD void operator()(Index i) const {
        keep[i] = !(pv.is_fluid(i) && faces.of_finite(pv.pos(i)) >= 0);
    }
};

// out[at[i]] = the face leaver i crossed, for the items with leave[i] (KeepInsideDomain's
// leavers, `at` the exclusive scan of leave).
struct LeaverFaces {
    particles::ParticleView pv;
    flow::ExitFaces faces;
    const Index* leave;
    const Index* at;
    int* out;
    DF_HD void operator()(Index i) const {
        if (leave[i]) out[at[i]] = faces.of_finite(pv.pos(i));
    }
};

// keep[i] = 0 for the fluid particles inside an outlet's box, 1 otherwise.
struct KeepOutsideBox {
    particles::ParticleView pv;
    flow::OutletBox box;
    Index* keep;
    DF_HD void operator()(Index i) const { keep[i] = !(pv.is_fluid(i) && box.contains(pv.pos(i))); }
};

// The mass of fluid particle i (0 for walls).
struct FluidMass {
    particles::ParticleView pv;
    DF_HD Real operator()(Index i) const { return pv.is_fluid(i) ? pv.mass[i] : Real(0); }
};

// f(i) >= value (the particle that attains a reduction's maximum).
template <class F> struct AtLeast {
    F f;
    Real value;
    DF_HD bool operator()(Index i) const { return f(i) >= value; }
};

// The particles the health check stops at.
struct Unhealthy {
    ParticleHealthy healthy;
    DF_HD bool operator()(Index i) const { return !healthy(i); }
};

static_assert(std::is_trivially_copyable_v<Unhealthy>);

} // namespace debrisflow::sph
