// Collapse of a 2D column of discs (cases/deposits/column_collapse2d.toml, no rolling
// resistance) at aspect ratio a = H0/L0 ~ 2, against the true-2D experiments with aluminium
// rods of Nguyen, Bui & Fukagawa (2015, "Failure mechanism of true 2D granular flows",
// arXiv:1512.05180): H0/H_final = 1.42 a^(2/3) (a >= 0.65) and
// (L_final - L0)/L0 = 3.80 a^0.73 (a >= 1.5). Rods are the experiment a disc model
// represents (a quasi-2D channel of 3D beads runs out less: 1.2 a, Lube et al. 2005).
// The run-out is the front of the linked deposit (the `runout` probe).
#include "run_case.hpp"
#include <cmath>
#include <cstdio>
#include <gtest/gtest.h>

using namespace debrisflow;

namespace {
struct Collapse {
    Real aspect, height_ratio, runout;
};

// 800 discs of 4-6 mm behind a gate at x = 0.1 m (about twice as high as wide once settled).
Collapse collapse_of_discs() {
    const std::string file = DEBRISFLOW_SOURCE_DIR "/cases/deposits/column_collapse2d.toml";
    app::Simulation sim(
        io::read_case(file, {"dem.rolling=\"none\"", "wall.2.point=[0.1,0,0]", "grains.0.count=800",
                             "grains.0.region.max=[0.1,0,0.52]", "domain.max=[1.6,0,0.57]",
                             "time.end=2.5", "probe.2.every=0.05"}));
    app::RunOptions opt;
    opt.quiet = true;
    sim.run(opt);
    const auto& h = sim.probe("runout").history(); // {t, front, front_95, front_max, height, ..}
    const Real L0 = h.front()[1], H0 = h.front()[4];
    const Real L = h.back()[1], H = h.back()[4];
    std::printf("a = %.3f: L0 %.4f m, H0 %.4f m; front %.4f m, height %.4f m, detached %g\n",
                H0 / L0, L0, H0, L, H, h.back()[5]);
    return {H0 / L0, H / H0, (L - L0) / L0};
}
} // namespace

// The deposit's final height: Nguyen et al. (2015) fit, tolerance 10 % (the abstract gives the
// fit, not its scatter; 10 % is our bound for a deposit shape against an empirical fit).
// Measured: H/H0 0.406 against 0.430 at a = 2.10 (and -4 to -12 % at a = 0.57-4.1 in
// tools/deposits/column_collapse_study.py, docs/validation.md).
TEST(DemColumnCollapse, DiscsFinalHeightFollowsTrue2DRods) {
    const Collapse c = collapse_of_discs();
    ASSERT_GT(c.aspect, 1.5); // the fit's regime
    const Real expected = 1 / (1.42 * std::pow(c.aspect, Real(2) / 3));
    std::printf("H/H0 %.3f against %.3f (rods); run-out dL/L0 %.2f against %.2f (rods)\n",
                c.height_ratio, expected, c.runout, 3.80 * std::pow(c.aspect, 0.73));
    EXPECT_NEAR(c.height_ratio / expected, 1, 0.10);
}

// The run-out of the same collapse: Nguyen et al. (2015) fit, tolerance 15 %. Not reached:
// the discs' linked deposit reaches dL/L0 4.66 against the rods' 6.53 (-29 %; -41 % in a 3 s
// study run); see docs/validation.md ("Deposit shape").
TEST(DemColumnCollapseKnownGap, DiscsRunOutFollowsTrue2DRods) {
    const Collapse c = collapse_of_discs();
    ASSERT_GT(c.aspect, 1.5);
    EXPECT_NEAR(c.runout / (3.80 * std::pow(c.aspect, 0.73)), 1, 0.15);
}
