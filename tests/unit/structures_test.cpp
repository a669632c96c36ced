// Structure builders ([[structure]]): geometry from parameters (issue #5), each structure one
// named wall for both the SPH (boundary particles) and the DEM (exact faces).
#include "debrisflow/core/error.hpp"
#include "run_case.hpp"
#include <cmath>
#include <fmt/format.h>
#include <gtest/gtest.h>

using namespace debrisflow;

namespace {
const char* grains_header = R"(
dimensions = 3
[time]
end = 0.01
[domain]
min = [-0.5, -0.2, -0.2]
max = [3.0, 0.8, 1.0]
[[material]]
name = "rock"
law = "hertz_mindlin"
density = 2650
youngs_modulus = 1e7
poisson = 0.3
restitution = 0.5
friction = 0.5
[[grains]]
name = "g"
material = "rock"
packing = "single"
position = [0.2, 0.3, 0.3]
diameter = 0.02
)";
} // namespace

TEST(Structures, SlitDamPostsAndSlitDensity) {
    const auto c = test::case_from_toml("slit_dam", std::string(grains_header) + R"(
[[structure]]
name = "dam"
type = "slit_dam"
position = 1.5
thickness = 0.05
height = 0.3
width = 0.5
slits = 3
slit_width = 0.05
)");
    ASSERT_EQ(c.walls.size(), 1u);
    const auto& w = c.walls[0];
    // 3 slits of 0.05 m in 0.5 m: 4 posts of (0.5 - 0.15) / 4 = 0.0875 m; density 0.3.
    ASSERT_EQ(w.boxes.size(), 4u);
    EXPECT_NEAR(w.slit_density, 0.3, 1e-12);
    for (std::size_t k = 0; k < 4; ++k) {
        EXPECT_NEAR(w.boxes[k][1].y - w.boxes[k][0].y, 0.0875, 1e-12);
        EXPECT_NEAR(w.boxes[k][0].y, k * (0.0875 + 0.05), 1e-12);
        EXPECT_NEAR(w.boxes[k][1].x - w.boxes[k][0].x, 0.05, 1e-12);
    }
    app::Simulation sim(c);
    // 4 boxes x 6 faces x 2 triangles in the DEM wall set.
    EXPECT_EQ(sim.grains().walls().primitives().size(), 48u);
    EXPECT_EQ(sim.grains().walls().walls()[0].name, "dam");
}

TEST(Structures, SlitDamP2CapsAndErrors) {
    const auto c = test::case_from_toml("slit_p2", std::string(grains_header) + R"(
[[structure]]
name = "dam"
type = "slit_dam"
post = "P2"
cap_width = 0.12
cap_depth = 0.02
position = 1.5
thickness = 0.05
height = 0.3
width = 0.5
slits = 3
slit_width = 0.05
)");
    ASSERT_EQ(c.walls[0].boxes.size(), 8u); // a post and its upstream cap, 4 times
    EXPECT_NEAR(c.walls[0].boxes[1][0].x, 1.5 - 0.02, 1e-12);
    EXPECT_THROW(test::case_from_toml("slit_bad", std::string(grains_header) + R"(
[[structure]]
name = "dam"
type = "slit_dam"
position = 1.5
thickness = 0.05
height = 0.3
width = 0.5
slits = 10
slit_width = 0.05
)"),
                 InputError);
}

TEST(Structures, StaggeredBafflesFlumeSlopeAndHopper) {
    const auto c = test::case_from_toml("baffles", std::string(grains_header) + R"(
[[structure]]
name = "flume"
type = "flume"
start = -0.4
length = 3.3
width = 0.6
wall_height = 0.5
slope_percent = 20
roughness_height = 0.01
roughness_spacing = 0.5
[[structure]]
name = "baffles"
type = "baffles"
position = 1.0
rows = 3
per_row = 3
row_spacing = 0.3
lateral_spacing = 0.2
center_y = 0.3
size = [0.05, 0.08, 0.15]
[[structure]]
name = "hopper"
type = "hopper"
min = [0.0, 0.1, 0.6]
max = [0.3, 0.5, 0.9]
orifice = 0.06
)");
    // 20 % slope: gravity tilted by atan(0.2).
    const double a = std::atan(0.2);
    EXPECT_NEAR(c.dem.params.gravity.x, 9.81 * std::sin(a), 1e-9);
    EXPECT_NEAR(c.dem.params.gravity.z, -9.81 * std::cos(a), 1e-9);
    ASSERT_EQ(c.walls.size(), 3u);
    // Flume: bed + 2 side walls + ribs at -0.15, 0.35, ..., 2.85 (7 ribs).
    EXPECT_EQ(c.walls[0].boxes.size(), 3u + 7u);
    // Baffles: 3 + 2 + 3, the middle row shifted by half the lateral spacing.
    const auto& b = c.walls[1].boxes;
    ASSERT_EQ(b.size(), 8u);
    EXPECT_NEAR(0.5 * (b[0][0].y + b[0][1].y), 0.1, 1e-12);
    EXPECT_NEAR(0.5 * (b[3][0].y + b[3][1].y), 0.2, 1e-12);
    EXPECT_NEAR(b[3][0].x, 1.3, 1e-12);
    // Hopper: 4 side plates and a floor in two parts around the 6 cm slot.
    const auto& h = c.walls[2].boxes;
    ASSERT_EQ(h.size(), 6u);
    EXPECT_NEAR(h[5][0].x - h[4][1].x, 0.06, 1e-12);
}

// Geometry that round-off or size would break is refused at input, naming the key: a box
// thinner than round-off has faces without a normal; a box count beyond the cap would make
// the set-up quadratic (fuzzing found a 1e-12 m thin structure reaching the DEM wall set).
TEST(Structures, UnresolvableOrOversizedGeometryIsAnInputError) {
    const auto rejected = [](const std::string& name, const std::string& block,
                             const std::string& key) {
        try {
            test::case_from_toml(name, std::string(grains_header) + block);
        } catch (const InputError& e) {
            EXPECT_NE(std::string(e.what()).find(key), std::string::npos) << e.what();
            return;
        }
        ADD_FAILURE() << name << " was accepted";
    };
    rejected("thin_dam", R"(
[[structure]]
name = "dam"
type = "check_dam"
position = 1.5
thickness = 1e-12
height = 0.3
width = 0.5
)",
             "structure.0.type");
    rejected("inverted_hopper", R"(
[[structure]]
name = "hopper"
type = "hopper"
min = [0.3, 0.1, 0.6]
max = [0.0, 0.5, 0.9]
)",
             "structure.0.max");
    rejected("wide_orifice", R"(
[[structure]]
name = "hopper"
type = "hopper"
min = [0.0, 0.1, 0.6]
max = [0.3, 0.5, 0.9]
orifice = 0.3
)",
             "structure.0.orifice");
    rejected("many_baffles", R"(
[[structure]]
name = "baffles"
type = "baffles"
position = 1.0
rows = 100
per_row = 100
row_spacing = 0.01
lateral_spacing = 0.01
center_y = 0.3
size = [0.005, 0.005, 0.15]
)",
             "structure.0.per_row");
    rejected("many_ribs", R"(
[[structure]]
name = "flume"
type = "flume"
length = 3.0
width = 0.6
wall_height = 0.5
roughness_height = 1e-4
roughness_spacing = 1e-4
)",
             "structure.0.roughness_spacing");
    rejected("far_wall", R"(
[[wall]]
name = "far"
shape = "box"
min = [0, 0, 0]
max = [1e12, 1, 1]
)",
             "wall.0.max");
    rejected("thin_wall", R"(
[[wall]]
name = "thin"
shape = "box"
min = [1000, 0, 0]
max = [1000.0000000001, 1, 1]
)",
             "wall.0.max");
}

TEST(Structures, CheckDamIsOneWallForFluidAndGrains) {
    app::Simulation sim(test::case_from_toml("check_dam", R"(
dimensions = 2
dp = 0.01
[time]
end = 0.001
[domain]
min = [-0.1, -0.1]
max = [1.1, 0.6]
[sph]
c0 = 20
[[material]]
name = "rock"
law = "linear"
density = 2650
kn = 1e5
restitution = 0.5
friction = 0.5
[dem]
thickness = 0.01
[[grains]]
name = "g"
material = "rock"
packing = "single"
position = [0.3, 0, 0.3]
diameter = 0.02
[[fluid]]
name = "water"
shape = "box"
min = [0, 0]
max = [0.2, 0.2]
[[structure]]
name = "bed"
type = "flume"
start = -0.05
length = 1.1
wall_height = 0.3
[[structure]]
name = "dam"
type = "check_dam"
position = 0.8
thickness = 0.04
height = 0.15
)"));
    long dam_particles = 0;
    const auto& s = sim.particles();
    for (Index i = 0; i < s.size(); ++i) dam_particles += s.kind[i] == 1 && s.group[i] == 1;
    // 4 x 15 particles at dp = 0.01 (the block is thinner than two kernel skins: all of it).
    EXPECT_EQ(dam_particles, 60);
    EXPECT_EQ(sim.grains().walls().walls()[1].name, "dam");
    // 2D: each box gives 4 faces of 2 triangles (y faces left out); bed and dam: 16.
    EXPECT_EQ(sim.grains().walls().primitives().size(), 16u);
}

// The baffle study's slurries (nu = 0.1, 1, 5 m^2/s): the viscous limit 0.125 h^2 / nu (Morris
// et al. 1997, eq. 19) sets dt and is reported; for a Bingham slurry the limit follows the
// largest apparent viscosity present, which at rest is mu_w + mu_p + tau_y m (mu_w = rho0 nu, the
// interstitial water). (c0 = 5 m/s keeps the CFL step, 1.2e-3 s, above the viscous one at
// nu = 0.1, 1.125e-3 s, and a column 0.2 m deep within the 10 % that its weight may compress a
// fluid, 6.5 %; the runs last 0.01 s.)
TEST(ViscousTimeStep, NewtonianAndBinghamLimitsAreReported) {
    const std::string base = R"(
dimensions = 2
dp = 0.02
[time]
end = 0.01
[output]
vtk = false
[domain]
min = [-0.1, -0.1]
max = [1.0, 1.0]
[sph]
c0 = 5
viscosity = "laminar"
nu = 1.0
[[fluid]]
name = "slurry"
shape = "box"
min = [0, 0]
max = [0.4, 0.2]
[[wall]]
name = "tank"
shape = "open_tank"
min = [0, 0]
max = [0.9, 0.8]
)";
    const double h = 1.5 * 0.02;
    for (double nu : {0.1, 1.0, 5.0}) {
        app::Simulation sim(
            test::case_from_toml("viscous_dt", base, {fmt::format("sph.nu={}", nu)}));
        const auto lim = sim.solver().initial_dt();
        EXPECT_EQ(lim.limiter, "viscous") << nu;
        EXPECT_NEAR(lim.dt, 0.125 * h * h / nu, 1e-15) << nu;
        sim.run({"", true, 0});
        // Once the column moves, the sound speed of the Tait state rises: at nu = 0.1 the CFL
        // step may take over; the viscous limit is never exceeded.
        const auto now = sim.solver().stable_dt();
        EXPECT_LE(now.dt, 0.125 * h * h / nu * (1 + 1e-12)) << nu;
        if (nu >= 1.0) {
            EXPECT_EQ(now.limiter, "viscous") << nu;
            EXPECT_NEAR(now.dt, 0.125 * h * h / nu, 1e-15) << nu;
        }
    }
    app::Simulation sim(
        test::case_from_toml("bingham_dt", base,
                             {"sph.viscosity=\"bingham\"", "sph.nu=1e-6", "sph.consistency=50",
                              "sph.yield_stress=100", "sph.regularization=2"}));
    sim.run({"", true, 0});
    // A column at rest barely shears: some particle sits near mu_w + mu_p + tau_y m = 250 Pa s.
    const auto lim = sim.solver().stable_dt();
    EXPECT_EQ(lim.limiter, "viscous");
    const auto& s = sim.particles();
    double nu_max = 0, mu_max = 0;
    for (Index i = 0; i < s.size(); ++i)
        if (s.kind[i] == 0) {
            nu_max = std::max(nu_max, s.mu[i] / s.rho[i]);
            mu_max = std::max(mu_max, double(s.mu[i]));
        }
    EXPECT_NEAR(lim.dt, 0.125 * h * h / nu_max, 1e-15);
    EXPECT_LE(mu_max, 250.001 * (1 + 1e-12));
    EXPECT_GT(mu_max, 0.5 * 250.0);
}
