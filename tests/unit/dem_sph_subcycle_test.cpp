// A case with fluid and grains: the DEM sub-cycles inside the SPH step and its grains move
// as in a grains-only run (no fluid-grain coupling yet: that is the rigid-body issue's).
#include "run_case.hpp"
#include <cmath>
#include <gtest/gtest.h>

using namespace debrisflow;

namespace {
const char* grains = R"(
[[material]]
name = "stone"
density = 2650
kn = 1e5
restitution = 0.5
friction = 0.3
[[grains]]
name = "stone"
material = "stone"
packing = "single"
diameter = 0.02
position = [0.5, 0.2]
[[wall]]
name = "floor"
shape = "plane"
point = [0, 0]
normal = [0, 1]
)";
const char* frame = R"(dimensions = 2
[time]
end = 0.4
[output]
vtk = false
[domain]
min = [-0.05, -0.05]
max = [1.05, 0.5]
[dem]
thickness = 0.1
)";
const char* fluid = R"(
[sph]
c0 = 10
[[fluid]]
name = "pool"
shape = "box"
min = [0.02, 0.02]
max = [0.18, 0.1]
[[wall]]
name = "pool"
shape = "open_tank"
min = [0.02, 0.02]
max = [0.18, 0.15]
)";
} // namespace

// The grain falls 0.19 m onto the floor and bounces (e = 0.5); its height at t = 0.4 s agrees
// with the grains-only run to 1 mm (the sub-steps differ in size, not in physics).
TEST(DemWithSph, SubcyclesAndMatchesGrainsOnlyRun) {
    app::Simulation alone(test::case_from_toml("dem_alone", std::string(frame) + grains));
    app::Simulation mixed(
        test::case_from_toml("dem_mixed", "dp = 0.01\n" + std::string(frame) + fluid + grains));
    ASSERT_TRUE(mixed.has_fluid());
    ASSERT_TRUE(mixed.spec().dem.params.subcycle);
    app::RunOptions opt;
    opt.quiet = true;
    const auto ra = alone.run(opt);
    const auto rm = mixed.run(opt);
    EXPECT_LT(rm.result.steps, ra.result.steps / 2); // SPH steps, each with several DEM steps
    EXPECT_NEAR(mixed.grains().grains().pos[0].z, alone.grains().grains().pos[0].z, 1e-3);
    EXPECT_GT(mixed.grains().list_builds(), 1);
}
