#include "debrisflow/dem/dem_solver.hpp"
#include "debrisflow/exec/parallel.hpp"

// A force evaluation in the device's layout (dem.contact_pass = "slots"): the grain-grain
// contacts with one evaluation per candidate slot, then a gather per grain
// (dem/grain_slot_pass_k.hpp); the per-grain pass with the reactions on walls and bodies kept
// per slot, then summed per wall and per body (dem/grain_own_pass_k.hpp).
namespace debrisflow::dem {

SlotReport DemSolver::slot_contacts(Real h_contact, bool measure) {
    const Index n = grains_.size();
    const Index cap = grain_slots_.capacity();
    const std::size_t slots = std::size_t(n) * std::size_t(cap);
    const Index* count = grain_slots_.counts();
    const Index* partner = grain_slots_.partners();
    if (reverse_builds_ != builds_ || reverse_start_.size() != std::size_t(n) + 1) {
        // The reverse index by counting sort on the partner, in slot order (a run repeats).
        reverse_start_.assign(std::size_t(n) + 1, 0);
        for (Index i = 0; i < n; ++i)
            for (Index k = 0; k < count[i]; ++k)
                ++reverse_start_[std::size_t(partner[std::size_t(i) * cap + k]) + 1];
        for (Index j = 0; j < n; ++j) reverse_start_[std::size_t(j) + 1] += reverse_start_[j];
        reverse_.resize(std::size_t(reverse_start_.back()));
        std::vector<Index> next(reverse_start_.begin(), reverse_start_.end() - 1);
        for (Index i = 0; i < n; ++i)
            for (Index k = 0; k < count[i]; ++k) {
                const Index s = i * cap + k;
                reverse_[std::size_t(next[std::size_t(partner[s])]++)] = s;
            }
        reverse_builds_ = builds_;
    }
    slot_out_.resize(9 * slots);
    slot_touching_.resize(slots);
    const GrainContactInputs in = contact_inputs(h_contact);
    const exec::Loop loop = exec::serial_below(parallel_min + 1);
    exec::for_each(Index(slots), GrainSlotForces{in, slot_out_.data(), slot_touching_.data()},
                   loop);
    acc_.resize(6 * std::size_t(n));
    const GrainSlotGather gather{cap,
                                 count,
                                 slot_out_.data(),
                                 slot_touching_.data(),
                                 reverse_start_.data(),
                                 reverse_.data(),
                                 acc_.data(),
                                 measure};
    return exec::reduce(n, SlotReport{}, gather, SlotReport::combine, loop);
}

SlotReport DemSolver::own_slots(Real half_kick, bool measure) {
    const Index n = grains_.size();
    const GrainOwnPass pass{own_inputs(half_kick)};
    const GrainOwnInputs& in = pass.in;
    const std::size_t wslots = std::size_t(n) * std::size_t(in.wall_capacity);
    const std::size_t oslots =
        in.obstacle_count ? std::size_t(n) * std::size_t(in.obstacle_capacity) : 0;
    wall_out_.resize(9 * wslots);
    wall_touching_.resize(wslots);
    obstacle_out_.resize(6 * oslots);
    obstacle_touching_.resize(oslots);
    const exec::Loop loop = exec::serial_below(parallel_min + 1);
    const SlotReport report =
        exec::reduce(n, SlotReport{},
                     GrainOwnSlots{pass, wall_out_.data(), wall_touching_.data(),
                                   obstacle_out_.data(), obstacle_touching_.data(), measure},
                     SlotReport::combine, loop);
    // Each wall's and body's load: one reduction over the grains each (few walls and bodies).
    auto& wl = walls_.walls();
    for (std::size_t w = 0; w < wl.size(); ++w) {
        if (in.wall_capacity == 0) break;
        const WallSlotLoad load{int(w),           wl[w].origin,         in.prims,
                                in.wall_partner,  in.wall_count,        in.wall_capacity,
                                wall_out_.data(), wall_touching_.data()};
        const LoadSum sum = exec::reduce(n, LoadSum{}, load, LoadSum::combine, loop);
        const Real v[6] = {sum.force.x,  sum.force.y,  sum.force.z,
                           sum.moment.x, sum.moment.y, sum.moment.z};
        for (int k = 0; k < 6; ++k) wall_sum_[6 * w + std::size_t(k)] = v[k];
    }
    const std::size_t nb = in.obstacle_count ? obstacles_->body_com.size() : 0;
    for (std::size_t b = 0; b < nb; ++b) {
        const BodySlotLoad load{int(b),
                                obstacles_->body_com[b],
                                in.spheres,
                                in.obstacle_partner,
                                in.obstacle_count,
                                in.obstacle_capacity,
                                obstacle_out_.data(),
                                obstacle_touching_.data()};
        const LoadSum sum = exec::reduce(n, LoadSum{}, load, LoadSum::combine, loop);
        const Real v[6] = {sum.force.x,  sum.force.y,  sum.force.z,
                           sum.moment.x, sum.moment.y, sum.moment.z};
        for (int k = 0; k < 6; ++k) body_sum_[6 * b + std::size_t(k)] = v[k];
    }
    // On the host, in grain and slot order: the contact loads a pressure map reads and the
    // nodal triangles' share of the impulse (a device would scatter these with atomics).
    Vec3* node_j = half_kick > 0 ? walls_.nodes().impulse.data() : nullptr;
    bool any_record = false;
    for (std::size_t w = 0; w < wl.size(); ++w) any_record = any_record || in.walls[w].record;
    const bool nodal = node_j && !walls_.corners().empty();
    for (Index i = 0; i < n && in.wall_capacity > 0 && (any_record || nodal); ++i) {
        const std::size_t base = std::size_t(i) * std::size_t(in.wall_capacity);
        for (Index k = 0; k < in.wall_count[i]; ++k) {
            const std::size_t s = base + std::size_t(k);
            if (!wall_touching_[s]) continue;
            const WallPrimitive& pr = in.prims[in.wall_partner[s]];
            const bool record = in.walls[pr.wall].record;
            if (!record && !(node_j && pr.corners >= 0)) continue;
            const Real* o = wall_out_.data() + 9 * s;
            const Vec3 f{o[0], o[1], o[2]}, q{o[3], o[4], o[5]};
            if (record) wl[std::size_t(pr.wall)].contacts.push_back({q, -f});
            if (node_j && pr.corners >= 0) {
                const NodalCorners& nc = in.corners[pr.corners];
                const Vec3 bw = barycentric(q, pr.a, pr.b, pr.c);
                for (int a = 0; a < 3; ++a)
                    node_j[nc.node[std::size_t(a)]] += (-current_h_ * bw[a]) * f;
            }
        }
    }
    return report;
}

} // namespace debrisflow::dem
