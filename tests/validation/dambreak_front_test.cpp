// 2D dam break surge front against experiments (issue #2 validation 3):
//  - Martin & Moyce (1952), square column a x a: Z = z/a vs T = t sqrt(g/a), within 5 % for
//    1 <= T <= 3 (reference: dambreak_2d_martin_moyce/MM1952_table_front_square_column.csv).
//  - Koshizuka & Oka (1996), column L wide and 2L high: Z = z/L vs T = t sqrt(2 g/L), within
//    5 % (reference: dambreak_2d_koshizuka_oka/pysph_KO1996_exp.csv), for T >= 1 as for MM:
//    earlier times depend on how the gate is removed.
#include "reference_data.hpp"
#include "run_case.hpp"
#include <cmath>
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <memory>

using namespace debrisflow;

namespace {

// A case of cases/validation/ with overrides.
io::CaseSpec validation_case(const std::string& name, std::vector<std::string> sets) {
    return io::read_case(std::string(DEBRISFLOW_SOURCE_DIR) + "/cases/validation/" + name, sets);
}

// Largest relative error of the simulated front against reference points in [t_lo, t_hi]
// (dimensionless); `t_scale` converts T to seconds, `z_scale` metres to Z.
double front_error(const probes::Probe& front, const test::Curve& ref, double t_scale,
                   double z_scale, double t_lo, double t_hi, double dp) {
    test::Curve sim;
    for (const auto& row : front.history())
        sim.emplace_back(row[0] / t_scale, (row[1] + 0.5 * dp) * z_scale); // leading edge
    double worst = 0;
    for (const auto& [T, Z] : ref) {
        if (T < t_lo || T > t_hi) continue;
        const double z = test::interpolate(sim, T);
        std::cout << fmt::format("  T = {:.3f}: Z = {:.3f} (reference {:.3f}, {:+.1f} %)\n", T, z,
                                 Z, 100 * (z - Z) / Z);
        worst = std::max(worst, std::abs(z - Z) / Z);
    }
    return worst;
}

struct FrontRun {
    double t_scale, z_scale, dp;
    std::unique_ptr<app::Simulation> sim;
};

FrontRun run_martin_moyce() {
    const double a = 0.1, dp = a / 40, g = 9.81;
    const double t_scale = std::sqrt(a / g); // T = t sqrt(g/a)
    FrontRun r{t_scale, 1 / a, dp,
               std::make_unique<app::Simulation>(validation_case(
                   "dambreak_mm.toml",
                   {fmt::format("dp={}", dp), fmt::format("time.end={}", 3.2 * t_scale)}))};
    r.sim->run({"", true, 0});
    return r;
}

FrontRun run_koshizuka_oka(const std::vector<std::string>& sets = {}) {
    const double L = 0.146, dp = L / 40, g = 9.81;
    const double t_scale = std::sqrt(L / (2 * g)); // T = t sqrt(2g/L)
    std::vector<std::string> all = {fmt::format("dp={}", dp),
                                    fmt::format("time.end={}", 3.2 * t_scale)};
    all.insert(all.end(), sets.begin(), sets.end());
    FrontRun r{t_scale, 1 / L, dp,
               std::make_unique<app::Simulation>(validation_case("dambreak_ko.toml", all))};
    r.sim->run({"", true, 0});
    return r;
}

double front_error(const FrontRun& r, const std::string& ref, double t_lo, double t_hi) {
    return front_error(r.sim->probe("front"), test::read_curve(test::reference(ref)), r.t_scale,
                       r.z_scale, t_lo, t_hi, r.dp);
}

} // namespace

// Cross-code check: Koshizuka & Oka's own MPS simulation of their experiment (digitised by
// PySPH). Tolerance 5 % for 1 <= T <= 3 (the tolerance for the experiment).
TEST(DamBreakFront, KoshizukaOkaMpsSimulation) {
    const FrontRun r = run_koshizuka_oka();
    EXPECT_LT(front_error(r, "dambreak_2d_koshizuka_oka/pysph_KO1996_MPS_sim.csv", 1.0, 3.0), 0.05);
}

// The Verlet scheme (one force evaluation per step) must meet the same check.
TEST(DamBreakFront, KoshizukaOkaMpsSimulationVerlet) {
    const FrontRun r = run_koshizuka_oka({"time.scheme=\"verlet\""});
    EXPECT_LT(front_error(r, "dambreak_2d_koshizuka_oka/pysph_KO1996_MPS_sim.csv", 1.0, 3.0), 0.05);
}

// The Wendland C4 kernel (at its default h = 2 dp) must meet the same check.
TEST(DamBreakFront, KoshizukaOkaMpsSimulationWendlandC4) {
    const FrontRun r = run_koshizuka_oka({"sph.kernel=\"wendland_c4\""});
    EXPECT_LT(front_error(r, "dambreak_2d_koshizuka_oka/pysph_KO1996_MPS_sim.csv", 1.0, 3.0), 0.05);
}
// Known gap (docs/validation.md): the inviscid, frictionless simulation runs 10-15 % (MM) and
// 10-20 % (KO) ahead of the experiments, as KO's own MPS simulation does; the experiments'
// front is slowed by the gate and the bed, which the model does not represent.
TEST(DamBreakFrontKnownGap, MartinMoyceSquareColumn) {
    const FrontRun r = run_martin_moyce();
    // Source: Martin & Moyce 1952 (square column); tolerance 5 % for 1 <= T <= 3 (issue #2).
    EXPECT_LT(
        front_error(r, "dambreak_2d_martin_moyce/MM1952_table_front_square_column.csv", 1.0, 3.0),
        0.05);
}

TEST(DamBreakFrontKnownGap, KoshizukaOkaExperiment) {
    const FrontRun r = run_koshizuka_oka();
    // Source: Koshizuka & Oka 1996 experiment; tolerance 5 % (issue #2).
    EXPECT_LT(front_error(r, "dambreak_2d_koshizuka_oka/pysph_KO1996_exp.csv", 1.0, 3.2), 0.05);
}
