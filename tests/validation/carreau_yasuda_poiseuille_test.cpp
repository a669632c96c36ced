// Plane Poiseuille flow of a Carreau-Yasuda fluid (Yasuda, Armstrong & Cohen 1981) between
// fixed plates, started from rest, periodic in x and driven by a body force F (issue #32).
// Semi-analytic steady solution: the shear stress is rho F s at the distance s from the centre
// line, so the shear rate solves mu(gdot) gdot = rho F s (monotone for n > 0: bisection) and
// u(s) = integral from s to a of gdot ds' (trapezoid rule on 4,000 intervals, converged to
// 1e-7 of the centre speed). Parameters: mu_0 = 5, mu_inf = 0.5 Pa s, lambda = 5 s,
// n = 0.3, a = 2: the viscosity falls 6.8-fold from the centre line to the wall and the centre
// speed is 5.6 times that of a Newtonian fluid of viscosity mu_0.
#include "plane_channel.hpp"
#include "run_case.hpp"
#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <gtest/gtest.h>

using namespace debrisflow;

namespace {

constexpr double rho = 1000, F = 1.0, L = 0.02, a = L / 2;
constexpr double mu_0 = 5, mu_inf = 0.5, lambda = 5, n_index = 0.3, yasuda = 2;
constexpr int layers = 40;

double viscosity(double gdot) {
    return mu_inf +
           (mu_0 - mu_inf) * std::pow(1 + std::pow(lambda * gdot, yasuda), (n_index - 1) / yasuda);
}

// Shear rate where the stress mu(gdot) gdot equals tau.
double shear_rate(double tau) {
    double lo = 0, hi = tau / mu_inf + 1;
    for (int k = 0; k < 200; ++k) {
        const double mid = 0.5 * (lo + hi);
        (viscosity(mid) * mid < tau ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

// u at distance s from the centre line, tabulated on `intervals` + 1 points.
struct SemiAnalytic {
    std::vector<double> s, u;
    explicit SemiAnalytic(int intervals) {
        const double ds = a / intervals;
        std::vector<double> g(std::size_t(intervals) + 1);
        for (int k = 0; k <= intervals; ++k) {
            s.push_back(k * ds);
            g[std::size_t(k)] = shear_rate(rho * F * k * ds);
        }
        u.assign(s.size(), 0);
        for (int k = intervals - 1; k >= 0; --k)
            u[std::size_t(k)] =
                u[std::size_t(k) + 1] + 0.5 * ds * (g[std::size_t(k)] + g[std::size_t(k) + 1]);
    }
    double at(double z) const {
        const double d = std::abs(z - a);
        const auto k = std::min<std::size_t>(std::size_t(d / s[1]), s.size() - 2);
        const double f = (d - s[k]) / s[1];
        return (1 - f) * u[k] + f * u[k + 1];
    }
};

std::string channel_case(double dp) {
    return test::plane_channel_case(
        dp, L, F, 0.6,
        fmt::format("c0 = 1.0\nviscosity = \"carreau_yasuda\"\nviscosity_zero = {}\n"
                    "viscosity_infinity = {}\nrelaxation_time = {}\nflow_index = {}\n"
                    "yasuda_a = {}\ndiffusion = \"none\"",
                    mu_0, mu_inf, lambda, n_index, yasuda));
}

} // namespace

// The semi-analytic solution against itself at half the intervals: the quadrature is
// converged (so the 3 % below measures the SPH model, not the reference).
TEST(CarreauYasudaPoiseuille, SemiAnalyticSolutionConverged) {
    const SemiAnalytic fine(4000), coarse(2000);
    EXPECT_NEAR(fine.at(a), coarse.at(a), 1e-7 * fine.at(a));
    // the Newtonian limit mu_inf = mu_0 would give rho F a^2 / (2 mu_0) = 0.01 m/s
    EXPECT_GT(fine.at(a), 5 * rho * F * a * a / (2 * mu_0));
}

TEST(CarreauYasudaPoiseuille, SteadyVelocityProfile) {
    const double dp = L / layers;
    const SemiAnalytic exact(4000);
    app::Simulation sim(test::case_from_toml("carreau_yasuda_poiseuille", channel_case(dp)));
    sim.run({"", true, 0, 0.45});
    const auto early = test::layer_profile(sim, dp);
    sim.run({"", true, 0, 0.6});
    const auto prof = test::layer_profile(sim, dp);
    double num = 0, den = 0, change = 0, u_max = 0;
    for (std::size_t k = 0; k < prof.size(); ++k) {
        const double ua = exact.at(prof[k].first);
        num += (prof[k].second - ua) * (prof[k].second - ua);
        den += ua * ua;
        change = std::max(change, std::abs(prof[k].second - early[k].second));
        u_max = std::max(u_max, prof[k].second);
    }
    const double l2 = std::sqrt(num / den), u_centre = exact.at(a);
    std::cout << fmt::format("Carreau-Yasuda Poiseuille: L2 {:.4f}, centre speed {:.5f} vs "
                             "{:.5f} m/s, change 0.45->0.6 s {:.2e} m/s\n",
                             l2, u_max, u_centre, change);
    // Steady state: the profile changes by < 0.5 % of the centre speed between 0.45 and 0.6 s.
    EXPECT_LT(change, 0.005 * u_centre);
    // Source: the semi-analytic solution above; tolerance 3 % (as the Bingham channel, #5).
    EXPECT_LT(l2, 0.03);
    EXPECT_NEAR(u_max, u_centre, 0.03 * u_centre);
}
