// 2D dam break after Lobovsky et al. (2014), H = 0.3 m, column 0.6 m, tank 1.61 m: pressure on
// the downstream wall against the experiment (issue #2 validation 4, issue #29):
//  - sensor 1 (y = 3 mm): impact arrival time (first p/(rho g H) >= 0.5) within +-0.05 in
//    T = t sqrt(g/H); post-impact plateau, mean p/(rho g H) over 3 <= T <= 6, within 15 %;
//  - sensor 3 (y = 30 mm): the same plateau check;
//  - sensor 1's impact load over 50 ms (the peak of its 50 ms moving mean) within 25 % of the
//    experiment's event at two sound speeds and two resolutions;
//  - the water levels at gauges H1-H3 (Fig. 16), mean over the window from the surge's arrival
//    to T = 5.5 (before the bore reflected from the wall returns), within 15 %;
//  - known gaps: the level at gauge H4 (0.25 m from the wall) is high, the surge's body reaches
//    the gauges early and the reflected bore returns early; sensors 3 and 4 (y = 80 mm) arrive
//    early (arrival: first p/(rho g H) at half the experiment's plateau, +-0.05 in T), sensor 4's
//    plateau is low, sensors 3 and 4's impact load over 50 ms is low, and sensor 1's instantaneous
//    peak is the water hammer rho c0 u.
// References: dambreak_2d_lobovsky2014/pysph_lobovsky_p{1_y3mm,3_y30mm,4_y80mm}.csv (the
// experiment's curves as digitised by PySPH; sensor 4's ends at T = 5.04, so its plateau is
// the mean over 3 <= T <= 5.04); Fig16_WaterLevels_H*.dat (h/H against T; one series at H1,
// two at H2-H4, whose spread is the experiment's repeatability here).
#include "reference_data.hpp"
#include "run_case.hpp"
#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <gtest/gtest.h>

using namespace debrisflow;

namespace {

constexpr double H = 0.3, g = 9.81, rho0 = 1000;

// First T (from `after` on) at which the curve reaches `level`.
double arrival(const test::Curve& c, double level, double after = 0) {
    for (const auto& [T, P] : c)
        if (T >= after && P >= level) return T;
    return NAN;
}

double mean_between(const test::Curve& c, double a, double b) {
    double s = 0;
    int n = 0;
    for (const auto& [T, P] : c)
        if (T >= a && T <= b) s += P, ++n;
    return s / n;
}

// The demo case (cases/dambreak2d.toml) at dp = 6 mm (or the given dp) to T = 6.1, sensors 1-4
// sampled every 0.5 ms: each sensor's p/(rho g H) against T.
std::vector<test::Curve> run_sensors(const char* dp = "0.006") {
    const double t_scale = std::sqrt(H / g);
    app::Simulation sim(
        io::read_case(std::string(DEBRISFLOW_SOURCE_DIR) + "/cases/dambreak2d.toml",
                      {fmt::format("dp={}", dp), fmt::format("time.end={}", 6.1 * t_scale),
                       "probe.0.every=0.0005", "probe.1.every=0.0005", "probe.2.every=0.0005",
                       "probe.3.every=0.0005", "output.vtk=false"}));
    sim.run({"", true, 0});
    std::vector<test::Curve> out;
    for (const char* name : {"sensor1", "sensor2", "sensor3", "sensor4"}) {
        test::Curve c;
        for (const auto& row : sim.probe(name).history())
            c.emplace_back(row[0] / t_scale, row[1] / (rho0 * g * H));
        out.push_back(c);
    }
    return out;
}

test::Curve experiment(const char* file) {
    return test::read_curve(test::reference(std::string("dambreak_2d_lobovsky2014/") + file));
}

// An experiment's event (Lobovsky et al. 2014, Fig. 18; sensor 1 by default: the files are
// numbered from the top sensor down, _5 sensor 1, _4 sensor 2, _2 sensor 3, _1 sensor 4) as
// p/(rho g H) against t [s].
void experiment_event(std::vector<Real>& t, std::vector<Real>& p,
                      const char* file = "Fig18_peak_event_5_sensors_5.dat") {
    const double t_scale = std::sqrt(H / g);
    for (const auto& [T, P] : experiment(file)) t.push_back(T * t_scale), p.push_back(P);
}

// The experiment's water-level gauges (Fig. 16): the case's probe, the files of its series and
// the window [from, to] in T over which its level is judged: from the surge's arrival (H1: from
// T = 1, when the gate's lift no longer sets the reservoir's level) to T = 5.5, before the bore
// reflected from the downstream wall returns (the experiment's reaches H4 at T = 6.1).
struct LevelGauge {
    const char* probe;
    std::vector<const char*> files;
    double from, to;
};

const std::vector<LevelGauge>& level_gauges() {
    static const std::vector<LevelGauge> gauges = {
        {"gauge_h1", {"Fig16_WaterLevels_H1_2.dat"}, 1.0, 5.5},
        {"gauge_h2", {"Fig16_WaterLevels_H2_3.dat", "Fig16_WaterLevels_H2_4.dat"}, 1.5, 5.5},
        {"gauge_h3", {"Fig16_WaterLevels_H3_3.dat", "Fig16_WaterLevels_H3_4.dat"}, 2.0, 5.5},
        {"gauge_h4", {"Fig16_WaterLevels_H4_4.dat", "Fig16_WaterLevels_H4_5.dat"}, 2.5, 5.5}};
    return gauges;
}

// The demo case at dp = 6 mm to `T_end`: each gauge's h/H against T, in the order of
// level_gauges().
std::vector<test::Curve> run_levels(double T_end) {
    const double t_scale = std::sqrt(H / g);
    app::Simulation sim(io::read_case(
        std::string(DEBRISFLOW_SOURCE_DIR) + "/cases/dambreak2d.toml",
        {"dp=0.006", fmt::format("time.end={}", T_end * t_scale), "output.vtk=false"}));
    sim.run({"", true, 0});
    std::vector<test::Curve> out;
    for (const LevelGauge& gauge : level_gauges()) {
        test::Curve c;
        for (const auto& row : sim.probe(gauge.probe).history())
            c.emplace_back(row[0] / t_scale, row[1] / H);
        out.push_back(c);
    }
    return out;
}

// The mean of a gauge's experimental series, each its mean over [a, b].
double experiment_mean(const LevelGauge& gauge, double a, double b) {
    double sum = 0;
    for (const char* file : gauge.files) sum += mean_between(experiment(file), a, b);
    return sum / gauge.files.size();
}

// The experiment's arrival of `level` from `after` on: the mean over a gauge's series.
double experiment_first_after(const LevelGauge& gauge, double level, double after) {
    double sum = 0;
    for (const char* file : gauge.files) sum += arrival(experiment(file), level, after);
    return sum / gauge.files.size();
}

} // namespace

// Water levels behind the surge (docs/validation.md, "Water levels"): the demo case's gauges
// H1 (in the reservoir), H2 and H3 (0.265 and 0.514 m beyond the gate), mean h/H over each
// gauge's window against the experiment's (the mean of its series). Measured at dp = 6 mm:
// H1 -2 %, H2 +10 %, H3 +11 % (the surge's body runs deeper than measured, at dp = 7.5, 6 and
// 4 mm alike).
TEST(DamBreakLobovsky, WaterLevelsBehindTheSurge) {
    const std::vector<test::Curve> sim = run_levels(5.6);
    for (size_t i = 0; i < 3; ++i) {
        const LevelGauge& gauge = level_gauges()[i];
        const double level = mean_between(sim[i], gauge.from, gauge.to);
        const double level_exp = experiment_mean(gauge, gauge.from, gauge.to);
        std::cout << fmt::format("Lobovsky {}: mean h/H over {} <= T <= {} {:.3f} (experiment "
                                 "{:.3f}, {:+.1f} %)\n",
                                 gauge.probe, gauge.from, gauge.to, level, level_exp,
                                 100 * (level - level_exp) / level_exp);
        // Source: Lobovsky et al. 2014, Fig. 16; tolerance 15 %, as the pressure plateaus'.
        EXPECT_NEAR(level, level_exp, 0.15 * level_exp) << gauge.probe;
    }
}

// Known gap (docs/validation.md, "Water levels"): near the wall and in time the flow is not the
// experiment's. At dp = 6 mm: H4's level (0.25 m from the wall) over 2.5 <= T <= 5.5 is +57 %
// (a jet thrown back from the run-up falls across the gauge at T = 4; its median is +22 %); the
// surge's body (h = 0.05 H) reaches H2, H3 and H4 0.07-0.2 T early (its tip is blunt where the
// experiment's is a thin tongue; the tip's arrival at the wall agrees, sensor 1 above); the bore
// reflected from the wall (h = 0.5 H after T = 5) returns to H3 and H4 0.36 and 0.82 T early.
// Tolerances: the level 15 % as above; the arrivals +-0.05 T as the sensors'; the reflected bore
// +-0.1 T, twice the spread of the experiment's two series at H3 and H4 (0.04-0.06 T).
TEST(DamBreakLobovskyKnownGap, LevelNearTheWallSurgeBodyAndReflectedBore) {
    const std::vector<test::Curve> sim = run_levels(8.0);
    const LevelGauge& h4 = level_gauges()[3];
    const double level = mean_between(sim[3], h4.from, h4.to);
    const double level_exp = experiment_mean(h4, h4.from, h4.to);
    std::cout << fmt::format("Lobovsky gauge_h4: mean h/H {:.3f} (experiment {:.3f}, {:+.1f} %)\n",
                             level, level_exp, 100 * (level - level_exp) / level_exp);
    EXPECT_NEAR(level, level_exp, 0.15 * level_exp);
    for (size_t i = 1; i < 4; ++i) {
        const LevelGauge& gauge = level_gauges()[i];
        const double body = arrival(sim[i], 0.05);
        const double body_exp = experiment_first_after(gauge, 0.05, 0);
        // The reflected bore is judged where it comes back as a bore, at H3 and H4.
        const bool bore = i >= 2;
        const double back = bore ? arrival(sim[i], 0.5, 5) : NAN;
        const double back_exp = bore ? experiment_first_after(gauge, 0.5, 5) : NAN;
        std::cout << fmt::format("Lobovsky {}: surge body (h = 0.05 H) at T = {:.2f} (experiment "
                                 "{:.2f}); reflected bore (h = 0.5 H after T = 5) at T = {:.2f} "
                                 "(experiment {:.2f})\n",
                                 gauge.probe, body, body_exp, back, back_exp);
        EXPECT_NEAR(body, body_exp, 0.05) << gauge.probe;
        if (bore) {
            EXPECT_NEAR(back, back_exp, 0.1) << gauge.probe;
        }
    }
}

TEST(DamBreakLobovsky, SensorArrivalAndPlateaus) {
    const std::vector<test::Curve> sim = run_sensors();
    const test::Curve exp1 = experiment("pysph_lobovsky_p1_y3mm.csv");
    const test::Curve exp3 = experiment("pysph_lobovsky_p3_y30mm.csv");
    const double t_sim = arrival(sim[0], 0.5), t_exp = arrival(exp1, 0.5);
    const double p_sim = mean_between(sim[0], 3, 6), p_exp = mean_between(exp1, 3, 6);
    const double p3_sim = mean_between(sim[2], 3, 6), p3_exp = mean_between(exp3, 3, 6);
    std::cout << fmt::format("Lobovsky sensor 1: arrival T = {:.3f} (experiment {:.3f}); "
                             "plateau {:.3f} (experiment {:.3f}, {:+.1f} %); sensor 3 plateau "
                             "{:.3f} (experiment {:.3f}, {:+.1f} %)\n",
                             t_sim, t_exp, p_sim, p_exp, 100 * (p_sim - p_exp) / p_exp, p3_sim,
                             p3_exp, 100 * (p3_sim - p3_exp) / p3_exp);
    // Source: Lobovsky et al. 2014; tolerance +-0.05 in T (issue #2).
    EXPECT_NEAR(t_sim, t_exp, 0.05);
    // Source: Lobovsky et al. 2014; tolerance 15 % (issue #2).
    EXPECT_NEAR(p_sim, p_exp, 0.15 * p_exp);
    // Source: Lobovsky et al. 2014, sensor 3 (y = 30 mm); tolerance 15 %, as sensor 1's.
    EXPECT_NEAR(p3_sim, p3_exp, 0.15 * p3_exp);
}

// Known gap (docs/validation.md, "Sensors up the wall"): the upper sensors read the impact's
// pressure pulse before the water reaches them (sensor 3 at T = 2.456 against 2.538, sensor 4
// at 2.553 against 2.919, dp = 6 mm), and sensor 4 (y = 80 mm) reads 53 % below the
// experiment's plateau (0.257 against 0.544; with mDBC walls 0.444, -18 %). Arrival: first
// p/(rho g H) at half the experiment's plateau; tolerances as sensor 1's (+-0.05 in T, 15 %).
TEST(DamBreakLobovskyKnownGap, UpperSensorsArrivalAndSensor4Plateau) {
    const std::vector<test::Curve> sim = run_sensors();
    const test::Curve exp3 = experiment("pysph_lobovsky_p3_y30mm.csv");
    const test::Curve exp4 = experiment("pysph_lobovsky_p4_y80mm.csv");
    const double level3 = 0.5 * mean_between(exp3, 3, 6);
    const double level4 = 0.5 * mean_between(exp4, 3, 6);
    const double t3 = arrival(sim[2], level3), t3_exp = arrival(exp3, level3);
    const double t4 = arrival(sim[3], level4), t4_exp = arrival(exp4, level4);
    const double p4 = mean_between(sim[3], 3, 5.04), p4_exp = mean_between(exp4, 3, 6);
    std::cout << fmt::format("Lobovsky sensor 3 arrival T = {:.3f} (experiment {:.3f}); sensor 4 "
                             "arrival {:.3f} (experiment {:.3f}), plateau {:.3f} (experiment "
                             "{:.3f}, {:+.1f} %)\n",
                             t3, t3_exp, t4, t4_exp, p4, p4_exp, 100 * (p4 - p4_exp) / p4_exp);
    EXPECT_NEAR(t3, t3_exp, 0.05);
    EXPECT_NEAR(t4, t4_exp, 0.05);
    EXPECT_NEAR(p4, p4_exp, 0.15 * p4_exp);
}

// Known gap (docs/validation.md, "Under refinement"): with DBC walls sensor 1's plateau moves
// away from the experiment as dp falls (+13 % at the suite's dp = 6 mm, +29 % at 4 mm, +36 % at
// 3 mm over 3 <= T <= 5.7; mDBC +5 and +4 %), so the plateau check above holds at dp = 6 mm only.
// Same quantity and tolerance as that check (mean over 3 <= T <= 6, 15 %), at dp = 4 mm.
TEST(DamBreakLobovskyKnownGap, Sensor1PlateauAtDp4mmDbc) {
    const std::vector<test::Curve> sim = run_sensors("0.004");
    const test::Curve exp1 = experiment("pysph_lobovsky_p1_y3mm.csv");
    const double p_sim = mean_between(sim[0], 3, 6), p_exp = mean_between(exp1, 3, 6);
    std::cout << fmt::format("Lobovsky sensor 1 plateau at dp = 4 mm: {:.3f} (experiment {:.3f}, "
                             "{:+.1f} %)\n",
                             p_sim, p_exp, 100 * (p_sim - p_exp) / p_exp);
    // Source: Lobovsky et al. 2014 (PySPH's digitised curve); tolerance 15 % (issue #2).
    EXPECT_NEAR(p_sim, p_exp, 0.15 * p_exp);
}

// The impact load that a structure slower than the ringing responds to (docs/validation.md,
// "The impact peak is acoustic"): the peak of the 50 ms moving mean at sensors 1 and 2 (3 and
// 15 mm up the wall, where the surge stagnates), sampled at 20 kHz, against the same quantity
// of the Fig. 18 events (1.94 and 1.72). Run at c0 = 10 and 20 sqrt(g H) at dp = 6 mm and at
// c0 = 10 sqrt(g H) at dp = 7.5 mm: the window spans seven or more periods of the acoustic
// ringing, whose impulse rho c0 u x L/c0 does not depend on c0, so the mean must neither follow
// c0 nor drift with dp (the instantaneous peaks, 10.5-21.3 at sensor 1, are 3.5-7 times the
// event's 3.04 and move with both).
// Tolerance: the event +-25 %, the band of the peak test below (one event, no scatter band).
TEST(DamBreakLobovsky, FootOfWallLoadOver50msFollowsTheFlowNotC0) {
    const double t_scale = std::sqrt(H / g);
    double event[2];
    for (int s = 0; s < 2; ++s) {
        std::vector<Real> t, p;
        experiment_event(
            t, p, s == 0 ? "Fig18_peak_event_5_sensors_5.dat" : "Fig18_peak_event_5_sensors_4.dat");
        event[s] = probes::peak_moving_mean(t, p, 0.05);
    }
    for (const auto& [dp, c0] :
         {std::pair{"0.006", "10"}, std::pair{"0.006", "20"}, std::pair{"0.0075", "10"}}) {
        app::Simulation sim(io::read_case(
            std::string(DEBRISFLOW_SOURCE_DIR) + "/cases/dambreak2d.toml",
            {fmt::format("dp={}", dp), fmt::format("sph.c0_coefficient={}", c0), "time.end=0.6",
             "probe.0.every=0.00005", "probe.1.every=0.00005", "output.vtk=false"}));
        sim.run({"", true, 0});
        for (int s = 0; s < 2; ++s) {
            const auto& probe = sim.probe(s == 0 ? "sensor1" : "sensor2");
            const double peak = probe.peaks()[0] / (rho0 * g * H);
            const double mean50 = probe.peak_window_mean(0, 0.05) / (rho0 * g * H);
            std::cout << fmt::format("Lobovsky sensor {}, dp = {} m, c0 = {} sqrt(gH): peak {:.2f} "
                                     "at T = {:.3f}; 50 ms mean {:.2f} (event {:.2f}, {:+.1f} %)\n",
                                     s + 1, dp, c0, peak, probe.peak_time(0) / t_scale, mean50,
                                     event[s], 100 * (mean50 - event[s]) / event[s]);
            // Source: Lobovsky et al. 2014, Fig. 18 events; tolerance 25 % (stated above).
            EXPECT_NEAR(mean50, event[s], 0.25 * event[s])
                << "sensor " << s + 1 << ", dp = " << dp << ", c0 = " << c0;
        }
    }
}

// Known gap (docs/validation.md, "Up the wall it does not hold"): the impact load over 50 ms
// 30 and 80 mm up the wall (sensors 3 and 4, sampled at 2 kHz) against the Fig. 18 events over
// the same span, t <= 0.6 s (1.49 and 0.53; sensor 4's event peaks later, 0.72 at T = 6.1, when
// the overturned run-up falls back, which a run to 0.6 s cannot see), tolerance +-25 % as
// sensor 1's. Measured at dp = 6 mm, c0 = 10 sqrt(g H), DBC: 0.69 (-54 %) and 0.19 (-64 %);
// at dp = 3 mm -24 % and -59 %: the run-up sheet rises off the wall.
TEST(DamBreakLobovskyKnownGap, UpperSensorsLoadOver50ms) {
    app::Simulation sim(io::read_case(std::string(DEBRISFLOW_SOURCE_DIR) + "/cases/dambreak2d.toml",
                                      {"dp=0.006", "time.end=0.6", "probe.2.every=0.0005",
                                       "probe.3.every=0.0005", "output.vtk=false"}));
    sim.run({"", true, 0});
    for (const auto& [name, file] : {std::pair{"sensor3", "Fig18_peak_event_5_sensors_2.dat"},
                                     std::pair{"sensor4", "Fig18_peak_event_5_sensors_1.dat"}}) {
        std::vector<Real> t, p;
        experiment_event(t, p, file);
        // the event over the run's span only
        const auto end = std::upper_bound(t.begin(), t.end(), Real(0.6)) - t.begin();
        t.resize(std::size_t(end)), p.resize(std::size_t(end));
        const double event = probes::peak_moving_mean(t, p, 0.05);
        const double mean50 = sim.probe(name).peak_window_mean(0, 0.05) / (rho0 * g * H);
        std::cout << fmt::format("Lobovsky {}: 50 ms mean {:.2f} (event {:.2f}, {:+.1f} %)\n", name,
                                 mean50, event, 100 * (mean50 - event) / event);
        // Source: Lobovsky et al. 2014, Fig. 18 events; tolerance 25 % (as sensor 1's).
        EXPECT_NEAR(mean50, event, 0.25 * event) << name;
    }
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
    std::vector<Real> t, p;
    experiment_event(t, p);
    const double exp_peak = *std::max_element(p.begin(), p.end());
    const double exp_mean5 = probes::peak_moving_mean(t, p, 0.005);
    std::cout << fmt::format("Lobovsky sensor 1 peak: {:.2f} (event {:.2f}); 5 ms mean {:.2f} "
                             "(event {:.2f})\n",
                             peak, exp_peak, mean5, exp_mean5);
    EXPECT_NEAR(peak, exp_peak, 0.25 * exp_peak);
    EXPECT_NEAR(mean5, exp_mean5, 0.25 * exp_mean5);
}
