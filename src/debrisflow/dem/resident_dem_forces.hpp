#pragma once
// The resident DEM phase's force evaluation (dem/resident_dem.hpp, included at its end), as
// DemSolver::forces in the device's layout: one evaluation per grain-grain slot gathered per
// grain, the per-grain pass (gravity, walls, bodies, the fluid's load, the closing kick), the
// clumps' sums, and each wall's and body's load reduced where the grains are.
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

namespace debrisflow::dem {

template <class Space> void ResidentDem<Space>::forces(Real half_kick, bool collect_obstacles) {
    ++changes_;
    const bool ends_step = half_kick > 0;
    const bool measure = host_.measure_contact_force_;
    const Real h = host_.current_h_;
    auto& wl = host_.walls_.walls();
    for (auto& w : wl) w.contacts.clear();
    recorded_ = false; // this evaluation's contact loads are still where the grains are
    // the walls' states (few: every evaluation) and their faces if they moved; a FEM solid's
    // surface moves with its nodes at every FEM step
    const bool nodal = !host_.walls_.corners().empty();
    if (faces_stale_ || nodal) upload_faces();
    if (nodal) {
        const auto& v = host_.walls_.nodes().v;
        node_v_.upload(v.data(), Index(v.size()));
    }
    const auto& states = host_.refresh_wall_states();
    wall_states_.upload(states.data(), Index(states.size()));
    if (n_ == 0) {
        for (auto& w : wl) w.force = w.moment = {};
        host_.contacts_ = 0;
        return;
    }
    if (reverse_built_ != host_.builds_) build_reverse();
    acc_.resize(6 * n_);
    const Index gcap = grain_.cap, gslots = n_ * gcap;
    slot_out_.resize(9 * gslots);
    slot_touching_.resize(gslots);
    const GrainContactInputs cin{hot_.data(),
                                 n_,
                                 grain_.partner.data(),
                                 grain_.count.data(),
                                 grain_.xi.data(),
                                 rolling_ ? grain_.mroll.data() : nullptr,
                                 gcap,
                                 table(),
                                 grid_,
                                 ends_step ? h : 0};
    Space::for_each(gslots, GrainSlotForces{cin, slot_out_.data(), slot_touching_.data()});
    const SlotReport gg = Space::template fold<SlotReport>(
        n_, GrainSlotGather{gcap, grain_.count.data(), slot_out_.data(), slot_touching_.data(),
                            reverse_start_.data(), reverse_.data(), acc_.data(), measure});
    GrainOwnInputs in{};
    in.g = view();
    in.hot = hot_.data();
    in.acc = acc_.data();
    in.clump_of = clump_of();
    in.table = table();
    in.gravity = host_.params_.gravity;
    in.h_contact = ends_step ? h : 0;
    in.h_step = h;
    in.half = half_kick;
    in.plane = host_.params_.dim == 2;
    in.prims = prims_.data();
    in.corners = nodal ? corners_.data() : nullptr;
    in.node_v = nodal ? node_v_.data() : nullptr;
    in.walls = wall_states_.data();
    in.wall_partner = wall_.partner.data();
    in.wall_count = wall_.count.data();
    in.wall_xi = wall_.xi.data();
    in.wall_roll = rolling_ ? wall_.mroll.data() : nullptr;
    in.wall_capacity = wall_.cap;
    ObstacleSet* o = host_.obstacles_;
    const bool bodies = o && obstacle_.count.size() == n_ && obstacle_.cap > 0;
    if (o) upload_spheres(); // moved since the slots were built (an evaluation between steps)
    in.spheres = o ? spheres_.data() : nullptr;
    in.obstacle_partner = bodies ? obstacle_.partner.data() : nullptr;
    in.obstacle_count = bodies ? obstacle_.count.data() : nullptr;
    in.obstacle_xi = obstacle_.xi.data();
    in.obstacle_roll = rolling_ ? obstacle_.mroll.data() : nullptr;
    in.obstacle_capacity = obstacle_.cap;
    if (host_.fluid_) {
        in.fluid_force = fl_force_.data();
        in.fluid_u = fl_u_.data();
        in.fluid_beta = fl_beta_.data();
        in.fluid_impulse = ends_step ? fl_impulse_.data() : nullptr;
        in.fluid_felt = fl_felt_.data();
    }
    const Index wslots = n_ * wall_.cap, oslots = bodies ? n_ * obstacle_.cap : 0;
    wall_out_.resize(9 * wslots);
    wall_touching_.resize(wslots);
    obstacle_out_.resize(6 * oslots);
    obstacle_touching_.resize(oslots);
    const SlotReport own = Space::template fold<SlotReport>(
        n_, GrainOwnSlots{GrainOwnPass{in}, wall_out_.data(), wall_touching_.data(),
                          obstacle_out_.data(), obstacle_touching_.data(), measure});
    if (clumps_ > 0) // DemSolver::clump_forces
        Space::for_each(clumps_,
                        ClumpSum{clump_view(), view(), index_of_id_.data(), host_.params_.gravity,
                                 host_.params_.dim == 2, half_kick});
    // each wall's and body's load split over the threads as the host's slot pass splits it
    // (DemSolver::own_slots), so that a moved body and a wall's load repeat it bitwise
    const Index serial_below = DemSolver::parallel_min + 1;
    for (std::size_t w = 0; w < wl.size(); ++w) {
        const WallSlotLoad load{int(w),
                                wl[w].origin,
                                prims_.data(),
                                wall_.partner.data(),
                                wall_.count.data(),
                                wall_.cap,
                                wall_out_.data(),
                                wall_touching_.data()};
        const LoadSum sum = Space::template fold<LoadSum>(n_, load, serial_below);
        wl[w].force = sum.force;
        wl[w].moment = sum.moment;
    }
    // each body's load, reduced where the grains are; its impulse on the host, as
    // DemSolver::forces adds it (the few bodies are moved there)
    if (o && (ends_step || collect_obstacles) && h > 0) {
        const std::size_t nb = o->body_com.size();
        o->impulse.resize(nb);
        o->angular_impulse.resize(nb);
        for (std::size_t b = 0; b < nb && bodies; ++b) {
            const BodySlotLoad load{int(b),
                                    o->body_com[b],
                                    spheres_.data(),
                                    obstacle_.partner.data(),
                                    obstacle_.count.data(),
                                    obstacle_.cap,
                                    obstacle_out_.data(),
                                    obstacle_touching_.data()};
            const LoadSum sum = Space::template fold<LoadSum>(n_, load, serial_below);
            o->impulse[b] += h * sum.force;
            o->angular_impulse[b] += h * sum.moment;
        }
        o->time += h;
    }
    if (nodal && ends_step) scatter_nodal_impulse(h);
    if (host_.fluid_ && ends_step) host_.fluid_->time += h;
    host_.contacts_ = gg.touching + own.touching;
    host_.sum_contact_force_ = measure ? gg.force_sum + own.force_sum : 0;
}

template <class Space>
auto ResidentDem<Space>::wall_contacts(bool nodal) -> std::vector<WallContactRow> {
    const Index slots = n_ * wall_.cap;
    contact_flag_.resize(slots);
    contact_at_.resize(slots);
    Space::for_each(slots,
                    FlagWallContacts{wall_.count.data(), wall_.partner.data(),
                                     wall_touching_.data(), prims_.data(), wall_states_.data(),
                                     wall_.cap, nodal, contact_flag_.data()});
    const Index m = Space::exclusive_scan(slots, contact_flag_.data(), contact_at_.data());
    std::vector<WallContactRow> rows(static_cast<std::size_t>(m));
    if (m == 0) return rows;
    contact_rows_.resize(m);
    Space::for_each(slots,
                    GatherWallContacts{wall_.partner.data(), wall_out_.data(), contact_flag_.data(),
                                       contact_at_.data(), contact_rows_.data()});
    contact_rows_.download(rows.data());
    return rows;
}

template <class Space> void ResidentDem<Space>::scatter_nodal_impulse(Real h) {
    const auto& prims = host_.walls_.primitives();
    const auto& corners = host_.walls_.corners();
    std::vector<Vec3>& impulse = host_.walls_.nodes().impulse;
    for (const WallContactRow& c : wall_contacts(true)) {
        const WallPrimitive& pr = prims[std::size_t(c.prim)];
        const NodalCorners& nc = corners[std::size_t(pr.corners)];
        const Vec3 bw = barycentric(c.q, pr.a, pr.b, pr.c);
        for (int a = 0; a < 3; ++a)
            impulse[std::size_t(nc.node[std::size_t(a)])] += (-h * bw[a]) * c.f;
    }
}

} // namespace debrisflow::dem
