#pragma once
#include "debrisflow/dem/contact_params.hpp"
#include "debrisflow/dem/grain_contact_k.hpp"
#include "debrisflow/neighbors/grid_view_k.hpp"
#include <type_traits>
#include <vector>

namespace debrisflow::dem {

// What DemSolver's grain-grain contact loop reads (DemSolver::grain_contact_inputs): grain
// i's candidates are slots [i * capacity, i * capacity + count[i]).
struct GrainContactInputs {
    const GrainState* grains; // the loop's interleaved copy of the grain state
    Index n;
    const Index *partner, *count;
    Vec3 *xi, *mroll; // the slots' tangential springs and rolling moments (null: no rolling)
    Index capacity;
    PairTable table;
    neighbors::GridView grid; // separation() only (periodic images)
    Real h;                   // size of the step the evaluation ends (spring increment)
};
static_assert(std::is_trivially_copyable_v<GrainContactInputs>);

// Grain i's contact with candidate j, as the contact loop evaluates every slot: true and the
// force in c when they touch (or are within an adhesive law's reach); false, and the slot's
// history cleared, when they do not.
DF_HD DF_HOT_INLINE bool grain_slot_force(const PairTable& table, const neighbors::GridView& grid,
                                          const GrainState& si, const GrainState& sj, Real h,
                                          HistoryRef history, GrainPairForce& c) {
    const Vec3 r = grid.separation(si.x, sj.x);
    const Real rs = si.r + sj.r, d2 = dot(r, r);
    if (d2 >= rs * rs && !(table.adhesive && within_reach(table(si.material, sj.material),
                                                          std::sqrt(d2) - rs, si.r * sj.r / rs))) {
        history.clear();
        return false;
    }
    c = grain_pair_force(table(si.material, sj.material), si, sj, r, d2, h, history);
    return true;
}

// Every slot's history as one array of ContactHistory (zero rolling moments without rolling),
// for GrainSlotContact.
inline std::vector<ContactHistory> slot_histories(const GrainContactInputs& in) {
    std::vector<ContactHistory> h(std::size_t(in.n) * std::size_t(in.capacity));
    for (std::size_t s = 0; s < h.size(); ++s) h[s] = {in.xi[s], in.mroll ? in.mroll[s] : Vec3{}};
    return h;
}

// One contact slot s = i * capacity + k as DemSolver::forces evaluates it (grain_slot_force):
// writes the force on i and the torques on i and j (9 reals at out + 9 s) and the updated
// history; zeros and a cleared history where the pair does not touch; zeros and the history
// unchanged for an empty slot. Reads history_in, writes history_out (may be the same array).
struct GrainSlotContact {
    GrainContactInputs in;
    const ContactHistory* history_in;
    Real* out;
    ContactHistory* history_out;

    DF_HD void operator()(Index s) const {
        const Index i = s / in.capacity, k = s % in.capacity;
        Real* o = out + 9 * std::size_t(s);
        for (int c = 0; c < 9; ++c) o[c] = 0;
        ContactHistory h = history_in[s];
        GrainPairForce c;
        if (k < in.count[i] &&
            grain_slot_force(in.table, in.grid, in.grains[i], in.grains[in.partner[s]], in.h,
                             HistoryRef::of(h), c)) {
            const Vec3 v[3] = {c.force_i, c.torque_i, c.torque_j};
            for (int q = 0; q < 3; ++q)
                o[3 * q] = v[q].x, o[3 * q + 1] = v[q].y, o[3 * q + 2] = v[q].z;
        }
        history_out[s] = h;
    }
};

} // namespace debrisflow::dem
