// Rigid-rock feed (section A's hopper of non-spherical rocks): shapes from the mesh library,
// stretched within the sphericity bound, released as rigid bodies at the target discharge.
#include "debrisflow/app/simulation.hpp"
#include "debrisflow/flow/rock_feed.hpp"
#include "run_case.hpp"
#include <fmt/format.h>
#include <fstream>
#include <gtest/gtest.h>

using namespace debrisflow;

namespace {

constexpr double pi = 3.14159265358979323846;
const std::string library = std::string(DEBRISFLOW_SOURCE_DIR) + "/cases/shapes/";

std::string rock_case(double d50, const std::string& extra) {
    return fmt::format(R"(
dimensions = 3
[time]
end = 0.6
[output]
vtk = false
[domain]
min = [-0.05, -0.05, -0.05]
max = [0.35, 0.35, 0.6]
[rigid]
dt = 2e-5
contact_spacing = 0.004
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
rocks = ["{0}rock_a.stl", "{0}rock_b.stl", "{0}rock_c.stl"]
min = [0.03, 0.03, 0.35]
max = [0.27, 0.27, 0.55]
times = [0, 0.3, 0.6]
discharge = [4e-5, 4e-5, 0]
size = {{distribution = "lognormal", d50 = {2}, sigma = 0.15, min = {3}, max = {4}}}
[[wall]]
name = "bin"
shape = "box"
min = [0, 0, 0]
max = [0.3, 0.3, 0.02]
{1}
)",
                       library, extra, d50, 0.75 * d50, 1.3 * d50);
}

} // namespace

// Wadell sphericity psi = pi^(1/3) (6V)^(2/3) / A: a cube's is (pi/6)^(1/3) = 0.80600 exactly.
TEST(RockFeed, SphericityOfACubeIsExact) {
    const std::string path = ::testing::TempDir() + "/cube_psi.stl";
    {
        std::ofstream o(path);
        o << "solid cube\n";
        const double v[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                                {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
        const int f[12][3] = {{0, 2, 1}, {0, 3, 2}, {4, 5, 6}, {4, 6, 7}, {0, 1, 5}, {0, 5, 4},
                              {1, 2, 6}, {1, 6, 5}, {2, 3, 7}, {2, 7, 6}, {3, 0, 4}, {3, 4, 7}};
        for (const auto& t : f) {
            o << " facet normal 0 0 0\n  outer loop\n";
            for (int k : t)
                o << "   vertex " << v[k][0] << ' ' << v[k][1] << ' ' << v[k][2] << '\n';
            o << "  endloop\n endfacet\n";
        }
        o << "endsolid cube\n";
    }
    const auto cube = scenario::TriangleMesh::read_stl(path, 2.5, {1, 2, 3});
    EXPECT_NEAR(flow::sphericity(cube), std::cbrt(pi / 6), 1e-12);
}

// Every rock keeps its equivalent-sphere volume (stretch a b c = 1), its sphericity within
// +-15 % of its library shape (the section A bound) and is actually reshaped.
TEST(RockFeed, RocksKeepVolumeAndSphericityBound) {
    const auto spec = test::case_from_toml("rocks_shape", rock_case(0.015, ""));
    flow::RockFeed feed(spec.rigid.feeds.at(0), spec);
    for (std::size_t k = 0; k < 3; ++k) { // tools/make_rock_library.py: 0.900, 0.868, 0.935
        EXPECT_GT(feed.shape_sphericity(k), 0.8);
        EXPECT_LT(feed.shape_sphericity(k), 1.0);
    }
    double lo = 1, hi = 1;
    for (int n = 0; n < 200; ++n) {
        const double d = 0.02 + 0.0001 * n;
        double ratio;
        const auto rock = feed.make_rock(d, ratio);
        double v = 0;
        for (const auto& t : rock.triangles) v += dot(t.a, cross(t.b, t.c)) / 6;
        EXPECT_NEAR(v / (pi / 6 * d * d * d), 1, 1e-9) << n;
        lo = std::min(lo, ratio), hi = std::max(hi, ratio);
        EXPECT_LE(std::fabs(ratio - 1), 0.15 + 1e-12) << n;
    }
    std::cout << fmt::format("sphericity / shape's: {:.3f} .. {:.3f}\n", lo, hi);
    EXPECT_LT(lo, 0.95); // stretching does reshape the rocks
}

// Released volume follows the hydrograph (4e-5 m^3/s for 0.3 s, then to 0 at 0.6 s:
// 1.8e-5 m^3) within one rock; the rocks are rigid bodies of the material's density that fall
// into the bin.
TEST(RockFeed, ReleasesTargetDischargeAsRigidBodies) {
    app::Simulation sim(test::case_from_toml("rocks_feed", rock_case(0.015, "")));
    sim.run({"", true, 0});
    const auto& f = sim.probe("hopper").finals();
    const double target = 4e-5 * 0.3 + 2e-5 * 0.3;
    const double largest = pi / 6 * std::pow(1.3 * 0.015, 3);
    std::cout << fmt::format("rock feed released {:.4e} m^3 ({} rocks, owed {:.2e}) of {:.4e}\n",
                             f[1], f[3], f[4], target);
    EXPECT_NEAR(f[1], target, largest);
    const auto& bodies = sim.bodies();
    ASSERT_EQ(long(f[3]), long(bodies.bodies().size()));
    double mass = 0, lowest = 1;
    for (std::size_t b = 0; b < bodies.bodies().size(); ++b) {
        mass += bodies.bodies()[b].mass;
        lowest = std::min(lowest, double(bodies.bodies()[b].pos.z));
        EXPECT_NEAR(bodies.bodies()[b].mass / bodies.models()[b].volume, 2650, 1e-9);
    }
    EXPECT_NEAR(mass, f[2], 1e-12 * mass);
    EXPECT_NEAR(mass, 2650 * f[1], 1e-9 * mass);
    // The first rocks (released at ~0.0 s from 0.35-0.55 m) have landed on the bin (z = 0.02).
    EXPECT_LT(lowest, 0.06);
    EXPECT_GT(lowest, 0.02);
}

// With a fluid, each rock brings its SPH shell: boundary particles that move with it, pushed
// by the water it falls into.
TEST(RockFeed, RocksIntoWaterCarryTheirBoundaryParticles) {
    app::Simulation sim(test::case_from_toml("rocks_water", fmt::format(R"(
dimensions = 3
dp = 0.01
[time]
end = 0.3
[output]
vtk = false
[domain]
min = [-0.05, -0.05, -0.05]
max = [0.35, 0.35, 0.4]
[sph]
c0 = 15
[rigid]
contact_spacing = 0.01
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
rocks = ["{0}rock_a.stl", "{0}rock_b.stl"]
min = [0.03, 0.03, 0.19]
max = [0.27, 0.27, 0.3]
discharge = 1e-3
size = {{distribution = "mono", diameter = 0.04}}
[[fluid]]
name = "pool"
shape = "box"
min = [0.03, 0.03, 0.0]
max = [0.27, 0.27, 0.1]
[[wall]]
name = "tank"
shape = "open_tank"
min = [0.03, 0.03, 0.0]
max = [0.27, 0.27, 0.18]
)",
                                                                        library)));
    const auto boundary0 = sim.particles().count(particles::Kind::boundary);
    const auto fluid0 = sim.particles().count(particles::Kind::fluid);
    sim.run({"", true, 0});
    const auto& f = sim.probe("hopper").finals();
    const auto& bodies = sim.bodies();
    ASSERT_GE(bodies.bodies().size(), 2u);
    EXPECT_EQ(long(f[3]), long(bodies.bodies().size()));
    EXPECT_GT(sim.particles().count(particles::Kind::boundary), boundary0);
    EXPECT_EQ(sim.particles().count(particles::Kind::fluid), fluid0);
    // The first rock (released at 0.034 s, centre z >= 0.21 m) has fallen into the pool
    // (surface z = 0.1 m) by 0.3 s: the water pushed up on it.
    double lowest = 1, fluid_push = 0;
    for (std::size_t b = 0; b < bodies.bodies().size(); ++b) {
        lowest = std::min(lowest, double(bodies.bodies()[b].pos.z));
        fluid_push = std::max(fluid_push, double(bodies.loads()[b].fluid_force.z));
    }
    std::cout << fmt::format(
        "{} rocks, lowest at z = {:.3f} m, largest upward fluid force {:.3g} N\n",
        bodies.bodies().size(), lowest, fluid_push);
    EXPECT_LT(lowest, 0.1);
    EXPECT_GT(fluid_push, 0);
}

// An outlet takes the rocks that fall through it, with their SPH shells: a dry band between
// the hopper and the pool (z 0.12-0.16 m). Every rock released early enough falls through it
// and is removed there (parked at rest, no boundary particles left, its mass counted once);
// none reaches the water, and no fluid is touched.
TEST(RockFeed, RocksFallingThroughAnOutletLeaveWithTheirShells) {
    app::Simulation sim(test::case_from_toml("rocks_outlet", fmt::format(R"(
dimensions = 3
dp = 0.01
[time]
end = 0.3
[output]
vtk = false
[domain]
min = [-0.05, -0.05, -0.05]
max = [0.35, 0.35, 0.4]
[sph]
c0 = 15
[rigid]
contact_spacing = 0.01
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
rocks = ["{0}rock_a.stl", "{0}rock_b.stl"]
min = [0.03, 0.03, 0.19]
max = [0.27, 0.27, 0.3]
discharge = 1e-3
size = {{distribution = "mono", diameter = 0.04}}
[[fluid]]
name = "pool"
shape = "box"
min = [0.03, 0.03, 0.0]
max = [0.27, 0.27, 0.1]
[[wall]]
name = "tank"
shape = "open_tank"
min = [0.03, 0.03, 0.0]
max = [0.27, 0.27, 0.18]
[[outlet]]
name = "band"
min = [0.0, 0.0, 0.12]
max = [0.3, 0.3, 0.16]
every = 0.01
)",
                                                                         library)));
    const auto fluid0 = sim.particles().count(particles::Kind::fluid);
    sim.run({"", true, 0});
    const auto& bodies = sim.bodies();
    const auto& band = sim.probe("band").finals(); // ..., body_mass, bodies
    double mass = 0;
    long removed = 0;
    for (std::size_t b = 0; b < bodies.bodies().size(); ++b) {
        const auto& s = bodies.bodies()[b];
        if (bodies.removed(int(b))) {
            ++removed;
            mass += s.mass;
            EXPECT_EQ(bodies.particles_of(int(b)), 0u) << b;
            EXPECT_EQ(norm(s.vel), 0) << b;
            EXPECT_GE(s.pos.z, 0.12) << b;
            EXPECT_LE(s.pos.z, 0.16) << b;
        } else {
            EXPECT_GT(bodies.particles_of(int(b)), 0u) << b;
            EXPECT_GT(s.pos.z, 0.16) << b << ": a rock got past the band";
        }
    }
    std::cout << fmt::format("{} of {} rocks taken by the outlet ({:.4g} kg)\n", removed,
                             bodies.bodies().size(), mass);
    // Released from 0.034 s at ~30 rocks/s, falling 0.05-0.14 m to the band: most by 0.3 s.
    EXPECT_GE(removed, 3);
    EXPECT_LT(removed, long(bodies.bodies().size())); // the last ones are still falling
    EXPECT_EQ(long(band.at(band.size() - 1)), removed);
    EXPECT_NEAR(band.at(band.size() - 2), mass, 1e-12 * mass);
    EXPECT_EQ(sim.particles().count(particles::Kind::fluid), fluid0);
}
