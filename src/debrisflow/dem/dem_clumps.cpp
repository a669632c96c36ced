#include "debrisflow/dem/clump_step_k.hpp"
#include "debrisflow/dem/dem_solver.hpp"
#include "debrisflow/exec/parallel.hpp"
#include <algorithm>

// The DemSolver's clump stepping (grains_.clumps): members found by id, the rigid-body kick
// and drift of each clump with its members placed and moved with it, and the members' forces
// summed on the clump (multi-sphere method, Favier et al. 1999).
namespace debrisflow::dem {

namespace {
// Below this many clumps the loops run on one thread (the grains' threshold / 4: a clump
// visits several members).
constexpr Index clump_parallel_min = 1024;
} // namespace

void DemSolver::expand_to_clumps(std::vector<std::uint8_t>& keep) const {
    const ClumpSet& cl = grains_.clumps;
    for (Index c = 0; c < cl.size(); ++c) {
        const std::size_t b = cl.first[std::size_t(c)], e = cl.first[std::size_t(c) + 1];
        bool whole = true;
        for (std::size_t k = b; k < e; ++k)
            whole = whole && keep[std::size_t(index_of_id_[cl.member_id[k]])];
        if (whole) continue;
        for (std::size_t k = b; k < e; ++k) keep[std::size_t(index_of_id_[cl.member_id[k]])] = 0;
    }
}

void DemSolver::spread_clump_faces(std::vector<int>& face) const {
    const ClumpSet& cl = grains_.clumps;
    for (Index c = 0; c < cl.size(); ++c) {
        const std::size_t b = cl.first[std::size_t(c)], e = cl.first[std::size_t(c) + 1];
        int crossed = -1;
        for (std::size_t k = b; k < e; ++k)
            crossed = std::max(crossed, face[std::size_t(index_of_id_[cl.member_id[k]])]);
        if (crossed < 0) continue;
        for (std::size_t k = b; k < e; ++k) {
            int& f = face[std::size_t(index_of_id_[cl.member_id[k]])];
            if (f < 0) f = crossed;
        }
    }
}

void DemSolver::map_clumps() {
    const ClumpSet& cl = grains_.clumps;
    if (cl.empty()) {
        clump_of_id_.clear();
        index_of_id_.clear();
        return;
    }
    clump_of_id_.assign(grains_.next_id(), -1);
    for (Index c = 0; c < cl.size(); ++c)
        for (std::size_t k = cl.first[std::size_t(c)]; k < cl.first[std::size_t(c) + 1]; ++k)
            clump_of_id_[cl.member_id[k]] = std::int32_t(c);
    index_of_id_.assign(grains_.next_id(), -1);
    for (Index i = 0; i < grains_.size(); ++i) index_of_id_[grains_.id[std::size_t(i)]] = i;
}

ClumpView DemSolver::clump_view() {
    ClumpSet& cl = grains_.clumps;
    return {cl.pos.data(),    cl.vel.data(),       cl.ang_mom.data(), cl.force.data(),
            cl.torque.data(), cl.orient.data(),    cl.mass.data(),    cl.inv_inertia.data(),
            cl.first.data(),  cl.member_id.data(), cl.offset.data()};
}

Real DemSolver::clump_kick_drift(Real h) {
    const ClumpKickDrift move{clump_view(),     grains_.view(), hot_.data(), index_of_id_.data(), h,
                              params_.dim == 2, domain_};
    const DriftReport m =
        exec::reduce(grains_.clumps.size(), DriftReport{}, move, DriftReport::combine,
                     exec::serial_below(clump_parallel_min + 1));
    if (m.outside > 0) bad_ = true;
    return m.vmax2;
}

void DemSolver::clump_forces(Real half) {
    const ClumpSum sum{clump_view(),    grains_.view(),   index_of_id_.data(),
                       params_.gravity, params_.dim == 2, half};
    exec::for_each(grains_.clumps.size(), sum, exec::serial_below(clump_parallel_min + 1));
}

} // namespace debrisflow::dem
