// The resident SPH loop (sph/resident_sph.hpp: every particle array in the backend's memory,
// every part of a step through the backend's primitives) run on the host's memory and threads
// (exec.backend = "host_resident", exec/host_space.hpp) against the host solver with the same
// pair visit (sph.pair_loop = "cells"), on whole cases: issue #33 asks that everything of the
// CUDA backend but the CUDA runtime be exercised in CI. Both runs launch the same functors in
// the same pair order, so they agree to round-off (bound 1e-10 relative, the issue's); they
// measured bitwise equal when the test was written (2026-12-04).
#include "probe_difference.hpp"
#include "run_case.hpp"
#include <filesystem>
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <map>

using namespace debrisflow;

namespace {

struct State {
    std::map<ParticleId, std::array<double, 8>> particles; // x, y, z, vx, vy, vz, rho, p
    std::map<std::uint32_t, std::array<Vec3, 4>> grains;   // x, v, spin, force (SPH-DEM cases)
    test::ProbeHistories probes;
    long steps = 0;
    Index count = 0;
    std::array<long, 6> exits{}; // fluid particles that left, by face
    long copies_to_host = -1;    // the resident SPH phase's copies of the particles
    long grain_copies = -1;      // the resident DEM phase's copies of the grains
    double vmax = 0;
    long fem_eroded = 0;  // FEM elements eroded by the end
    long ids_claimed = 0; // particle ids claimed during the run (inlets, exposed surfaces)
};

State run(const std::string& file, std::vector<std::string> sets, const std::string& backend,
          Real until) {
    sets.push_back("sph.pair_loop=\"cells\"");
    sets.push_back(fmt::format("exec.backend=\"{}\"", backend));
    app::Simulation sim(io::read_case(std::string(DEBRISFLOW_SOURCE_DIR) + "/" + file, sets));
    const auto top_id = [&sim] {
        ParticleId top = 0;
        for (const ParticleId id : sim.particles().id) top = std::max(top, id + 1);
        return top;
    };
    const ParticleId top_before = top_id();
    const auto report = sim.run({"", true, 0, until});
    State s;
    s.fem_eroded = report.fem_eroded;
    s.ids_claimed = long(top_id() - top_before);
    s.steps = report.result.steps;
    s.exits = report.fluid_exit.count;
    s.copies_to_host = report.sph_copies_to_host;
    s.grain_copies = report.dem_copies_to_host;
    const auto& p = sim.particles();
    s.count = p.size();
    for (Index i = 0; i < p.size(); ++i) {
        s.particles[p.id[i]] = {p.x[i],  p.y[i],  p.z[i],   p.vx[i],
                                p.vy[i], p.vz[i], p.rho[i], p.p[i]};
        s.vmax = std::max(s.vmax, std::hypot(p.vx[i], p.vy[i], p.vz[i]));
    }
    if (sim.has_grains()) {
        const auto& g = sim.grains().grains();
        for (Index i = 0; i < g.size(); ++i) {
            const auto k = std::size_t(i);
            s.grains[g.id[k]] = {g.pos[k], g.vel[k], g.spin[k], g.force[k]};
        }
    }
    for (const auto& pr : sim.probes()) s.probes.push_back(pr->history());
    return s;
}

// Largest differences over every particle (fluid and walls, by persistent id): positions in
// dp, velocities against the largest speed, densities against rho0, pressures against the
// largest; and over the probe samples against each column's largest magnitude.
// `resident_copies`, `grain_copies`: where given, the resident run's copies of the particles and
// of the grains to the host.
// `host_state`: where given, the host run's state.
void check(const std::string& file, const std::vector<std::string>& sets, Real until, double dp,
           double rho0, long* resident_copies = nullptr, long* grain_copies = nullptr,
           State* host_state = nullptr) {
    const State host = run(file, sets, "host", until);
    const State resident = run(file, sets, "host_resident", until);
    if (host_state) *host_state = host;
    if (resident_copies) *resident_copies = resident.copies_to_host;
    if (grain_copies) *grain_copies = resident.grain_copies;
    ASSERT_EQ(host.steps, resident.steps);
    ASSERT_EQ(host.count, resident.count);
    EXPECT_EQ(host.fem_eroded, resident.fem_eroded);
    EXPECT_EQ(host.ids_claimed, resident.ids_claimed);
    EXPECT_EQ(host.exits, resident.exits);
    ASSERT_EQ(host.probes.size(), resident.probes.size());
    for (std::size_t k = 0; k < host.probes.size(); ++k)
        ASSERT_EQ(host.probes[k].size(), resident.probes[k].size());
    double dx = 0, dv = 0, drho = 0, dpress = 0, pmax = 0;
    for (const auto& [id, s] : host.particles) pmax = std::max(pmax, std::abs(s[7]));
    for (const auto& [id, s] : host.particles) {
        const auto it = resident.particles.find(id);
        ASSERT_NE(it, resident.particles.end()) << "particle id " << id << " missing";
        const auto& t = it->second;
        dx = std::max(dx, std::hypot(s[0] - t[0], s[1] - t[1], s[2] - t[2]) / dp);
        dv = std::max(dv, std::hypot(s[3] - t[3], s[4] - t[4], s[5] - t[5]) / host.vmax);
        drho = std::max(drho, std::abs(s[6] - t[6]) / rho0);
        dpress = std::max(dpress, std::abs(s[7] - t[7]) / pmax);
    }
    // grains (SPH-DEM): positions in dp, the rest against their largest values
    ASSERT_EQ(host.grains.size(), resident.grains.size());
    std::array<double, 4> gmax{}, dgrain{};
    for (const auto& [id, g] : host.grains)
        for (int q = 0; q < 4; ++q) gmax[q] = std::max(gmax[q], double(norm(g[q])));
    for (const auto& [id, g] : host.grains) {
        const auto it = resident.grains.find(id);
        ASSERT_NE(it, resident.grains.end()) << "grain id " << id << " missing";
        for (int q = 0; q < 4; ++q)
            dgrain[q] = std::max(dgrain[q], double(norm(g[q] - it->second[q])) /
                                                (q == 0 ? dp : std::max(gmax[q], 1e-300)));
    }
    const double dprobe = test::probe_difference(host.probes, resident.probes);
    std::cout << fmt::format("{}: {} steps, {} particles; largest differences: position {:.2e} "
                             "dp, velocity {:.2e}, density {:.2e} rho0, pressure {:.2e}, probes "
                             "{:.2e}\n",
                             file, host.steps, host.count, dx, dv, drho, dpress, dprobe);
    // Source: issue #33, "within 1e-10 relative where the pair order is the same".
    EXPECT_LE(dx, 1e-10);
    EXPECT_LE(dv, 1e-10);
    EXPECT_LE(drho, 1e-10);
    EXPECT_LE(dpress, 1e-10);
    EXPECT_LE(dprobe, 1e-10);
    if (host.grains.empty()) return;
    std::cout << fmt::format("{} grains; largest differences: position {:.2e} dp, velocity "
                             "{:.2e}, spin {:.2e}, force {:.2e}\n",
                             host.grains.size(), dgrain[0], dgrain[1], dgrain[2], dgrain[3]);
    for (double d : dgrain) EXPECT_LE(d, 1e-10);
}

} // namespace

// DualSPHysics's CaseDambreak in 3D: wall pairs, cubic spline, Fourtakas, 0.05 s.
TEST(ResidentBackend, DamBreak3D) {
    check("cases/bench/dambreak3d.toml", {"dp=0.034"}, 0.05, 0.034, 1000);
}

// Periodic channel with Laminar+SPS: the lagged SPS stress carried and reordered with the
// particles, periodic separations in the grid's stencil.
TEST(ResidentBackend, ChannelLaminarSps) {
    check("cases/bench/channel_sph.toml", {}, 0.05, 0.02, 1000);
}

// A gate removed at 0.05 s and a surge leaving the domain through its end (domain.exit =
// "remove"): both removed by stream compaction where the particles are, the leavers' faces
// and masses copied to the host's tally.
TEST(ResidentBackend, GateAndDomainExit) {
    check("cases/validation/gate_exit2d.toml", {"output.vtk=false"}, 0.6, 0.01, 1000);
}

// The gate case fed by an inlet and drained by an outlet: the buffer's state prescribed and
// its new layers appended where the particles are (ids claimed from the host's set), the
// outlet's fluid removed by stream compaction and its masses tallied on the host. The inlet's
// and outlet's probes (mass in, mass out) are among the probes compared.
TEST(ResidentBackend, GateInletOutlet) {
    check("cases/validation/gate_inlet_outlet2d.toml", {"output.vtk=false"}, 0.6, 0.01, 1000);
}

// The same with the Verlet scheme (the buffer's state at t_n-1 prescribed and appended too).
TEST(ResidentBackend, InletOutletVerlet) {
    check("cases/validation/gate_inlet_outlet2d.toml",
          {"output.vtk=false", "time.scheme=\"verlet\""}, 0.3, 0.01, 1000);
}

// Water against an elastic wall (SPH-FEM): the wall's carried boundary particles moved from the
// nodes where the particles are (twice a step), their loads compacted in index order and handed
// to the nodes on the host. The tip's displacement and the water's load are among the probes
// compared; the particles are copied to the host once, at the end.
TEST(ResidentBackend, WaterOnAnElasticWall) {
    long copies = -1;
    check("cases/fem/water_on_elastic_wall2d.toml", {"dp=0.01", "output.vtk=false"}, 0.1, 0.01,
          1000, &copies);
    EXPECT_EQ(copies, 1);
}

// The same wall made three times thicker and soft enough to erode (E = 2 MPa, erosion at a
// principal strain of 0.005): eroded elements' particles removed by compaction where the
// particles are, the exposed surface's new particles appended there with their rows (ids
// claimed from the host's set), and every survivor's normal and depth set from the new
// surface. The run must erode elements and expose new particles, or the test proves nothing.
TEST(ResidentBackend, ErodingElasticWall) {
    State host;
    check("cases/fem/water_on_elastic_wall2d.toml",
          {"dp=0.01", "output.vtk=false", "fem_material.0.youngs_modulus=2e6",
           "fem_material.0.erosion_strain=0.005", "solid.0.max=[0.38,0.4]",
           "solid.0.divisions=[8,40]", "wall.0.max=[0.6,0.45]", "domain.max=[0.7,0.6]"},
          0.15, 0.01, 1000, nullptr, nullptr, &host);
    EXPECT_GE(host.fem_eroded, 5);
    EXPECT_GE(host.ids_claimed, 1);
}

// A floating box (Archimedes draft): the body's fluid force and moment reduced where the
// particles are (sorted by body, a segmented sum in index order), the 6-DOF update on the host,
// the box's particles moved where they are. The body probe is among the probes compared.
TEST(ResidentBackend, FloatingBox) {
    check("cases/rigid/floating_box2d.toml", {"output.vtk=false"}, 0.3, 0.01, 1000);
}

// Three bodies (a sphere, a clump and a block) in a 3D dam break at a coarse dp, the reservoir
// lengthened to the sphere and the bodies moved closer, so that within 0.1 s the sphere and the
// clump are hit, roll and turn while the block still rests: the loads of several bodies
// reduced in one segmented sum, their contacts with the walls on the host.
TEST(ResidentBackend, BouldersDamBreak3D) {
    check("cases/rigid/boulders_dambreak.toml",
          {"dp=0.04", "output.vtk=false", "fluid.0.max=[1.3,0.4,0.5]", "wall.1.min=[1.3,0.0,0.0]",
           "wall.1.max=[1.36,0.4,0.7]",
           "body.1.spheres=[[1.50,0.12,0.05,0.05],[1.57,0.15,0.06,0.06],[1.63,0.2,0.045,0.045]]",
           "body.2.min=[1.70,0.22,0.0]", "body.2.max=[1.84,0.32,0.08]"},
          0.1, 0.04, 1000);
}

// A block carried by the surge into an outlet, which removes it with its particles (where they
// are) and the water; the probes that select particles (pressure map, hazard map, flow
// section, run-up, discharge, deposit) read their rows, sorted by id on both backends.
TEST(ResidentBackend, BodyIntoOutletAndRowProbes) {
    check("cases/validation/gate_body_outlet2d.toml", {"output.vtk=false"}, 0.6, 0.01, 1000);
}

// The reduced slit check dam fed with rocks from a hopper (two placed by 0.15 s): the rows
// of the particles near the hopper read where they are (is there room for a rock?), each new
// rock's shell appended there with its body rows, the rows' id map kept by the host's coupling.
TEST(ResidentBackend, RockFeed) {
    check("cases/papers/slit_check_dam_reduced.toml", {"output.vtk=false"}, 0.15, 0.02, 1000);
}

// The demo case (Lobovsky dam break) with the Verlet scheme: the state at t_n-1 resident too.
TEST(ResidentBackend, DamBreakVerlet) {
    check("cases/dambreak2d.toml", {"dp=0.015", "time.scheme=\"verlet\"", "output.vtk=false"}, 0.3,
          0.015, 1000);
}

// A Bingham slurry (apparent viscosity gathered per particle, the viscous step limit reduced
// over the particles' viscosities).
TEST(ResidentBackend, BinghamCollapse) {
    check("cases/validation/viscous_collapse2d.toml",
          {"sph.viscosity=\"bingham\"", "sph.consistency=10", "sph.yield_stress=20",
           "sph.regularization=10", "dp=0.005", "output.vtk=false"},
          0.05, 0.005, 1000);
}

// Grains in water with their unresolved coupling (issue #34: "SPH + DEM cases run with both
// phases on the device"): both resident phases and the coupling between them
// (coupling/resident_sph_dem.hpp: the fluid sampled at the grains over the resident grid, the
// DEM's impulse handed back to the fluid) against the host's loops in the same layouts. The
// benchmark tank at dp = 20 mm (8,000 fluid particles) with 800 sand grains of 3 mm packed
// above its floor, Di Felice drag, 170 fluid steps (each sub-cycled by the DEM), 511 contacts
// at the end; bitwise equal when written (2026-12-05).
TEST(ResidentBackend, GrainsInWater) {
    long copies = -1, grain_copies = -1;
    check("cases/bench/sph_dem_tank.toml",
          {"dp=0.02", "grains.0.count=800",
           "grains.0.region={shape=\"box\", min=[0.1,0.1,0.0], max=[0.16,0.16,0.03]}",
           "dem.contact_pass=\"slots\""},
          0.05, 0.02, 1000, &copies, &grain_copies);
    // The grains' energy probe samples 11 times where the grains are (GrainReader::sums): it
    // brings back its three numbers, neither the fluid nor the grains, whose one copy to the
    // host each is the end's.
    EXPECT_EQ(copies, 1);
    EXPECT_EQ(grain_copies, 1);
}

// The retaining dam (SPH-DEM-FEM, section D of seed_experiments.md) with every coupling on the
// resident loops: slurry and rocks (their drag coupling where both are), the slurry on the dam's
// carried boundary particles, the rocks on its surface triangles. Reduced to 0.12 s: the dam
// moved up to the debris (its toe at x = 8 m), 720 rocks next to it, the debris released at
// 3 m/s towards it. Both the slurry's and the rocks' loads on the dam must be non-zero by the
// end, or the test proves nothing; the dam's load by source, its crest's displacement and its
// face's load by height are among the probes compared.
TEST(ResidentBackend, RetainingDamSphDemFem) {
    long copies = -1, grain_copies = -1;
    State host;
    check("cases/papers/retaining_dam.toml",
          {"output.vtk=false", "solid.0.origin=[8.0,0.0,0.0]", "grains.0.region.min=[5.5,0.25,0.2]",
           "grains.0.region.max=[7.96,5.75,1.75]", "grains.0.velocity=[3,0,0]",
           "fluid.0.velocity=[3,0,0]", "probe.3.min=[7.0,0.0,-0.1]", "probe.3.max=[8.0,6.0,6.0]",
           "dem.contact_pass=\"slots\""},
          0.12, 0.25, 1000, &copies, &grain_copies, &host);
    EXPECT_EQ(copies, 1);
    EXPECT_EQ(grain_copies, 1);
    // probe 1, dam_load: time, then fluid (Fx, Fy, Fz, |F|), grains (Fx, Fy, Fz, |F|), ...
    ASSERT_GE(host.probes.size(), 2u);
    ASSERT_FALSE(host.probes[1].empty());
    const auto& last = host.probes[1].back();
    ASSERT_GE(last.size(), 9u);
    EXPECT_GT(last[4], 1e4); // N: the slurry's load
    EXPECT_GT(last[8], 1e4); // N: the rocks' load
}

// mDBC walls: the ghost-node densities where the particles are, before the pressures.
TEST(ResidentBackend, DamBreakMdbc) {
    check("cases/dambreak2d.toml", {"sph.boundary=\"mdbc\"", "dp=0.015", "output.vtk=false"}, 0.3,
          0.015, 1000);
}

// Antuono's delta-SPH diffusion: the renormalised density gradients computed where the
// particles are, in their own pass before the pair terms.
TEST(ResidentBackend, DamBreakAntuono) {
    check("cases/dambreak2d.toml", {"sph.diffusion=\"antuono\"", "dp=0.015", "output.vtk=false"},
          0.3, 0.015, 1000);
}

// mDBC's no-slip with a Bingham slurry: the ghost-node velocities, held where the particles
// are, in the apparent viscosity's strain rate and in the viscous pair term.
TEST(ResidentBackend, BinghamCollapseMdbcNoSlip) {
    check("cases/validation/viscous_collapse2d.toml",
          {"sph.boundary=\"mdbc\"", "sph.no_slip=\"mdbc\"", "sph.viscosity=\"bingham\"",
           "sph.consistency=10", "sph.yield_stress=20", "sph.regularization=10", "dp=0.005",
           "output.vtk=false"},
          0.05, 0.005, 1000);
}

// Probes read the fluid through its reader (point samples, reductions, the rows they select)
// where the particles are: without frames, the particles are copied to the host once, at the
// end; each VTK frame copies them (issue #33: copies only for what is scheduled).
TEST(ResidentBackend, ProbesDoNotCopyTheParticles) {
    const auto copies = [](const std::vector<std::string>& extra, const std::string& out,
                           const std::string& file = "cases/bench/dambreak3d.toml") {
        std::vector<std::string> sets = {"exec.backend=\"host_resident\""};
        if (file == "cases/bench/dambreak3d.toml") sets.push_back("dp=0.034");
        sets.insert(sets.end(), extra.begin(), extra.end());
        app::Simulation sim(io::read_case(std::string(DEBRISFLOW_SOURCE_DIR) + "/" + file, sets));
        const auto report = sim.run({out, true, 0, 0.05});
        EXPECT_FALSE(sim.probes().empty());
        EXPECT_GT(sim.probes().front()->history().size(), 10u);
        return report.sph_copies_to_host;
    };
    EXPECT_EQ(copies({"output.vtk=false"}, ""), 1);
    // pressure map, hazard map, flow section, run-up, discharge and deposit
    EXPECT_EQ(copies({"output.vtk=false"}, "", "cases/validation/gate_body_outlet2d.toml"), 1);
    // with files: frames at t = 0, 0.01, ..., 0.05, each a copy
    const std::string out =
        (std::filesystem::temp_directory_path() / "resident_backend_copies").string();
    std::filesystem::remove_all(out);
    EXPECT_GE(copies({"output.vtk_every=0.01"}, out), 6);
    std::filesystem::remove_all(out);
}
