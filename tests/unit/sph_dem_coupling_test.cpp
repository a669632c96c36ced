// Unresolved SPH-DEM coupling (coupling/sph_dem.hpp): momentum exchange and input checks.
#include "debrisflow/core/error.hpp"
#include "run_case.hpp"
#include <cmath>
#include <cstdio>
#include <gtest/gtest.h>

using namespace debrisflow;

namespace {

// A box without gravity, periodic in all three directions.
const std::string box = R"(
name = "sph_dem_momentum"
dimensions = 3
dp = 0.02
[time]
end = 0.05
[output]
vtk = false
[physics]
gravity = [0, 0, 0]
[domain]
min = [0, 0, 0]
max = [0.2, 0.2, 0.2]
periodic = ["x", "y", "z"]
)";
// Water filling it.
const std::string water = R"(
[sph]
rho0 = 1000
c0 = 5
viscosity = "laminar"
nu = 1e-2
[[fluid]]
name = "water"
shape = "box"
min = [0.0, 0.0, 0.0]
max = [0.2, 0.2, 0.2]
)";
// Three sand grains shot through it, coupled to a fluid by the Di Felice drag.
const std::string grains = R"(
[[material]]
name = "sand"
density = 2650
law = "hertz_mindlin"
youngs_modulus = 1e7
poisson = 0.3
restitution = 0.5
friction = 0.3
[[grains]]
name = "a"
material = "sand"
packing = "single"
position = [0.05, 0.1, 0.1]
diameter = 0.005
velocity = [1.0, 0.0, 0.2]
[[grains]]
name = "b"
material = "sand"
packing = "single"
position = [0.15, 0.07, 0.12]
diameter = 0.006
velocity = [-0.5, 0.8, 0.0]
[[grains]]
name = "c"
material = "sand"
packing = "single"
position = [0.1, 0.15, 0.05]
diameter = 0.004
velocity = [0.0, -0.3, 0.9]
[dem]
fluid_drag = "di_felice"
reference_velocity = 1.0
)";
// A fully periodic box of fluid at rest without gravity and three grains shot through it: no
// wall takes momentum, so the grains' loss must all show up in the fluid.
const std::string periodic_box = box + water + grains;

Vec3 fluid_momentum(particles::ParticleSet& s) {
    Vec3 p{};
    for (Index i = 0; i < s.size(); ++i)
        if (s.kind[std::size_t(i)] == std::uint8_t(particles::Kind::fluid))
            p += s.mass[std::size_t(i)] *
                 Vec3{s.vx[std::size_t(i)], s.vy[std::size_t(i)], s.vz[std::size_t(i)]};
    return p;
}

Vec3 grain_momentum(const dem::GrainSet& g) {
    Vec3 p{};
    for (Index i = 0; i < g.size(); ++i) p += g.mass[std::size_t(i)] * g.vel[std::size_t(i)];
    return p;
}

} // namespace

// Newton's third law across the coupling: the fluid gains what the grains lose, up to the
// impulse of the last DEM advance (handed to the fluid at the next step).
void check_momentum(const std::vector<std::string>& sets, double tolerance) {
    app::Simulation sim(test::case_from_toml("sph_dem_momentum", periodic_box, sets));
    const Vec3 g0 = grain_momentum(sim.grains().grains());
    const Vec3 total0 = g0 + fluid_momentum(sim.particles());
    sim.run({"", true, 1, 0});
    const Vec3 g1 = grain_momentum(sim.grains().grains());
    const Vec3 total1 = g1 + fluid_momentum(sim.particles());
    std::printf("grain momentum %.4g -> %.4g kg m/s; total changed by %.3g kg m/s\n", norm(g0),
                norm(g1), norm(total1 - total0));
    // the drag took a sizeable share of the grains' momentum ...
    EXPECT_LT(norm(g1), 0.8 * norm(g0));
    // ... and the total kept all but what the last step has yet to hand over
    EXPECT_LT(norm(total1 - total0), tolerance * norm(g0 - g1));
}

TEST(SphDemCoupling, ConservesMomentumInAPeriodicBox) {
    check_momentum({}, 1e-3);
}

// The Verlet scheme hands the reaction over with the step just taken (it has no predictor).
// Its leapfrog v_n+1 = v_n-1 + 2 dt a_n carries the impulse of every other step twice, so the
// fluid's momentum differs from the exchanged total by the alternating sum of the step
// impulses, at most the largest one: with the drag relaxing over ~10 fluid steps (ν = 1e-4,
// Re ~50), up to ~10 %. Without the handover the fluid would gain nothing.
TEST(SphDemCoupling, ExchangesMomentumWithTheVerletScheme) {
    check_momentum({"time.scheme=\"verlet\"", "sph.nu=1e-4", "time.end=0.1"}, 0.1);
}

// The reaction is gathered per fluid particle (no atomic scatter, whose order of additions
// varies between runs), so a coupled run on two threads repeats itself to the last bit. A
// cloud of 60 grains, whose kernel neighbourhoods overlap, crosses the box.
TEST(SphDemCoupling, RepeatsItselfBitwiseOnTwoThreads) {
    const std::string cloud = grains + R"(
[[grains]]
name = "cloud"
material = "sand"
diameter = 0.004
count = 60
velocity = [0.8, 0.3, 0.0]
[grains.region]
shape = "box"
min = [0.06, 0.06, 0.06]
max = [0.14, 0.14, 0.14]
)";
    std::vector<Vec3> grain_vel[2];
    std::vector<Real> fluid_vx[2];
    for (int t = 0; t < 2; ++t) {
        app::Simulation sim(test::case_from_toml("sph_dem_cloud", box + water + cloud, {}));
        sim.run({"", true, 2, 0});
        grain_vel[t] = sim.grains().grains().vel;
        fluid_vx[t] = sim.particles().vx;
    }
    ASSERT_EQ(grain_vel[0].size(), grain_vel[1].size());
    for (std::size_t i = 0; i < grain_vel[0].size(); ++i)
        for (int d = 0; d < 3; ++d) EXPECT_EQ(grain_vel[0][i][d], grain_vel[1][i][d]) << i;
    ASSERT_EQ(fluid_vx[0].size(), fluid_vx[1].size());
    std::size_t differ = 0;
    for (std::size_t j = 0; j < fluid_vx[0].size(); ++j) differ += fluid_vx[0][j] != fluid_vx[1][j];
    EXPECT_EQ(differ, 0u) << "fluid particles whose velocity differs between the runs";
}

// The coupling needs a fluid and 3D spheres; the reader says so with the key.
TEST(SphDemCoupling, RejectsACaseWithoutFluid) {
    try {
        test::case_from_toml("sph_dem_no_fluid", box + grains);
        FAIL() << "accepted fluid_drag without a fluid";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("fluid_drag"), std::string::npos) << e.what();
    }
}
