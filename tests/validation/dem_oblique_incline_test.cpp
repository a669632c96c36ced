// Chung & Ooi (2011) benchmark 4 (oblique impact of an Al oxide sphere on a rigid wall,
// curves digitised in ../shared/reference/dem_chung_ooi_2011/) and a sphere on an incline
// (../shared/reference/analytic/sphere_on_incline_mu0.3.csv).
#include "dem_rig.hpp"
#include "reference_data.hpp"
#include "run_case.hpp"
#include <cmath>
#include <cstdio>
#include <fstream>
#include <gtest/gtest.h>
#include <sstream>

using namespace debrisflow;
using test::DemRig;

namespace {

constexpr Real pi = 3.14159265358979323846;

std::vector<std::pair<Real, Real>> read_pairs(const std::string& rel) {
    std::ifstream in(test::reference(rel));
    EXPECT_TRUE(in.good()) << rel;
    std::vector<std::pair<Real, Real>> out;
    std::string line;
    while (std::getline(in, line)) {
        if (line.empty() || line[0] == '#') {
            if (!out.empty()) break; // first block only
            continue;
        }
        for (auto& c : line)
            if (c == ',') c = ' ';
        std::stringstream s(line);
        Real a, b;
        if (s >> a >> b) out.emplace_back(a, b);
    }
    return out;
}

struct Oblique {
    Real et, spin, rebound_deg;
};

// Al oxide sphere (R 2.5 mm, rho 4000, E 380 GPa, nu 0.23), 3.9 m/s at `angle` from the wall
// normal, e = 0.98, mu = 0.092 (Chung & Ooi 2011, Table 4), rigid wall z = 0, no gravity.
Oblique oblique_impact(Real angle_deg) {
    const Real r = 0.0025, v = 3.9, a = angle_deg * pi / 180;
    dem::Material m;
    m.name = "al_oxide";
    m.law = "hertz_mindlin";
    m.density = 4000;
    m.youngs_modulus = 3.8e11;
    m.poisson = 0.23;
    m.restitution = 0.98;
    m.friction = 0.092;
    dem::Material wall = m;
    wall.name = "rigid";
    wall.rigid = true;
    DemRig rig;
    const Real vt = v * std::sin(a), vn = v * std::cos(a);
    rig.add_sphere({0, 0, r * 1.0001}, {vt, 0, -vn}, r, m.density, 0);
    rig.add_plane("floor", {0, 0, 0}, {0, 0, 1}, 1);
    dem::DemParams p;
    p.gravity = {0, 0, 0};
    p.dt = 6.1e-6 / 2000;
    rig.start(p, {m, wall}, {-1, -1, -1}, {1, 1, 1});
    bool touched = false;
    for (int s = 0; s < 20000; ++s) {
        rig.solver->advance(p.dt);
        const bool touching = rig.grains.pos[0].z < r;
        touched = touched || touching;
        if (touched && !touching) break;
    }
    const auto& g = rig.grains;
    // Chung & Ooi plot forward spin (rolling along +x on a floor below: w_y > 0) as negative.
    const Real spin = -g.spin[0].y;
    const Real vct = g.vel[0].x - r * g.spin[0].y; // contact-point tangential velocity (x)
    return {g.vel[0].x / vt, spin, std::atan(vct / g.vel[0].z) * 180 / pi};
}

} // namespace

// Tangential restitution, post-impact spin and rebound angle at each reference incidence
// angle, tolerance 3 % (issue 3): relative for the tangential restitution (a coefficient,
// 0.6-0.98); of the curve's span for spin and rebound angle, which pass through or near zero
// at small incidence where a relative error is meaningless.
TEST(DemChungOoi, ObliqueImpactMatchesBenchmark4) {
    const auto et = read_pairs("dem_chung_ooi_2011/benchmark4_graph1_ref.dat");
    const auto spin = read_pairs("dem_chung_ooi_2011/benchmark4_graph2_ref.dat");
    const auto angle = read_pairs("dem_chung_ooi_2011/benchmark4_graph3.dat");
    ASSERT_GE(et.size(), 10u);
    auto check = [](const std::vector<std::pair<Real, Real>>& ref, auto get, const char* what,
                    bool relative) {
        Real lo = 1e30, hi = -1e30, worst = 0;
        for (const auto& [x, y] : ref) lo = std::min(lo, y), hi = std::max(hi, y);
        for (const auto& [x, y] : ref) {
            const Real got = get(oblique_impact(x));
            worst = std::max(worst, std::fabs(got - y) / (hi - lo));
            std::printf("  %s at %5.1f deg: %.4g (reference %.4g, %+.2f %%)\n", what, x, got, y,
                        100 * (got / y - 1));
            const Real scale = relative ? std::fabs(y) : hi - lo;
            EXPECT_NEAR(got, y, 0.03 * scale) << what << " at " << x << " deg";
        }
        std::printf("benchmark 4 %s: worst deviation %.2f %% of range\n", what, 100 * worst);
    };
    check(
        et, [](const Oblique& o) { return o.et; }, "tangential restitution", true);
    check(
        spin, [](const Oblique& o) { return o.spin; }, "spin [rad/s]", false);
    check(
        angle, [](const Oblique& o) { return o.rebound_deg; }, "rebound angle [deg]", false);
}

// A solid sphere released on a plane inclined at theta (gravity tilted), mu = 0.3: rolls with
// a = 5/7 g sin(theta) for tan(theta) <= 7 mu / 2, slides with a = g (sin(theta) - mu cos(theta))
// above. Acceleration from a least-squares fit of v(t) over 0.1-0.4 s; tolerance 0.5 % (issue 3).
TEST(DemIncline, RollingAndSlidingAccelerations) {
    std::ifstream in(test::reference("analytic/sphere_on_incline_mu0.3.csv"));
    ASSERT_TRUE(in.good());
    std::string line;
    std::getline(in, line);
    while (std::getline(in, line)) {
        std::stringstream s(line);
        std::string f[5];
        for (auto& x : f) std::getline(s, x, ',');
        const Real theta = std::stod(f[1]) * pi / 180, a_ref = std::stod(f[3]);
        for (const char* law : {"linear", "hertz_mindlin"}) {
            dem::Material m;
            m.name = "glass";
            m.law = law;
            m.density = 2550;
            m.kn = m.kt = 1e6;
            m.youngs_modulus = 1e8;
            m.poisson = 0.25;
            m.restitution = 0.3;
            m.friction = 0.3;
            DemRig rig;
            const Real r = 0.01, g = 9.81;
            rig.add_sphere({0, 0, r}, {}, r, m.density, 0);
            rig.add_plane("incline", {0, 0, 0}, {0, 0, 1}, -1);
            dem::DemParams p;
            p.gravity = {g * std::sin(theta), 0, -g * std::cos(theta)};
            rig.start(p, {m}, {-1, -1, -1}, {10, 1, 1});
            const Real a = rig.fitted_acceleration(0.1, 0.4);
            SCOPED_TRACE(std::string(law) + " theta " + f[1] + " " + f[2]);
            EXPECT_NEAR(a / a_ref, 1, 0.005);
            std::printf("incline %s %s deg (%s): a = %.5f, reference %.5f, error %+.3f %%\n", law,
                        f[1].c_str(), f[2].c_str(), a, a_ref, 100 * (a / a_ref - 1));
        }
    }
}
