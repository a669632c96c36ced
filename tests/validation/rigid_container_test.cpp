// Container carried by a dam-break flood (issue 4, test 6; section C of seed_experiments.md),
// reduced to a 2D slice with a 3 m reservoir: cases/papers/container_dambreak2d_reduced.toml.
#include "run_case.hpp"
#include <cmath>
#include <gtest/gtest.h>

using namespace debrisflow;

namespace {

struct ContainerRun {
    std::vector<std::vector<Real>> front, container, wg1;
    Real fluid_mass0 = 0, fluid_mass1 = 0;
};

ContainerRun run_container(Real until) {
    app::Simulation sim(io::read_case(std::string(DEBRISFLOW_SOURCE_DIR) +
                                          "/cases/papers/container_dambreak2d_reduced.toml",
                                      {}));
    auto fluid_mass = [&] {
        Real m = 0;
        const auto& s = sim.particles();
        for (Index i = 0; i < s.size(); ++i)
            if (s.kind[i] == std::uint8_t(particles::Kind::fluid)) m += s.mass[i];
        return m;
    };
    ContainerRun r;
    r.fluid_mass0 = fluid_mass();
    sim.run({"", true, 0, until});
    r.fluid_mass1 = fluid_mass();
    r.front = sim.probe("front").history();
    r.container = sim.probe("container").history();
    r.wg1 = sim.probe("WG1").history();
    return r;
}

// Time at which the front first reaches x.
Real arrival(const std::vector<std::vector<Real>>& front, Real x) {
    for (std::size_t k = 1; k < front.size(); ++k)
        if (front[k][1] >= x) {
            const Real f = (x - front[k - 1][1]) / (front[k][1] - front[k - 1][1]);
            return front[k - 1][0] + f * (front[k][0] - front[k - 1][0]);
        }
    return -1;
}

} // namespace

TEST(RigidContainer, ContainerRestsUntilTheBoreArrivesThenIsCarried) {
    // Causality and conservation (no published number involved): the container does not move
    // before the front is within the kernel support of its upstream face (x = 3.125 m; 0.05 s at
    // the bore speed), is moving downstream within
    // 0.25 s of it, the floor contact keeps it on the floor (|dz| < 2 mm, it is too heavy to
    // float in the thin bore), and no fluid mass is created or lost.
    const ContainerRun r = run_container(2.2);
    const Real t_hit = arrival(r.front, 3.125);
    ASSERT_GT(t_hit, 0);
    const Real x0 = r.container[0][1], z0 = r.container[0][3];
    Real moved_before = 0, dz = 0, vx_after = 0;
    for (const auto& row : r.container) {
        if (row[0] < t_hit - 0.05) moved_before = std::max(moved_before, std::fabs(row[1] - x0));
        dz = std::max(dz, std::fabs(row[3] - z0));
        if (row[0] <= t_hit + 0.25) vx_after = row[7];
    }
    std::printf("container: bore reaches it at %.3f s; max |dx| before %.2e m; vx %.3f m/s "
                "0.25 s later; max |dz| %.2e m\n",
                t_hit, moved_before, vx_after, dz);
    EXPECT_LT(moved_before, 1e-3);
    EXPECT_GT(vx_after, 0.1);
    EXPECT_LT(dz, 2e-3);
    EXPECT_NEAR(r.fluid_mass1 / r.fluid_mass0, 1, 1e-12);
}

TEST(RigidContainerKnownGap, BoreFrontSpeedAtWG3) {
    // Section C: bore front speed at WG3 2.53 m/s (DualSPHysics), 2.46 m/s (experiment),
    // 2.65 m/s (Chanson). Tolerance 10 % of the experiment. The 2D slice gives 1.4 m/s with
    // the paper's x9 boundary viscosity (1.9 m/s without it): see docs/validation.md.
    const ContainerRun r = run_container(2.2);
    const Real speed = 0.4 / (arrival(r.front, 3.1) - arrival(r.front, 2.7));
    std::printf("bore front speed 2.7-3.1 m: %.3f m/s (experiment 2.46, paper SPH 2.53)\n", speed);
    EXPECT_NEAR(speed / 2.46, 1, 0.10);
}
