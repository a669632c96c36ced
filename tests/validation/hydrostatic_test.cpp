// Hydrostatic tank, 2D and 3D: after settling, the pressure at depth d equals rho0 g d
// within 1 % (analytic; probes below the top two and above the bottom two particle layers),
// and, once settled (t > 0.75 s), no fluid particle drifts by more than 0.1 dp.
#include "run_case.hpp"
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <map>

using namespace debrisflow;

namespace {

// `sph_extra`: more lines of the [sph] table (another kernel and its h_over_dp).
std::string tank_case(int dim, double dp, double width, double depth, const std::string& boundary,
                      const std::string& diffusion, const std::string& sph_extra) {
    const std::string y = dim == 3 ? fmt::format("{}, ", 0.0) : "";
    const std::string yw = dim == 3 ? fmt::format("{}, ", width) : "";
    std::string s = fmt::format(R"(
dimensions = {0}
dp = {1}
[time]
end = 1.5
[output]
vtk = false
[domain]
min = [-0.05, {6}-0.05]
max = [{7}, {8}{9}]
[sph]
c0_coefficient = 10
reference_depth = {3}
viscosity = "artificial"
alpha = 0.05
diffusion = "{12}"
boundary = "{11}"
{13}
[[fluid]]
name = "water"
shape = "box"
min = [0, {4}0]
max = [{2}, {5}{3}]
[[wall]]
name = "tank"
shape = "open_tank"
min = [0, {4}0]
max = [{2}, {5}{10}]
)",
                                dim, dp, width, depth, y, yw, dim == 3 ? "-0.05, " : "",
                                width + 0.05, dim == 3 ? fmt::format("{}, ", width + 0.05) : "",
                                depth + 0.1, depth + 0.05, boundary, diffusion, sph_extra);
    for (double z : {0.25, 0.5, 0.75})
        s += fmt::format("[[probe]]\nname = \"p{0:.0f}\"\ntype = \"pressure\"\nposition = [{1}, "
                         "{2}{3}]\nevery = 0.01\n",
                         z * 100, width / 2, dim == 3 ? fmt::format("{}, ", width / 2) : "",
                         z * depth);
    return s;
}

enum class Check { pressure, drift };

void check_tank(int dim, double dp, double width, double depth, Check check,
                const std::string& boundary = "dbc", const std::string& diffusion = "fourtakas",
                const std::string& sph_extra = "") {
    app::Simulation sim(
        test::case_from_toml(fmt::format("hydrostatic{}d_{}_{}", dim, boundary, diffusion),
                             tank_case(dim, dp, width, depth, boundary, diffusion, sph_extra)));
    // Settle for 0.75 s, then measure the drift over the next 0.75 s.
    sim.run({"", true, 0, 0.75});
    std::map<ParticleId, Vec3> start;
    const auto& s = sim.particles();
    for (Index i = 0; i < s.size(); ++i)
        if (s.kind[i] == 0) start[s.id[i]] = {s.x[i], s.y[i], s.z[i]};
    sim.run({"", true, 0});
    if (check == Check::pressure)
        for (const auto& p : sim.probes()) {
            const double z = std::stod(p->name().substr(1)) / 100 * depth;
            const double expected = 1000 * 9.81 * (depth - z);
            // Mean over the last 0.25 s, so that the remaining acoustic oscillation averages out.
            // Source: hydrostatics p = rho0 g d; tolerance 1 % (issue #2, validation 1).
            const double mean = p->mean(0, 1.25, 1.5);
            EXPECT_NEAR(mean, expected, 0.01 * expected) << p->name();
            std::cout << fmt::format("{}D {}: {:.2f} Pa vs rho g d = {:.2f} Pa ({:+.2f} %)\n", dim,
                                     p->name(), mean, expected, 100 * (mean - expected) / expected);
        }
    if (check != Check::drift) return;
    double max_drift = 0, lowest = 1e9, nearest_side = 1e9;
    for (Index i = 0; i < s.size(); ++i)
        if (s.kind[i] == 0) {
            max_drift = std::max(max_drift, norm(Vec3{s.x[i], s.y[i], s.z[i]} - start[s.id[i]]));
            lowest = std::min(lowest, s.z[i]);
            nearest_side = std::min({nearest_side, s.x[i], width - s.x[i]});
        }
    // The gap between the fluid and the wall: how much further than dp/2 (where the lattice
    // starts it) the nearest fluid particle centre stands from the wall surface.
    const double floor_gap = lowest - 0.5 * dp, side_gap = nearest_side - 0.5 * dp;
    std::cout << fmt::format("{}D {}: drift {:.3f} dp, gap at the floor {:.2f} dp, at the side "
                             "walls {:.2f} dp\n",
                             dim, boundary, max_drift / dp, floor_gap / dp, side_gap / dp);
    // Tolerance: 0.1 dp (issue #2, validation 1).
    EXPECT_LT(max_drift, 0.1 * dp) << "worst particle drift " << max_drift / dp << " dp";
    // Issue #29: the gap at the wall <= 0.6 dp with mDBC.
    if (boundary == "mdbc") {
        EXPECT_LE(floor_gap, 0.6 * dp);
        EXPECT_LE(side_gap, 0.6 * dp);
    }
}

} // namespace

TEST(Hydrostatic, Pressure2D) {
    check_tank(2, 0.005, 0.2, 0.2, Check::pressure);
}
TEST(Hydrostatic, Pressure3D) {
    check_tank(3, 0.005, 0.1, 0.1, Check::pressure);
}
// Known gap (docs/validation.md): DBC walls drive a slow spurious circulation (~1-3 mm/s)
// that moves particles ~0.5 dp in 0.75 s. Run with: ctest -L known_gap
TEST(HydrostaticKnownGap, Drift2D) {
    check_tank(2, 0.005, 0.2, 0.2, Check::drift);
}

// mDBC (English et al. 2022): the hydrostatic pressure with the boundary density mirrored from
// the fluid, same tolerance.
TEST(Hydrostatic, Pressure2DMdbc) {
    check_tank(2, 0.005, 0.2, 0.2, Check::pressure, "mdbc");
}
// Known gap (docs/validation.md): mDBC does not remove the drift either (0.53 dp over 0.75 s;
// DBC 0.46 dp). With C2 at h = 1.5 dp the square lattice is metastable under the hydrostatic
// load and gives way where the side walls seed it: a circulation that sinks along the side
// walls at ~2 mm/s at 0.75 s. Issue #29 asks <= 0.1 dp.
TEST(HydrostaticKnownGap, Drift2DMdbc) {
    check_tank(2, 0.005, 0.2, 0.2, Check::drift, "mdbc");
}

// Antuono et al.'s (2010) delta-SPH diffusion with renormalised density gradients: it vanishes
// for any linear density field, so it leaves the hydrostatic pressure alone; same tolerance.
TEST(Hydrostatic, Pressure2DAntuono) {
    check_tank(2, 0.005, 0.2, 0.2, Check::pressure, "dbc", "antuono");
}
// Known gap (docs/validation.md): with it the drift of the mDBC tank is 0.44 dp instead of
// 0.53 dp; the lattice still gives way at h = 1.5 dp.
TEST(HydrostaticKnownGap, Drift2DMdbcAntuono) {
    check_tank(2, 0.005, 0.2, 0.2, Check::drift, "mdbc", "antuono");
}

// The Wendland C4 kernel (Dehnen & Aly 2012) at h = 2.5 dp with mDBC walls: the hydrostatic
// pressure, same tolerance.
const std::string wendland_c4 = "kernel = \"wendland_c4\"\nh_over_dp = 2.5";
TEST(Hydrostatic, Pressure2DMdbcWendlandC4) {
    check_tank(2, 0.005, 0.2, 0.2, Check::pressure, "mdbc", "fourtakas", wendland_c4);
}
// The same tank's drift, 0.1 dp as above (issue #29): C4 holds the square lattice below the free
// surface (at most 0.06 dp there, 0.014 dp on average), and since mDBC's walls standing in air
// carry no more than p = 0 the free surface's corners hold too (0.097 dp; 0.138 dp when those
// walls kept DBC's density, docs/validation.md).
TEST(Hydrostatic, Drift2DMdbcWendlandC4) {
    check_tank(2, 0.005, 0.2, 0.2, Check::drift, "mdbc", "fourtakas", wendland_c4);
}
