// mDBC boundary density (sph/mdbc_k.hpp): a boundary particle whose ghost node lies inside a
// fluid of uniform density takes that density; one whose ghost node sees less than half a
// kernel of fluid keeps the density DBC's continuity equation gave it (never below rho_min)
// where the ghost lies in a thin sheet or sees no fluid at all, and carries at most the air's
// pressure (p = 0) where the ghost lies in air beside the fluid.
// The no-slip variant (sph.no_slip = "mdbc") also mirrors the fluid's velocity at the ghost
// node: a linear shear flow is reproduced there exactly (first-order consistency).
#include "debrisflow/kernels/wendland_c2_k.hpp"
#include "debrisflow/neighbors/cell_grid.hpp"
#include "debrisflow/particles/particle_set.hpp"
#include "debrisflow/sph/mdbc_k.hpp"
#include <array>
#include <gtest/gtest.h>
#include <vector>

using namespace debrisflow;

namespace {

constexpr Real dp = 0.01, h = 1.5 * dp, rho_fluid = 1003;

// A 2D floor of three boundary layers under `fluid_rows` rows of fluid at rho_fluid, the first
// `empty_rows` rows above the floor left empty; `probe` is the middle particle of the floor's
// top layer (its ghost node at z = dp/2, the first row's height).
struct Floor {
    particles::ParticleSet set;
    neighbors::CellGrid grid;
    Index probe = -1;

    explicit Floor(int fluid_rows, int empty_rows = 0) {
        const int nx = 20;
        for (int layer = 0; layer < 3; ++layer)
            for (int i = 0; i < nx; ++i) {
                const Index k = set.size();
                set.add({(i + Real(0.5)) * dp, 0, -(layer + Real(0.5)) * dp}, {}, 1000,
                        1000 * dp * dp, particles::Kind::boundary, 0);
                set.wnz[k] = 1;
                set.wd[k] = (layer + Real(0.5)) * dp;
                if (layer == 0 && i == nx / 2) probe = k;
            }
        for (int row = empty_rows; row < empty_rows + fluid_rows; ++row)
            for (int i = 0; i < nx; ++i)
                set.add({(i + Real(0.5)) * dp, 0, (row + Real(0.5)) * dp}, {}, rho_fluid,
                        1000 * dp * dp, particles::Kind::fluid, 0);
        grid.configure({0, 0, -4 * dp}, {nx * dp, 0, 12 * dp}, 2 * h, 2, {false, false, false});
        grid.build(set.x.data(), set.y.data(), set.z.data(), set.size());
    }

    // The ghost-node record (v_g - v_b, seen) of the probe after mDBC with the no-slip variant.
    std::array<Real, 4> ghost_after_mdbc() {
        std::vector<Real> ghost(4 * std::size_t(set.size()), Real(-1));
        const sph::MdbcDensity<kernels::WendlandC2> mdbc{
            set.view(), grid.view(), kernels::WendlandC2(h, 2), h, 1000, 1000, dp, 2, ghost.data()};
        mdbc(probe);
        const auto k = 4 * std::size_t(probe);
        return {ghost[k], ghost[k + 1], ghost[k + 2], ghost[k + 3]};
    }

    Real boundary_density_after_mdbc(Real before, Real rho_min = 1000) {
        set.rho[probe] = before;
        const sph::MdbcDensity<kernels::WendlandC2> mdbc{
            set.view(), grid.view(), kernels::WendlandC2(h, 2), h, rho_min, 1000, dp, 2};
        mdbc(probe);
        return set.rho[probe];
    }
};

TEST(MdbcDensity, GhostInsideTheFluidTakesTheFluidsDensity) {
    Floor f(8); // the ghost, 1 dp above the surface, is under 7 more rows of fluid
    EXPECT_NEAR(f.boundary_density_after_mdbc(1000), rho_fluid, 1e-9 * rho_fluid);
    EXPECT_NEAR(f.boundary_density_after_mdbc(1010), rho_fluid, 1e-9 * rho_fluid);
}

TEST(MdbcDensity, DryGhostKeepsTheContinuityDensity) {
    Floor f(0); // no fluid at all: nothing to mirror
    EXPECT_EQ(f.boundary_density_after_mdbc(1007), 1007);
    EXPECT_EQ(f.boundary_density_after_mdbc(990), 1000); // never below rho_min
}

TEST(MdbcDensity, GhostInASheetKeepsTheContinuityDensity) {
    // one row of fluid on the floor: the ghost node sits on a fluid particle, the kernel sum
    // is below 1/2 and the matrix singular (no extent across the row); the sheet is pressing
    // on the wall, and DBC's density repels it
    Floor f(1);
    EXPECT_EQ(f.boundary_density_after_mdbc(1007), 1007);
}

TEST(MdbcDensity, GhostInAirCarriesAtMostTheAirsPressure) {
    // the same row 1 dp higher: the nearest fluid particle is 1 dp from the ghost node, more
    // than half a lattice cell's diagonal (0.71 dp), so the ghost lies in air beside the fluid
    Floor f(1, 1);
    EXPECT_EQ(f.boundary_density_after_mdbc(1007), 1000);    // p = 0, not DBC's 1007
    EXPECT_EQ(f.boundary_density_after_mdbc(999), 1000);     // never below rho_min
    EXPECT_EQ(f.boundary_density_after_mdbc(999, 990), 999); // below p = 0 if rho_min allows
}

TEST(MdbcDensity, NoSlipGhostVelocityOfALinearShearFlow) {
    Floor f(8);
    // u = gamma z in the fluid; the probe's ghost node is at z = dp/2 (the probe at -dp/2)
    const Real gamma = 3;
    for (Index i = 0; i < f.set.size(); ++i)
        if (f.set.kind[i] == std::uint8_t(particles::Kind::fluid)) f.set.vx[i] = gamma * f.set.z[i];
    const auto g = f.ghost_after_mdbc();
    EXPECT_NEAR(g[0], gamma * Real(0.5) * dp, 1e-12);
    EXPECT_EQ(g[1], 0);
    EXPECT_NEAR(g[2], 0, 1e-12);
    EXPECT_EQ(g[3], 1);
    // the mirrored wall velocity 2 v_w - v_g continues the profile linearly to z = -dp/2
    EXPECT_NEAR(-g[0], gamma * f.set.z[f.probe], 1e-12);
}

TEST(MdbcDensity, NoSlipDryGhostCarriesNoVelocity) {
    Floor f(0);
    const auto g = f.ghost_after_mdbc();
    for (Real c : g) EXPECT_EQ(c, 0);
}

} // namespace
