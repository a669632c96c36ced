#pragma once
// The SPH phase resident in a memory space (issue #33): every particle array lives in the
// Space's memory (exec/host_space.hpp, exec/cuda_space.cuh) and every part of a step runs
// there through the Space's primitives, launching the same host/device functors as the host
// solver: the cell grid (CellKeys, a stable sort, CellStarts), reordering by cell, pressures,
// apparent viscosities, the gather pair loop (FluidInteraction), both time schemes, and the
// reductions of the stable step and the health check. The host's ParticleSet is brought up to
// date only when an observer reads it (publish: probes, VTK frames, checkpoints, the end).
// Written once; sph/resident_sph_host.cpp instantiates it for the host's threads (what CI
// runs), exec/cuda_instantiations.cu for a CUDA device.
#include "debrisflow/core/error.hpp"
#include "debrisflow/core/stopwatch.hpp"
#include "debrisflow/neighbors/cell_grid.hpp"
#include "debrisflow/neighbors/cell_keys_k.hpp"
#include "debrisflow/rigid/body_solver.hpp"
#include "debrisflow/sph/apparent_viscosity_k.hpp"
#include "debrisflow/sph/density_gradient_k.hpp"
#include "debrisflow/sph/interaction_k.hpp"
#include "debrisflow/sph/mdbc_k.hpp"
#include "debrisflow/sph/resident_backend.hpp"
#include "debrisflow/sph/resident_bodies.hpp"
#include "debrisflow/sph/resident_fem.hpp"
#include "debrisflow/sph/resident_fluid_reader.hpp"
#include "debrisflow/sph/resident_steps_k.hpp"
#include "debrisflow/sph/sph_solver.hpp"
#include "debrisflow/sph/sph_solver_gather.hpp"
#include "debrisflow/sph/step_limit.hpp"
#include "debrisflow/sph/time_schemes_k.hpp"
#include <algorithm>
#include <array>
#include <memory>
#include <type_traits>
#include <variant>

namespace debrisflow::coupling {
template <class Space> class ResidentSphDem;
}

namespace debrisflow::sph {

template <class Space> class ResidentSph final : public ResidentPhase {
    template <class T> using Buffer = typename Space::template Buffer<T>;
    friend class ResidentBodies<Space>;
    friend class ResidentFem<Space>;
    friend class ResidentFluidReader<Space>;
    friend class coupling::ResidentSphDem<Space>;

public:
    // Takes over the host solver's particles at the first neighbour search; the host solver
    // keeps the parameters, the models and the grid its probes read.
    explicit ResidentSph(SphSolver& host) : host_(host), set_(host.particles()) {
        const SphParams& p = host.params();
        // the gather's grid: cells of the kernel support, each cell's fluid before its walls
        config_.configure(host.domain().lo, host.domain().hi, host.support(), p.dim,
                          host.domain().periodic);
        grid_ = config_.view();
        grid_.classes = 2;
        keys_count_ = Index(config_.cell_count()) * 2;
        sps_ = std::holds_alternative<models::LaminarSpsViscosity>(host.models().viscosity);
    }

    const char* name() const override { return "sph"; }

    void update_neighbors(bool reorder) override {
        ScopedTimer timer(t_neighbors_);
        upload_once();
        build_grid();
        // as the host's gather path: sort the particles by cell whenever the step allows
        if (reorder && host_.params().reorder_every > 0 &&
            Space::first_where(n_, OutOfOrder{order_.data()}) < n_) {
            permute();
            build_grid();
            ++sorts_;
        }
        Space::synchronize();
    }

    void compute_forces() override {
        ScopedTimer timer(t_forces_);
        const auto pv = view();
        const SphParams& p = host_.params();
        const auto& m = host_.models();
        // mDBC: the boundary particles' densities (and with its no-slip, the ghost nodes'
        // velocities) from their ghost nodes, before the pressures, as the host solver
        if (p.boundary == "mdbc") {
            const bool mirrored = p.no_slip == "mdbc";
            ghost_.resize(mirrored ? 4 * n_ : 0);
            std::visit(
                [&](const auto& kernel) {
                    using K = std::decay_t<decltype(kernel)>;
                    Space::for_each(n_, MdbcDensity<K>{pv, grid_, kernel, p.h,
                                                       host_.boundary_min_density(),
                                                       host_.eos().density(0), p.dp, p.dim,
                                                       mirrored ? ghost_.data() : nullptr});
                },
                m.kernel);
        }
        // the wall velocity the viscous terms see: Morris's, or mDBC's mirrored ghost
        const NoSlipWall wall{ghost_.size() > 0 ? ghost_.data() : nullptr, Real(0.5) * p.dp};
        Space::for_each(n_, TaitPressure{pv, host_.eos()});
        std::visit(
            [&](const auto& kernel, const auto& visc) {
                using K = std::decay_t<decltype(kernel)>;
                using V = std::decay_t<decltype(visc)>;
                if constexpr (V::needs_apparent_viscosity)
                    Space::for_each(n_, ApparentViscosity<K, V>{pv, grid_, kernel, visc, wall});
                else
                    Space::for_each(n_, FluidViscosity{pv, p.rho0 * visc.kinematic_viscosity()});
            },
            m.kernel, m.viscosity);
        const auto sps = host_.sps_constants();
        if (sps_) tau_next_.resize(6 * n_); // appended particles
        std::visit(
            [&](const auto& kernel, const auto& visc, const auto& diff) {
                // pressures, sound speeds and volumes computed where a side is loaded
                auto terms = host_.pair_terms(pv, kernel, visc, diff, nullptr, nullptr, nullptr,
                                              sps_ ? tau_.data() : nullptr);
                terms.wall = wall;
                if constexpr (std::decay_t<decltype(diff)>::needs_density_gradient) {
                    using K = std::decay_t<decltype(kernel)>;
                    grad_rho_.resize(3 * n_); // scratch of this evaluation
                    Space::for_each(n_, RenormalisedDensityGradient<K>{pv, grid_, kernel,
                                                                       grad_rho_.data(), p.dim});
                    terms.grad_rho = grad_rho_.data();
                }
                Space::for_each(n_, make_gather(terms, grid_, p.gravity, sps.smag, sps.blin,
                                                sps_ ? tau_next_.data() : nullptr));
            },
            m.kernel, m.viscosity, m.diffusion);
        if (sps_) tau_.swap(tau_next_); // the stress this evaluation wrote, read by the next
        Space::synchronize();
    }

    void predictor(Real dt) override {
        ScopedTimer timer(t_integrate_);
        for (auto& b : start_) b.resize(n_);
        Space::for_each(n_, SymplecticPredictor{view(), step_start(), Real(0.5) * dt,
                                                host_.boundary_min_density(), host_.domain()});
        Space::synchronize();
    }

    void corrector(Real dt) override {
        ScopedTimer timer(t_integrate_);
        Space::for_each(n_, SymplecticCorrector{view(), step_start(), dt,
                                                host_.boundary_min_density(), host_.domain()});
        Space::synchronize();
    }

    void verlet_step(Real dt, bool euler) override {
        ScopedTimer timer(t_integrate_);
        if (!set_.keeps_previous_state())
            throw std::logic_error("resident SPH: the Verlet scheme needs the state at t_n-1");
        const PreviousState old{old_[0].data(), old_[1].data(), old_[2].data(), old_[3].data()};
        Space::for_each(
            n_, VerletUpdate{view(), old, dt, host_.boundary_min_density(), euler, host_.domain()});
        Space::synchronize();
    }

    time::DtLimit stable_dt() const override {
        const auto pv = view();
        const SignalSpeed signal{pv, host_.eos()};
        const AccelerationNorm accel{pv};
        const StepExtremes e{Space::max_of(n_, signal), Space::max_of(n_, accel),
                             max_kinematic_viscosity()};
        time::DtLimit lim = step_limit(host_.params(), e);
        const LowStep low = low_step(host_.params(), lim, e);
        if (low == LowStep::none) return lim;
        const Index i = low == LowStep::signal
                            ? Space::first_where(n_, AtLeast<SignalSpeed>{signal, e.cmax})
                            : Space::first_where(n_, AtLeast<AccelerationNorm>{accel, e.amax});
        if (i < n_) lim.limiter += low_step_words(state_at(i), host_.params().rho0);
        return lim;
    }

    void check_health(Real t) const override {
        const Index bad = Space::first_where(
            n_, Unhealthy{ParticleHealthy::of(view(), host_.domain(), host_.params().rho0)});
        if (bad < n_)
            throw InstabilityError(
                unhealthy_message(state_at(bad), t, host_.domain(), host_.params()));
    }

    void add_timings(time::Timings& t) const override {
        t.neighbors += t_neighbors_;
        t.forces += t_forces_;
        t.integration += t_integrate_;
    }

    // Copies the particles to the host's ParticleSet (in the resident order) and rebuilds the
    // host grid that the probes interpolate on.
    void publish() override {
        if (!resident_) return;
        ++copies_;
        std::vector<ParticleId> host_ids; // the order of the host's wall geometry, if kept there
        if (!geometry_) host_ids = set_.id;
        auto fields = real_fields(set_);
        for (std::size_t f = 0; f < fields.size(); ++f)
            if (held(f)) download(real_[f], *fields[f]);
        if (set_.keeps_previous_state()) {
            auto old = old_fields(set_);
            for (std::size_t f = 0; f < old.size(); ++f) download(old_[f], *old[f]);
        }
        if (sps_) download(tau_, set_.sps_tau);
        download(kind_, set_.kind);
        download(group_, set_.group);
        download(id_, set_.id);
        if (!geometry_) reorder_wall_geometry(host_ids);
        set_.layout_changed();
        host_.rebuild_grid();
    }

    // Bytes this phase holds in its memory space, and per particle.
    std::size_t memory_bytes() const override {
        std::size_t b = sorter_bytes() + keys_.bytes() + order_.bytes() + start_cells_.bytes() +
                        tau_.bytes() + tau_next_.bytes() + kind_.bytes() + group_.bytes() +
                        id_.bytes() + ghost_.bytes() + grad_rho_.bytes() + leave_.bytes() +
                        pos_.bytes();
        for (const auto& a : real_) b += a.bytes();
        for (const auto& a : old_) b += a.bytes();
        for (const auto& a : start_) b += a.bytes();
        if (bodies_) b += row_.bytes() + bodies_->bytes();
        if (fem_) b += fem_row_.bytes() + fem_->bytes();
        b += reader_.bytes();
        return b;
    }
    Index size() const override { return resident_ ? n_ : set_.size(); }

    void remove_group(std::int16_t group) override {
        remove_where(KeepOutsideGroup{view(), group, nullptr});
    }

    // Removes the particles that `flags` (a functor with a `keep` pointer, which is set here)
    // marks 0, by stream compaction.
    template <class Flags> void remove_where(Flags flags);

    Leaving remove_fluid_outside(const flow::ExitFaces& faces) override;

    Leaving remove_fluid_inside(const flow::OutletBox& box) override;

    void prescribe(const flow::InletBuffer& buffer) override;

    // The new particles' arrays as ParticleSet::add fills them, each uploaded after the last.
    void append(const std::vector<particles::NewParticle>& fresh) override {
        append_particles(fresh, {}, {});
    }

    // As append, with each new particle's wall normal and depth (a body's shell, a solid's
    // exposed surface), body row and FEM row when given; returns the first new particle's id
    // (the others follow it).
    ParticleId append_particles(const std::vector<particles::NewParticle>& fresh,
                                const std::vector<rigid::ShellPoint>& walls,
                                const std::vector<std::int32_t>& rows,
                                const std::vector<std::int32_t>& fem_rows = {});

    void couple_bodies(rigid::BodySolver& bodies, coupling::SphBodyCoupling& coupling) override {
        if (resident_) throw std::logic_error("resident SPH: bodies are coupled before the run");
        bodies_ = std::make_unique<ResidentBodies<Space>>(*this, coupling);
        bodies.attach_fluid(bodies_.get());
    }

    void couple_fem(coupling::SphFemCoupling& coupling) override {
        if (resident_)
            throw std::logic_error("resident SPH: FEM solids are coupled before the run");
        fem_ = std::make_unique<ResidentFem<Space>>(*this, coupling);
        coupling.attach(fem_.get());
    }

    const probes::FluidReader& fluid_reader() const override {
        const_cast<ResidentSph*>(this)->upload_once(); // a sample before the first step
        return reader_;
    }

    void reload() override {
        resident_ = false;
        upload_once();
    }

    // How many times the particles were sorted by cell.
    long sorts() const override { return sorts_; }
    long copies_to_host() const override { return copies_; }

private:
    static constexpr std::size_t kReal = 18; // the ParticleView's Real arrays, x .. mu

    static std::array<std::vector<Real>*, kReal> real_fields(particles::ParticleSet& s) {
        return {&s.x,   &s.y,    &s.z, &s.vx,   &s.vy,  &s.vz,  &s.ax,  &s.ay, &s.az,
                &s.rho, &s.drho, &s.p, &s.mass, &s.wnx, &s.wny, &s.wnz, &s.wd, &s.mu};
    }
    // The wall geometry (normal and depth, arrays 13 .. 16) is held only where a functor of
    // this case reads or writes it: mDBC, a no-slip wall's viscous terms, the bodies' or the
    // FEM solids' motion.
    // Otherwise it stays on the host (fixed walls keep it; fluid has none), reordered by id
    // when the particles are published: 32 B per particle less.
    bool needs_wall_geometry() const {
        const SphParams& p = host_.params();
        const bool viscous_walls = std::visit(
            [](const auto& v) {
                using V = std::decay_t<decltype(v)>;
                return V::no_slip_walls || V::needs_apparent_viscosity;
            },
            host_.models().viscosity);
        return p.boundary == "mdbc" || viscous_walls || bodies_ != nullptr || fem_ != nullptr;
    }
    bool held(std::size_t field) const { return geometry_ || field < 13 || field > 16; }

    // The host's wall geometry, in the order of `host_ids`, put in the order of the published
    // ids (particles added since: none).
    void reorder_wall_geometry(const std::vector<ParticleId>& host_ids) {
        ParticleId top = 0;
        for (const ParticleId id : set_.id) top = std::max(top, id + 1);
        std::vector<Index> from(std::size_t(top), -1);
        for (std::size_t k = 0; k < host_ids.size(); ++k)
            if (host_ids[k] < top) from[std::size_t(host_ids[k])] = Index(k);
        for (auto* a : {&set_.wnx, &set_.wny, &set_.wnz, &set_.wd}) {
            std::vector<Real> out(set_.id.size(), Real(0));
            for (std::size_t i = 0; i < out.size(); ++i) {
                const Index k = from[std::size_t(set_.id[i])];
                if (k >= 0) out[i] = (*a)[std::size_t(k)];
            }
            a->swap(out);
        }
    }

    static std::array<std::vector<Real>*, 4> old_fields(particles::ParticleSet& s) {
        return {&s.vx_old, &s.vy_old, &s.vz_old, &s.rho_old};
    }

    template <class T> static void upload(Buffer<T>& b, const std::vector<T>& v) {
        b.upload(v.data(), Index(v.size()));
    }
    template <class T> static void download(const Buffer<T>& b, std::vector<T>& v) {
        v.resize(std::size_t(b.size()));
        b.download(v.data());
    }

    // The host's particles, moved into the space once, before the first step.
    void upload_once() {
        if (resident_) return;
        n_ = set_.size();
        geometry_ = needs_wall_geometry();
        auto fields = real_fields(set_);
        for (std::size_t f = 0; f < fields.size(); ++f)
            if (held(f)) upload(real_[f], *fields[f]);
        if (set_.keeps_previous_state()) {
            auto old = old_fields(set_);
            for (std::size_t f = 0; f < old.size(); ++f) upload(old_[f], *old[f]);
        }
        if (sps_) {
            if (set_.sps_tau.size() != 6 * std::size_t(n_))
                set_.sps_tau.assign(6 * std::size_t(n_), Real(0)); // first evaluation
            upload(tau_, set_.sps_tau);
            tau_next_.resize(6 * n_);
        }
        upload(kind_, set_.kind);
        upload(group_, set_.group);
        upload(id_, set_.id);
        if (bodies_) upload(row_, bodies_->rows_of(set_.id));
        if (fem_) {
            fem_->carriers_changed();
            upload(fem_row_, fem_->rows_of(set_.id));
        }
        ++layout_;
        keys_.resize(n_);
        order_.resize(n_);
        start_cells_.resize(keys_count_ + 1);
        resident_ = true;
    }

    particles::ParticleView view() const {
        auto& r = const_cast<std::array<Buffer<Real>, kReal>&>(real_);
        return {r[0].data(),
                r[1].data(),
                r[2].data(),
                r[3].data(),
                r[4].data(),
                r[5].data(),
                r[6].data(),
                r[7].data(),
                r[8].data(),
                r[9].data(),
                r[10].data(),
                r[11].data(),
                r[12].data(),
                r[13].data(),
                r[14].data(),
                r[15].data(),
                r[16].data(),
                r[17].data(),
                const_cast<Buffer<std::uint8_t>&>(kind_).data(),
                const_cast<Buffer<std::int16_t>&>(group_).data(),
                n_};
    }

    StepStart step_start() {
        return {start_[0].data(), start_[1].data(), start_[2].data(), start_[3].data(),
                start_[4].data(), start_[5].data(), start_[6].data()};
    }

    // Keys (cell, class), a stable sort of the indices by key, then each key's first sorted
    // position: the same grid as CellGrid::build's counting sort.
    void build_grid() {
        const auto pv = view();
        keys_.resize(n_);
        order_.resize(n_);
        Space::for_each(n_, neighbors::CellKeys{grid_, pv.x, pv.y, pv.z, 1, pv.kind, keys_.data()});
        sorter_.sort(keys_.data(), n_, keys_count_, order_.data());
        Space::for_each(keys_count_ + 1,
                        CellStarts{keys_.data(), order_.data(), n_, start_cells_.data()});
        grid_.start = start_cells_.data();
        grid_.order = order_.data();
    }

    // Every per-particle array gathered into the grid's order: the Real ones into the Real
    // scratch, which then takes their place, the narrower ones through it (gather_through),
    // the SPS stress into tau_next_; the order becomes the identity.
    void permute() {
        for (std::size_t f = 0; f < kReal; ++f)
            if (held(f)) gather(real_[f], real_scratch(), 1);
        if (set_.keeps_previous_state())
            for (auto& a : old_) gather(a, real_scratch(), 1);
        if (sps_) gather(tau_, tau_next_, 6); // tau_next_ is free between force evaluations
        gather_through(kind_);
        gather_through(group_);
        gather_through(id_);
        if (bodies_) gather_through(row_);
        if (fem_) gather_through(fem_row_);
        ++layout_;
    }
    // The same for an array of a narrower type, through the Real scratch as a carrier of its
    // bytes (gathered there, then copied back): no scratch array of its own.
    template <class T> void gather_through(Buffer<T>& a) {
        Buffer<Real>& carrier = real_scratch();
        carrier.resize(n_);
        Space::for_each(n_, GatherIntoCarrier<T, Real>{a.data(), order_.data(), carrier.data()});
        Space::for_each(n_, FromCarrier<T, Real>{carrier.data(), a.data()});
    }
    template <class T> void gather(Buffer<T>& a, Buffer<T>& scratch, int width) {
        scratch.resize(width * n_);
        Space::for_each(n_, GatherByOrder<T>{a.data(), order_.data(), scratch.data(), width});
        a.swap(scratch);
    }

    // Copies the leavers (keep_[i] = 0) to the host in index order (their masses, and the
    // faces they crossed when `faces` is given), then removes them.
    Leaving remove_leavers(const flow::ExitFaces* faces);
    template <class T> std::vector<T> gather_leavers(const T* values, Index m);

    // Appends `width` values per new particle after the n_ particles held.
    template <class T> void append_tail(Buffer<T>& b, const std::vector<T>& tail, int width);

    // The scratch array of reordering and compaction: the symplectic scheme's copy of x at
    // t_n, which is free then (the particles are reordered in the neighbour search after the
    // corrector and compacted between steps; the predictor writes it whole), and unused by
    // the Verlet scheme.
    Buffer<Real>& real_scratch() { return start_[0]; }

    // Keeps the particles with keep_[i] = 1, in order (stream compaction: an exclusive scan of
    // the flags, then every array scattered to its new place).
    void compact();
    template <class T> void scatter_through(Buffer<T>& a, Index m);
    template <class T> void scatter(Buffer<T>& a, Buffer<T>& scratch, int width, Index m);

    Real max_kinematic_viscosity() const {
        return std::visit(
            [&](const auto& v) {
                if constexpr (std::decay_t<decltype(v)>::needs_apparent_viscosity)
                    return Space::max_of(n_, FluidKinematicViscosity{view()});
                else
                    return Real(v.kinematic_viscosity());
            },
            host_.models().viscosity);
    }

    ParticleState state_at(Index i) const {
        const auto& r = real_;
        return {id_.at(i),
                {r[0].at(i), r[1].at(i), r[2].at(i)},
                {r[3].at(i), r[4].at(i), r[5].at(i)},
                {r[6].at(i), r[7].at(i), r[8].at(i)},
                r[9].at(i),
                kind_.at(i) == std::uint8_t(particles::Kind::fluid)};
    }

    std::size_t sorter_bytes() const { return sorter_.bytes(); }

    SphSolver& host_;
    particles::ParticleSet& set_;
    neighbors::CellGrid config_; // the grid's geometry only; its cells live in start_cells_
    neighbors::GridView grid_{};
    Index keys_count_ = 0, n_ = 0;
    bool sps_ = false, resident_ = false;
    bool geometry_ = true; // the wall geometry is held here (needs_wall_geometry)
    std::array<Buffer<Real>, kReal> real_;
    std::array<Buffer<Real>, 4> old_;   // Verlet: v and rho at t_n-1
    std::array<Buffer<Real>, 7> start_; // symplectic: x, v and rho at t_n
    Buffer<Real> tau_, tau_next_;
    Buffer<Real> grad_rho_; // renormalised density gradients (diffusion "antuono"), each evaluation
    Buffer<Real> ghost_;    // mDBC's no-slip: (v_g - v_b, seen) per particle, each evaluation
    Buffer<std::uint8_t> kind_;
    Buffer<std::int16_t> group_;
    Buffer<ParticleId> id_;
    Buffer<Index> keys_, order_, start_cells_;
    // Stream compaction: the keep flags (in keys_, which only the grid's build uses), the
    // leavers' flags and the scan.
    Buffer<Index>& keep_ = keys_;
    Buffer<Index> leave_, pos_;
    // Rigid bodies: each particle's body-particle row (or -1), and the bodies' fluid side.
    Buffer<std::int32_t> row_;
    std::unique_ptr<ResidentBodies<Space>> bodies_;
    // FEM solids: each particle's carried row (or -1), and the solids' fluid side.
    Buffer<std::int32_t> fem_row_;
    std::unique_ptr<ResidentFem<Space>> fem_;
    std::uint64_t layout_ = 0; // changes when particles are reordered, removed or added
    ResidentFluidReader<Space> reader_{*this}; // the probes' point samples and reductions
    mutable typename Space::Sorter sorter_;
    long sorts_ = 0, copies_ = 0;
    double t_neighbors_ = 0, t_forces_ = 0, t_integrate_ = 0;
};

} // namespace debrisflow::sph

// The members defined outside the class: particles removed, prescribed and added
// (declared above, with what each does).
#include "debrisflow/sph/resident_sph_population.hpp"
