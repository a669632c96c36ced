#pragma once
// The DEM phase resident in a memory space (issue #34): the grains, their interleaved contact
// state and their contact slots (partners, keys, tangential springs and rolling moments) live
// in the Space's memory (exec/host_space.hpp, exec/cuda_space.cuh), and every part of a step
// runs there through the Space's primitives, launching the same host/device functors as the
// DemSolver's device layout (dem.contact_pass = "slots"): the opening kick and drift
// (GrainKickDrift), the cell grid (CellKeys, a stable sort, CellStarts), reordering by cell,
// the neighbour rebuild's rows with their carried history (SlotRowFill with GrainCandidates and
// WallCandidatesOf), the reverse index (a stable sort on the partner), one contact evaluation
// per slot (GrainSlotForces) gathered per grain (GrainSlotGather), and the per-grain pass
// (GrainOwnSlots: gravity, walls, closing kick) with each wall's load reduced there
// (WallSlotLoad). Rigid bodies are obstacles (their contact spheres uploaded when they move,
// found through a cell grid of the spheres, each body's load folded here: BodySlotLoad), and
// clumps of grains step here (ClumpKickDrift, ClumpSum). Only a few numbers cross to the host
// in a step: the drift's report, each wall's and body's load and the contact count. The host's
// DemSolver keeps the parameters, the walls (moved on the host and uploaded when they move), the
// step and the counters; its grains and slots are brought up to date by publish() (probes that read
// grains, frames, checkpoints, the end). Grains that leave (outlets, the domain exit) are removed
// here by stream compaction, only their masses, materials and faces coming back; a feed's new
// grains are placed on the host clear of the few grains near its region (brought back) and appended
// here. Written once; dem/resident_dem_host.cpp instantiates it for the host's threads (what CI
// runs), exec/cuda_instantiations.cu for a CUDA device.
#include "debrisflow/core/stopwatch.hpp"
#include "debrisflow/dem/clump_step_k.hpp"
#include "debrisflow/dem/dem_solver.hpp"
#include "debrisflow/dem/grain_kick_drift_k.hpp"
#include "debrisflow/dem/resident_dem_backend.hpp"
#include "debrisflow/dem/resident_dem_k.hpp"
#include "debrisflow/dem/slot_candidates_k.hpp"
#include "debrisflow/exec/compact_k.hpp"
#include "debrisflow/exec/reorder_k.hpp"
#include "debrisflow/neighbors/cell_keys_k.hpp"
#include <cmath>
#include <utility>
#include <vector>

namespace debrisflow::coupling {
template <class Space> class ResidentSphDem;
}

namespace debrisflow::dem {

template <class Space> class ResidentDem final : public ResidentDemPhase {
    template <class T> using Buffer = typename Space::template Buffer<T>;
    friend class coupling::ResidentSphDem<Space>;

    // One kind of contact slots (grain-grain or grain-wall) with the rows of the last rebuild
    // (old_*), which the next rebuild carries the history from (ContactSlots on the host).
    struct Slots {
        Index cap = 8;
        Buffer<Index> count, partner, old_count;
        Buffer<std::uint32_t> key, old_key;
        Buffer<Vec3> xi, old_xi, mroll, old_mroll; // mroll empty without rolling memory
        std::size_t bytes() const {
            return count.bytes() + partner.bytes() + old_count.bytes() + key.bytes() +
                   old_key.bytes() + xi.bytes() + old_xi.bytes() + mroll.bytes() +
                   old_mroll.bytes();
        }
    };

public:
    explicit ResidentDem(DemSolver& host) : host_(host), g_(host.grains()) {}

    const char* name() const override { return "dem"; }

    void update_neighbors(bool) override {
        upload_once();
        if (!host_.built_) rebuild();
    }

    // As DemSolver::compute_forces: the step just taken ended with a force evaluation that the
    // grains were kicked with; evaluate again only for a new wall layout, a removed wall or
    // bodies that moved their contact spheres after the step (they take this reaction too).
    void compute_forces() override {
        upload_once();
        const bool bodies_moved =
            host_.obstacles_ && host_.obstacles_->version != host_.obstacles_seen_;
        if (host_.evaluated_ && !bodies_moved && host_.walls_.layout() == host_.walls_seen_) {
            host_.evaluated_ = false;
            return;
        }
        host_.evaluated_ = false;
        if (!host_.built_ || host_.walls_.layout() != host_.walls_seen_) rebuild();
        ScopedTimer timer(t_forces_);
        forces(0, bodies_moved);
    }

    void predictor(Real) override {}
    void corrector(Real dt) override { advance(dt); }
    void verlet_step(Real dt, bool) override { advance(dt); }
    time::DtLimit stable_dt() const override { return host_.stable_dt(); }

    // A grain left the domain or is not finite: the host's health check names it.
    void check_health(Real t) const override {
        if (!host_.bad_) return;
        const_cast<ResidentDem*>(this)->publish();
        host_.check_health(t);
    }

    void add_timings(time::Timings& t) const override {
        host_.add_timings(t); // settling, before the resident loop took over
        t.neighbors += t_neighbors_;
        t.forces += t_forces_;
        t.integration += t_integration_;
    }

    // The grains, their contact state and slots to the host's GrainSet and DemSolver.
    void publish() override {
        if (!resident_) return;
        download_grains();
        down(hot_, host_.hot_);
        const auto down_slots = [&](const Slots& from, ContactSlots& to) {
            to.cap_ = from.cap;
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

    void publish_grains() override {
        if (resident_) download_grains();
    }

    void reload() override {
        resident_ = false;
        ++changes_;
    }

    // Defined with the coupling (coupling/resident_sph_dem.hpp).
    std::unique_ptr<time::Phase> couple_fluid(sph::ResidentPhase& fluid,
                                              coupling::SphDemCoupling& coupling) override;

    Index size() const override { return resident_ ? n_ : g_.size(); }

    std::vector<std::pair<Vec3, Real>> grains_near(const flow::FeedReach& region) override {
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

    void append(const GrainSet& fresh) override {
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
            for (auto* a : {&fl_force_, &fl_u_, &fl_impulse_, &fl_felt_, &fl_handover_})
                tail(*a, none);
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

    Leaving remove_outside(const flow::ExitFaces& faces) override {
        upload_once();
        keep_.resize(n_);
        Space::for_each(n_, GrainKeepInsideDomain{pos_.data(), faces, keep_.data()});
        if (clumps_ > 0) return remove_with_clumps(&faces);
        return remove_leavers(&faces);
    }

    Leaving remove_inside(const flow::OutletBox& box) override {
        upload_once();
        keep_.resize(n_);
        Space::for_each(n_, GrainKeepOutsideBox{pos_.data(), box, keep_.data()});
        if (clumps_ > 0) return remove_with_clumps(nullptr);
        return remove_leavers(nullptr);
    }

    std::size_t memory_bytes() const override {
        std::size_t b =
            pos_.bytes() + vel_.bytes() + spin_.bytes() + force_.bytes() + torque_.bytes() +
            radius_.bytes() + mass_.bytes() + inv_mass_.bytes() + inv_inertia_.bytes() +
            material_.bytes() + id_.bytes() + hot_.bytes() + acc_.bytes() + fl_force_.bytes() +
            fl_u_.bytes() + fl_impulse_.bytes() + fl_felt_.bytes() + fl_handover_.bytes() +
            fl_beta_.bytes() + grain_.bytes() + wall_.bytes() + obstacle_.bytes() +
            spheres_.bytes() + obstacle_out_.bytes() + obstacle_touching_.bytes() +
            sphere_keys_.bytes() + sphere_order_.bytes() + sphere_starts_.bytes() +
            slot_out_.bytes() + slot_touching_.bytes() + wall_out_.bytes() +
            wall_touching_.bytes() + reverse_key_.bytes() + reverse_.bytes() +
            reverse_start_.bytes() + keys_.bytes() + order_.bytes() + start_cells_.bytes() +
            table_.bytes() + prims_.bytes() + wall_states_.bytes() + active_.bytes() +
            bounds_.bytes() + bin_start_.bytes() + bin_items_.bytes() + bin_always_.bytes() +
            cl_pos_.bytes() + cl_vel_.bytes() + cl_ang_mom_.bytes() + cl_force_.bytes() +
            cl_torque_.bytes() + cl_inv_inertia_.bytes() + cl_offset_.bytes() + cl_orient_.bytes() +
            cl_mass_.bytes() + cl_first_.bytes() + cl_member_.bytes() + clump_of_.bytes() +
            index_of_id_.bytes() + vec_scratch_.bytes() + real_scratch_.bytes() +
            index_scratch_.bytes() + key_scratch_.bytes() + byte_scratch_.bytes() + keep_.bytes() +
            leave_.bytes() + at_.bytes();
        return b + sorter_.bytes() + reverse_sorter_.bytes() + sphere_sorter_.bytes();
    }
    long copies_to_host() const override { return copies_to_host_; }
    long copies_from_host() const override { return copies_from_host_; }

private:
    template <class From, class To> static void down(const From& from, To& to) {
        to.resize(std::size_t(from.size()));
        from.download(to.data());
    }
    // The grains' arrays and clumps to the host's GrainSet, the walls' contact loads of the
    // last evaluation to the walls that keep them: one copy to the host.
    void download_grains() {
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

    // --- the state taken over from the host -----------------------------------------------
    void upload_once() {
        if (resident_) return;
        n_ = g_.size();
        const auto up = [](auto& to, const auto& from) {
            to.upload(from.data(), Index(from.size()));
        };
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
            to.cap = from.cap_;
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

    // --- grains that leave (DemSolver::remove_grains) --------------------------------------
    // The leavers (keep_[i] = 0) reported in index order; the others kept in their order with
    // their slot rows (the history the rebuild carries, keyed by the partners' ids), then the
    // neighbour rebuild, as on the host.
    Leaving remove_leavers(const flow::ExitFaces* faces) {
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
            Space::for_each(n_, GrainLeaverFaces{pos_.data(), *faces, leave_.data(), at_.data(),
                                                 crossed.data()});
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
    // Grains leaving with clumps among them (rare: a clump leaves whole, its members still
    // inside counted at a face one of them crossed): the grains to the host, removed there as
    // Outlet::apply and DomainExit::apply remove them (DemSolver::remove_grains), and taken over
    // again at the next use.
    Leaving remove_with_clumps(const flow::ExitFaces* faces) {
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

    // The contact loads of the last evaluation on the walls that keep them (a pressure map
    // reads them), in grain and slot order as the host's slot pass records them: each touching
    // wall slot's force and point, brought to the host once per evaluation when asked for.
    void record_wall_contacts() {
        if (recorded_ || n_ == 0 || wall_touching_.size() != n_ * wall_.cap) return;
        recorded_ = true;
        auto& wl = host_.walls_.walls();
        bool any = false;
        for (const auto& w : wl) any = any || w.record_contacts;
        if (!any) return;
        std::vector<Index> count(static_cast<std::size_t>(n_)),
            partner(static_cast<std::size_t>(wall_.partner.size()));
        std::vector<std::uint8_t> touching(static_cast<std::size_t>(wall_touching_.size()));
        std::vector<Real> out(static_cast<std::size_t>(wall_out_.size()));
        wall_.count.download(count.data());
        wall_.partner.download(partner.data());
        wall_touching_.download(touching.data());
        wall_out_.download(out.data());
        const auto& prims = host_.walls_.primitives();
        for (std::size_t i = 0; i < count.size(); ++i)
            for (Index k = 0; k < count[i]; ++k) {
                const std::size_t s = i * std::size_t(wall_.cap) + std::size_t(k);
                if (!touching[s]) continue;
                auto& w = wl[std::size_t(prims[std::size_t(partner[s])].wall)];
                if (!w.record_contacts) continue;
                const Real* o = out.data() + 9 * s;
                w.contacts.push_back({{o[3], o[4], o[5]}, {-o[0], -o[1], -o[2]}});
            }
    }

    // values[i] of the m items with flags[i], in index order (at_ holds the flags' scan).
    template <class T>
    std::vector<T> picked(const Buffer<T>& values, const Buffer<Index>& flags, Index m) {
        Buffer<T> out;
        out.resize(m);
        Space::for_each(
            n_, exec::ScatterKept<T>{values.data(), flags.data(), at_.data(), out.data(), 1});
        std::vector<T> host(static_cast<std::size_t>(m));
        out.download(host.data());
        return host;
    }

    GrainView view() {
        return {pos_.data(),         vel_.data(),      spin_.data(), force_.data(),
                torque_.data(),      radius_.data(),   mass_.data(), inv_mass_.data(),
                inv_inertia_.data(), material_.data(), id_.data(),   n_};
    }

    PairTable table() { return {table_.data(), int(host_.materials_.size()), host_.reach_ > 0}; }

    // The walls' faces, from the host's WallSet: at the take-over, at each rebuild and after
    // the walls moved.
    void upload_faces() {
        const auto& prims = host_.walls_.primitives();
        prims_.upload(prims.data(), Index(prims.size()));
        faces_stale_ = false;
    }

    // --- the step (DemSolver::advance and step) ------------------------------------------
    void advance(Real dt) {
        ++changes_;
        const auto& p = host_.params_;
        if (!p.subcycle) {
            step(dt);
            return;
        }
        const long n = std::max(1L, long(std::ceil(dt / host_.dt_ - 1e-9)));
        for (long s = 0; s < n; ++s) step(dt / Real(n));
    }

    void step(Real h) {
        host_.current_h_ = h;
        kick_drift(h);
        host_.advance_walls(h);
        faces_stale_ = faces_stale_ || host_.walls_.max_speed() > 0;
        if (host_.drift_ > Real(0.5) * host_.skin_ || host_.walls_.layout() != host_.walls_seen_)
            rebuild();
        const dem::ObstacleSet* o = host_.obstacles_;
        if (o &&
            (o->version != host_.obstacles_seen_ || host_.builds_ != host_.obstacle_builds_seen_))
            build_obstacle_slots();
        {
            ScopedTimer timer(t_forces_);
            forces(Real(0.5) * h);
        }
        host_.evaluated_ = true;
    }

    void kick_drift(Real h) {
        ScopedTimer timer(t_integration_);
        const bool plane = host_.params_.dim == 2;
        const GrainKickDrift move{view(), hot_.data(), clump_of(), h, plane, host_.domain_};
        const DriftReport moved = Space::template fold<DriftReport>(n_, move);
        Real vmax2 = moved.vmax2;
        if (clumps_ > 0) { // DemSolver::clump_kick_drift
            const ClumpKickDrift step{
                clump_view(), view(), hot_.data(), index_of_id_.data(), h, plane, host_.domain_};
            const DriftReport m = Space::template fold<DriftReport>(clumps_, step);
            if (m.outside > 0) host_.bad_ = true;
            vmax2 = vmax2 < m.vmax2 ? m.vmax2 : vmax2;
        }
        if (moved.outside > 0 || !std::isfinite(vmax2)) host_.bad_ = true;
        host_.drift_ += h * (std::sqrt(vmax2) + host_.walls_.max_speed());
    }

    // --- clumps (DemSolver's clump stepping, dem/clump_step_k.hpp) ------------------------
    const std::int32_t* clump_of() { return clumps_ > 0 ? clump_of_.data() : nullptr; }
    ClumpView clump_view() {
        return {cl_pos_.data(),    cl_vel_.data(),    cl_ang_mom_.data(), cl_force_.data(),
                cl_torque_.data(), cl_orient_.data(), cl_mass_.data(),    cl_inv_inertia_.data(),
                cl_first_.data(),  cl_member_.data(), cl_offset_.data()};
    }

    // --- the neighbour rebuild (DemSolver::rebuild) ---------------------------------------
    void rebuild() {
        ScopedTimer timer(t_neighbors_);
        host_.built_ = true;
        host_.drift_ = 0;
        host_.walls_seen_ = host_.walls_.layout();
        ++host_.builds_;
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
        build_slots(grain_, GrainCandidates{grid_, pos_.data(), radius_.data(), id_.data(),
                                            clump_of(), skin});
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

    // Cells of one search radius over the grains' box, as DemSolver::configure_grid.
    void configure_grid() {
        Bounds box = Space::template fold<Bounds>(n_, GrainBounds{pos_.data()});
        Bounds::combine(box, Bounds{host_.domain_.hi, host_.domain_.lo}); // the host's start
        host_.set_grid_box(box);
        configure(host_.grid_lo_, host_.grid_hi_);
    }

    void configure(Vec3 lo, Vec3 hi) {
        config_.configure(lo, hi, host_.grid_cell(), host_.params_.dim, host_.domain_.periodic);
        grid_ = config_.view();
        keys_count_ = Index(config_.cell_count());
    }

    void build_grid() {
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

    // Every grain array and both kinds of slot rows gathered into order_ (the grid's order, or
    // the kept grains after a removal), m of them (the slots' partners are rebuilt right after;
    // their keys and history move with their rows).
    void permute(Index m) {
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
    template <class T> void gather(Buffer<T>& a, Buffer<T>& scratch, int width) {
        scratch.resize(width * n_);
        Space::for_each(n_, exec::GatherByOrder<T>{a.data(), order_.data(), scratch.data(), width});
        a.swap(scratch);
    }

    // ContactSlots::build: each grain's row from its candidates, carrying the history of keys
    // that reappear; a row past the capacity grows it and the rows are filled again.
    template <class Candidates> void build_slots(Slots& s, const Candidates& candidates) {
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
        for (;;) {
            const Index cap = s.cap, slots = n_ * cap;
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
            if (worst <= cap) return;
            s.cap = worst + worst / 4 + 2; // history still in old_*: retry with room
        }
    }

    // The slots naming each grain as partner, in slot order: a stable sort of the slots on
    // the partner they name (empty slots last), rebuilt with the lists.
    void build_reverse() {
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

    // --- the rigid bodies' contact spheres (DemSolver::build_obstacle_slots) ---------------
    // The spheres as the bodies left them (the few bodies move on the host): uploaded when
    // they moved or changed.
    void upload_spheres() {
        const ObstacleSet& o = *host_.obstacles_;
        if (spheres_version_ == o.version && spheres_.size() == Index(o.spheres.size())) return;
        spheres_.upload(o.spheres.data(), Index(o.spheres.size()));
        spheres_version_ = o.version;
    }
    // Each grain's candidate spheres within reach, from a cell grid of the spheres (a sort of
    // the spheres by cell, as the grains'), carrying the history of the spheres that stay.
    void build_obstacle_slots() {
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
            Space::for_each(ns,
                            neighbors::CellKeys{grid, c, c + 1, c + 2, ObstacleCandidates::stride,
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

    // --- the force evaluation (DemSolver::forces in the device's layout) -----------------
    void forces(Real half_kick, bool collect_obstacles = false) {
        ++changes_;
        const bool ends_step = half_kick > 0;
        const bool measure = host_.measure_contact_force_;
        const Real h = host_.current_h_;
        auto& wl = host_.walls_.walls();
        for (auto& w : wl) w.contacts.clear();
        recorded_ = false; // this evaluation's contact loads are still where the grains are
        // the walls' states (few: every evaluation) and their faces if they moved
        if (faces_stale_) upload_faces();
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
                            ClumpSum{clump_view(), view(), index_of_id_.data(),
                                     host_.params_.gravity, host_.params_.dim == 2, half_kick});
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
        if (host_.fluid_ && ends_step) host_.fluid_->time += h;
        host_.contacts_ = gg.touching + own.touching;
        host_.sum_contact_force_ = measure ? gg.force_sum + own.force_sum : 0;
    }

    DemSolver& host_;
    GrainSet& g_;
    bool resident_ = false, rolling_ = false, faces_stale_ = false;
    bool recorded_ = false; // the walls' contact loads of the last evaluation are on the host
    Index n_ = 0;
    // grains (GrainView's arrays), their contact pass's copy, their contact sums
    Buffer<Vec3> pos_, vel_, spin_, force_, torque_;
    Buffer<Real> radius_, mass_, inv_mass_, inv_inertia_;
    Buffer<std::uint8_t> material_;
    Buffer<std::uint32_t> id_;
    Buffer<GrainState> hot_;
    Buffer<Real> acc_;
    // a surrounding fluid's load on each grain (FluidLoad's arrays), with a fluid only
    Buffer<Vec3> fl_force_, fl_u_, fl_impulse_, fl_felt_, fl_handover_;
    Buffer<Real> fl_beta_;
    // contact slots, each slot's evaluation, the reverse index
    Slots grain_, wall_, obstacle_;
    Buffer<Real> slot_out_, wall_out_;
    Buffer<std::uint8_t> slot_touching_, wall_touching_;
    // clumps of grains (ClumpSet's arrays), each grain id's clump and index
    Index clumps_ = 0;
    Buffer<Vec3> cl_pos_, cl_vel_, cl_ang_mom_, cl_force_, cl_torque_, cl_inv_inertia_, cl_offset_;
    Buffer<rigid::Quat> cl_orient_;
    Buffer<Real> cl_mass_;
    Buffer<std::uint32_t> cl_first_, cl_member_;
    Buffer<std::int32_t> clump_of_;
    Buffer<Index> index_of_id_;
    // the rigid bodies' contact spheres (version: the ObstacleSet's when uploaded), their
    // cell grid, each grain-sphere slot's evaluation
    Buffer<ObstacleSphere> spheres_;
    std::uint64_t spheres_version_ = ~std::uint64_t(0);
    neighbors::CellGrid sphere_config_; // configured on the host: only its view is used
    Buffer<Index> sphere_keys_, sphere_order_, sphere_starts_;
    typename Space::Sorter sphere_sorter_;
    Buffer<Real> obstacle_out_;
    Buffer<std::uint8_t> obstacle_touching_;
    Buffer<Index> reverse_key_, reverse_, reverse_start_;
    long reverse_built_ = -1;
    typename Space::Sorter reverse_sorter_;
    // the cell grid
    neighbors::CellGrid config_; // configured on the host: only its view is used
    neighbors::GridView grid_{};
    Index keys_count_ = 0;
    Buffer<Index> keys_, order_, start_cells_;
    typename Space::Sorter sorter_;
    // materials and walls
    Buffer<PairParams> table_;
    Buffer<WallPrimitive> prims_;
    Buffer<WallState> wall_states_;
    Buffer<Index> active_;
    Buffer<PrimitiveBounds> bounds_;
    Buffer<Index> bin_start_, bin_items_, bin_always_; // WallBins of many faces
    std::vector<Index> active_host_;
    std::vector<PrimitiveBounds> bounds_host_;
    // reordering's scratch
    Buffer<Vec3> vec_scratch_;
    Buffer<Real> real_scratch_;
    Buffer<Index> index_scratch_;
    Buffer<std::uint32_t> key_scratch_;
    Buffer<std::uint8_t> byte_scratch_;
    // selections: the flags of the grains kept (a removal) or near a feed, the leavers' flags,
    // the exclusive scan of either
    Buffer<Index> keep_, leave_, at_;
    long copies_to_host_ = 0, copies_from_host_ = 0;
    // counts the changes to the grains where they are; the host's copy is of change downloaded_
    std::uint64_t changes_ = 1, downloaded_ = 0;
    double t_neighbors_ = 0, t_forces_ = 0, t_integration_ = 0;
};

} // namespace debrisflow::dem
