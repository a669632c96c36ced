// The SPH time loop with the GPU's pair visit (`sph.pair_loop = "cells"`: each particle gathers
// its neighbours from the cell grid rebuilt every step, every pair evaluated from both sides)
// run on the host against the host's (`"list"`: half pair list with a skin, scattered to both
// particles), on whole cases: issue #33 asks that the device code path be exercised in CI.
// The two loops sum the same terms in another order, so they differ by round-off from the
// first step; the bound on each comparison is that round-off after the number of steps run,
// measured below (the largest differences seen, times ten).
#include "probe_difference.hpp"
#include "run_case.hpp"
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <map>

using namespace debrisflow;

namespace {

struct State {
    std::map<ParticleId, std::array<double, 7>> fluid; // x, y, z, vx, vy, vz, rho
    test::ProbeHistories probes;
    std::vector<std::array<double, 6>> bodies; // centre and velocity
    long steps = 0;
    Index fluid_count = 0;
};

State run(const std::string& file, std::vector<std::string> sets, const std::string& loop,
          Real until) {
    sets.push_back(fmt::format("sph.pair_loop=\"{}\"", loop));
    app::Simulation sim(io::read_case(std::string(DEBRISFLOW_SOURCE_DIR) + "/" + file, sets));
    const auto report = sim.run({"", true, 0, until});
    State s;
    s.steps = report.result.steps;
    const auto& p = sim.particles();
    for (Index i = 0; i < p.size(); ++i)
        if (p.kind[i] == 0) {
            s.fluid[p.id[i]] = {p.x[i], p.y[i], p.z[i], p.vx[i], p.vy[i], p.vz[i], p.rho[i]};
            ++s.fluid_count;
        }
    for (const auto& pr : sim.probes()) s.probes.push_back(pr->history());
    if (sim.has_bodies())
        for (const auto& b : sim.bodies().bodies())
            s.bodies.push_back({b.pos.x, b.pos.y, b.pos.z, b.vel.x, b.vel.y, b.vel.z});
    return s;
}

// Largest |a - b| over the fluid particles (positions in dp, velocities against the largest
// speed, densities against rho0), over the probe samples (against each column's largest
// magnitude) and over the bodies' centres (in dp).
struct Diff {
    double x = 0, v = 0, rho = 0, probe = 0, body = 0;
};

Diff compare(const State& a, const State& b, double dp, double rho0) {
    Diff d;
    double vmax = 0;
    for (const auto& [id, s] : a.fluid) vmax = std::max(vmax, std::hypot(s[3], s[4], s[5]));
    for (const auto& [id, s] : a.fluid) {
        const auto& t = b.fluid.at(id);
        d.x = std::max(d.x, std::hypot(s[0] - t[0], s[1] - t[1], s[2] - t[2]) / dp);
        d.v = std::max(d.v, std::hypot(s[3] - t[3], s[4] - t[4], s[5] - t[5]) / vmax);
        d.rho = std::max(d.rho, std::abs(s[6] - t[6]) / rho0);
    }
    d.probe = test::probe_difference(a.probes, b.probes);
    for (std::size_t k = 0; k < a.bodies.size(); ++k)
        for (int c = 0; c < 3; ++c)
            d.body = std::max(d.body, std::abs(a.bodies[k][c] - b.bodies[k][c]) / dp);
    return d;
}

void check(const std::string& file, const std::vector<std::string>& sets, Real until, double dp,
           double rho0, Diff bound) {
    const State list = run(file, sets, "list", until);
    const State cells = run(file, sets, "cells", until);
    ASSERT_EQ(list.steps, cells.steps);
    ASSERT_EQ(list.fluid_count, cells.fluid_count);
    ASSERT_EQ(list.probes.size(), cells.probes.size());
    for (std::size_t k = 0; k < list.probes.size(); ++k)
        ASSERT_EQ(list.probes[k].size(), cells.probes[k].size());
    const Diff d = compare(list, cells, dp, rho0);
    std::cout << fmt::format("{}: {} steps, {} fluid particles; largest differences: position "
                             "{:.2e} dp, velocity {:.2e} of the largest speed, density {:.2e} "
                             "rho0, probes {:.2e} of their largest value, bodies {:.2e} dp\n",
                             file, list.steps, list.fluid_count, d.x, d.v, d.rho, d.probe, d.body);
    EXPECT_LE(d.x, bound.x);
    EXPECT_LE(d.v, bound.v);
    EXPECT_LE(d.rho, bound.rho);
    EXPECT_LE(d.probe, bound.probe);
    EXPECT_LE(d.body, bound.body);
}

} // namespace

// Bounds: round-off after a few thousand steps. The largest differences measured when the
// test was written (2026-12-03, 2 threads) were 3e-10 dp in position, 9e-11 of the largest
// speed, 1.2e-12 rho0 in density (inlet and outlet case, 5,371 steps); the bounds leave a
// factor of about 30 for other thread counts and compilers. A pair term that differed between
// the two loops would show at 1e-3 or more.
const Diff round_off{1e-8, 1e-8, 1e-10, 1e-8, 1e-8};

// DualSPHysics's CaseDambreak at 2 dp, 150 steps: wall pairs, cubic spline, Fourtakas.
TEST(SphDevicePath, DamBreak3D) {
    check("cases/bench/dambreak3d.toml", {"dp=0.034"}, 0.05, 0.034, 1000, round_off);
}
// Periodic channel with Laminar+SPS: the velocity-gradient sums and the stress carried over.
TEST(SphDevicePath, ChannelLaminarSps) {
    check("cases/bench/channel_sph.toml", {}, 0.05, 0.02, 1000, round_off);
}
// A gate removed, an inlet adding particles, an outlet taking them (the particle set changes).
TEST(SphDevicePath, GateInletOutlet) {
    // 0.58 s, not the case's 0.6 s: the inlet lets in a row every 0.05 s, and at 0.6 s whether
    // the last row enters hangs on the last bit of the time.
    check("cases/validation/gate_inlet_outlet2d.toml", {}, 0.58, 0.01, 1000, round_off);
}
// A floating body: the fluid's force on its boundary particles, the body moving them.
TEST(SphDevicePath, FloatingBox) {
    check("cases/rigid/floating_box2d.toml", {}, 0.2, 0.01, 1000, round_off);
}
// mDBC walls: the ghost-node density gathered before the force loop.
TEST(SphDevicePath, DamBreakMdbc) {
    check("cases/dambreak2d.toml", {"sph.boundary=\"mdbc\"", "dp=0.015"}, 0.3, 0.015, 1000,
          round_off);
}
// mDBC's no-slip variant with a Bingham slurry: the mirrored ghost-node velocities in the
// viscous pair term and in the apparent viscosity's strain rate, in both loops.
TEST(SphDevicePath, BinghamCollapseMdbcNoSlip) {
    check("cases/validation/viscous_collapse2d.toml",
          {"sph.boundary=\"mdbc\"", "sph.no_slip=\"mdbc\"", "sph.viscosity=\"bingham\"",
           "sph.consistency=10", "sph.yield_stress=20", "sph.regularization=10", "dp=0.005"},
          0.05, 0.005, 1000, round_off);
}
