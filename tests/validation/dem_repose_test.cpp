// The smallest heap: a disc resting in the pocket of two touching fixed discs of its size,
// under gravity tilted by beta. Closed form (statics of the top disc): the two contact normals
// lie 30 deg either side of the vertical, so without rolling resistance the disc stays while
// gravity points between them (beta <= 30 deg, whatever the sliding friction) and rolls out
// over the downhill disc beyond. With rolling resistance the moment at that contact carries
// the torque of the friction force, F R = m g R sin(phi), up to mu_r R* F_n =
// mu_r R* m g cos(phi), so the disc stays up to beta = 30 deg + atan(mu_r R* / R)
// = 30 deg + atan(mu_r / 2) for equal discs (R* = R / 2), as long as atan(mu) exceeds that
// (rolling, not sliding). The same heap of two-sphere clumps is not built here: grains are
// spheres (discs in 2D) only.
#include "dem_rig.hpp"
#include <cmath>
#include <cstdio>
#include <gtest/gtest.h>

using namespace debrisflow;
using test::DemRig;

namespace {

constexpr Real pi = 3.14159265358979323846;

// The tilting table: gravity turns from `beta0_deg` at `rate_deg` per second (after 0.1 s at
// rest at beta0); returns the tilt [deg] at which the top disc has moved half its radius from
// where it rested (90 if it never does by 60 deg).
Real departure_angle(Real mu_roll, const std::string& rolling, Real beta0_deg, Real rate_deg) {
    const Real r = 0.005, thickness = 0.005, rho = 2500, g = 9.81;
    dem::Material m;
    m.name = "glass";
    m.density = rho;
    m.kn = m.kt = 1e5;
    m.restitution = 0.3;
    m.friction = 0.8; // atan(0.8) = 38.7 deg: rolling, not sliding, sets the limit below
    m.rolling_friction = mu_roll;
    DemRig rig;
    const Real mass = rho * pi * r * r * thickness;
    rig.grains.add({0, 0, std::sqrt(3.0) * r}, {}, r, mass, 0.5 * mass * r * r, 0);
    // The two base discs: fixed spheres of a body that never moves (the reaction is dropped).
    dem::ObstacleSet base;
    for (Real x : {-r, r}) base.spheres.push_back({{x, 0, 0}, {}, {}, r, 1e6 * mass, 0, 0});
    base.body_com = {{0, 0, 0}};
    base.impulse.assign(1, {});
    base.angular_impulse.assign(1, {});
    dem::DemParams p;
    p.dim = 2;
    p.rolling = rolling;
    p.safety = 0.05;
    Domain d;
    d.lo = {-0.1, 0, -0.1};
    d.hi = {0.1, 0, 0.1};
    rig.solver =
        std::make_unique<dem::DemSolver>(p, rig.grains, rig.walls, std::vector<dem::Material>{m},
                                         std::vector<dem::PairOverride>{}, d);
    rig.solver->attach_obstacles(&base);
    rig.solver->update_neighbors(true);
    rig.solver->compute_forces();
    return rig.tilt_until_moved(g, beta0_deg, rate_deg, 0.1, 0.5 * r,
                                [&] { return rig.grains.pos[0]; });
}

} // namespace

// Tilted at 5 deg/s, the top disc leaves its pocket at the closed-form angle: within 1 deg
// (the lag of a ramp: near the critical angle the disc needs about 0.1-0.2 s to roll half a
// radius, 0.5-1 deg of tilt at this rate; the contacts' elastic overlap, ~1e-5 R, tilts the
// normals by far less), and never before it.
TEST(DemRepose, DiscInAPocketLeavesAtTheClosedFormAngle) {
    struct Case {
        Real mu_roll;
        const char* rolling;
    };
    for (const Case c :
         {Case{0, "none"}, Case{0.3, "epsd"}, Case{0.3, "constant_torque"}, Case{0.6, "epsd"}}) {
        const Real critical = 30 + std::atan(c.mu_roll / 2) * 180 / pi;
        const Real beta = departure_angle(c.mu_roll, c.rolling, critical - 4, 2.5);
        std::printf("%s mu_r %.2f: leaves at %.2f deg (closed form %.2f deg)\n", c.rolling,
                    c.mu_roll, beta, critical);
        EXPECT_GE(beta, critical) << c.rolling << " mu_r " << c.mu_roll;
        EXPECT_LE(beta, critical + 1) << c.rolling << " mu_r " << c.mu_roll;
    }
}
