#pragma once
#include "debrisflow/coupling/coupling.hpp"
#include "debrisflow/coupling/drag_laws_k.hpp"
#include "debrisflow/coupling/sph_dem_k.hpp"
#include "debrisflow/dem/dem_solver.hpp"
#include "debrisflow/dem/fluid_load.hpp"
#include "debrisflow/neighbors/cell_grid.hpp"
#include "debrisflow/sph/sph_solver.hpp"
#include "debrisflow/time/phase.hpp"
#include <string>
#include <variant>
#include <vector>

namespace debrisflow::checkpoint {
class Archive;
}

namespace debrisflow::coupling {

// Unresolved SPH-DEM coupling for grains smaller than the kernel (smoothed fields as Robinson,
// Ramaioli & Luding 2014; drag by a chosen law). At each grain i the SPH fields are
// interpolated with the fluid's kernel W (V_j = m_j / rho_j):
//   fluid and wall shares   S_f = sum_fluid V_j W_ij,   S_b = sum_boundary V_j W_ij
//   submerged fraction      phi = min(1, S_f / (1 - min(S_b, 0.9)))
//   fluid velocity, density u = sum_fluid V_j v_j W_ij / S_f,  rho_f = sum_fluid m_j W_ij / S_f
//   pressure gradient       grad p = L^-1 sum_all V_j (p_j - p_i) grad W_ij (Bonet & Lok 1999)
//   fluid fraction          eps = 1 - sum_k V_k W_ik over the grains (clamped to >= 0.2)
// and the grain feels F = -phi V_i grad p + phi beta (u - v_i) (beta from the drag law with the
// slip of this evaluation; the DEM evaluates the drag with the grain's velocity at every
// sub-step). The reaction, the impulse the DEM recorded over its last advance divided by the
// fluid step that follows, goes to the fluid particles around the grain with weights
// V_j W_ij / S_f, so the exchanged momentum balances exactly (one fluid step behind, with the
// symplectic scheme). The fluid equations are not
// volume-averaged: the fluid does not see the room the grains take, which holds for dilute
// mixtures. 3D only (sphere drag laws).
class SphDemCoupling : public time::Phase, public Coupling {
public:
    SphDemCoupling(sph::SphSolver& fluid, dem::DemSolver& dem, std::string drag_law);

    const char* name() const override { return "sph-dem"; }
    const char* coupling_name() const override { return "sph-dem"; }
    std::vector<Exchange> exchanges() const override;
    void update_neighbors(bool) override {}
    // Collects the reaction of the last DEM advance, interpolates the fluid at the grains
    // (their new loads) and adds the reaction to the fluid particles' accelerations. Runs after
    // the SPH and DEM force evaluations.
    void compute_forces() override;
    // Remembers the step the fluid is about to take: the reaction is handed over in it.
    void predictor(Real dt) override { step_dt_ = dt; }
    void corrector(Real) override {}
    // Verlet scheme: the fluid has just taken its step with the reaction already in its
    // accelerations; the next step's dt is not known yet, so the reaction is spread over this
    // one's (exact while dt holds, as it does under a CFL limit that does not move much).
    void verlet_step(Real dt, bool) override { step_dt_ = dt; }
    time::DtLimit stable_dt() const override;
    void check_health(Real) const override {}
    void add_timings(time::Timings& t) const override { t.forces += t_forces_; }

    const dem::FluidLoad& load() const { return load_; }
    const std::string& drag_law() const { return drag_law_; }

    // Saves or restores the grains' fluid loads and the reaction's weights
    // (coupling/coupling_checkpoint.cpp).
    void state(checkpoint::Archive& ar);

    // Calls f(kernel, Drag{}) with the fluid's kernel and the chosen drag law; returns its
    // result (GrainFluidSample is made for these two).
    template <class F> Real with_models(F&& f) const {
        Real out = 0;
        std::visit(
            [&](const auto& kernel_model) {
                // A copy captured by value: clang 14 rejects the enclosing generic lambda's
                // parameter inside the nested lambda below.
                const auto kernel = kernel_model;
                DragRegistry::visit_name(drag_law_,
                                         [&, kernel]<class Drag>() { out = f(kernel, Drag{}); });
            },
            fluid_.models().kernel);
        return out;
    }

private:
    template <class Space> friend class ResidentSphDem;
    void interpolate();
    void apply_reaction();

    sph::SphSolver& fluid_;
    dem::DemSolver& dem_;
    std::string drag_law_;
    dem::FluidLoad load_;
    neighbors::CellGrid fluid_grid_, grain_grid_;
    std::vector<Real> share_;    // S_f per grain (weights of the reaction)
    std::vector<Vec3> reaction_; // -F_i / S_f per grain: the reaction per unit weight
    Real step_dt_ = 0;           // the fluid step in progress [s]
    double t_forces_ = 0;
};

} // namespace debrisflow::coupling
