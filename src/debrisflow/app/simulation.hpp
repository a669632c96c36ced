#pragma once
#include "debrisflow/app/summary.hpp"
#include "debrisflow/core/log.hpp"
#include "debrisflow/coupling/dem_body.hpp"
#include "debrisflow/coupling/dem_fem.hpp"
#include "debrisflow/coupling/sph_body.hpp"
#include "debrisflow/coupling/sph_dem.hpp"
#include "debrisflow/coupling/sph_fem.hpp"
#include "debrisflow/coupling/step_order.hpp"
#include "debrisflow/dem/dem_solver.hpp"
#include "debrisflow/dem/resident_dem_backend.hpp"
#include "debrisflow/fem/fem_solver.hpp"
#include "debrisflow/flow/domain_exit.hpp"
#include "debrisflow/flow/fluid_inlet.hpp"
#include "debrisflow/flow/grain_feed.hpp"
#include "debrisflow/flow/outlet.hpp"
#include "debrisflow/flow/rock_feed.hpp"
#include "debrisflow/io/case_spec.hpp"
#include "debrisflow/io/vtk_writer.hpp"
#include "debrisflow/probes/design_formulas.hpp"
#include "debrisflow/probes/fluid_reader.hpp"
#include "debrisflow/probes/grain_reader.hpp"
#include "debrisflow/probes/probe.hpp"
#include "debrisflow/rigid/body_solver.hpp"
#include "debrisflow/scenario/grain_bed_load.hpp"
#include "debrisflow/sph/resident_backend.hpp"
#include "debrisflow/sph/sph_solver.hpp"
#include "debrisflow/time/integrator.hpp"
#include <memory>

namespace debrisflow::checkpoint {
class Archive;
}

namespace debrisflow::app {

struct RunOptions {
    std::string out_dir; // empty: no files (tests); probes still sample in memory
    bool quiet = false;
    int threads = 0; // 0: OpenMP default
    Real until = 0;  // stop at this time instead of time.end (0: time.end)
};

// A case assembled from its spec: fluid particles and the SPH phase, grains, geometric walls
// and the DEM phase (each when the case has them), the integrator, gates, probes and output
// observers. Used by the CLI and by the tests.
class Simulation {
public:
    explicit Simulation(io::CaseSpec spec);

    // Runs from the current time (0, or where the previous run stopped) to time.end. On instability
    // the output so far is kept, summary.json is written with status "unstable", and the
    // InstabilityError is rethrown.
    RunReport run(const RunOptions& opt);

    const io::CaseSpec& spec() const { return spec_; }
    particles::ParticleSet& particles() { return set_; }
    sph::SphSolver& solver() { return *solver_; }
    bool has_fluid() const { return solver_ != nullptr; }
    bool has_grains() const { return dem_ != nullptr; }
    dem::DemSolver& grains() { return *dem_; }
    // The deepest overlap the grain blocks' own weight presses into their contacts at t = 0.
    const scenario::BedOverlap& bed_overlap() const { return bed_overlap_; }
    bool has_bodies() const { return rigid_ != nullptr; }
    rigid::BodySolver& bodies() { return *rigid_; }
    // The unresolved SPH-DEM coupling ([dem] fluid_drag), or null.
    coupling::SphDemCoupling* fluid_grain_coupling() { return sph_dem_.get(); }
    // Every coupling of the case (each states its exchanges).
    std::vector<const coupling::Coupling*> couplings() const;
    bool has_fem() const { return fem_ != nullptr; }
    fem::FemSolver& fem() { return *fem_; }
    const std::vector<std::unique_ptr<probes::Probe>>& probes() const { return probes_; }
    probes::Probe& probe(const std::string& name);
    // Memory held by particle data and neighbour lists, in bytes (estimate).
    std::size_t memory_bytes() const;

    // Continues from a checkpoint file (app/simulation_checkpoint.cpp): the next run() starts
    // at its time and step and continues its output folder. CheckpointError (exit 2) when the
    // file is damaged, of another format, or written for another case (a key outside
    // [output] and time.end differs).
    void restore(const std::string& file);
    // Writes OUT/checkpoint/step_<step>.dfc (atomic, the two newest kept); returns its path.
    std::string write_checkpoint(const std::string& out_dir, long step, Real t, Real first_dt);

private:
    // Opens the output folder (app/simulation_log.cpp): log, case.toml, probe files, VTK
    // series (continued after a restore); logs a restart.
    void open_output(const RunOptions& opt);
    // Writes the case, its models and couplings to the log before the first step
    // (app/simulation_log.cpp).
    void log_case(const RunReport& report);
    // The design-formula companions of the measured peak loads, to the log.
    void log_design(const std::vector<probes::DesignCheck>& design);
    // Grains and bodies touch the solids' surface triangles (DEM-FEM contact).
    void couple_fem_to_contacts();
    // Runs the DEM alone, gates closed, until PFC's equilibrium ratio (mean unbalanced force /
    // mean contact force) drops below dem.settle_ratio; then zeroes grain velocities.
    void settle_grains();
    probes::ProbeContext probe_context() {
        const probes::FluidReader* fluid =
            resident_ ? &resident_->fluid_reader() : host_fluid_.get();
        probes::GrainReader* grains =
            resident_dem_ ? &resident_dem_->grain_reader() : host_grains_.get();
        return {solver_.get(), dem_.get(), rigid_.get(), fem_.get(), &domain_exit_, fluid, grains};
    }
    // World positions, velocities, radii and body index of the bodies' contact samples (or
    // vertices) for the VTK output.
    void write_bodies(io::VtkSeries& vtk, Real t) const;
    // Saves or restores the whole state (app/simulation_checkpoint.cpp).
    void state(checkpoint::Archive& ar);

    io::CaseSpec spec_;
    particles::ParticleSet set_;
    std::unique_ptr<sph::SphSolver> solver_;
    // The SPH phase's time loop on a resident backend (exec.backend other than "host"); the
    // solver above then keeps the parameters and the grid the probes read.
    std::unique_ptr<sph::ResidentPhase> resident_;
    std::unique_ptr<probes::FluidReader> host_fluid_; // the probes' view of the host solver's fluid
    dem::GrainSet grains_;
    scenario::BedOverlap bed_overlap_;
    dem::WallSet dem_walls_;
    std::unique_ptr<dem::DemSolver> dem_;
    std::unique_ptr<probes::GrainReader> host_grains_; // the probes' view of the host's grains
    // The DEM phase's time loop on a resident backend (exec.backend other than "host"); the
    // solver above then keeps the parameters, walls, step and counters.
    std::unique_ptr<dem::ResidentDemPhase> resident_dem_;
    std::unique_ptr<rigid::BodySolver> rigid_;
    std::unique_ptr<fem::FemSolver> fem_;
    std::unique_ptr<coupling::SphFemCoupling> sph_fem_; // with a fluid
    std::unique_ptr<coupling::DemFemCoupling> dem_fem_; // with grains or bodies
    std::unique_ptr<coupling::SphDemCoupling> sph_dem_; // grains in a fluid ([dem] fluid_drag)
    std::unique_ptr<time::Phase> resident_sph_dem_; // the same where a resident backend keeps them
    std::unique_ptr<coupling::DemBodyCoupling> dem_body_; // grains and bodies
    std::unique_ptr<coupling::SphBodyCoupling> sph_body_; // bodies in a fluid
    bool settled_ = false;
    std::vector<std::unique_ptr<flow::FluidInlet>> inlets_;
    std::vector<std::unique_ptr<flow::Outlet>> outlets_;
    flow::DomainExit domain_exit_;
    std::vector<std::unique_ptr<flow::GrainFeed>> feeds_;
    std::vector<std::unique_ptr<flow::RockFeed>> rock_feeds_;
    std::vector<std::unique_ptr<probes::Probe>> probes_;
    Log log_;
    Real t_ = 0;
    std::vector<std::uint8_t> wall_removed_; // per wall: a gate already lifted
    std::unique_ptr<io::VtkSeries> vtk_, vtk_grains_, vtk_bodies_, vtk_fem_;
    // A restored run: its step, first dt, thread count and the frames of its VTK series.
    struct Resume {
        bool active = false;
        std::string file;
        long step = 0;
        Real first_dt = 0;
        int threads = 0;
        std::array<io::VtkSeries::Entries, 4> frames;
    } resume_;
};

} // namespace debrisflow::app
