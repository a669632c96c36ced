// The half-pair-list scatter loop (host) and the per-particle gather loop (the GPU layout)
// evaluate the same WCSPH terms: accelerations and density rates must agree.
#include "run_case.hpp"
#include <gtest/gtest.h>

using namespace debrisflow;

namespace {

void compare(const std::vector<std::string>& sets,
             const std::string& file = "cases/dambreak2d.toml") {
    auto spec = io::read_case(std::string(DEBRISFLOW_SOURCE_DIR) + "/" + file, sets);
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
    // A first evaluation leaves the SPS stress of this state for the second (Laminar+SPS uses
    // the previous evaluation's stress): both loops then start from the same stress.
    solver.compute_forces();
    const std::vector<Real> tau0 = s.sps_tau;
    solver.compute_forces();
    const std::vector<Real> ax = s.ax, az = s.az, drho = s.drho, tau = s.sps_tau;
    s.sps_tau = tau0;
    solver.compute_forces_gather();
    double amax = 0, dmax = 0, tmax = 0;
    for (Index i = 0; i < s.size(); ++i) {
        amax = std::max({amax, std::abs(s.ax[i]), std::abs(s.az[i])});
        dmax = std::max(dmax, std::abs(s.drho[i]));
    }
    for (Real t : tau) tmax = std::max(tmax, std::abs(t));
    for (Index i = 0; i < s.size(); ++i) {
        ASSERT_NEAR(ax[i], s.ax[i], 1e-9 * amax) << i;
        ASSERT_NEAR(az[i], s.az[i], 1e-9 * amax) << i;
        ASSERT_NEAR(drho[i], s.drho[i], 1e-9 * dmax) << i;
    }
    // The stress each loop leaves for the next evaluation (zero without SPS).
    ASSERT_EQ(tau.size(), s.sps_tau.size());
    for (std::size_t k = 0; k < tau.size(); ++k)
        ASSERT_NEAR(tau[k], s.sps_tau[k], 1e-9 * tmax) << k;
}

} // namespace

TEST(ScatterGather, ArtificialFourtakas) {
    compare({});
}
TEST(ScatterGather, LaminarMolteni) {
    compare({"sph.viscosity=\"laminar\"", "sph.nu=1e-3", "sph.diffusion=\"molteni\""});
}
// Antuono's diffusion reads the renormalised density gradients: the half list sums them over
// its pairs (SphSolver::update_density_gradient), the gather over cells.
TEST(ScatterGather, ArtificialAntuono) {
    compare({"sph.diffusion=\"antuono\""});
}
// the same in 3D (the half list's 9 sums per particle)
TEST(ScatterGather, ArtificialAntuono3D) {
    compare({"sph.diffusion=\"antuono\"", "dp=0.034"}, "cases/bench/dambreak3d.toml");
}
TEST(ScatterGather, SpsCubic) {
    compare({"sph.viscosity=\"laminar_sps\"", "sph.nu=1e-6", "sph.kernel=\"cubic_spline\""});
}
// The SPS stress the pair loop leaves for the next evaluation (Dalrymple & Rogers 2006 eq. 11
// from the SPH velocity gradient) is non-zero in a shear flow and follows its particle when the set
// is reordered.
TEST(ScatterGather, SpsStressFollowsItsParticle) {
    auto spec = io::read_case(std::string(DEBRISFLOW_SOURCE_DIR) + "/cases/dambreak2d.toml",
                              {"sph.viscosity=\"laminar_sps\"", "sph.nu=1e-6"});
    app::Simulation sim(spec);
    auto& solver = sim.solver();
    auto& s = sim.particles();
    for (Index i = 0; i < s.size(); ++i)
        if (s.kind[i] == 0) s.vx[i] = 0.5 * std::sin(7.0 * s.z[i]) + 0.1 * std::cos(13.0 * i);
    solver.update_neighbors(true);
    solver.compute_forces();
    double tmax = 0;
    for (Real t : s.sps_tau) tmax = std::max(tmax, std::abs(t));
    ASSERT_GT(tmax, 0);
    std::vector<Index> perm(std::size_t(s.size()));
    for (Index i = 0; i < s.size(); ++i) perm[std::size_t(i)] = s.size() - 1 - i;
    const std::vector<Real> before = s.sps_tau;
    const std::vector<ParticleId> ids = s.id;
    s.permute(perm);
    for (Index i = 0; i < s.size(); ++i) {
        const Index old = perm[std::size_t(i)];
        ASSERT_EQ(s.id[std::size_t(i)], ids[std::size_t(old)]);
        for (int k = 0; k < 6; ++k) ASSERT_EQ(s.sps_tau[6 * i + k], before[6 * old + k]);
    }
    std::vector<std::uint8_t> keep(std::size_t(s.size()), 1);
    for (std::size_t i = 0; i < keep.size(); i += 3) keep[i] = 0;
    const std::vector<Real> permuted = s.sps_tau;
    s.compact(keep);
    std::size_t w = 0;
    for (std::size_t i = 0; i < keep.size(); ++i) {
        if (!keep[i]) continue;
        for (int k = 0; k < 6; ++k) ASSERT_EQ(s.sps_tau[6 * w + k], permuted[6 * i + k]);
        ++w;
    }
    ASSERT_EQ(s.sps_tau.size(), 6 * w);
}
