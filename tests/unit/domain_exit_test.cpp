// What leaves the domain: removed and counted by phase and face, or the run stops.
#include "debrisflow/core/error.hpp"
#include "run_case.hpp"
#include <gtest/gtest.h>

using namespace debrisflow;

namespace {

// Six discs on a floor, three thrown towards -x and three towards +x, at 1 m/s: the first of
// each leaves the 0.2 m box within 0.1 s; the others stay (slower, they roll on).
const char* leaving_grains = R"(
name = "leaving"
dimensions = 2
[time]
end = 0.15
[output]
vtk = false
[domain]
min = [-0.1, 0, 0]
max = [0.1, 0, 0.2]
[dem]
thickness = 0.005
[[material]]
name = "glass"
density = 2500
kn = 1e5
restitution = 0.5
friction = 0.5
[[wall]]
name = "floor"
shape = "plane"
material = "glass"
point = [0, 0, 0]
normal = [0, 0, 1]
[[grains]]
name = "left"
material = "glass"
packing = "single"
position = [-0.05, 0, 0.0025]
diameter = 0.005
velocity = [-1, 0, 0]
[[grains]]
name = "right"
material = "glass"
packing = "single"
position = [0.05, 0, 0.0025]
diameter = 0.005
velocity = [1, 0, 0]
[[grains]]
name = "slow"
material = "glass"
packing = "single"
position = [0, 0, 0.0025]
diameter = 0.005
velocity = [0.1, 0, 0]
[[probe]]
name = "lost"
type = "domain_exit"
every = 0.01
)";

} // namespace

TEST(DomainExit, GrainsThatLeaveAreRemovedAndCountedByFace) {
    app::Simulation sim(test::case_from_toml("leaving", leaving_grains));
    app::RunOptions opt;
    opt.quiet = true;
    const auto report = sim.run(opt);
    EXPECT_EQ(report.status, "completed");
    EXPECT_EQ(sim.grains().grains().size(), 1);
    const auto& lost = report.grain_exit;
    EXPECT_EQ(lost.count[0], 1); // xmin
    EXPECT_EQ(lost.count[1], 1); // xmax
    EXPECT_EQ(lost.total_count(), 2);
    const Real m = 2500 * 3.14159265358979 * 0.0025 * 0.0025 * 0.005;
    EXPECT_NEAR(lost.total_mass() / (2 * m), 1, 1e-9);
    EXPECT_EQ(report.fluid_exit.total_count(), 0);
    const auto& probe = sim.probe("lost");
    EXPECT_EQ(probe.finals()[2], 2); // grain_count
    EXPECT_EQ(probe.columns()[10], "grain_xmin [-]");
    EXPECT_EQ(probe.finals()[10], 1);
    EXPECT_EQ(probe.finals()[11], 1);
}

TEST(DomainExit, StopPolicyStopsTheRunNamingTheGrain) {
    std::string text = leaving_grains;
    text.replace(text.find("[[probe]]"), std::string::npos, "");
    app::Simulation sim(test::case_from_toml("leaving_stop", text, {"domain.exit=stop"}));
    app::RunOptions opt;
    opt.quiet = true;
    try {
        sim.run(opt);
        FAIL() << "the run should have stopped";
    } catch (const InstabilityError& e) {
        EXPECT_NE(std::string(e.what()).find("left the domain"), std::string::npos) << e.what();
    }
}

TEST(DomainExit, AProbeNeedsTheRemovePolicy) {
    // the probe reads its settings when it is made, before anything is built
    const auto spec = test::case_from_toml("leaving_probe", leaving_grains, {"domain.exit=stop"});
    try {
        app::Simulation sim(spec);
        FAIL() << "a domain_exit probe under domain.exit = \"stop\" should be rejected";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("probe.0.type"), std::string::npos) << e.what();
    }
}

// A clump leaves whole as soon as one member is out: every member is removed and counted at the
// face that member crossed, so the tally's mass is the clump's.
TEST(DomainExit, AClumpLeavesWhole) {
    std::string text = leaving_grains;
    text.replace(text.find("[[grains]]\nname = \"left\""), std::string::npos,
                 "[[grains]]\nname = \"pair\"\nmaterial = \"glass\"\npacking = \"single\"\n"
                 "position = [0.08, 0, 0.004]\ndiameter = 0.006\nvelocity = [1, 0, 0]\n"
                 "clump = [[-1, 0, 0, 1], [1, 0, 0, 1]]\norientation = \"aligned\"\n");
    app::Simulation sim(test::case_from_toml("leaving_clump", text));
    const Real mass = sim.grains().grains().clumps.total_mass();
    app::RunOptions opt;
    opt.quiet = true;
    const auto report = sim.run(opt);
    EXPECT_EQ(sim.grains().grains().size(), 0);
    EXPECT_EQ(sim.grains().grains().clumps.size(), 0);
    EXPECT_EQ(report.grain_exit.count[1], 2); // both members, through xmax
    EXPECT_NEAR(report.grain_exit.total_mass() / mass, 1, 1e-12);
}
