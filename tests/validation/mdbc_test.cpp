// mDBC (English et al. 2022) against DBC on a running flow: a 2D dam break (column 0.3 m x
// 0.15 m, dp = 5 mm) spreads along the floor of a 1 m tank. Issue #29: the gap between the
// wall and the fluid <= 0.6 dp, measured as the mean height of the first layer of fluid
// particles above the wall surface, minus the dp/2 at which the lattice starts it, under the
// running surge (0.35 m < x < 0.6 m at t = 0.3 s, before it reaches the far wall).
#include "run_case.hpp"
#include <algorithm>
#include <fmt/format.h>
#include <gtest/gtest.h>

using namespace debrisflow;

namespace {
double first_layer_gap(const std::string& boundary) {
    const double dp = 0.005;
    app::Simulation sim(test::case_from_toml("mdbc_gap_" + boundary, fmt::format(R"(
dimensions = 2
dp = {0}
[time]
end = 0.3
[output]
vtk = false
[domain]
min = [-0.05, -0.05]
max = [1.05, 0.4]
[sph]
h_over_dp = 1.5
c0_coefficient = 10
reference_depth = 0.15
viscosity = "artificial"
alpha = 0.01
boundary = "{1}"
[[fluid]]
name = "column"
shape = "box"
min = [0, 0]
max = [0.3, 0.15]
[[wall]]
name = "tank"
shape = "open_tank"
min = [0, 0]
max = [1.0, 0.3]
)",
                                                                                 dp, boundary)));
    sim.run({"", true, 0});
    const auto& s = sim.particles();
    std::vector<double> z;
    for (Index i = 0; i < s.size(); ++i)
        if (s.kind[i] == 0 && s.x[i] > 0.35 && s.x[i] < 0.6) z.push_back(s.z[i] / dp);
    EXPECT_GT(z.size(), 100u) << "the surge has not reached the window";
    const double lowest = *std::min_element(z.begin(), z.end());
    double sum = 0;
    int n = 0;
    for (double v : z)
        if (v < lowest + 0.6) sum += v, ++n; // the first layer: within 0.6 dp of the lowest
    const double gap = sum / n - 0.5;
    std::cout << fmt::format("{}: lowest fluid particle {:.2f} dp above the floor, first layer "
                             "at {:.2f} dp: gap {:.2f} dp\n",
                             boundary, lowest, sum / n, gap);
    return gap;
}
} // namespace

TEST(Mdbc, NoGapUnderARunningSurge) {
    first_layer_gap("dbc"); // for the record: DBC holds the flow about 1 dp off the wall
    EXPECT_LE(first_layer_gap("mdbc"), 0.6);
}
