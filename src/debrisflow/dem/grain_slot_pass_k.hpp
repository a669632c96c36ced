#pragma once
// The grain-grain contacts in the device's layout (`dem.contact_pass = "slots"`), two passes
// written once for the host (exec/) and a device: (1) one evaluation per candidate slot, in
// place of the slot's history, into a buffer; (2) each grain gathers the force and torque of
// its own slots and the reactions of the slots that name it as partner (a reverse index built
// at each neighbour rebuild). No two threads write the same memory, so no atomics. The host's
// default pass (DemSolver::forces, contiguous ranges with Newton's third law) sums the same
// terms in another order.
#include "debrisflow/dem/grain_slot_contact_k.hpp"
#include <cstdint>
#include <type_traits>

namespace debrisflow::dem {

// Pass 1, slot s = i * capacity + k: out[9 s ...] = force on i, torque on i, torque on j, and
// touching[s] = whether the pair touched (or was within an adhesive reach). An empty slot
// (k >= count[i]) is left alone: pass 2 reads only the slots below a grain's count. The slot's
// tangential spring (and rolling moment) is updated where it is stored.
struct GrainSlotForces {
    GrainContactInputs in;
    Real* out;
    std::uint8_t* touching;
    DF_HD void operator()(Index s) const {
        const Index i = s / in.capacity, k = s % in.capacity;
        if (k >= in.count[i]) return;
        Real* o = out + 9 * std::size_t(s);
        GrainPairForce c{};
        const HistoryRef h{in.xi + s, in.mroll ? in.mroll + s : nullptr};
        const bool t =
            grain_slot_force(in.table, in.grid, in.grains[i], in.grains[in.partner[s]], in.h, h, c);
        touching[s] = t ? 1 : 0;
        const Vec3 v[3] = {c.force_i, c.torque_i, c.torque_j};
        for (int q = 0; q < 3; ++q) o[3 * q] = v[q].x, o[3 * q + 1] = v[q].y, o[3 * q + 2] = v[q].z;
    }
};

// What pass 2 folds over the grains: contacts (each pair once, at the grain that owns the slot)
// and, while settling measures it, the sum of their force magnitudes.
struct SlotReport {
    long touching = 0;
    Real force_sum = 0;
    DF_HD static void combine(SlotReport& a, const SlotReport& b) {
        a.touching += b.touching;
        a.force_sum += b.force_sum;
    }
};

// Pass 2, grain i: acc[6 i ...] = sum over its touching slots of (force on i, torque on i),
// plus over the touching slots s that name i as partner (reverse[reverse_start[i]] ...) of
// (-force, torque on j).
struct GrainSlotGather {
    Index capacity;
    const Index* count;
    const Real* out;
    const std::uint8_t* touching;
    const Index *reverse_start, *reverse;
    Real* acc;
    bool measure; // sum |F| (the settling ratio)
    DF_HD void operator()(Index i, SlotReport& report) const {
        Vec3 f{}, t{};
        const std::size_t base = std::size_t(i) * std::size_t(capacity);
        for (Index k = 0; k < count[i]; ++k) {
            const std::size_t s = base + std::size_t(k);
            if (!touching[s]) continue;
            const Real* o = out + 9 * s;
            const Vec3 fi{o[0], o[1], o[2]};
            f += fi;
            t += Vec3{o[3], o[4], o[5]};
            ++report.touching;
            if (measure) report.force_sum += norm(fi);
        }
        for (Index r = reverse_start[i]; r < reverse_start[i + 1]; ++r) {
            const std::size_t s = std::size_t(reverse[r]);
            if (!touching[s]) continue;
            const Real* o = out + 9 * s;
            f -= Vec3{o[0], o[1], o[2]};
            t += Vec3{o[6], o[7], o[8]};
        }
        Real* a = acc + 6 * std::size_t(i);
        a[0] = f.x, a[1] = f.y, a[2] = f.z, a[3] = t.x, a[4] = t.y, a[5] = t.z;
    }
};

static_assert(std::is_trivially_copyable_v<GrainSlotForces>);
static_assert(std::is_trivially_copyable_v<GrainSlotGather>);

} // namespace debrisflow::dem
