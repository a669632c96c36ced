#pragma once
// The small per-grain steps of the resident DEM loop (dem/resident_dem.hpp) that the host
// solver does with its own containers: the contact pass's copy of the grain state, the grains'
// bounding box (dem/grain_bounds_k.hpp), and the keys of the reverse index. Host/device functors.
#include "debrisflow/dem/grain_bounds_k.hpp"
#include "debrisflow/dem/grain_contact_k.hpp"
#include "debrisflow/flow/outlet_box_k.hpp"
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

// Whether grain i's centre is inside an outlet's box.
struct GrainInside {
    const Vec3* pos;
    flow::OutletBox box;
    DF_HD bool operator()(Index i) const { return box.contains(pos[i]); }
};

static_assert(std::is_trivially_copyable_v<LoadHot>);
static_assert(std::is_trivially_copyable_v<GrainInside>);
static_assert(std::is_trivially_copyable_v<SlotPartnerKey>);

} // namespace debrisflow::dem
