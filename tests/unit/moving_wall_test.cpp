// A [[wall]] with a prescribed `velocity`: its fluid boundary particles translate with it and
// carry the velocity, in step with the grains' geometric wall (before, only the grains' wall
// moved and the fluid kept a tank that stood still); fixed walls stay bitwise where they were.
#include "debrisflow/dem/dem_solver.hpp"
#include "run_case.hpp"
#include <gtest/gtest.h>
#include <map>

using namespace debrisflow;

namespace {

// A 3D water block in an open tank (group 0, moving) on a fixed floor slab (group 1), with one
// grain so that the DEM walls exist too.
const char* const moving_tank = R"(
dimensions = 3
dp = 0.02
[time]
end = 0.02
[output]
vtk = false
[domain]
min = [-0.2, -0.2, -0.2]
max = [0.6, 0.4, 0.4]
[sph]
c0 = 10
[[fluid]]
name = "water"
shape = "box"
min = [0.0, 0.0, 0.0]
max = [0.2, 0.2, 0.1]
[[wall]]
name = "tank"
shape = "open_tank"
min = [0.0, 0.0, 0.0]
max = [0.2, 0.2, 0.2]
velocity = [0.5, 0, 0]
[[wall]]
name = "slab"
shape = "box"
min = [0.3, 0.0, -0.1]
max = [0.5, 0.2, -0.05]
[[material]]
name = "glass"
density = 2500
law = "hertz_mindlin"
youngs_modulus = 1e7
poisson = 0.3
restitution = 0.5
friction = 0.3
[[grains]]
name = "g"
material = "glass"
packing = "single"
position = [0.1, 0.1, 0.05]
diameter = 0.01
)";

} // namespace

TEST(MovingWall, FluidBoundaryParticlesFollowTheWall) {
    app::Simulation sim(test::case_from_toml("moving_tank", moving_tank));
    const auto& s = sim.particles();
    std::map<ParticleId, Vec3> start;
    for (Index i = 0; i < s.size(); ++i)
        if (s.kind[i] != 0) start[s.id[i]] = {s.x[i], s.y[i], s.z[i]};
    sim.run({"", true, 0});
    const Real t = 0.02, v = 0.5;
    int moved = 0, fixed = 0;
    for (Index i = 0; i < s.size(); ++i) {
        if (s.kind[i] == 0) continue;
        const Vec3 d = Vec3{s.x[i], s.y[i], s.z[i]} - start[s.id[i]];
        if (s.group[i] == 0) {
            EXPECT_NEAR(d.x, v * t, 1e-12);
            EXPECT_EQ(d.y, 0);
            EXPECT_EQ(d.z, 0);
            EXPECT_EQ(s.vx[i], v);
            ++moved;
        } else {
            EXPECT_EQ(d.x, 0);
            EXPECT_EQ(s.vx[i], 0);
            ++fixed;
        }
    }
    EXPECT_GT(moved, 100);
    EXPECT_GT(fixed, 10);
    // The grains' geometric wall moved by the same amount: its origin (the tank's centre at
    // x = 0.1 m) is now at 0.1 + v t; the slab's stays at its centre, 0.4 m.
    const auto& walls = sim.grains().walls().walls();
    ASSERT_EQ(walls.size(), 2u);
    EXPECT_NEAR(walls[0].origin.x, 0.1 + v * t, 1e-12);
    EXPECT_EQ(walls[1].origin.x, 0.4);
}
