// Instruments of issue #5 against answers known in closed form:
//  - discharge through a plane of a uniform periodic stream: q = rho U H exactly;
//  - trapping efficiency and outlet counts with grains in free flight: E = caught / passed;
//  - a solid feed releases its target discharge Q_s t (within one grain) from a log-normal
//    size distribution, and its grains settle in a bin;
// (The pressure map's tests are in pressure_map_test.cpp.)
#include "run_case.hpp"
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <gtest/gtest.h>
#include <iterator>

using namespace debrisflow;

TEST(Instruments, FluidDischargeOfUniformStream) {
    // Periodic in x and z, no gravity: the lattice moves as a whole at U = 0.5 m/s.
    app::Simulation sim(test::case_from_toml("uniform_stream", R"(
dimensions = 2
dp = 0.01
[time]
end = 0.2
[output]
vtk = false
[physics]
gravity = [0, 0]
[domain]
min = [0, 0]
max = [0.4, 0.2]
periodic = ["x", "z"]
[sph]
c0 = 10
[[fluid]]
name = "water"
shape = "box"
min = [0, 0]
max = [0.4, 0.2]
velocity = [0.5, 0]
hydrostatic = false
[[probe]]
name = "q"
type = "discharge"
point = [0.2, 0]
normal = [1, 0]
every = 0.01
)"));
    sim.run({"", true, 0});
    const auto& f = sim.probe("q").finals();
    std::cout << fmt::format("discharge {:.6f} kg/s/m, {:.6e} m2/s, cumulative {:.6f} kg/m\n", f[0],
                             f[1], f[2]);
    // rho U H = 1000 x 0.5 x 0.2 = 100 kg/s per metre; over 0.2 s, 20 kg/m.
    EXPECT_NEAR(f[0], 100.0, 1e-6);
    EXPECT_NEAR(f[1], 0.1, 1e-9);
    EXPECT_NEAR(f[2], 20.0, 1e-6);
}

TEST(Instruments, TrappingEfficiencyOutletAndDepositWithGrainsInFlight) {
    // Ten grains fly along +x at 1 m/s (no gravity) at y = 0.05, 0.15, ..., 0.95; an outlet
    // between the planes removes the three with y < 0.3: E = 3 / 10 exactly.
    std::string grains;
    for (int k = 0; k < 10; ++k)
        grains += fmt::format(R"(
[[grains]]
name = "g{0}"
material = "rock"
packing = "single"
position = [0.2, {1}, 0.5]
diameter = 0.02
velocity = [1, 0, 0]
)",
                              k, 0.05 + 0.1 * k);
    app::Simulation sim(test::case_from_toml("trapping", R"(
dimensions = 3
[time]
end = 2.0
[output]
vtk = false
[physics]
gravity = [0, 0, 0]
[domain]
min = [0, 0, 0]
max = [3, 1, 1]
[[material]]
name = "rock"
law = "linear"
density = 2500
kn = 1e4
restitution = 0.5
friction = 0.3
[[outlet]]
name = "catch"
min = [1.0, 0.0, 0.0]
max = [1.2, 0.3, 1.0]
[[probe]]
name = "E"
type = "trapping"
upstream = [0.5, 0, 0]
downstream = [1.5, 0, 0]
window = [0.0, 2.0]
every = 0.01
[[probe]]
name = "q_down"
type = "discharge"
point = [1.5, 0, 0]
normal = [1, 0, 0]
every = 0.01
[[probe]]
name = "pile"
type = "deposit"
min = [2.0, 0, 0]
max = [3.0, 1, 1]
every = 0.01
)" + grains));
    sim.run({"", true, 0});
    const double m = 2500 * 3.14159265358979323846 / 6 * 0.02 * 0.02 * 0.02;
    const auto& e = sim.probe("E").finals();
    const auto& out = sim.probe("catch").finals();
    const auto& q = sim.probe("q_down").finals();
    const auto& pile = sim.probe("pile").finals();
    std::cout << fmt::format("M_up {:.6g} kg, M_down {:.6g} kg, E = {:.4f}; outlet {:.6g} kg; "
                             "deposit {:.6g} kg\n",
                             e[0], e[1], e[2], out[2], pile[1]);
    EXPECT_NEAR(e[0], 10 * m, 1e-12);
    EXPECT_NEAR(e[1], 7 * m, 1e-12);
    EXPECT_NEAR(e[2], 0.3, 1e-12);
    EXPECT_NEAR(out[2], 3 * m, 1e-12);        // grain mass removed by the outlet
    EXPECT_NEAR(out[3], 3 * m / 2500, 1e-15); // and its solid volume
    EXPECT_NEAR(q[2], 7 * m, 1e-12);          // cumulative solid discharge downstream
    EXPECT_NEAR(pile[1], 7 * m, 1e-12);       // the seven survivors end in x in [2, 3]
    EXPECT_EQ(sim.grains().grains().size(), 7);
}

TEST(Instruments, SolidFeedReleasesTargetDischarge) {
    app::Simulation sim(test::case_from_toml("feed", R"(
dimensions = 3
[time]
end = 1.0
[output]
vtk = false
[domain]
min = [0, 0, 0]
max = [0.3, 0.3, 0.6]
[[material]]
name = "rock"
law = "hertz_mindlin"
density = 2650
youngs_modulus = 5e6
poisson = 0.3
restitution = 0.3
friction = 0.5
[[feed]]
name = "hopper"
material = "rock"
min = [0.05, 0.05, 0.4]
max = [0.25, 0.25, 0.5]
times = [0, 0.5, 1.0]
discharge = [2e-5, 2e-5, 0]
size = {distribution = "lognormal", d50 = 0.012, sigma = 0.2, min = 0.008, max = 0.018}
[[wall]]
name = "bin"
shape = "box"
min = [0, 0, 0]
max = [0.3, 0.3, 0.02]
[[probe]]
name = "pile"
type = "deposit"
min = [0, 0, 0]
max = [0.3, 0.3, 0.2]
every = 0.01
)"));
    sim.run({"", true, 0});
    const auto& f = sim.probe("hopper").finals();
    // Hydrograph: 2e-5 m^3/s for 0.5 s, then down to 0 at 1 s: 1.5e-5 m^3 of solid.
    const double target = 2e-5 * 0.5 + 1e-5 * 0.5;
    const double largest = 3.14159265358979323846 / 6 * 0.018 * 0.018 * 0.018;
    std::cout << fmt::format("feed released {:.4e} m^3 ({} grains, owed {:.2e}) of {:.4e}\n", f[1],
                             f[3], f[4], target);
    EXPECT_NEAR(f[1], target, largest); // within one grain of the target
    EXPECT_EQ(long(f[3]), long(sim.grains().grains().size()));
    EXPECT_NEAR(sim.grains().grains().total_mass(), f[2], 1e-12);
    // After 1 s the first grains have fallen ~0.4 m into the bin (free fall: 0.3 s).
    EXPECT_GT(sim.probe("pile").finals()[0], 0.5 * target);
}

// A feed whose region cannot hold its discharge: with no gravity the grains stay where they are
// placed, the region fills, and the feed owes more and more. The run says so in its log, once
// (flow/solid_feed.cpp), and the probe's debt column is what was asked minus what was placed.
TEST(Instruments, ChokedFeedWarnsOnceThatItFallsBehind) {
    const auto run = [](const std::string& name, const std::string& gravity, double discharge) {
        const auto out = std::filesystem::temp_directory_path() / "debrisflow_tests" / name;
        std::filesystem::remove_all(out);
        app::Simulation sim(test::case_from_toml(name, fmt::format(R"(
dimensions = 3
[time]
end = 0.5
[output]
vtk = false
[physics]
gravity = {}
[domain]
min = [0, 0, 0]
max = [0.3, 0.3, 0.6]
[[material]]
name = "rock"
law = "hertz_mindlin"
density = 2650
youngs_modulus = 5e6
poisson = 0.3
restitution = 0.3
friction = 0.5
[[feed]]
name = "hopper"
material = "rock"
min = [0.1, 0.1, 0.4]
max = [0.16, 0.16, 0.46]
discharge = {}
size = {{distribution = "mono", diameter = 0.01}}
[[wall]]
name = "bin"
shape = "box"
min = [0, 0, 0]
max = [0.3, 0.3, 0.02]
)",
                                                                   gravity, discharge)));
        sim.run({out.string(), true, 1});
        std::ifstream log(out / "log.txt");
        const std::string text{std::istreambuf_iterator<char>(log), {}};
        long warnings = 0;
        for (auto at = text.find("falls behind"); at != std::string::npos;
             at = text.find("falls behind", at + 1))
            ++warnings;
        const auto& f = sim.probe("hopper").finals();
        std::cout << fmt::format("{}: released {:.4e} m^3, owed {:.4e}, {} warning(s)\n", name,
                                 f[1], f[4], warnings);
        // what was asked is what was placed plus what is owed
        EXPECT_NEAR(f[1] + f[4], discharge * 0.5, 1e-12) << name;
        return std::pair{warnings, f[4] / (discharge * 0.5)};
    };
    // 4e-4 m^3/s of 10 mm grains (760 a second) into a 60 mm cube, where random placement fits
    // about 130 (a third of its volume): choked within 0.2 s, two thirds of 2e-4 m^3 owed
    const auto [choked, choked_owed] = run("feed_choked", "[0, 0, 0]", 4e-4);
    EXPECT_EQ(choked, 1);
    EXPECT_GT(choked_owed, 0.5);
    // the same region emptied by gravity at a tenth of the rate keeps up: no warning
    const auto [free, free_owed] = run("feed_free", "[0, 0, -9.81]", 2e-5);
    EXPECT_EQ(free, 0);
    EXPECT_LT(free_owed, 0.05);
}

// A feed's region that cuts walls: half of it lies below a floor plane and a solid block fills
// a corner. With no gravity the grains stay where they were placed: none may start inside a
// wall (dem/wall_proximity.hpp), and the feed still releases in the free part of the region.
TEST(Instruments, FeedPlacesGrainsClearOfWalls) {
    app::Simulation sim(test::case_from_toml("feed_walls", R"(
dimensions = 3
[time]
end = 0.2
[output]
vtk = false
[physics]
gravity = [0, 0, 0]
[domain]
min = [-0.1, -0.1, -0.1]
max = [0.4, 0.4, 0.4]
[[material]]
name = "rock"
law = "hertz_mindlin"
density = 2650
youngs_modulus = 5e6
poisson = 0.3
restitution = 0.3
friction = 0.5
[[feed]]
name = "hopper"
material = "rock"
min = [0.0, 0.0, -0.1]
max = [0.2, 0.2, 0.1]
discharge = 2e-4
size = {distribution = "mono", diameter = 0.01}
[[wall]]
name = "floor"
shape = "plane"
point = [0, 0, 0]
normal = [0, 0, 1]
[[wall]]
name = "block"
shape = "box"
min = [0.1, 0.1, 0.0]
max = [0.3, 0.3, 0.3]
)"));
    sim.run({"", true, 1});
    const auto& g = sim.grains().grains();
    long in_free_part = 0;
    for (Index i = 0; i < g.size(); ++i) {
        const Vec3 p = g.pos[std::size_t(i)];
        const Real r = g.radius[std::size_t(i)];
        // above the floor, and outside the block or at most touching it
        EXPECT_GE(p.z, r * (1 - 1e-6)) << i;
        const Real dx = std::max({Real(0.1) - p.x, p.x - Real(0.3), Real(0)});
        const Real dy = std::max({Real(0.1) - p.y, p.y - Real(0.3), Real(0)});
        const Real dz = std::max({Real(0.0) - p.z, p.z - Real(0.3), Real(0)});
        EXPECT_GE(std::sqrt(dx * dx + dy * dy + dz * dz), r * (1 - 1e-6)) << i;
        in_free_part += p.z > 0;
    }
    std::cout << fmt::format("{} grains placed, all clear of the floor and the block\n", g.size());
    // 2e-4 m^3/s for 0.2 s is 4e-5 m^3, 76 grains: the free part of the region holds them
    EXPECT_EQ(g.size(), 76);
    EXPECT_EQ(in_free_part, g.size());
}

TEST(Instruments, SolidCrossingCountsLapsInPeriodicFlume) {
    // One grain circulates at 1 m/s in a 1 m periodic box (no gravity): in 2.5 s it crosses the
    // plane x = 0.5 three times (t = 0.3, 1.3, 2.3 s) and wraps twice, which are not crossings.
    app::Simulation sim(test::case_from_toml("laps", R"(
dimensions = 3
[time]
end = 2.5
[output]
vtk = false
[physics]
gravity = [0, 0, 0]
[domain]
min = [0, 0, 0]
max = [1, 1, 1]
periodic = ["x"]
[[material]]
name = "rock"
law = "linear"
density = 2500
kn = 1e4
restitution = 0.5
friction = 0.3
[[grains]]
name = "g"
material = "rock"
packing = "single"
position = [0.2, 0.5, 0.5]
diameter = 0.02
velocity = [1, 0, 0]
[[probe]]
name = "flux"
type = "mass_flux"
point = [0.5, 0, 0]
normal = [1, 0, 0]
every = 0.01
)"));
    sim.run({"", true, 0});
    const double m = 2500 * 3.14159265358979323846 / 6 * 0.02 * 0.02 * 0.02;
    EXPECT_NEAR(sim.probe("flux").finals()[1], 3 * m, 1e-12);
}
