#pragma once
#include "debrisflow/flow/domain_exit.hpp"
#include "debrisflow/io/case_spec.hpp"
#include "debrisflow/probes/design_formulas.hpp"
#include "debrisflow/probes/probe.hpp"
#include "debrisflow/time/integrator.hpp"
#include <memory>
#include <string>
#include <vector>

namespace debrisflow::app {

struct RunReport {
    std::string status = "completed"; // completed | unstable
    std::string message;
    long fluid = 0, boundary = 0, grains = 0, bodies = 0;
    long body_contacts = 0;
    time::DtLimit dem_dt{0, ""};
    long dem_contacts = 0, dem_list_builds = 0;
    int threads = 1;
    time::RunResult result;
    time::DtLimit initial_dt{0, ""};
    long pair_list_builds = 0;
    long fluid_end = 0, grains_end = 0; // at the end (inlets, feeds and outlets change them)
    double particle_steps = 0;    // sum over steps of the particles present (fluid, walls, grains)
    std::size_t pairs = 0;        // half pair list entries at the end (pairs within support + skin)
    std::size_t sph_bytes = 0;    // memory the SPH phase holds at the end (SphSolver::memory_bytes)
    long sph_particles = 0;       // fluid and boundary particles at the end
    long sph_copies_to_host = -1; // a resident backend's copies of the particles to the host
    // A resident DEM phase: bytes in its memory, copies of the grains to and from the host.
    std::size_t dem_bytes = 0;
    long dem_copies_to_host = -1, dem_copies_from_host = -1;
    // FEM solids: nodes, elements, eroded elements, critical step and FEM steps taken.
    long fem_nodes = 0, fem_elements = 0, fem_eroded = 0, fem_substeps = 0;
    double fem_dt = 0;
    // What left the domain and was removed (domain.exit = "remove"), by phase and face.
    flow::ExitTally fluid_exit, grain_exit;
};

// summary.json: counts, steps, times, throughput, timing breakdown and probe peaks/finals.
// `design`: design-formula companions of measured peak wall loads (may be empty).
void write_summary(const std::string& path, const io::CaseSpec& spec, const RunReport& report,
                   const std::vector<std::unique_ptr<probes::Probe>>& probes,
                   const std::vector<probes::DesignCheck>& design = {});

} // namespace debrisflow::app
