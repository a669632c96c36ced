// delta-plus-SPH particle shifting (Sun et al. 2017; sph/particle_shifting.cpp) on the demo's
// water column (0.6 x 0.3 m, dp = 7.5 mm, against the tank's left wall and floor).
#include "run_case.hpp"
#include <cmath>
#include <gtest/gtest.h>

using namespace debrisflow;

namespace {

struct Column {
    io::CaseSpec spec;
    std::unique_ptr<app::Simulation> sim;
    explicit Column(const std::vector<std::string>& sets) {
        std::vector<std::string> all{"sph.shifting=\"delta_plus\""};
        all.insert(all.end(), sets.begin(), sets.end());
        spec = io::read_case(std::string(DEBRISFLOW_SOURCE_DIR) + "/cases/dambreak2d.toml", all);
        sim = std::make_unique<app::Simulation>(spec);
    }
    particles::ParticleSet& set() { return sim->particles(); }
};

constexpr Real column_top = 0.3, column_right = 0.6;

} // namespace

// On a regular lattice moving as a whole the concentration is uniform inside the fluid: no
// particle away from the free surface moves; on the free surface and the rows below it (inside
// the kernel support) no particle moves outward.
TEST(ParticleShifting, UniformLatticeStaysAndSurfaceHoldsItsPlace) {
    Column c({});
    auto& s = c.set();
    for (Index i = 0; i < s.size(); ++i)
        if (s.kind[i] == 0) s.vx[i] = 1;
    c.sim->solver().update_neighbors(false);
    const std::vector<Real> x0 = s.x, z0 = s.z;
    const Real dt = 1e-4, dp = c.spec.dp, h = c.spec.sph.h;
    c.sim->solver().shift_particles(dt);
    const Real limit = 0.5 * 1.0 * dt; // |dr| <= U_max dt / 2
    int interior = 0, top = 0, right = 0;
    for (Index i = 0; i < s.size(); ++i) {
        if (s.kind[i] != 0) continue;
        const Real dx = s.x[i] - x0[i], dz = s.z[i] - z0[i];
        ASSERT_LE(std::hypot(dx, dz), limit * (1 + 1e-12)) << i;
        const bool near_top = z0[i] > column_top - 2 * h, near_right = x0[i] > column_right - 2 * h;
        if (!near_top && !near_right) {
            ++interior; // lattice and wall layers at the same spacing: the sums cancel
            ASSERT_NEAR(dx, 0, 1e-9 * dp) << "x " << x0[i] << " z " << z0[i];
            ASSERT_NEAR(dz, 0, 1e-9 * dp) << "x " << x0[i] << " z " << z0[i];
        }
        if (near_top && x0[i] < 4 * h) {
            // within two kernel supports of where the surface meets the wall (the boundary
            // particles above the water tilt the surface particles' normals, which are summed
            // over a support) a small outward part remains
            ASSERT_LE(dz, 0.02 * limit) << "x " << x0[i] << " z " << z0[i];
        } else if (near_top && x0[i] < column_right - 3 * h) {
            ++top;
            ASSERT_LE(dz, 1e-9 * dp) << "moved out of the top surface: x " << x0[i] << " z "
                                     << z0[i];
        }
        if (near_right && z0[i] < 4 * h) {
            ASSERT_LE(dx, 0.02 * limit) << "x " << x0[i] << " z " << z0[i]; // floor contact line
        } else if (near_right && z0[i] < column_top - 3 * h) {
            ++right;
            ASSERT_LE(dx, 1e-9 * dp) << "moved out of the right surface: x " << x0[i] << " z "
                                     << z0[i];
        }
    }
    EXPECT_GT(interior, 2000);
    EXPECT_GT(top, 100);
    EXPECT_GT(right, 40);
}

// A particle pushed off its lattice site inside the fluid is shifted back towards it, by no
// more than U_max dt / 2, and its neighbours move the other way (the sums are antisymmetric).
TEST(ParticleShifting, DisplacedParticleIsPushedBack) {
    Column c({});
    auto& s = c.set();
    const Real dp = c.spec.dp;
    Index k = -1;
    for (Index i = 0; i < s.size(); ++i) {
        if (s.kind[i] != 0) continue;
        s.vx[i] = 0.5;
        if (k < 0 && std::abs(s.x[i] - 0.3) < 0.6 * dp && std::abs(s.z[i] - 0.15) < 0.6 * dp)
            k = i;
    }
    ASSERT_GE(k, 0);
    const Real site = s.x[k];
    s.x[k] += 0.2 * dp;
    c.sim->solver().update_neighbors(false);
    const Real moved = s.x[k];
    const Real dt = 1e-4;
    c.sim->solver().shift_particles(dt);
    const Real dx = s.x[k] - moved;
    EXPECT_LT(dx, 0); // back towards the site
    EXPECT_GE(dx, -0.5 * 0.5 * dt * (1 + 1e-12));
    EXPECT_GT(s.x[k], site); // not past it
}

// No shifting unless asked for.
TEST(ParticleShifting, NoneLeavesParticlesAlone) {
    Column c({"sph.shifting=\"none\""});
    auto& s = c.set();
    for (Index i = 0; i < s.size(); ++i)
        if (s.kind[i] == 0) s.vx[i] = 1, s.x[i] += 0.1 * c.spec.dp * std::sin(3.0 * i);
    c.sim->solver().update_neighbors(false);
    const std::vector<Real> x0 = s.x;
    c.sim->solver().shift_particles(1e-4);
    EXPECT_EQ(x0, s.x);
}
