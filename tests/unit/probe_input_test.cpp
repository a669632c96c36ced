// Probe keys of issue #29: a front along -x, and the walls a pressure map can tile.
#include "debrisflow/probes/pressure_notes.hpp"
#include "run_case.hpp"
#include <fmt/format.h>
#include <gtest/gtest.h>

using namespace debrisflow;

namespace {
// A 2D water column 0.1 m x 0.1 m against the left (x0 = 0) or the right (x0 = 0.3) side of
// a tank 0.4 m long, with a front probe along `axis`.
std::string column_case(double x0, const std::string& axis) {
    return fmt::format(R"(
dimensions = 2
dp = 0.01
[time]
end = 0.15
[output]
vtk = false
[domain]
min = [-0.05, -0.05]
max = [0.45, 0.3]
[sph]
c0 = 20
[[fluid]]
name = "water"
shape = "box"
min = [{0}, 0]
max = [{1}, 0.1]
[[wall]]
name = "tank"
shape = "open_tank"
min = [0, 0]
max = [0.4, 0.25]
[[probe]]
name = "front"
type = "front"
axis = "{2}"
every = 0.01
)",
                       x0, x0 + 0.1, axis);
}
} // namespace

TEST(ProbeInput, FrontAlongMinusXFollowsASurgeRunningLeft) {
    // The same collapse mirrored: the +x front of the left column and the -x front of the
    // right column travel the same distance (mirror symmetry of the method; 1 %: the lattice
    // and the summation order are not mirrored exactly).
    app::Simulation right_running(test::case_from_toml("front_plus", column_case(0, "+x")));
    right_running.run({"", true, 0});
    app::Simulation left_running(test::case_from_toml("front_minus", column_case(0.3, "-x")));
    left_running.run({"", true, 0});
    const auto& a = right_running.probe("front").history();
    const auto& b = left_running.probe("front").history();
    ASSERT_EQ(a.size(), b.size());
    const double a0 = a.front()[1], b0 = b.front()[1];
    EXPECT_NEAR(a0, 0.095, 1e-9); // the centre of the last column of particles
    EXPECT_NEAR(b0, 0.305, 1e-9);
    const double da = a.back()[1] - a0, db = b0 - b.back()[1];
    EXPECT_GT(da, 0.05); // the surge has run
    EXPECT_NEAR(db, da, 0.01 * da);
}

TEST(ProbeInput, PressureMapNeedsAWallWithABoundingBox) {
    const std::string base = R"(
dimensions = 3
dp = 0.02
[time]
end = 0.01
[domain]
min = [0, 0, 0]
max = [0.4, 0.4, 0.4]
[sph]
c0 = 20
[[fluid]]
name = "water"
shape = "box"
min = [0.1, 0.1, 0.1]
max = [0.2, 0.2, 0.2]
[[wall]]
name = "ground"
shape = "plane"
point = [0, 0, 0.05]
normal = [0, 0, 1]
[[probe]]
name = "map"
type = "pressure_map"
wall = "ground"
axis = "z"
normal = [0, 0, 1]
panels = [2, 2]
)";
    const std::string e = test::input_error_of("map_on_plane", base);
    EXPECT_NE(e.find("probe.0.wall"), std::string::npos) << e;
    EXPECT_NE(e.find("bounding box"), std::string::npos) << e;
}

TEST(ProbeInput, FluidInsideASolidWallIsLeftOut) {
    // A fluid block drawn through a solid box wall: the box is solid (its particles are a
    // shell of `layers`), so no fluid starts inside it.
    app::Simulation sim(test::case_from_toml("fluid_in_wall", R"(
dimensions = 2
dp = 0.01
[time]
end = 0.001
[output]
vtk = false
[domain]
min = [-0.1, -0.1]
max = [0.5, 0.4]
[sph]
c0 = 20
[[fluid]]
name = "water"
shape = "box"
min = [0, 0]
max = [0.4, 0.2]
[[wall]]
name = "block"
shape = "box"
min = [0.1, 0]
max = [0.3, 0.15]
)"));
    const auto& s = sim.particles();
    for (Index i = 0; i < s.size(); ++i) {
        if (s.kind[i] != 0) continue;
        EXPECT_FALSE(s.x[i] > 0.1 && s.x[i] < 0.3 && s.z[i] < 0.15)
            << "fluid at (" << s.x[i] << ", " << s.z[i] << ") inside the block";
    }
}

TEST(ProbeInput, PressureMapRefusesAMovingWall) {
    // The column case with its tank moving and a pressure map on the tank's right side.
    std::string toml = column_case(0, "+x");
    const std::string tank_max = "max = [0.4, 0.25]\n";
    toml.insert(toml.find(tank_max) + tank_max.size(), "velocity = [0.1, 0]\n");
    toml += "[[probe]]\nname = \"map\"\ntype = \"pressure_map\"\nwall = \"tank\"\naxis = \"x\"\n"
            "normal = [-1, 0]\npanels = [2, 1]\n";
    const std::string e = test::input_error_of("map_on_moving_wall", toml);
    EXPECT_NE(e.find("probe.1.wall"), std::string::npos) << e;
    EXPECT_NE(e.find("moves"), std::string::npos) << e;
}

// What `check` and the log say a wall-pressure probe measures (probes/pressure_notes.hpp):
// the water-hammer peak on any wall, the low load up a DBC wall only with DBC, nothing for a
// case without wall-pressure probes.
TEST(ProbeInput, WallPressureNoteFollowsTheWallTreatment) {
    const std::string demo = std::string(DEBRISFLOW_SOURCE_DIR) + "/cases/dambreak2d.toml";
    const std::string dbc = probes::wall_pressure_note(io::read_case(demo, {}));
    EXPECT_NE(dbc.find("'sensor1', 'sensor2', 'sensor3' and 1 more"), std::string::npos) << dbc;
    EXPECT_NE(dbc.find("water hammer, about rho c0 u, which follows c0 = 17.16 m/s"),
              std::string::npos)
        << dbc;
    EXPECT_NE(dbc.find("set sph.boundary = \"mdbc\""), std::string::npos) << dbc;
    const std::string mdbc =
        probes::wall_pressure_note(io::read_case(demo, {"sph.boundary=\"mdbc\""}));
    EXPECT_NE(mdbc.find("water hammer"), std::string::npos) << mdbc;
    EXPECT_EQ(mdbc.find("sph.boundary"), std::string::npos) << mdbc;
    const std::string none = probes::wall_pressure_note(
        io::read_case(std::string(DEBRISFLOW_SOURCE_DIR) + "/cases/validation/marin3d.toml", {}));
    EXPECT_EQ(none, "");
}
