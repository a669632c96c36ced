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
#include "debrisflow/dem/resident_grain_reader.hpp"
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
    friend class ResidentGrainReader<Space>;

    // One kind of contact slots (grain-grain or grain-wall) with the rows of the last rebuild
    // (old_*), which the next rebuild carries the history from (ContactSlots on the host).
    struct Slots {
        Index cap = 0;      // the rows' stride now
        Index next_cap = 2; // the next build's (ContactSlots)
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
    void publish() override;

    void publish_wall_contacts() override {
        if (resident_) record_wall_contacts();
    }

    probes::GrainReader& grain_reader() override { return reader_; }

    void reload() override {
        resident_ = false;
        ++changes_;
    }

    // Defined with the coupling (coupling/resident_sph_dem.hpp).
    std::unique_ptr<time::Phase> couple_fluid(sph::ResidentPhase& fluid,
                                              coupling::SphDemCoupling& coupling) override;

    Index size() const override { return resident_ ? n_ : g_.size(); }

    std::vector<std::pair<Vec3, Real>> grains_near(const flow::FeedReach& region) override;

    void append(const GrainSet& fresh) override;

    Leaving remove_outside(const flow::ExitFaces& faces) override;

    Leaving remove_inside(const flow::OutletBox& box) override;

    std::size_t memory_bytes() const override;
    long copies_to_host() const override { return copies_to_host_; }
    long copies_from_host() const override { return copies_from_host_; }

private:
    template <class From, class To> static void down(const From& from, To& to) {
        to.resize(std::size_t(from.size()));
        from.download(to.data());
    }
    // The grains' arrays and clumps to the host's GrainSet, the walls' contact loads of the
    // last evaluation to the walls that keep them: one copy to the host.
    void download_grains();

    // --- the state taken over from the host -----------------------------------------------
    void upload_once();

    // --- grains that leave (DemSolver::remove_grains) --------------------------------------
    // The leavers (keep_[i] = 0) reported in index order; the others kept in their order with
    // their slot rows (the history the rebuild carries, keyed by the partners' ids), then the
    // neighbour rebuild, as on the host.
    Leaving remove_leavers(const flow::ExitFaces* faces);
    // Grains leaving with clumps among them (rare: a clump leaves whole, its members still
    // inside counted at a face one of them crossed): the grains to the host, removed there as
    // Outlet::apply and DomainExit::apply remove them (DemSolver::remove_grains), and taken over
    // again at the next use.
    Leaving remove_with_clumps(const flow::ExitFaces* faces);

    // The contact loads of the last evaluation on the walls that keep them (a pressure map
    // reads them), in grain and slot order as the host's slot pass records them: the touching
    // slots' forces and points on those walls, brought to the host once per evaluation when
    // asked for.
    void record_wall_contacts();

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
        const auto& corners = host_.walls_.corners();
        corners_.upload(corners.data(), Index(corners.size()));
        faces_stale_ = false;
    }

    // The touching wall slots of the last evaluation on triangles on moving nodes (nodal) or on
    // walls that record their contacts, in grain and slot order: stream compaction of the
    // slots, only these rows come to the host.
    std::vector<WallContactRow> wall_contacts(bool nodal);
    // The contacts on FEM surfaces in this evaluation hand their impulse -h w_a f to the corners
    // in slot order, as the host's slot pass does (DemSolver::own_slots).
    void scatter_nodal_impulse(Real h);

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
    void rebuild();

    // Cells of one search radius over the grains' box, as DemSolver::configure_grid.
    void configure_grid();

    void configure(Vec3 lo, Vec3 hi) {
        config_.configure(lo, hi, host_.grid_cell(), host_.params_.dim, host_.domain_.periodic);
        grid_ = config_.view();
        keys_count_ = Index(config_.cell_count());
    }

    void build_grid();

    // Every grain array and both kinds of slot rows gathered into order_ (the grid's order, or
    // the kept grains after a removal), m of them (the slots' partners are rebuilt right after;
    // their keys and history move with their rows).
    void permute(Index m);
    template <class T> void gather(Buffer<T>& a, Buffer<T>& scratch, int width) {
        scratch.resize(width * n_);
        Space::for_each(n_, exec::GatherByOrder<T>{a.data(), order_.data(), scratch.data(), width});
        a.swap(scratch);
    }

    // ContactSlots::build: each grain's row from its candidates, carrying the history of keys
    // that reappear; a row past the capacity grows it and the rows are filled again.
    template <class Candidates> void build_slots(Slots& s, const Candidates& candidates);

    // The slots naming each grain as partner, in slot order: a stable sort of the slots on
    // the partner they name (empty slots last), rebuilt with the lists.
    void build_reverse();

    // --- the rigid bodies' contact spheres (DemSolver::build_obstacle_slots) ---------------
    // The spheres as the bodies left them (the few bodies move on the host): uploaded when
    // they moved or changed.
    void upload_spheres();
    // Each grain's candidate spheres within reach, from a cell grid of the spheres (a sort of
    // the spheres by cell, as the grains'), carrying the history of the spheres that stay.
    void build_obstacle_slots();

    // --- the force evaluation (DemSolver::forces in the device's layout) -----------------
    void forces(Real half_kick, bool collect_obstacles = false);

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
    // triangles on moving nodes (FEM surfaces): corners, the nodes' velocities
    Buffer<NodalCorners> corners_;
    Buffer<Vec3> node_v_;
    Buffer<Index> contact_flag_, contact_at_; // the wall contacts brought back
    Buffer<WallContactRow> contact_rows_;
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
    ResidentGrainReader<Space> reader_{*this}; // the grain probes' sums, maxima and rows
};

} // namespace debrisflow::dem

// The members defined outside the class, one part each.
#include "debrisflow/dem/resident_dem_forces.hpp"
#include "debrisflow/dem/resident_dem_population.hpp"
#include "debrisflow/dem/resident_dem_rebuild.hpp"
