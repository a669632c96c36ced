// Removing particles (an outlet) compacts the half pair list instead of rebuilding it: the
// compacted list must hold exactly the pairs a fresh build gives at the same positions, and
// the forces evaluated with it must equal those after a rebuild.
#include "run_case.hpp"
#include <algorithm>
#include <gtest/gtest.h>
#include <set>
#include <utility>

using namespace debrisflow;

namespace {

std::set<std::pair<ParticleId, ParticleId>> pairs_by_id(const neighbors::PairList& list,
                                                        const particles::ParticleSet& s) {
    std::set<std::pair<ParticleId, ParticleId>> out;
    for (Index i = 0; i < list.particles(); ++i)
        for (Index k = 0; k < list.count(i); ++k) {
            const ParticleId a = s.id[std::size_t(i)];
            const ParticleId b = s.id[std::size_t(list.neighbors()[list.begin(i) + k])];
            out.insert({std::min(a, b), std::max(a, b)});
        }
    return out;
}

} // namespace

TEST(PairListCompact, EqualsAFreshBuildAndGivesTheSameForces) {
    auto spec = io::read_case(std::string(DEBRISFLOW_SOURCE_DIR) + "/cases/dambreak2d.toml",
                              {"sph.viscosity=\"laminar_sps\"", "sph.nu=1e-6"});
    app::Simulation sim(spec);
    auto& solver = sim.solver();
    auto& s = sim.particles();
    for (Index i = 0; i < s.size(); ++i)
        if (s.kind[i] == 0) s.vx[i] = 0.3 * std::sin(37.0 * i);
    solver.update_neighbors(true);
    const long builds = solver.list_builds();
    // Remove every fifth fluid particle and a few boundary particles.
    std::vector<std::uint8_t> keep(std::size_t(s.size()), 1);
    Index removed = 0;
    for (Index i = 0; i < s.size(); ++i)
        if ((s.kind[i] == 0 && i % 5 == 0) || (s.kind[i] != 0 && i % 97 == 0)) {
            keep[std::size_t(i)] = 0;
            ++removed;
        }
    ASSERT_GT(removed, 10);
    solver.remove_particles(keep);
    solver.update_neighbors(false);
    ASSERT_EQ(solver.list_builds(), builds) << "removal forced a rebuild";
    ASSERT_EQ(solver.pair_list().particles(), s.size());
    const auto compacted = pairs_by_id(solver.pair_list(), s);
    const std::vector<Real> tau = s.sps_tau; // the stress both evaluations start from
    solver.compute_forces();
    const std::vector<Real> ax = s.ax, az = s.az, drho = s.drho;

    neighbors::PairList fresh;
    neighbors::CellGrid grid;
    const Real radius = 1.1 * solver.support(); // support + skin, as the solver's list
    grid.configure(spec.domain.lo, spec.domain.hi, radius, spec.dim, spec.domain.periodic);
    grid.build(s.x.data(), s.y.data(), s.z.data(), s.size());
    fresh.build(grid.view(), s.view());
    EXPECT_EQ(compacted, pairs_by_id(fresh, s));

    // Forces with a rebuilt list (an inlet particle forces one; it is then removed again).
    s.add({0.05, 0, 0.05}, {}, spec.sph.rho0, s.mass[0], particles::Kind::fluid, 0);
    solver.update_neighbors(false);
    ASSERT_EQ(solver.list_builds(), builds + 1);
    std::vector<std::uint8_t> last(std::size_t(s.size()), 1);
    last.back() = 0;
    s.compact(last);
    solver.update_neighbors(false);
    ASSERT_EQ(solver.list_builds(), builds + 2);
    s.sps_tau = tau;
    solver.compute_forces();
    double amax = 0;
    for (Index i = 0; i < s.size(); ++i) amax = std::max({amax, std::abs(ax[i]), std::abs(az[i])});
    for (Index i = 0; i < s.size(); ++i) {
        ASSERT_NEAR(ax[i], s.ax[i], 1e-9 * amax) << i;
        ASSERT_NEAR(az[i], s.az[i], 1e-9 * amax) << i;
    }
}
