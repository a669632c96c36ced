#include "debrisflow/coupling/sph_dem.hpp"
#include "debrisflow/core/error.hpp"
#include "debrisflow/core/stopwatch.hpp"
#include "debrisflow/exec/parallel.hpp"
#include "debrisflow/kernels/kernel.hpp"
#include <limits>
#include <type_traits>
#include <variant>

namespace debrisflow::coupling {

SphDemCoupling::SphDemCoupling(sph::SphSolver& fluid, dem::DemSolver& dem, std::string drag_law)
    : fluid_(fluid), dem_(dem), drag_law_(std::move(drag_law)) {
    if (!DragRegistry::has(drag_law_))
        throw InputError("unknown drag law \"" + drag_law_ + "\" (" + DragRegistry::choices() +
                         ")");
    if (fluid_.params().dim != 3 || dem_.params().dim != 3)
        throw InputError("the SPH-DEM drag coupling is 3D only (sphere drag laws)");
    dem_.attach_fluid(&load_);
}

time::DtLimit SphDemCoupling::stable_dt() const {
    return {std::numeric_limits<Real>::max(), "none"};
}

std::vector<Exchange> SphDemCoupling::exchanges() const {
    return {{"sph", "dem",
             "fluid pressure gradient, velocity, density and viscosity at the grains, as their "
             "fluid load (dem::FluidLoad: held force, drag rate beta, fluid velocity)",
             When::force_evaluation},
            {"dem", "sph",
             "the fluid load's impulse over the DEM's last advance / dt, to the fluid particles' "
             "accelerations with weights V_j W_ij / S_f",
             When::force_evaluation}};
}

void SphDemCoupling::compute_forces() {
    ScopedTimer timer(t_forces_);
    const std::size_t n = std::size_t(dem_.grains().size());
    load_.resize(n);
    if (load_.time > 0) {
        exec::for_each(Index(n), FluidImpulseHandOver{load_.impulse.data(), load_.handover.data()});
        load_.time = 0;
    }
    if (n == 0) return;
    interpolate();
    apply_reaction();
}

void SphDemCoupling::interpolate() {
    const Real support = fluid_.support();
    const Domain& dom = fluid_.domain();
    particles::ParticleSet& set = fluid_.particles();
    const Index np = set.size();
    // fluid before walls in each cell, as the resident loop's grid lists them
    fluid_grid_.configure(dom.lo, dom.hi, support, 3, dom.periodic);
    fluid_grid_.build(set.x.data(), set.y.data(), set.z.data(), np, 1, set.kind.data());
    dem::GrainSet& grains = dem_.grains();
    const Index ng = grains.size();
    grain_grid_.configure(dom.lo, dom.hi, support, 3, dom.periodic);
    const Real* gp = &grains.pos[0].x;
    grain_grid_.build(gp, gp + 1, gp + 2, ng, 3);
    share_.assign(std::size_t(ng), 0);
    const GrainsInFluid g{grains.pos.data(),
                          grains.vel.data(),
                          grains.radius.data(),
                          grains.inv_mass.data(),
                          ng,
                          load_.force.data(),
                          load_.u.data(),
                          load_.beta.data(),
                          share_.data(),
                          load_.handover.data()};
    const bool has_mu = set.mu.size() == std::size_t(np);
    const Real nu = fluid_.params().nu;
    load_.max_rate = with_models([&](const auto& kernel, auto drag) {
        using K = std::decay_t<decltype(kernel)>;
        return exec::max_of(ng, GrainFluidSample<K, decltype(drag)>{set.view(), fluid_grid_.view(),
                                                                    grain_grid_.view(), g, kernel,
                                                                    nu, has_mu});
    });
}

void SphDemCoupling::apply_reaction() {
    if (step_dt_ <= 0) return; // before the first step: nothing to hand over
    const Index ng = dem_.grains().size();
    reaction_.assign(std::size_t(ng), Vec3{});
    exec::for_each(ng, ReactionPerWeight{load_.handover.data(), share_.data(), 1 / step_dt_,
                                         reaction_.data()});
    particles::ParticleSet& set = fluid_.particles();
    std::visit(
        [&](const auto& kernel) {
            using K = std::decay_t<decltype(kernel)>;
            exec::for_each(set.size(), FluidReactionGather<K>{set.view(), grain_grid_.view(),
                                                              dem_.grains().pos.data(),
                                                              reaction_.data(), kernel});
        },
        fluid_.models().kernel);
}

} // namespace debrisflow::coupling
