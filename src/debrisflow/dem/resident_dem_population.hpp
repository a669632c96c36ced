#pragma once
// The resident DEM phase's population (dem/resident_dem.hpp, included at its end): taking the
// host's grains over, bringing them back (publish), grains near a feed's region,
// a feed's new grains appended, and grains that leave through an outlet or the domain's faces
// removed by stream compaction (DemSolver::remove_grains on the host).
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

namespace debrisflow::dem {

template <class Space> void ResidentDem<Space>::publish() {
    if (!resident_) return;
    download_grains();
    down(hot_, host_.hot_);
    const auto down_slots = [&](const Slots& from, ContactSlots& to) {
        to.cap_ = from.cap, to.next_cap_ = from.next_cap;
        down(from.count, to.count_), down(from.partner, to.partner_);
        down(from.key, to.key_), down(from.xi, to.xi_), down(from.mroll, to.mroll_);
    };
    down_slots(grain_, host_.grain_slots_);
    down_slots(wall_, host_.wall_slots_);
    down_slots(obstacle_, host_.obstacle_slots_);
    if (FluidLoad* f = host_.fluid_) {
        down(fl_force_, f->force), down(fl_u_, f->u), down(fl_beta_, f->beta);
        down(fl_impulse_, f->impulse), down(fl_felt_, f->felt);
        down(fl_handover_, f->handover);
    }
}

template <class Space>
auto ResidentDem<Space>::grains_near(const flow::FeedReach& region)
    -> std::vector<std::pair<Vec3, Real>> {
    upload_once();
    keep_.resize(n_);
    at_.resize(n_);
    Space::for_each(n_, GrainNearFeed{pos_.data(), radius_.data(), region, keep_.data()});
    const Index m = Space::exclusive_scan(n_, keep_.data(), at_.data());
    const std::vector<Vec3> p = picked(pos_, keep_, m);
    const std::vector<Real> r = picked(radius_, keep_, m);
    std::vector<std::pair<Vec3, Real>> near(p.size());
    for (std::size_t k = 0; k < p.size(); ++k) near[k] = {p[k], r[k]};
    return near;
}

template <class Space> void ResidentDem<Space>::append(const GrainSet& fresh) {
    upload_once();
    ++changes_;
    const Index m = fresh.size(), held = n_;
    if (m == 0) return;
    record_wall_contacts(); // of the evaluation before the rows move
    const auto tail = [&](auto& to, const auto& from) {
        to.resize(held + m);
        to.upload_at(held, from.data(), m);
    };
    tail(pos_, fresh.pos), tail(vel_, fresh.vel), tail(spin_, fresh.spin);
    tail(force_, fresh.force), tail(torque_, fresh.torque), tail(radius_, fresh.radius);
    tail(mass_, fresh.mass), tail(inv_mass_, fresh.inv_mass);
    tail(inv_inertia_, fresh.inv_inertia), tail(material_, fresh.material);
    tail(id_, fresh.id);
    if (host_.fluid_) { // new grains start without a fluid load, as on the host
        const std::vector<Vec3> none(static_cast<std::size_t>(m));
        for (auto* a : {&fl_force_, &fl_u_, &fl_impulse_, &fl_felt_, &fl_handover_}) tail(*a, none);
        tail(fl_beta_, std::vector<Real>(static_cast<std::size_t>(m), Real(0)));
    }
    for (Slots* s : {&grain_, &wall_, &obstacle_}) {
        if (s->count.size() != held) continue; // never built: nothing to carry
        const Index slots = (held + m) * s->cap;
        s->count.resize(held + m);
        Space::for_each(m, FillWith<Index>{s->count.data() + held, 0}); // empty rows
        s->partner.resize(slots);
        s->key.resize(slots);
        s->xi.resize(slots);
        if (s->mroll.size() > 0) s->mroll.resize(slots);
    }
    n_ = held + m;
    if (clumps_ > 0) { // the new ids in no clump, and where they are (DemSolver::map_clumps)
        const Index ids = Index(fresh.next_id()), had = clump_of_.size();
        clump_of_.resize(ids);
        index_of_id_.resize(ids);
        Space::for_each(ids - had, FillWith<std::int32_t>{clump_of_.data() + had, -1});
        Space::for_each(n_, IndexOfId{id_.data(), index_of_id_.data()});
    }
    hot_.resize(n_); // filled by the rebuild
    host_.include_sizes(fresh);
    host_.evaluated_ = false;
    rebuild();
}

template <class Space>
auto ResidentDem<Space>::remove_outside(const flow::ExitFaces& faces) -> Leaving {
    upload_once();
    keep_.resize(n_);
    Space::for_each(n_, GrainKeepInsideDomain{pos_.data(), faces, keep_.data()});
    if (clumps_ > 0) return remove_with_clumps(&faces);
    return remove_leavers(&faces);
}

template <class Space>
auto ResidentDem<Space>::remove_inside(const flow::OutletBox& box) -> Leaving {
    upload_once();
    keep_.resize(n_);
    Space::for_each(n_, GrainKeepOutsideBox{pos_.data(), box, keep_.data()});
    if (clumps_ > 0) return remove_with_clumps(nullptr);
    return remove_leavers(nullptr);
}

template <class Space> auto ResidentDem<Space>::memory_bytes() const -> std::size_t {
    std::size_t b =
        pos_.bytes() + vel_.bytes() + spin_.bytes() + force_.bytes() + torque_.bytes() +
        radius_.bytes() + mass_.bytes() + inv_mass_.bytes() + inv_inertia_.bytes() +
        material_.bytes() + id_.bytes() + hot_.bytes() + acc_.bytes() + fl_force_.bytes() +
        fl_u_.bytes() + fl_impulse_.bytes() + fl_felt_.bytes() + fl_handover_.bytes() +
        fl_beta_.bytes() + grain_.bytes() + wall_.bytes() + obstacle_.bytes() + spheres_.bytes() +
        obstacle_out_.bytes() + obstacle_touching_.bytes() + sphere_keys_.bytes() +
        sphere_order_.bytes() + sphere_starts_.bytes() + slot_out_.bytes() +
        slot_touching_.bytes() + wall_out_.bytes() + wall_touching_.bytes() + reverse_key_.bytes() +
        reverse_.bytes() + reverse_start_.bytes() + keys_.bytes() + order_.bytes() +
        start_cells_.bytes() + table_.bytes() + prims_.bytes() + wall_states_.bytes() +
        active_.bytes() + bounds_.bytes() + bin_start_.bytes() + bin_items_.bytes() +
        bin_always_.bytes() + cl_pos_.bytes() + cl_vel_.bytes() + cl_ang_mom_.bytes() +
        cl_force_.bytes() + cl_torque_.bytes() + cl_inv_inertia_.bytes() + cl_offset_.bytes() +
        cl_orient_.bytes() + cl_mass_.bytes() + cl_first_.bytes() + cl_member_.bytes() +
        clump_of_.bytes() + index_of_id_.bytes() + vec_scratch_.bytes() + real_scratch_.bytes() +
        index_scratch_.bytes() + key_scratch_.bytes() + byte_scratch_.bytes() + keep_.bytes() +
        leave_.bytes() + at_.bytes() + reader_.bytes() + corners_.bytes() + node_v_.bytes() +
        contact_flag_.bytes() + contact_at_.bytes() + contact_rows_.bytes();
    return b + sorter_.bytes() + reverse_sorter_.bytes() + sphere_sorter_.bytes();
}

template <class Space> void ResidentDem<Space>::download_grains() {
    if (downloaded_ == changes_) return; // the host's copy is this state already
    downloaded_ = changes_;
    Space::synchronize();
    down(pos_, g_.pos), down(vel_, g_.vel), down(spin_, g_.spin);
    down(force_, g_.force), down(torque_, g_.torque);
    down(radius_, g_.radius), down(mass_, g_.mass), down(inv_mass_, g_.inv_mass);
    down(inv_inertia_, g_.inv_inertia), down(material_, g_.material), down(id_, g_.id);
    if (clumps_ > 0) {
        ClumpSet& cl = g_.clumps;
        down(cl_pos_, cl.pos), down(cl_vel_, cl.vel), down(cl_ang_mom_, cl.ang_mom);
        down(cl_force_, cl.force), down(cl_torque_, cl.torque), down(cl_orient_, cl.orient);
        host_.map_clumps(); // members' indices in the grains' present order
    }
    record_wall_contacts();
    ++copies_to_host_;
}

template <class Space> void ResidentDem<Space>::upload_once() {
    if (resident_) return;
    n_ = g_.size();
    const auto up = [](auto& to, const auto& from) { to.upload(from.data(), Index(from.size())); };
    up(pos_, g_.pos), up(vel_, g_.vel), up(spin_, g_.spin), up(force_, g_.force);
    up(torque_, g_.torque), up(radius_, g_.radius), up(mass_, g_.mass);
    up(inv_mass_, g_.inv_mass), up(inv_inertia_, g_.inv_inertia);
    up(material_, g_.material), up(id_, g_.id);
    if (FluidLoad* f = host_.fluid_) {
        f->resize(std::size_t(n_));
        up(fl_force_, f->force), up(fl_u_, f->u), up(fl_beta_, f->beta);
        up(fl_impulse_, f->impulse), up(fl_felt_, f->felt), up(fl_handover_, f->handover);
    }
    if (host_.hot_.size() == std::size_t(n_)) {
        up(hot_, host_.hot_);
    } else {
        hot_.resize(n_);
        Space::for_each(n_, LoadHot{view(), hot_.data()});
    }
    const auto up_slots = [&](Slots& to, const ContactSlots& from) {
        to.cap = from.cap_, to.next_cap = from.next_cap_;
        up(to.count, from.count_), up(to.partner, from.partner_), up(to.key, from.key_);
        up(to.xi, from.xi_), up(to.mroll, from.mroll_);
    };
    up_slots(grain_, host_.grain_slots_);
    up_slots(wall_, host_.wall_slots_);
    up_slots(obstacle_, host_.obstacle_slots_);
    rolling_ = host_.grain_slots_.rolling_;
    const ClumpSet& cl = g_.clumps;
    clumps_ = cl.size();
    if (clumps_ > 0) {
        up(cl_pos_, cl.pos), up(cl_vel_, cl.vel), up(cl_ang_mom_, cl.ang_mom);
        up(cl_force_, cl.force), up(cl_torque_, cl.torque), up(cl_orient_, cl.orient);
        up(cl_mass_, cl.mass), up(cl_inv_inertia_, cl.inv_inertia), up(cl_first_, cl.first);
        up(cl_member_, cl.member_id), up(cl_offset_, cl.offset);
        up(clump_of_, host_.clump_of_id_), up(index_of_id_, host_.index_of_id_);
    }
    up(table_, host_.table_);
    upload_faces();
    // the grid's box as at the host's last rebuild (its periodic lengths give separations)
    if (host_.built_ && n_ > 0) configure(host_.grid_lo_, host_.grid_hi_);
    reverse_built_ = -1;
    resident_ = true;
    ++copies_from_host_;
}

template <class Space>
auto ResidentDem<Space>::remove_leavers(const flow::ExitFaces* faces) -> Leaving {
    Leaving out;
    if (Space::first_where(n_, exec::Dropped{keep_.data()}) == n_) return out; // none
    record_wall_contacts(); // of the evaluation before the rows move
    if (faces) out.mass_in_set = Space::sum_of(n_, GrainMass{mass_.data()});
    leave_.resize(n_);
    at_.resize(n_);
    Space::for_each(n_, exec::Complement{keep_.data(), leave_.data()});
    const Index gone = Space::exclusive_scan(n_, leave_.data(), at_.data());
    out.mass = picked(mass_, leave_, gone);
    out.material = picked(material_, leave_, gone);
    if (faces) {
        Buffer<int> crossed;
        crossed.resize(gone);
        Space::for_each(
            n_, GrainLeaverFaces{pos_.data(), *faces, leave_.data(), at_.data(), crossed.data()});
        out.face.resize(std::size_t(gone));
        crossed.download(out.face.data());
    }
    const Index kept = Space::exclusive_scan(n_, keep_.data(), at_.data());
    order_.resize(kept);
    Space::for_each(n_, exec::KeptOrder{keep_.data(), at_.data(), order_.data()});
    permute(kept);
    host_.evaluated_ = false;
    const GrainEscaped escaped{pos_.data(), vel_.data(), host_.domain_, host_.params_.dim == 2};
    host_.bad_ = Space::first_where(n_, escaped) < n_;
    rebuild();
    return out;
}

template <class Space>
auto ResidentDem<Space>::remove_with_clumps(const flow::ExitFaces* faces) -> Leaving {
    Leaving out;
    if (Space::first_where(n_, exec::Dropped{keep_.data()}) == n_) return out; // none
    std::vector<Index> flags(static_cast<std::size_t>(n_));
    keep_.download(flags.data());
    publish();
    std::vector<std::uint8_t> keep(flags.begin(), flags.end());
    const auto& g = host_.grains();
    std::vector<int> face(keep.size(), -1);
    if (faces) {
        for (std::size_t k = 0; k < keep.size(); ++k) {
            out.mass_in_set += g.mass[k];
            if (!keep[k]) face[k] = faces->of_finite(g.pos[k]);
        }
    }
    host_.expand_to_clumps(keep);
    if (faces) host_.spread_clump_faces(face);
    for (std::size_t k = 0; k < keep.size(); ++k) {
        if (keep[k] || (faces && face[k] < 0)) continue; // not finite: the health check
        out.mass.push_back(g.mass[k]);
        out.material.push_back(g.material[k]);
        if (faces) out.face.push_back(face[k]);
    }
    host_.remove_grains(keep);
    reload();
    return out;
}

template <class Space> void ResidentDem<Space>::record_wall_contacts() {
    if (recorded_ || n_ == 0 || wall_touching_.size() != n_ * wall_.cap) return;
    recorded_ = true;
    auto& wl = host_.walls_.walls();
    bool any = false;
    for (const auto& w : wl) any = any || w.record_contacts;
    if (!any) return;
    const auto& prims = host_.walls_.primitives();
    for (const WallContactRow& c : wall_contacts(false))
        wl[std::size_t(prims[std::size_t(c.prim)].wall)].contacts.push_back({c.q, -c.f});
}

} // namespace debrisflow::dem
