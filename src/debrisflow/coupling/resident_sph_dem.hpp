#pragma once
// The unresolved SPH-DEM coupling (coupling/sph_dem.hpp) where a resident backend keeps the
// fluid and the grains (issue #34): the same functors (coupling/sph_dem_k.hpp) on the resident
// SPH phase's particles and cell grid and the resident DEM phase's grains and fluid loads, with
// a cell grid of the grains built there (CellKeys, the space's sort, CellStarts). The host's
// SphDemCoupling keeps the drag law and the scalars (the time the DEM's impulses cover, the
// largest drag rate, the fluid step); the grains' weights and reactions come to it only when
// the phases publish (checkpoints). Bitwise the host's coupling with sph.pair_loop = "cells"
// and dem.contact_pass = "slots", whose particles and grains are in the same order.
#include "debrisflow/core/stopwatch.hpp"
#include "debrisflow/coupling/sph_dem.hpp"
#include "debrisflow/coupling/sph_dem_k.hpp"
#include "debrisflow/dem/resident_dem.hpp"
#include "debrisflow/exec/reorder_k.hpp"
#include "debrisflow/neighbors/cell_grid.hpp"
#include "debrisflow/neighbors/cell_keys_k.hpp"
#include "debrisflow/sph/resident_sph.hpp"
#include <limits>
#include <memory>
#include <stdexcept>
#include <type_traits>
#include <variant>

namespace debrisflow::coupling {

template <class Space> class ResidentSphDem final : public time::Phase {
    template <class T> using Buffer = typename Space::template Buffer<T>;

public:
    ResidentSphDem(SphDemCoupling& host, sph::ResidentSph<Space>& fluid,
                   dem::ResidentDem<Space>& grains)
        : host_(host), fluid_(fluid), grains_(grains) {
        const Domain& dom = host.fluid_.domain();
        config_.configure(dom.lo, dom.hi, host.fluid_.support(), 3, dom.periodic);
        grid_ = config_.view();
        cells_ = Index(config_.cell_count());
    }

    const char* name() const override { return "sph-dem"; }
    void update_neighbors(bool) override {}

    // As SphDemCoupling::compute_forces: the DEM's impulse handed over, the fluid sampled at
    // the grains (their new loads), the reaction added to the fluid's accelerations.
    void compute_forces() override {
        ScopedTimer timer(t_forces_);
        dem::FluidLoad& load = host_.load_;
        const Index n = grains_.n_;
        if (load.time > 0) {
            Space::for_each(
                n, FluidImpulseHandOver{grains_.fl_impulse_.data(), grains_.fl_handover_.data()});
            load.time = 0;
        }
        if (n == 0) return;
        build_grain_grid();
        share_.resize(n);
        const GrainsInFluid g = grains();
        const auto pv = fluid_.view();
        const bool has_mu = fluid_.real_[17].size() == fluid_.n_;
        const Real nu = host_.fluid_.params().nu;
        load.max_rate = host_.with_models([&](const auto& kernel, auto drag) {
            using K = std::decay_t<decltype(kernel)>;
            return Space::max_of(n, GrainFluidSample<K, decltype(drag)>{pv, fluid_.grid_, grid_, g,
                                                                        kernel, nu, has_mu});
        });
        if (host_.step_dt_ > 0) { // before the first step: nothing to hand over
            reaction_.resize(n);
            Space::for_each(
                n, ReactionPerWeight{g.handover, g.share, 1 / host_.step_dt_, reaction_.data()});
            std::visit(
                [&](const auto& kernel) {
                    using K = std::decay_t<decltype(kernel)>;
                    Space::for_each(fluid_.n_, FluidReactionGather<K>{pv, grid_, g.pos,
                                                                      reaction_.data(), kernel});
                },
                host_.fluid_.models().kernel);
        }
        Space::synchronize();
    }

    // The fluid step in progress, as the host's coupling remembers it.
    void predictor(Real dt) override { host_.step_dt_ = dt; }
    void corrector(Real) override {}
    void verlet_step(Real dt, bool) override { host_.step_dt_ = dt; }
    time::DtLimit stable_dt() const override { return {std::numeric_limits<Real>::max(), "none"}; }
    void check_health(Real) const override {}
    void add_timings(time::Timings& t) const override { t.forces += t_forces_; }

    // The weights and reactions of the last evaluation to the host's coupling (checkpoints).
    void publish() override {
        const auto down = [](const auto& from, auto& to) {
            to.resize(std::size_t(from.size()));
            from.download(to.data());
        };
        down(share_, host_.share_);
        if (host_.step_dt_ > 0) down(reaction_, host_.reaction_);
    }

private:
    GrainsInFluid grains() {
        auto& d = grains_;
        return {d.pos_.data(), d.vel_.data(),        d.radius_.data(), d.inv_mass_.data(),
                d.n_,          d.fl_force_.data(),   d.fl_u_.data(),   d.fl_beta_.data(),
                share_.data(), d.fl_handover_.data()};
    }

    // The grains in cells of the kernel support (CellGrid::build's counting sort, as the
    // host's coupling builds it).
    void build_grain_grid() {
        const Index n = grains_.n_;
        keys_.resize(n);
        order_.resize(n);
        starts_.resize(cells_ + 1);
        const Real* p = &grains_.pos_.data()[0].x;
        Space::for_each(n, neighbors::CellKeys{grid_, p, p + 1, p + 2, 3, nullptr, keys_.data()});
        sorter_.sort(keys_.data(), n, cells_, order_.data());
        Space::for_each(cells_ + 1,
                        exec::CellStarts{keys_.data(), order_.data(), n, starts_.data()});
        grid_.start = starts_.data();
        grid_.order = order_.data();
    }

    SphDemCoupling& host_;
    sph::ResidentSph<Space>& fluid_;
    dem::ResidentDem<Space>& grains_;
    neighbors::CellGrid config_; // the grains' grid geometry; its cells live in starts_
    neighbors::GridView grid_{};
    Index cells_ = 0;
    Buffer<Index> keys_, order_, starts_;
    typename Space::Sorter sorter_;
    Buffer<Real> share_;    // S_f per grain
    Buffer<Vec3> reaction_; // -F_i / S_f per grain
    double t_forces_ = 0;
};

} // namespace debrisflow::coupling

namespace debrisflow::dem {

template <class Space>
std::unique_ptr<time::Phase> ResidentDem<Space>::couple_fluid(sph::ResidentPhase& fluid,
                                                              coupling::SphDemCoupling& coupling) {
    auto* same = dynamic_cast<sph::ResidentSph<Space>*>(&fluid);
    if (!same) throw std::logic_error("resident SPH-DEM: the fluid runs on another backend");
    return std::make_unique<coupling::ResidentSphDem<Space>>(coupling, *same, *this);
}

} // namespace debrisflow::dem
