#include "debrisflow/dem/dem_solver.hpp"
#include "debrisflow/exec/parallel.hpp"

// The grain-grain contacts in the device's layout (dem.contact_pass = "slots";
// dem/grain_slot_pass_k.hpp): one evaluation per candidate slot, then a gather per grain.
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

} // namespace debrisflow::dem
