#pragma once
#include "debrisflow/core/domain.hpp"
#include "debrisflow/exec/pair_scatter.hpp"
#include "debrisflow/models/eos_tait_k.hpp"
#include "debrisflow/neighbors/cell_grid.hpp"
#include "debrisflow/neighbors/pair_list.hpp"
#include "debrisflow/particles/particle_set.hpp"
#include "debrisflow/sph/no_slip_wall_k.hpp"
#include "debrisflow/sph/sph_models.hpp"
#include "debrisflow/time/phase.hpp"
#include <vector>

namespace debrisflow::checkpoint {
class Archive;
}

namespace debrisflow::sph {

struct StepStart;
template <class Kernel, class Viscosity, class Diffusion> struct PairTerms;

// The axis-aligned simulation box; particles leaving a non-periodic side stop the run.
// Weakly-compressible SPH phase: DBC boundaries, Tait EOS, selectable kernel, viscosity and
// density diffusion. Advanced by the Integrator's symplectic predictor-corrector.
class SphSolver : public time::Phase {
public:
    SphSolver(const SphParams& params, particles::ParticleSet& set, const Domain& domain);

    const char* name() const override { return "sph"; }
    void update_neighbors(bool reorder) override;
    void compute_forces() override;
    void predictor(Real dt) override;
    void corrector(Real dt) override;
    void verlet_step(Real dt, bool euler) override;
    time::DtLimit stable_dt() const override;
    void check_health(Real t) const override;
    void add_timings(time::Timings& t) const override;

    const SphParams& params() const { return params_; }
    const models::TaitEos& eos() const { return eos_; }
    const neighbors::CellGrid& grid() const { return grid_; }
    const SphModels& models() const { return models_; }
    const Domain& domain() const { return domain_; }
    particles::ParticleSet& particles() { return set_; }
    const particles::ParticleSet& particles() const { return set_; }
    // Removes all boundary particles of wall group `group` (a gate lifting).
    void remove_group(std::int16_t group);
    // Removes the particles with keep[i] == 0 (an outlet).
    void remove_particles(const std::vector<std::uint8_t>& keep);
    // Pair-list statistics: builds so far (the gather loop: sorts by cell), pairs in the list,
    // kernel support.
    long list_builds() const { return list_builds_; }
    const neighbors::PairList& pair_list() const { return list_; }
    Real support() const { return support_; }
    // Bytes the SPH phase holds allocated: the particle arrays, the cell grid, the pair list
    // and its scatter buffers, and the solver's own per-particle arrays.
    std::size_t memory_bytes() const;
    // Force evaluation by the gather loop over the cell grid (the GPU layout); the scatter
    // loop over the half pair list (compute_forces) must give the same result.
    void compute_forces_gather();
    // Hands f the gather loop body for the case's models and this state (pressures and
    // apparent viscosities updated), a FluidInteraction<K, V, D> to run for i = 0 .. n-1 (on
    // the host by compute_forces_gather, on a GPU by bench/gpu); then takes the SPS stresses
    // it wrote as the particles'. Defined in sph_solver_gather.hpp.
    template <class F> void with_gather(F&& f);
    // Initial time-step estimate from the parameters alone (before any motion).
    time::DtLimit initial_dt() const;
    // Saves or restores the particles and the pair list's reference positions; a restored
    // solver rebuilds its pair list at those positions, the list the saved run was using
    // (sph/sph_checkpoint.cpp).
    void state(checkpoint::Archive& ar);

    // The density below which a boundary particle is not allowed to fall (the pressure
    // sph.boundary_min_pressure; DBC's clamp).
    Real boundary_min_density() const;
    // The wall velocity the viscous terms see: Morris's extrapolation, or with
    // sph.no_slip = "mdbc" the ghost-node velocities of the last update_boundary_density.
    NoSlipWall no_slip_wall() const;
    // Laminar+SPS constants (C_s dp)^2 and 2/3 C_I dp^2 (zeros for other viscosities).
    struct SpsConstants {
        Real smag = 0, blin = 0;
    };
    SpsConstants sps_constants() const;
    // The pair terms of models (K, V, D) on the particles of pv: p / rho^2, c and m / rho read
    // from the arrays given or, where null, computed where a side is loaded; tau the SPS stress
    // of the last evaluation or null (sph_solver_gather.hpp).
    template <class K, class V, class D>
    PairTerms<K, V, D> pair_terms(const particles::ParticleView& pv, const K& kernel, const V& visc,
                                  const D& diff, const Real* prho, const Real* cs, const Real* vol,
                                  const Real* tau) const;
    // Sorts the particles into the cell grid again (after a resident phase has changed them,
    // for the probes that interpolate on the grid).
    void rebuild_grid() { build_grid(); }

private:
    // Sorts the particles into the cell grid (fluid before walls in each cell for the gather).
    void build_grid();
    // Pressures; with `arrays` also p / rho^2, sound speed and volume per particle (the half
    // list's pair loop reads them; the gather computes them where it loads a particle).
    void update_pressure(bool arrays);
    // mDBC: every boundary particle with wall geometry takes the density mirrored from the
    // fluid at its ghost node (MdbcDensity); run before the pressures of a force evaluation.
    void update_boundary_density();
    // The list path's mDBC rows: boundary particles whose ghost node may see fluid before the
    // next list build (boundary_density.cpp).
    void refresh_mdbc_rows();
    // Per-particle apparent viscosity (generalised-Newtonian models; constant otherwise).
    // Apparent viscosities of a generalised-Newtonian fluid: over the half pair list (`pairs`)
    // or by a per-particle gather over the cell grid.
    void update_viscosity(bool pairs);
    // Renormalised density gradients of the fluid particles into grad_rho_, over the half pair
    // list (`pairs`) or by a gather over the cell grid (diffusion models with
    // needs_density_gradient).
    void update_density_gradient(bool pairs);
    // The half list's pass of update_density_gradient, with 5 sums per particle in 2D, 9 in 3D.
    template <int Dim, class K> void density_gradient_over_pairs(const K& kernel);
    // Largest kinematic viscosity now (the viscous time-step limit).
    Real max_kinematic_viscosity() const;
    // Updates pressures (and SPS stresses) and calls f(PairTerms<K, V, D>) for the case's models.
    template <class F> void with_pair_terms(F&& f, bool pairs);
    Real max_displacement() const;
    // The symplectic scheme's saved state at t_n (x0_ ... rho0_).
    StepStart step_start();
    SphParams params_;
    particles::ParticleSet& set_;
    Domain domain_;
    models::TaitEos eos_;
    SphModels models_;
    neighbors::CellGrid grid_;
    std::vector<Real> prho_, cs_, vol_;
    std::vector<Real> tau_next_; // SPS stress of the gather loop, swapped in after it
    std::vector<Real> grad_rho_; // renormalised density gradients (diffusion "antuono")
    // sph.no_slip = "mdbc": per particle v_ghost - v_b and whether the ghost saw fluid (4 per
    // particle; written by update_boundary_density, read in the same force evaluation)
    std::vector<Real> ghost_velocity_;
    std::vector<Index> mdbc_rows_;
    long mdbc_rows_builds_ = -1;
    std::uint64_t mdbc_rows_layout_ = 0;
    neighbors::PairList list_;
    exec::ScatterBuffers buffers_;
    std::vector<Real> xref_, yref_, zref_; // positions at the last pair-list build
    Real support_ = 0, skin_ = 0;
    bool list_valid_ = false;
    long list_builds_ = 0;
    std::vector<Real> x0_, y0_, z0_, vx0_, vy0_, vz0_, rho0_; // state at t_n (predictor)
    double t_neighbors_ = 0, t_forces_ = 0, t_integrate_ = 0;
};

} // namespace debrisflow::sph
