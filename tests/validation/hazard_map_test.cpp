// hazard_map probe (issue #32) on a steady uniform open-channel flow computed by hand: a
// laminar film of depth H on a bed inclined at theta, periodic along the slope, no slip at the
// bed and no stress at the surface (Nusselt film; Bird, Stewart & Lightfoot 2002, section 2.2):
//   u(z) = g sin(theta) / nu (H z - z^2 / 2),  depth-averaged v = g sin(theta) H^2 / (3 nu),
//   momentum flux rho H v^2.
// Here H = 0.01 m, theta = 3 degrees, nu = 1e-3 m^2/s: v = 0.01711 m/s, rho H v^2 =
// 2.928e-3 N/m (cases/validation/laminar_film2d.toml, dp = H/20). The flow starts from rest and
// accelerates monotonically, so each cell's maximum over time is its steady value (reached to 1e-4
// after 0.5 s: the slowest mode decays as exp(-pi^2 nu t / (4 H^2))).
#include "debrisflow/probes/hazard_map.hpp"
#include "run_case.hpp"
#include <cmath>
#include <fmt/format.h>
#include <fstream>
#include <gtest/gtest.h>

using namespace debrisflow;

namespace {

constexpr double H = 0.01, nu = 1e-3, g = 9.81, rho = 1000;
constexpr double theta = 3 * 3.14159265358979323846 / 180;

} // namespace

TEST(HazardMap, SteadyLaminarFilmDepthSpeedAndMomentumFlux) {
    const double v = g * std::sin(theta) * H * H / (3 * nu), flux = rho * H * v * v;
    app::Simulation sim(io::read_case(
        std::string(DEBRISFLOW_SOURCE_DIR) + "/cases/validation/laminar_film2d.toml", {}));
    sim.run({"", true, 0});
    const auto& map = dynamic_cast<const probes::HazardMapProbe&>(sim.probe("hazard"));
    ASSERT_EQ(map.depth_max().size(), 3u);
    for (std::size_t k = 0; k < 3; ++k) {
        std::cout << fmt::format("cell {}: h {:.5f} (by hand {:.5f}), v {:.5f} ({:.5f}), "
                                 "rho h v^2 {:.4e} ({:.4e})\n",
                                 k, map.depth_max()[k], H, map.speed_max()[k], v, map.flux_max()[k],
                                 flux);
        // Source: the Nusselt film above. Tolerances: depth within 2 % (the highest particle
        // top; the column compresses by p/(rho c0^2) < 0.7 %), speed within 3 % and momentum
        // flux within 6 % (it goes as h v^2), as the other laminar channel checks' 3 %.
        EXPECT_NEAR(map.depth_max()[k], H, 0.02 * H);
        EXPECT_NEAR(map.speed_max()[k], v, 0.03 * v);
        EXPECT_NEAR(map.flux_max()[k], flux, 0.06 * flux);
    }
}
