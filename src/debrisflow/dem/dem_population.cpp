// The DemSolver when its population changes during a run: walls lifted, grains removed or
// added (feeds), bodies and feed sizes that lower the stable step, grains stopped after
// settling.
#include "debrisflow/dem/critical_dt.hpp"
#include "debrisflow/dem/dem_solver.hpp"
#include <algorithm>

namespace debrisflow::dem {

void DemSolver::remove_wall(int wall) {
    evaluated_ = false;
    walls_.walls()[std::size_t(wall)].active = false;
    walls_.walls()[std::size_t(wall)].force = {};
}

void DemSolver::remove_grains(std::vector<std::uint8_t> keep) {
    evaluated_ = false;
    expand_to_clumps(keep);
    std::vector<Index> kept;
    for (Index i = 0; i < grains_.size(); ++i)
        if (keep[std::size_t(i)]) kept.push_back(i);
    if (kept.size() == std::size_t(grains_.size())) return;
    if (!grains_.clumps.empty()) {
        ClumpSet& cl = grains_.clumps;
        std::vector<std::uint8_t> keep_clump(std::size_t(cl.size()));
        for (Index c = 0; c < cl.size(); ++c)
            keep_clump[std::size_t(c)] =
                keep[std::size_t(index_of_id_[cl.member_id[cl.first[std::size_t(c)]]])];
        cl.select(keep_clump);
    }
    grains_.select(kept);
    map_clumps();
    if (fluid_) fluid_->select(kept);
    for (auto* slots : {&grain_slots_, &wall_slots_, &obstacle_slots_}) slots->remap(kept);
    obstacle_builds_seen_ = -1;
    bad_ = false;
    for (Index i = 0; i < grains_.size() && !bad_; ++i) bad_ = escaped(i);
    rebuild();
}

void DemSolver::grains_added(Index old_count) {
    evaluated_ = false;
    map_clumps();
    std::vector<Index> from(std::size_t(grains_.size()), -1);
    for (Index i = 0; i < old_count; ++i) from[std::size_t(i)] = i;
    if (fluid_) fluid_->permute(from);
    for (auto* slots : {&grain_slots_, &wall_slots_, &obstacle_slots_}) slots->remap(from);
    obstacle_builds_seen_ = -1;
    // New sizes may need a wider search and a shorter step (the step never grows).
    for (Real r : grains_.radius) max_radius_ = std::max(max_radius_, r);
    size_search_margin();
    if (params_.dt <= 0) {
        const auto lim = critical_dt(grains_, wall_materials(), materials_, table_, params_,
                                     domain_, params_.safety, obstacles_);
        if (lim.dt < auto_dt_.dt) auto_dt_ = lim;
        dt_ = auto_dt_.dt;
    }
    rebuild();
}

void DemSolver::include_bodies() {
    obstacle_spheres_timed_ = obstacles_->spheres.size();
    const auto lim = critical_dt(grains_, wall_materials(), materials_, table_, params_, domain_,
                                 params_.safety, obstacles_);
    if (lim.dt < auto_dt_.dt) auto_dt_ = lim;
    const auto stab = critical_dt(grains_, wall_materials(), materials_, table_, params_, domain_,
                                  stability_fraction, obstacles_);
    if (stab.dt < stability_dt_.dt) stability_dt_ = stab;
    if (params_.dt <= 0) dt_ = auto_dt_.dt;
}

void DemSolver::include_sizes(const GrainSet& prototypes) {
    const std::vector<int> wall_materials = this->wall_materials();
    for (Real r : prototypes.radius) max_radius_ = std::max(max_radius_, r);
    size_search_margin();
    const auto lim = critical_dt(prototypes, wall_materials, materials_, table_, params_, domain_,
                                 params_.safety);
    if (lim.dt < auto_dt_.dt) auto_dt_ = lim;
    const auto stab = critical_dt(prototypes, wall_materials, materials_, table_, params_, domain_,
                                  stability_fraction);
    if (stab.dt < stability_dt_.dt) stability_dt_ = stab;
    if (params_.dt <= 0) dt_ = auto_dt_.dt;
}

void DemSolver::stop_grains() {
    evaluated_ = false;
    for (auto* v : {&grains_.vel, &grains_.spin}) std::fill(v->begin(), v->end(), Vec3{});
    for (auto* v : {&grains_.clumps.vel, &grains_.clumps.ang_mom})
        std::fill(v->begin(), v->end(), Vec3{});
    refresh_hot();
}

} // namespace debrisflow::dem
