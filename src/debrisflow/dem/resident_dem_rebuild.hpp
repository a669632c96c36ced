#pragma once
// The resident DEM phase's neighbour rebuild (dem/resident_dem.hpp, included at its end), as
// DemSolver::rebuild: the cell grid over the grains' box, reordering by cell, each grain's
// contact slot rows with their carried history (grains, walls through their bins, the rigid
// bodies' contact spheres through a grid of the spheres) and the reverse index of the
// grain-grain slots.
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

namespace debrisflow::dem {

template <class Space> void ResidentDem<Space>::rebuild() {
    ScopedTimer timer(t_neighbors_);
    host_.built_ = true;
    host_.drift_ = 0;
    host_.walls_seen_ = host_.walls_.layout();
    ++host_.builds_;
    hot_.resize(n_); // one per grain held: fewer after a removal
    if (n_ == 0) return;
    configure_grid();
    build_grid();
    if (host_.params_.reorder) {
        permute(n_);
        if (clumps_ > 0) Space::for_each(n_, IndexOfId{id_.data(), index_of_id_.data()});
        build_grid();
    }
    Space::for_each(n_, LoadHot{view(), hot_.data()});
    const Real skin = host_.search_margin();
    build_slots(grain_,
                GrainCandidates{grid_, pos_.data(), radius_.data(), id_.data(), clump_of(), skin});
    // the active primitives and their boxes, few: on the host, then uploaded
    upload_faces();
    const auto& prims = host_.walls_.primitives();
    const auto& wl = host_.walls_.walls();
    active_host_.clear();
    bounds_host_.clear();
    for (std::size_t k = 0; k < prims.size(); ++k)
        if (wl[std::size_t(prims[k].wall)].active) {
            active_host_.push_back(Index(k));
            bounds_host_.push_back(PrimitiveBounds::of(prims[k]));
        }
    active_.upload(active_host_.data(), Index(active_host_.size()));
    bounds_.upload(bounds_host_.data(), Index(bounds_host_.size()));
    // the bins of many faces: built on the host with the faces, uploaded
    WallBins& bins = host_.wall_bins_;
    bins.build(bounds_host_, host_.max_radius_ + skin, host_.params_.dim);
    WallBinsView view = bins.view();
    if (view.binned) {
        bin_start_.upload(bins.start().data(), Index(bins.start().size()));
        bin_items_.upload(bins.items().data(), Index(bins.items().size()));
        bin_always_.upload(bins.always().data(), Index(bins.always().size()));
        view.start = bin_start_.data();
        view.items = bin_items_.data();
        view.always = bin_always_.data();
    }
    build_slots(wall_, WallCandidatesOf{prims_.data(), active_.data(), bounds_.data(),
                                        Index(active_host_.size()), pos_.data(), radius_.data(),
                                        skin, view});
    Space::synchronize();
}

template <class Space> void ResidentDem<Space>::configure_grid() {
    Bounds box = Space::template fold<Bounds>(n_, GrainBounds{pos_.data()});
    Bounds::combine(box, Bounds{host_.domain_.hi, host_.domain_.lo}); // the host's start
    host_.set_grid_box(box);
    configure(host_.grid_lo_, host_.grid_hi_);
}

template <class Space> void ResidentDem<Space>::build_grid() {
    keys_.resize(n_);
    order_.resize(n_);
    start_cells_.resize(keys_count_ + 1);
    const Real* p = &pos_.data()[0].x;
    Space::for_each(n_, neighbors::CellKeys{grid_, p, p + 1, p + 2, 3, nullptr, keys_.data()});
    sorter_.sort(keys_.data(), n_, keys_count_, order_.data());
    Space::for_each(keys_count_ + 1,
                    exec::CellStarts{keys_.data(), order_.data(), n_, start_cells_.data()});
    grid_.start = start_cells_.data();
    grid_.order = order_.data();
}

template <class Space> void ResidentDem<Space>::permute(Index m) {
    ++changes_;
    const Index held = n_;
    n_ = m;
    for (auto* a : {&pos_, &vel_, &spin_, &force_, &torque_}) gather(*a, vec_scratch_, 1);
    for (auto* a : {&radius_, &mass_, &inv_mass_, &inv_inertia_}) gather(*a, real_scratch_, 1);
    gather(material_, byte_scratch_, 1);
    gather(id_, key_scratch_, 1);
    if (host_.fluid_) { // the fluid loads follow their grains (FluidLoad::permute)
        for (auto* a : {&fl_force_, &fl_u_, &fl_impulse_, &fl_felt_, &fl_handover_})
            gather(*a, vec_scratch_, 1);
        gather(fl_beta_, real_scratch_, 1);
    }
    for (Slots* s : {&grain_, &wall_, &obstacle_}) {
        if (s->count.size() != held) continue; // never built: nothing to carry
        const int cap = int(s->cap);
        gather(s->count, index_scratch_, 1);
        gather(s->key, key_scratch_, cap);
        gather(s->xi, vec_scratch_, cap);
        if (s->mroll.size() > 0) gather(s->mroll, vec_scratch_, cap);
    }
}

template <class Space>
template <class Candidates>
void ResidentDem<Space>::build_slots(Slots& s, const Candidates& candidates) {
    s.old_count.swap(s.count);
    s.old_key.swap(s.key);
    s.old_xi.swap(s.xi);
    s.old_mroll.swap(s.mroll);
    const Index old_cap = s.cap;
    if (s.old_count.size() != n_) {
        s.old_count.resize(n_);
        Space::for_each(n_, FillWith<Index>{s.old_count.data(), 0});
    }
    const bool had_rolling = s.old_mroll.size() == s.old_xi.size() && s.old_xi.size() > 0;
    Index cap = s.next_cap;
    for (;;) {
        const Index slots = n_ * cap;
        s.count.resize(n_);
        s.partner.resize(slots);
        s.key.resize(slots);
        s.xi.resize(slots);
        s.mroll.resize(rolling_ ? slots : 0);
        const SlotRowFill<Candidates> fill{candidates,
                                           s.old_count.data(),
                                           s.old_key.data(),
                                           s.old_xi.data(),
                                           had_rolling ? s.old_mroll.data() : nullptr,
                                           s.count.data(),
                                           s.partner.data(),
                                           s.key.data(),
                                           s.xi.data(),
                                           rolling_ ? s.mroll.data() : nullptr,
                                           cap,
                                           old_cap};
        const Index worst = Index(Space::max_of(n_, fill));
        if (worst <= cap) {
            s.cap = cap;
            s.next_cap = slot_capacity_for(worst);
            return;
        }
        cap = slot_capacity_for(worst); // history still in old_*: retry with room
    }
}

template <class Space> void ResidentDem<Space>::build_reverse() {
    const Index cap = grain_.cap, slots = n_ * cap;
    reverse_key_.resize(slots);
    reverse_.resize(slots);
    reverse_start_.resize(n_ + 2);
    Space::for_each(slots, SlotPartnerKey{cap, grain_.count.data(), grain_.partner.data(), n_,
                                          reverse_key_.data()});
    reverse_sorter_.sort(reverse_key_.data(), slots, n_ + 1, reverse_.data());
    Space::for_each(n_ + 2, exec::CellStarts{reverse_key_.data(), reverse_.data(), slots,
                                             reverse_start_.data()});
    reverse_built_ = host_.builds_;
}

template <class Space> void ResidentDem<Space>::upload_spheres() {
    const ObstacleSet& o = *host_.obstacles_;
    if (spheres_version_ == o.version && spheres_.size() == Index(o.spheres.size())) return;
    spheres_.upload(o.spheres.data(), Index(o.spheres.size()));
    spheres_version_ = o.version;
}

template <class Space> void ResidentDem<Space>::build_obstacle_slots() {
    ScopedTimer timer(t_neighbors_);
    const ObstacleSet& o = *host_.obstacles_;
    if (o.spheres.size() != host_.obstacle_spheres_timed_) host_.include_bodies();
    host_.obstacles_seen_ = o.version;
    host_.obstacle_builds_seen_ = host_.builds_;
    upload_spheres();
    const Index ns = spheres_.size();
    host_.configure_obstacle_grid(sphere_config_);
    neighbors::GridView grid = sphere_config_.view();
    const Index cells = Index(sphere_config_.cell_count());
    sphere_keys_.resize(ns);
    sphere_order_.resize(ns);
    sphere_starts_.resize(cells + 1);
    if (ns > 0) {
        const Real* c = &spheres_.data()[0].x.x;
        Space::for_each(ns, neighbors::CellKeys{grid, c, c + 1, c + 2, ObstacleCandidates::stride,
                                                nullptr, sphere_keys_.data()});
        sphere_sorter_.sort(sphere_keys_.data(), ns, cells, sphere_order_.data());
    }
    Space::for_each(cells + 1, exec::CellStarts{sphere_keys_.data(), sphere_order_.data(), ns,
                                                sphere_starts_.data()});
    grid.start = sphere_starts_.data();
    grid.order = sphere_order_.data();
    build_slots(obstacle_, ObstacleCandidates{grid, spheres_.data(), ns, pos_.data(),
                                              radius_.data(), host_.search_margin()});
}

} // namespace debrisflow::dem
