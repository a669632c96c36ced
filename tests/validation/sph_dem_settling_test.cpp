// A grain settling in a quiescent viscous fluid with the unresolved SPH-DEM coupling
// (cases/coupling/settling_grain.toml: d = 15 mm in a 1 m tank, kernel support 10 d).
// Reference: the unbounded terminal velocity with the Schiller-Naumann drag of ten Cate et
// al.'s (2002) cases E1 and E4 (analytic/tencate_params_and_unbounded_terminal_velocity.csv):
// the buoyancy comes from the SPH pressure gradient, the drag from the interpolated fluid
// velocity. Tolerance 5 %: the buoyancy is 87 % of the weight, so a 1 % error of the SPH
// hydrostatic gradient moves the terminal velocity by about 7 %.
#include "reference_data.hpp"
#include "run_case.hpp"
#include <cmath>
#include <fmt/format.h>
#include <gtest/gtest.h>

using namespace debrisflow;

namespace {

struct TenCate {
    std::string name;
    Real rho_f, mu, v_sn;
};

TenCate reference_case(const std::string& name) {
    const auto rows = test::read_table(
        test::reference("analytic/tencate_params_and_unbounded_terminal_velocity.csv"));
    for (const auto& r : rows)
        if (r.at("case") == name)
            return {name, std::stod(r.at("rho_f")), std::stod(r.at("mu[Pa s]")),
                    std::stod(r.at("v_SchillerNaumann_unbounded[m/s]"))};
    throw std::runtime_error("no ten Cate case " + name);
}

// Settling velocity of the grain at the given times.
std::vector<Real> settle(const TenCate& c, const std::vector<Real>& times) {
    app::Simulation sim(io::read_case(
        std::string(DEBRISFLOW_SOURCE_DIR) + "/cases/coupling/settling_grain.toml",
        {fmt::format("sph.rho0={}", c.rho_f), fmt::format("sph.nu={}", c.mu / c.rho_f),
         fmt::format("time.end={}", times.back())}));
    std::vector<Real> v;
    for (Real t : times) {
        sim.run({"", true, 0, t});
        v.push_back(-sim.grains().grains().vel[0].z);
    }
    return v;
}

void check(const std::string& name, const std::vector<Real>& times) {
    const TenCate c = reference_case(name);
    const auto v = settle(c, times);
    for (std::size_t k = 0; k < times.size(); ++k)
        std::printf("ten Cate %s, unresolved: t = %.2f s, v = %.4f m/s vs Schiller-Naumann "
                    "%.4f (%+.1f %%)\n",
                    name.c_str(), times[k], v[k], c.v_sn, 100 * (v[k] / c.v_sn - 1));
    // terminal: the last two samples within the tolerance of the reference
    for (std::size_t k = times.size() - 2; k < times.size(); ++k)
        EXPECT_NEAR(v[k] / c.v_sn, 1, 0.05) << "t = " << times[k];
}

} // namespace

// Re 1.5: relaxation time ~0.03 s, terminal by 0.2 s.
TEST(SphDemSettling, TenCateE1TerminalVelocity) {
    check("E1", {0.1, 0.2, 0.3});
}

// Re 32: drag 2.6 x Stokes, relaxation time ~0.1 s, terminal by 0.6 s.
TEST(SphDemSettling, TenCateE4TerminalVelocity) {
    check("E4", {0.3, 0.6, 0.8});
}
