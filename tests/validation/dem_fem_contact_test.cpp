// DEM <-> FEM contact (issue #6, validation 5): a sphere dropped on an elastic concrete plate.
#include "run_case.hpp"
#include <Eigen/Dense>
#include <cmath>
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <iostream>

using namespace debrisflow;

namespace {

// Rock sphere (d 0.1 m, rho 2650, E 30 GPa, nu 0.3, e = 1: no contact damping) at 1 m/s onto
// the centre node of a C40 concrete plate 0.4 x 0.4 x 0.2 m (hex8 8 x 8 x 4), no gravity.
std::string plate_case(bool supported) {
    return fmt::format(R"(
dimensions = 3
[time]
end = 0.0025
[domain]
min = [-0.2, -0.2, -0.2]
max = [0.6, 0.6, 0.6]
[physics]
gravity = [0, 0, 0]
[[material]]
name = "rock"
law = "hertz_mindlin"
density = 2650
youngs_modulus = 30e9
poisson = 0.3
restitution = 1
friction = 0.3
[[material]]
name = "concrete"
law = "hertz_mindlin"
density = 2320
youngs_modulus = 32.5e9
poisson = 0.2
restitution = 1
friction = 0.3
[dem]
reference_velocity = 1
[[grains]]
name = "sphere"
material = "rock"
packing = "single"
diameter = 0.1
position = [0.2, 0.2, 0.2505]
velocity = [0, 0, -1]
[fem]
cfl = 0.9
[[fem_material]]
name = "c40"
model = "linear_elastic"
density = 2320
youngs_modulus = 32.5e9
poisson = 0.2
[[solid]]
name = "plate"
material = "c40"
dem_material = "concrete"
mesh = "box"
element = "hex8"
min = [0, 0, 0]
max = [0.4, 0.4, 0.2]
divisions = [8, 8, 4]
{}
[[probe]]
name = "contact"
type = "fem_force"
every = 1e-6
)",
                       supported ? "fixed = [\"zmin\"]" : "");
}

// Hertz contact in series with the plate's static stiffness k_p at the struck node:
// delta = (F / K)^(2/3) + F / k_p, K = 4/3 E* sqrt(R) (Johnson 1985, eq. 4.23); the sphere
// m x'' = -F(x) integrated with RK4; returns the peak force.
Real hertz_series_peak(Real m, Real R, Real e_star, Real k_p, Real v) {
    const Real K = Real(4) / 3 * e_star * std::sqrt(R);
    auto force = [&](Real x) {
        if (x <= 0) return Real(0);
        Real f = K * std::pow(x, Real(1.5)); // Newton on g(F) = (F/K)^(2/3) + F/k_p - x
        for (int it = 0; it < 60; ++it) {
            const Real g = std::pow(f / K, Real(2) / 3) + f / k_p - x;
            const Real dg = Real(2) / 3 * std::pow(f / K, Real(-1) / 3) / K + 1 / k_p;
            f = std::max(f - g / dg, Real(1e-3) * f);
        }
        return f;
    };
    Real x = 0, u = v, peak = 0;
    const Real h = 1e-8;
    for (int s = 0; s < 200000 && u > -v; ++s) {
        auto acc = [&](Real xx) { return -force(xx) / m; };
        const Real k1x = u, k1u = acc(x);
        const Real k2x = u + h / 2 * k1u, k2u = acc(x + h / 2 * k1x);
        const Real k3x = u + h / 2 * k2u, k3u = acc(x + h / 2 * k2x);
        const Real k4x = u + h * k3u, k4u = acc(x + h * k3x);
        x += h / 6 * (k1x + 2 * k2x + 2 * k3x + k4x);
        u += h / 6 * (k1u + 2 * k2u + 2 * k3u + k4u);
        peak = std::max(peak, force(x));
        if (x < 0 && u < 0) break;
    }
    return peak;
}

} // namespace

// Peak contact force of the sphere on the supported plate vs Hertz with the plate's
// compliance. Reference: Hertz (Johnson 1985, Contact Mechanics, 4.23 and 11.24) for the local
// contact of the two materials, 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2, in series with the
// plate's static stiffness under a point load at the struck node, k_p = 1/u (unit load), from
// a static solve of the same mesh (the compliance the coupling must transmit). Tolerance 5 %:
// the plate is not massless (its inertia and stress waves during the 0.5 ms contact make the
// quasi-static series model approximate to a few per cent).
TEST(DemFem, SphereOnElasticPlatePeakForceMatchesHertzWithPlateCompliance) {
    app::Simulation sim(test::case_from_toml("dem_fem_plate", plate_case(true)));
    // Static stiffness at the centre node of the top face (z = 0.2, x = y = 0.2).
    fem::FemSolver& fem = sim.fem();
    std::size_t node = 0;
    for (std::size_t n = 0; n < fem.nodes(); ++n)
        if (norm(fem.reference()[n] - Vec3{0.2, 0.2, 0.2}) < 1e-9) node = n;
    const Eigen::MatrixXd K = fem.assemble_stiffness();
    std::vector<int> free;
    const auto& base = fem.node_set("plate.zmin");
    std::vector<bool> fixed(fem.nodes(), false);
    for (auto b : base) fixed[std::size_t(b)] = true;
    for (std::size_t n = 0; n < fem.nodes(); ++n)
        if (!fixed[n])
            for (int k = 0; k < 3; ++k) free.push_back(int(3 * n + std::size_t(k)));
    Eigen::MatrixXd Kf(free.size(), free.size());
    for (std::size_t i = 0; i < free.size(); ++i)
        for (std::size_t j = 0; j < free.size(); ++j)
            Kf(Eigen::Index(i), Eigen::Index(j)) = K(free[i], free[j]);
    Eigen::VectorXd load = Eigen::VectorXd::Zero(Eigen::Index(free.size()));
    const auto it = std::find(free.begin(), free.end(), int(3 * node + 2));
    const Eigen::Index row = Eigen::Index(it - free.begin());
    load(row) = 1;
    const Eigen::VectorXd u = Kf.ldlt().solve(load);
    const Real k_p = 1 / u(row);

    sim.run({"", true, 0});
    const Real F_peak = sim.probe("contact").peaks()[7]; // |F| from the grains

    const Real R = 0.05, m = 2650 * 3.14159265358979 / 6 * 0.001, v = 1;
    const Real e_star = 1 / ((1 - 0.09) / 30e9 + (1 - 0.04) / 32.5e9);
    const Real rigid = hertz_series_peak(m, R, e_star, 1e30, v);
    const Real series = hertz_series_peak(m, R, e_star, k_p, v);
    std::cout << fmt::format("plate stiffness at the node {:.4g} N/m; peak force {:.1f} N; Hertz "
                             "on a rigid plate {:.1f} N ({:+.2f} %), with the plate compliance "
                             "{:.1f} N ({:+.2f} %)\n",
                             k_p, F_peak, rigid, 100 * (F_peak / rigid - 1), series,
                             100 * (F_peak / series - 1));
    EXPECT_NEAR(F_peak / series, 1, 0.05);
    EXPECT_LT(F_peak, rigid); // the plate's compliance lowers the peak
}

// Momentum conservation across the DEM-FEM interface: the sphere strikes a free plate (no
// support, no gravity); the sphere's momentum plus the plate's (sum of lumped nodal m v) stays
// at its initial value to round-off (tolerance 1e-9 of m v), and the sphere rebounds.
TEST(DemFem, SphereOnFreePlateConservesMomentum) {
    app::Simulation sim(test::case_from_toml("dem_fem_free_plate", plate_case(false)));
    auto total = [&]() {
        Vec3 p{};
        const auto& g = sim.grains().grains();
        for (Index i = 0; i < g.size(); ++i) p += g.mass[i] * g.vel[i];
        const auto& f = sim.fem();
        for (std::size_t n = 0; n < f.nodes(); ++n) p += f.masses()[n] * f.velocities()[n];
        return p;
    };
    const Vec3 p0 = total();
    sim.run({"", true, 0});
    const Vec3 p1 = total();
    const auto& g = sim.grains().grains();
    const Real mv = g.mass[0] * 1.0;
    std::cout << fmt::format("momentum before ({:.6e}, {:.6e}, {:.6e}), after ({:.6e}, {:.6e}, "
                             "{:.6e}) N s; sphere vz {:.4f} m/s\n",
                             p0.x, p0.y, p0.z, p1.x, p1.y, p1.z, g.vel[0].z);
    EXPECT_LT(norm(p1 - p0), 1e-9 * mv);
    EXPECT_GT(g.vel[0].z, 0); // it bounced off
}
