// DemSolver::grain_contact_inputs describes exactly what its contact loop evaluates: summing
// GrainSlotContact over every slot (the functor the GPU check runs) reproduces the force and
// torque the solver puts on each grain. This is what makes bench/gpu/gpu_dem_contacts a check
// of the engine and not of a copy of it.
#include "debrisflow/exec/parallel.hpp"
#include "dem_rig.hpp"
#include <cmath>
#include <gtest/gtest.h>

using namespace debrisflow;

namespace {

// A side^3 cube of overlapping Hertz-Mindlin spheres with rolling resistance, stirred with
// deterministic velocities and spins, no gravity, no walls: every force is a grain contact.
// After 50 steps (loaded tangential and rolling springs) the solver re-evaluates its forces
// (step size 0) and the slot sums must equal them to rounding (1e-12 of the largest).
void expect_slot_sums_equal_solver_forces(int side) {
    test::DemRig rig;
    dem::Material m;
    m.name = "rock";
    m.law = "hertz_mindlin";
    m.density = 2650;
    m.youngs_modulus = 1e7;
    m.poisson = 0.3;
    m.restitution = 0.5;
    m.friction = 0.4;
    m.rolling_friction = 0.1;
    const Real r = 0.01, spacing = 1.998 * r;
    int k = 0;
    for (int a = 0; a < side; ++a)
        for (int b = 0; b < side; ++b)
            for (int c = 0; c < side; ++c, ++k) {
                const Index i = rig.add_sphere({a * spacing, b * spacing, c * spacing},
                                               {0.05 * std::sin(1.3 * k), 0.05 * std::cos(0.7 * k),
                                                0.05 * std::sin(2.1 * k + 1)},
                                               r, m.density, 0);
                rig.grains.spin[std::size_t(i)] = {3 * std::cos(1.1 * k), 3 * std::sin(0.9 * k),
                                                   3 * std::cos(1.7 * k + 2)};
            }
    dem::DemParams p;
    p.gravity = {0, 0, 0};
    p.rolling = "epsd";
    rig.start(p, {m}, {-1, -1, -1}, {1, 1, 1});
    for (int s = 0; s < 50; ++s) rig.solver->advance(rig.solver->dt());
    rig.solver->compute_forces(); // the step's closing evaluation is current: no-op

    dem::GrainContactInputs in = rig.solver->grain_contact_inputs();
    in.h = 0; // what compute_forces evaluates with
    const std::size_t n = std::size_t(in.n), slots = n * std::size_t(in.capacity);
    const std::vector<dem::ContactHistory> history = dem::slot_histories(in);
    std::vector<Real> out(9 * slots);
    std::vector<dem::ContactHistory> history_out(slots);
    const dem::GrainSlotContact slot{in, history.data(), out.data(), history_out.data()};
    for (std::size_t s = 0; s < slots; ++s) slot(Index(s));
    rig.solver->compute_forces();

    std::vector<Vec3> f(n), t(n);
    long touching = 0;
    for (std::size_t s = 0; s < slots; ++s) {
        const std::size_t i = s / std::size_t(in.capacity), j = std::size_t(in.partner[s]);
        if (Index(s % std::size_t(in.capacity)) >= in.count[i]) continue;
        const Vec3 r = in.grains[i].x - in.grains[j].x;
        const Real rs = in.grains[i].r + in.grains[j].r;
        if (dot(r, r) >= rs * rs) continue;
        ++touching; // counted as the solver counts, force or not (a damped Hertz force may be 0)
        const Real* o = out.data() + 9 * s;
        f[i] += Vec3{o[0], o[1], o[2]};
        f[j] -= Vec3{o[0], o[1], o[2]};
        t[i] += Vec3{o[3], o[4], o[5]};
        t[j] += Vec3{o[6], o[7], o[8]};
    }
    // the cube is still in contact (3 side^2 (side - 1) lattice bonds at the start: 144 for 4)
    EXPECT_GT(touching, side * side * (side - 1));
    EXPECT_EQ(touching, rig.solver->contacts());
    Real fmax = 0, tmax = 0, df = 0, dt = 0;
    for (std::size_t i = 0; i < n; ++i) {
        fmax = std::max(fmax, norm(rig.grains.force[i]));
        tmax = std::max(tmax, norm(rig.grains.torque[i]));
        df = std::max(df, norm(f[i] - rig.grains.force[i]));
        dt = std::max(dt, norm(t[i] - rig.grains.torque[i]));
    }
    ASSERT_GT(fmax, 0);
    ASSERT_GT(tmax, 0);
    EXPECT_LT(df, 1e-12 * fmax);
    EXPECT_LT(dt, 1e-12 * tmax);
}

} // namespace

TEST(DemContactInputs, SlotSumsReproduceTheSolversContactForces) {
    expect_slot_sums_equal_solver_forces(4);
}

// 17^3 = 4,913 grains, above the size at which the contact loop runs on several threads: on
// two threads each owns a range of grains and hands the reactions on the other's grains over
// after a barrier; the sums must still be every contact's, once.
TEST(DemContactInputs, SlotSumsReproduceTheForcesOfTwoThreadRanges) {
    const int before = exec::max_threads();
    exec::set_threads(2);
    expect_slot_sums_equal_solver_forces(17);
    exec::set_threads(before);
}
