// Floating box at rest (issue 4, test 3): a 0.3 x 0.16 m box of density 500 kg/m^3 in still
// water (cases/rigid/floating_box2d.toml, dp = 0.01 m, 2D) must float at the Archimedes draft
// d = (rho_b / rho_w) H = 0.08 m within 2 %, without drifting or tilting.
#include "debrisflow/rigid/body_solver.hpp"
#include "run_case.hpp"
#include <cmath>
#include <gtest/gtest.h>

using namespace debrisflow;

TEST(RigidFloating, BoxFloatsAtArchimedesDraft) {
    app::Simulation sim(
        io::read_case(std::string(DEBRISFLOW_SOURCE_DIR) + "/cases/rigid/floating_box2d.toml", {}));
    sim.run({"", true, 0, 0});
    const auto& box = sim.probe("box").history();
    const auto& left = sim.probe("level").history();
    const auto& right = sim.probe("level_right").history();
    ASSERT_EQ(box.size(), left.size());
    const Real half_height = 0.08, archimedes = 500.0 / 1000.0 * 0.16, dp = 0.01;
    Real sum = 0, worst_x = 0, worst_pitch = 0, worst_z = 0;
    int n = 0;
    const Real x0 = box[0][1], z0 = box[0][3];
    for (std::size_t k = 0; k < box.size(); ++k) {
        worst_x = std::max(worst_x, std::fabs(box[k][1] - x0));
        worst_z = std::max(worst_z, std::fabs(box[k][3] - z0));
        worst_pitch = std::max(worst_pitch, std::fabs(box[k][18]));
        if (box[k][0] < 0.5) continue;
        const Real level = 0.5 * (left[k][1] + right[k][1]);
        sum += level - (box[k][3] - half_height);
        ++n;
    }
    const Real draft = sum / n;
    std::printf("floating box: mean draft %.5f m vs Archimedes %.5f m (%+.2f %%); max |dx| "
                "%.2e m, max |dz| %.2e m, max |pitch| %.3f deg\n",
                draft, archimedes, 100 * (draft / archimedes - 1), worst_x, worst_z, worst_pitch);
    EXPECT_NEAR(draft / archimedes, 1, 0.02); // issue 4: within 2 % of Archimedes
    EXPECT_LT(worst_x, 0.1 * dp);             // no drift
    EXPECT_LT(worst_z, 0.2 * dp);             // no sinking or rising
    EXPECT_LT(worst_pitch, 0.5);              // no tilting [deg]
}
