// Design-formula companions (probes/design_formulas.*).
#include "debrisflow/probes/design_formulas.hpp"
#include <cmath>
#include <gtest/gtest.h>

using namespace debrisflow;

// Hertz impact of a sphere on a flat (Johnson 1985): the work of F = 4/3 E* r^0.5 delta^1.5 up
// to the peak indentation, 8/15 E* r^0.5 delta^2.5, equals the kinetic energy 1/2 m v^2.
TEST(DesignFormulas, HertzImpactForceStoresTheKineticEnergy) {
    const double m = 500, r = 0.5, v = 6, e = 20e9;
    const double f = probes::hertz_impact_force(m, r, v, e);
    const double delta = std::pow(3 * f / (4 * e * std::sqrt(r)), 2.0 / 3.0);
    EXPECT_NEAR(8.0 / 15.0 * e * std::sqrt(r) * std::pow(delta, 2.5), 0.5 * m * v * v,
                1e-9 * 0.5 * m * v * v);
    // Scaling: F ~ m^0.6 v^1.2 r^0.2 E*^0.4.
    EXPECT_NEAR(probes::hertz_impact_force(2 * m, r, v, e) / f, std::pow(2.0, 0.6), 1e-12);
    EXPECT_NEAR(probes::hertz_impact_force(m, r, 2 * v, e) / f, std::pow(2.0, 1.2), 1e-12);
}
