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

// 800 discs of 4-6 mm behind a gate at x = 0.1 m (about twice as high as wide once settled),
// one random packing per seed, released at t = 0 and followed to `end`.
Collapse collapse_of_discs(int seed, Real end) {
    const std::string file = DEBRISFLOW_SOURCE_DIR "/cases/deposits/column_collapse2d.toml";
    app::Simulation sim(
        io::read_case(file, {"dem.rolling=\"none\"", "wall.2.point=[0.1,0,0]", "grains.0.count=800",
                             "grains.0.seed=" + std::to_string(seed),
                             "grains.0.region.max=[0.1,0,0.52]", "domain.max=[1.6,0,0.57]",
                             "time.end=" + std::to_string(end), "probe.2.every=0.05"}));
    app::RunOptions opt;
    opt.quiet = true;
    sim.run(opt);
    const auto& h = sim.probe("runout").history(); // {t, front, front_95, front_max, height, ..}
    const Real L0 = h.front()[1], H0 = h.front()[4];
    const Real L = h.back()[1], H = h.back()[4];
    const Real a = H0 / L0;
    std::printf("seed %d: a = %.3f (L0 %.4f m, H0 %.4f m); at %.2f s H/H0 %.3f against %.3f, "
                "dL/L0 %.2f against %.2f (rods)\n",
                seed, a, L0, H0, end, H / H0, 1 / (1.42 * std::pow(a, Real(2) / 3)), (L - L0) / L0,
                3.80 * std::pow(a, 0.73));
    return {a, H / H0, (L - L0) / L0};
}

constexpr int realisations = 5; // packings (seeds 1-5): one deposit varies by a few per cent
} // namespace

// The deposit's final height, the mean over five packings of (H/H0) / fit: Nguyen et al. (2015)
// fit, tolerance 10 % (the abstract gives the fit, not its scatter; 10 % is our bound for a
// deposit shape against an empirical fit). The height is at rest from about 0.75 s on, so the
// runs stop at 1 s. Measured: 0.927 (-7.3 %; the packings 0.87-0.96), a = 2.09-2.15.
TEST(DemColumnCollapse, DiscsFinalHeightFollowsTrue2DRods) {
    Real sum = 0;
    for (int seed = 1; seed <= realisations; ++seed) {
        const Collapse c = collapse_of_discs(seed, 1.0);
        ASSERT_GT(c.aspect, 1.5); // the fit's regime
        sum += c.height_ratio * 1.42 * std::pow(c.aspect, Real(2) / 3);
    }
    std::printf("mean (H/H0) / fit: %.3f\n", sum / realisations);
    EXPECT_NEAR(sum / realisations, 1, 0.10);
}

// The run-out of the same collapses at 2.5 s, the mean of dL/L0 / fit over the five packings:
// Nguyen et al. (2015) fit, tolerance 15 %. Not reached: 4.4-5.2 against 6.5-6.7 (mean
// -28.5 %); see docs/validation.md ("Deposit shape").
TEST(DemColumnCollapseKnownGap, DiscsRunOutFollowsTrue2DRods) {
    Real sum = 0;
    for (int seed = 1; seed <= realisations; ++seed) {
        const Collapse c = collapse_of_discs(seed, 2.5);
        ASSERT_GT(c.aspect, 1.5);
        sum += c.runout / (3.80 * std::pow(c.aspect, 0.73));
    }
    EXPECT_NEAR(sum / realisations, 1, 0.15);
}
