// 2D dam break after Lobovsky et al. (2014), H = 0.3 m, column 0.6 m, tank 1.61 m: pressure at
// sensor 1 (downstream wall, y = 3 mm) against the experiment (issue #2 validation 4):
//  - impact arrival time (first p/(rho g H) >= 0.5) within +-0.05 in T = t sqrt(g/H);
//  - post-impact plateau, mean p/(rho g H) over 3 <= T <= 6, within 15 %.
// Reference: dambreak_2d_lobovsky2014/pysph_lobovsky_p1_y3mm.csv (digitised by PySPH).
#include "reference_data.hpp"
#include "run_case.hpp"
#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <gtest/gtest.h>

using namespace debrisflow;

namespace {

constexpr double H = 0.3, g = 9.81, rho0 = 1000;

// First T at which the curve reaches `level`.
double arrival(const test::Curve& c, double level) {
    for (const auto& [T, P] : c)
        if (P >= level) return T;
    return NAN;
}

double mean_between(const test::Curve& c, double a, double b) {
    double s = 0;
    int n = 0;
    for (const auto& [T, P] : c)
        if (T >= a && T <= b) s += P, ++n;
    return s / n;
}

} // namespace

TEST(DamBreakLobovsky, Sensor1ArrivalAndPlateau) {
    const double t_scale = std::sqrt(H / g);
    // The demo case (cases/dambreak2d.toml) at dp = 6 mm.
    app::Simulation sim(io::read_case(
        std::string(DEBRISFLOW_SOURCE_DIR) + "/cases/dambreak2d.toml",
        {"dp=0.006", fmt::format("time.end={}", 6.1 * t_scale), "probe.0.every=0.0005"}));
    sim.run({"", true, 0});
    test::Curve simc;
    for (const auto& row : sim.probe("sensor1").history())
        simc.emplace_back(row[0] / t_scale, row[1] / (rho0 * g * H));
    const auto exp =
        test::read_curve(test::reference("dambreak_2d_lobovsky2014/pysph_lobovsky_p1_y3mm.csv"));
    const double t_sim = arrival(simc, 0.5), t_exp = arrival(exp, 0.5);
    const double p_sim = mean_between(simc, 3, 6), p_exp = mean_between(exp, 3, 6);
    std::cout << fmt::format("Lobovsky sensor 1: arrival T = {:.3f} (experiment {:.3f}); "
                             "plateau {:.3f} (experiment {:.3f}, {:+.1f} %)\n",
                             t_sim, t_exp, p_sim, p_exp, 100 * (p_sim - p_exp) / p_exp);
    // Source: Lobovsky et al. 2014; tolerance +-0.05 in T (issue #2).
    EXPECT_NEAR(t_sim, t_exp, 0.05);
    // Source: Lobovsky et al. 2014; tolerance 15 % (issue #2).
    EXPECT_NEAR(p_sim, p_exp, 0.15 * p_exp);
}

// Known gap (docs/validation.md, "The impact peak is acoustic"): the impact peak at sensor 1,
// sampled at 20 kHz as in the experiment, against the event of Lobovsky et al.'s Fig. 18 in
// ../shared/reference (p/(rho g H) = 3.04; 2.67 as a 5 ms moving mean). The folder holds one
// event, not the scatter of the repeats, so the band is that event +-25 % (our choice, stated
// here). Measured at this test's dp = 6 mm: 21.3 (peak) and 9.1 (5 ms mean); the peak is the water
// hammer rho c0 u and grows with c0 (tools/impact_peak_study.py).
TEST(DamBreakLobovskyKnownGap, Sensor1Peak) {
    const double t_scale = std::sqrt(H / g);
    app::Simulation sim(io::read_case(std::string(DEBRISFLOW_SOURCE_DIR) + "/cases/dambreak2d.toml",
                                      {"dp=0.006", fmt::format("time.end={}", 3.5 * t_scale),
                                       "probe.0.every=0.00005", "output.vtk=false"}));
    sim.run({"", true, 0});
    const auto& probe = sim.probe("sensor1");
    const double peak = probe.peaks()[0] / (rho0 * g * H);
    const double mean5 = probe.peak_window_mean(0, 0.005) / (rho0 * g * H);
    // the experiment's event and its 5 ms moving mean
    const auto exp = test::read_curve(
        test::reference("dambreak_2d_lobovsky2014/Fig18_peak_event_5_sensors_5.dat"));
    std::vector<Real> t, p;
    for (const auto& [T, P] : exp) t.push_back(T * t_scale), p.push_back(P);
    const double exp_peak = *std::max_element(p.begin(), p.end());
    const double exp_mean5 = probes::peak_moving_mean(t, p, 0.005);
    std::cout << fmt::format("Lobovsky sensor 1 peak: {:.2f} (event {:.2f}); 5 ms mean {:.2f} "
                             "(event {:.2f})\n",
                             peak, exp_peak, mean5, exp_mean5);
    EXPECT_NEAR(peak, exp_peak, 0.25 * exp_peak);
    EXPECT_NEAR(mean5, exp_mean5, 0.25 * exp_mean5);
}
