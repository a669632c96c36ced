// The half-pair-list scatter loop (host) and the per-particle gather loop (the GPU layout)
// evaluate the same WCSPH terms: accelerations and density rates must agree.
#include "run_case.hpp"
#include <gtest/gtest.h>

using namespace debrisflow;

namespace {

void compare(const std::vector<std::string>& sets) {
    auto spec = io::read_case(std::string(DEBRISFLOW_SOURCE_DIR) + "/cases/dambreak2d.toml", sets);
    app::Simulation sim(spec);
    auto& solver = sim.solver();
    auto& s = sim.particles();
    // Disturb the lattice so that every term is active.
    for (Index i = 0; i < s.size(); ++i) {
        if (s.kind[i] != 0) continue;
        s.vx[i] = 0.3 * std::sin(37.0 * i);
        s.vz[i] = 0.2 * std::cos(11.0 * i);
        s.rho[i] *= 1 + 0.002 * std::sin(5.0 * i);
        s.x[i] += 0.1 * spec.dp * std::sin(3.0 * i);
    }
    solver.update_neighbors(true);
    solver.compute_forces();
    const std::vector<Real> ax = s.ax, az = s.az, drho = s.drho;
    solver.compute_forces_gather();
    double amax = 0, dmax = 0;
    for (Index i = 0; i < s.size(); ++i) {
        amax = std::max({amax, std::abs(s.ax[i]), std::abs(s.az[i])});
        dmax = std::max(dmax, std::abs(s.drho[i]));
    }
    for (Index i = 0; i < s.size(); ++i) {
        ASSERT_NEAR(ax[i], s.ax[i], 1e-9 * amax) << i;
        ASSERT_NEAR(az[i], s.az[i], 1e-9 * amax) << i;
        ASSERT_NEAR(drho[i], s.drho[i], 1e-9 * dmax) << i;
    }
}

} // namespace

TEST(ScatterGather, ArtificialFourtakas) {
    compare({});
}
TEST(ScatterGather, LaminarMolteni) {
    compare({"sph.viscosity=\"laminar\"", "sph.nu=1e-3", "sph.diffusion=\"molteni\""});
}
TEST(ScatterGather, SpsCubic) {
    compare({"sph.viscosity=\"laminar_sps\"", "sph.nu=1e-6", "sph.kernel=\"cubic_spline\""});
}
