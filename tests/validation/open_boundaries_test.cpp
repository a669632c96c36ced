// Inlet, hydrograph and outlet of a 2D channel (cases/flow/channel_inlet_outlet2d.toml,
// issue #5 "material entering and leaving"). Expected values come from the case's own
// hydrograph: the volume entering is the integral of Q(t) (0.20 m^2 over 9 s), the mass in the
// domain obeys m(t) = m(0) + in - out exactly, and the outlet starts removing fluid when the
// front reaches it (2.3 m downstream). The late outflow rate is printed: at 9 s the channel is
// still filling slowly (outflow 18.8-19.0 kg/s against rho Q = 20.04 kg/s; storage grows by
// ~1 kg/s), so no steady-state rate is asserted.
#include "run_case.hpp"
#include <cmath>
#include <fmt/format.h>
#include <gtest/gtest.h>

using namespace debrisflow;

namespace {
double fluid_mass(app::Simulation& sim) {
    const auto& s = sim.particles();
    double m = 0;
    for (Index i = 0; i < s.size(); ++i)
        if (s.kind[i] == 0) m += s.mass[i];
    return m;
}
} // namespace

TEST(OpenBoundaries, HydrographInflowMassBalanceAndOutflow) {
    app::Simulation sim(io::read_case(std::string(DEBRISFLOW_SOURCE_DIR) +
                                          "/cases/flow/channel_inlet_outlet2d.toml",
                                      {"output.vtk=false", "time.end=9"}));
    const double m0 = fluid_mass(sim);
    sim.run({"", true, 0});
    const auto& in = sim.probe("upstream").finals();
    const auto& out = sim.probe("downstream");
    const double m1 = fluid_mass(sim);
    // Hydrograph 0.02 m^2/s, ramp to 0.04 at 3 s and back at 4 s, run to 9 s: 0.20 m^2.
    const double volume_expected = 0.02 * 2 + 0.03 + 0.03 + 0.02 * 5;
    const double balance = m1 - (m0 + in[2] - out.finals()[0]);
    const double rate = out.mean(4, 8.0, 9.0);
    std::cout << fmt::format("inflow volume {:.5f} m^2 (hydrograph {:.5f}); mass balance error "
                             "{:.2e} kg of {:.3f}; outflow rate 8-9 s {:.3f} kg/s (rho Q = 20)\n",
                             in[3], volume_expected, balance, m1, rate);
    // The inlet adds whole layers of dp: within one layer (0.001 m^2) of the integral.
    EXPECT_NEAR(in[3], volume_expected, 0.001);
    // Particles are created and removed, never lost: round-off only.
    EXPECT_NEAR(balance, 0.0, 1e-9 * m1);
    // The hydrograph is imposed as tabulated (linear between 2 and 3 s: 0.03 at 2.5 s).
    const auto& q = sim.probe("upstream").history();
    for (const auto& row : q) {
        if (std::abs(row[0] - 2.5) < 0.002) {
            EXPECT_NEAR(row[1], 0.03, 0.02 * (row[0] - 2.5) + 1e-6);
        }
    }
    // Nothing leaves before the front (which starts at x = 0.1 m at 0.2 m/s) can reach 2.3 m.
    for (const auto& row : out.history()) {
        if (row[0] < 2.0) {
            EXPECT_EQ(row[1], 0.0) << "t = " << row[0];
        }
    }
    EXPECT_GT(out.finals()[0], 50.0);
}
