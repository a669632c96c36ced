// Collapse of a 2D column of discs (cases/deposits/column_collapse2d.toml, no rolling
// resistance) at aspect ratio a = H0/L0 ~ 2, against the true-2D experiments with aluminium
// rods of Nguyen, Bui & Fukagawa (2015, "Failure mechanism of true 2D granular flows",
// arXiv:1512.05180): H0/H_final = 1.42 a^(2/3) (a >= 0.65) and
// (L_final - L0)/L0 = 3.80 a^0.73 (a >= 1.5). Rods are the experiment a disc model
// represents (a quasi-2D channel of 3D beads runs out less: 1.2 a, Lube et al. 2005).
// The run-out is the front of the linked deposit (the `runout` probe).
//
// The deposit depends on the column's width in grains, L0/d (a size effect measured in
// experiments, Warnett et al. 2014, and in DEM, Man, Huppert & Galindo-Torres 2021): at a ~ 2
// the run-out rises from -28 % of the rods' fit at L0/d = 20 to -17 % at 30, -8 to -17 % at
// 40 and -2 to +1 % at 60, while the final height falls from -7 % to -11 to -16 % (30-40) and
// -19 to -22 % (60) (docs/validation.md, "Deposit shape"; one packing per value above 20).
// Both are checked at L0/d = 60, where the run-out agrees; the height at 20 as well, cheaply,
// as a guard.
#include "run_case.hpp"
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fmt/format.h>
#include <gtest/gtest.h>

using namespace debrisflow;

namespace {
struct Collapse {
    Real aspect, height_ratio, runout;
};

// `count` discs of 4-6 mm (d50 = 5 mm) behind a gate at x = L0 = 0.1 m sqrt(count / 800)
// (about twice as high as wide once settled: 800 discs make a column 20 discs wide, 7200 one
// 60 wide), one random packing per seed, released at t = 0 and followed to `end`.
Collapse collapse_of_discs(int count, int seed, Real end) {
    const std::string file = DEBRISFLOW_SOURCE_DIR "/cases/deposits/column_collapse2d.toml";
    const Real scale = std::sqrt(Real(count) / 800), gate = 0.1 * scale, top = 0.52 * scale;
    const Real far = std::max(Real(1.6), 14 * gate); // room for twice the rods' run-out
    app::Simulation sim(io::read_case(
        file, {"dem.rolling=\"none\"", fmt::format("wall.2.point=[{:.4f},0,0]", gate),
               fmt::format("grains.0.count={}", count), fmt::format("grains.0.seed={}", seed),
               fmt::format("grains.0.region.max=[{:.4f},0,{:.4f}]", gate, top),
               fmt::format("domain.max=[{:.4f},0,{:.4f}]", far, top + 0.05),
               fmt::format("time.end={}", end), "probe.2.every=0.05"}));
    app::RunOptions opt;
    opt.quiet = true;
    sim.run(opt);
    const auto& h = sim.probe("runout").history(); // {t, front, front_95, front_max, height, ..}
    const Real L0 = h.front()[1], H0 = h.front()[4];
    const Real L = h.back()[1], H = h.back()[4];
    const Real a = H0 / L0;
    std::printf("%d discs, seed %d: a = %.3f (L0 %.4f m, H0 %.4f m); at %.2f s H/H0 %.3f against "
                "%.3f, dL/L0 %.2f against %.2f (rods)\n",
                count, seed, a, L0, H0, end, H / H0, 1 / (1.42 * std::pow(a, Real(2) / 3)),
                (L - L0) / L0, 3.80 * std::pow(a, 0.73));
    return {a, H / H0, (L - L0) / L0};
}

constexpr int realisations = 5; // packings (seeds 1-5): one deposit varies by a few per cent
constexpr int wide = 7200;      // discs of the wide column, L0/d = 60
constexpr int wide_realisations = 2;

Real height_over_fit(const Collapse& c) {
    return c.height_ratio * 1.42 * std::pow(c.aspect, Real(2) / 3);
}
Real runout_over_fit(const Collapse& c) {
    return c.runout / (3.80 * std::pow(c.aspect, 0.73));
}

// The mean of `over_fit` over packings 1..packings of `count` discs followed to `end`; every
// column must lie in the fits' regime (a > 1.5).
Real mean_over_packings(int count, int packings, Real end, Real (*over_fit)(const Collapse&)) {
    Real sum = 0;
    for (int seed = 1; seed <= packings; ++seed) {
        const Collapse c = collapse_of_discs(count, seed, end);
        EXPECT_GT(c.aspect, 1.5);
        sum += over_fit(c);
    }
    std::printf("mean over %d packings of %d discs, value / fit: %.3f\n", packings, count,
                sum / packings);
    return sum / packings;
}
} // namespace

// The deposit's final height of a column 20 discs wide, the mean over five packings of
// (H/H0) / fit: Nguyen et al. (2015) fit, tolerance 10 % (the abstract gives the fit, not its
// scatter; 10 % is our bound for a deposit shape against an empirical fit). The height is at
// rest from about 0.75 s on, so the runs stop at 1 s. Measured: 0.927 (-7.3 %; the packings
// 0.87-0.96), a = 2.09-2.15.
TEST(DemColumnCollapse, DiscsFinalHeightFollowsTrue2DRods) {
    EXPECT_NEAR(mean_over_packings(800, realisations, 1.0, height_over_fit), 1, 0.10);
}

// The run-out of a column 60 discs wide at 2 s (the front at rest from about 1.5 s), the mean
// of (dL/L0) / fit over two packings: Nguyen et al. (2015) fit, tolerance 15 % (a run-out
// against an empirical fit; one packing moves it by a few per cent). Measured: 0.992 (the
// packings 0.984 and 1.000), a = 2.00; 295 s on 2 threads.
TEST(DemColumnCollapse, WideColumnRunOutFollowsTrue2DRods) {
    EXPECT_NEAR(mean_over_packings(wide, wide_realisations, 2.0, runout_over_fit), 1, 0.15);
}

// The final height of the same wide column: Nguyen et al. (2015) fit, tolerance 10 %. Not
// reached: 0.810 (H/H0 0.363 and 0.356 against 0.444); the deposit of round discs is
// flatter than the rods' where its run-out agrees (docs/validation.md, "Deposit shape").
TEST(DemColumnCollapseKnownGap, WideColumnFinalHeightFollowsTrue2DRods) {
    EXPECT_NEAR(mean_over_packings(wide, wide_realisations, 2.0, height_over_fit), 1, 0.10);
}
