// Sphere settling in a viscous fluid (issue 4, test 5): ten Cate et al. (2002) case E1
// (Re 1.5), cases/rigid/tencate_E1.toml run at dp = d / 4.5 = 3.33 mm (66,876 particles).
// Reference: sedimentation_tencate2002/tencate_Re1_5.csv (gap h/d vs t) and the measured
// terminal velocity 0.038 m/s (analytic/tencate_params...). Tolerances from the issue:
// terminal velocity within 10 %, gap within 0.5 d until h/d = 1.
// Known gap: at this resolution the terminal velocity is 0.0419 m/s (+10.3 %) and the gap
// drifts 0.55 d ahead by t = 1.1 s (docs/validation.md).
#include "reference_data.hpp"
#include "run_case.hpp"
#include <cmath>
#include <gtest/gtest.h>

using namespace debrisflow;

TEST(RigidTenCateKnownGap, E1TerminalVelocityAndGapCurve) {
    app::Simulation sim(
        io::read_case(std::string(DEBRISFLOW_SOURCE_DIR) + "/cases/rigid/tencate_E1.toml",
                      {"dp=0.003333", "time.end=3.4"}));
    sim.run({"", true, 0, 0});
    const auto& h = sim.probe("sphere").history();
    const Real d = 0.015;
    Real vmax = 0;
    for (const auto& row : h) vmax = std::max(vmax, -row[9]);
    std::printf("ten Cate E1: terminal velocity %.4f m/s vs 0.038 (%+.1f %%)\n", vmax,
                100 * (vmax / 0.038 - 1));
    EXPECT_NEAR(vmax / 0.038, 1, 0.10);
    const auto ref =
        test::read_curve(test::reference("sedimentation_tencate2002/tencate_Re1_5.csv"));
    for (const auto& [t, gap_ref] : ref) {
        if (t < 0 || gap_ref < 1) continue;
        Real gap = 0;
        for (std::size_t j = 1; j < h.size(); ++j)
            if (h[j][0] >= t) {
                const Real f = (t - h[j - 1][0]) / (h[j][0] - h[j - 1][0]);
                const Real z = h[j - 1][3] + f * (h[j][3] - h[j - 1][3]);
                gap = (z - d / 2) / d;
                break;
            }
        std::printf("  t = %.2f s: h/d %.3f vs %.3f\n", t, gap, gap_ref);
        EXPECT_NEAR(gap, gap_ref, 0.5);
    }
}
