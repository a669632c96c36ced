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

// The next heap up: three equal discs, two touching on a floor and one resting on both. Closed
// form (statics; each bottom disc carries the top one's contact force N along the line of
// centres, 30 deg from the vertical, and a tangential F, the floor N_f and f, no force between
// the bottom discs): the top disc's weight W gives N cos30 - F sin30 = W/2 and N_f = 3W/2; the
// moment about a bottom disc's centre, R f - R F + M = 0, with M the rolling moments of its two
// contacts; its horizontal balance, N sin30 + F cos30 + f = 0.
// - Without rolling resistance (M = 0): f = F, so F/N = tan 15 deg = 2 - sqrt(3) = 0.268 and
//   f/N_f = tan 15 deg / 3 = 0.0893: the pyramid stands if and only if mu between the discs is at
//   least 0.268 and mu on the floor at least 0.0893.
// - With rolling resistance (EPSD, |M| <= mu_r R* F_n; R* = R/2 between discs, R on the floor)
//   and sliding at the discs' contact (F = -mu N): it stands only if
//   sin30 - mu (1 + cos30) <= mu_r (1/2 + 3 cos30 + 3 mu sin30), i.e. mu_r >= 0.0965 for
//   mu = 0.1 (which alone would not hold it) and mu_r >= 0.161 for mu = 0, and the floor must
//   hold f: mu_f >= 0.150 for mu = 0.1, 0.192 for mu = 0. Below the bound no equilibrium
//   exists, so the pyramid must collapse; above it one exists, which the elastic-plastic springs
//   must find (friction is not associated, so that half is not a theorem; it holds here).
namespace {

// How far the top disc's centre has fallen [m] after 0.5 s, gravity on at t = 0.
Real pyramid_drop(Real mu_discs, Real mu_floor, Real mu_roll) {
    const Real r = 0.005, thickness = 0.005, rho = 2500;
    dem::Material disc;
    disc.name = "disc";
    disc.density = rho;
    disc.kn = disc.kt = 1e5;
    disc.restitution = 0.3;
    disc.friction = mu_discs;
    disc.rolling_friction = mu_roll;
    dem::Material floor = disc;
    floor.name = "floor";
    dem::PairOverride on_floor;
    on_floor.a = "disc", on_floor.b = "floor";
    on_floor.friction = mu_floor;
    on_floor.rolling_friction = mu_roll;
    DemRig rig;
    const Real mass = rho * pi * r * r * thickness;
    for (Real x : {-r, r}) rig.grains.add({x, 0, r}, {}, r, mass, 0.5 * mass * r * r, 0);
    const Vec3 top{0, 0, r + std::sqrt(3.0) * r};
    rig.grains.add(top, {}, r, mass, 0.5 * mass * r * r, 0);
    rig.add_plane("floor", {0, 0, 0}, {0, 0, 1}, 1);
    dem::DemParams p;
    p.dim = 2;
    p.rolling = mu_roll > 0 ? "epsd" : "none";
    p.reorder = false; // grain 2 stays the top disc
    p.safety = 0.05;
    rig.start(p, {disc, floor}, {-0.1, 0, -0.01}, {0.1, 0, 0.1}, {on_floor});
    for (Real t = 0; t < 0.5; t += rig.solver->dt()) rig.solver->advance(rig.solver->dt());
    return top.z - rig.grains.pos[2].z;
}

} // namespace

// Each threshold approached from both sides: within 3-5 % without rolling resistance, 7-12 %
// with it (the pyramid at mu_r 0.105 stands and at 0.09 collapses, the bound 0.0965; between
// frictionless discs, mu = 0, the bound is 0.161): "stands" is a fall below 0.01 R (the
// contacts' elastic overlap is ~2e-5 R), "collapses" a fall beyond 0.2 R within 0.5 s.
TEST(DemRepose, ThreeDiscPyramidStandsAtTheClosedFormFriction) {
    const Real r = 0.005;
    struct Case {
        Real mu_discs, mu_floor, mu_roll;
        bool stands;
    };
    for (const Case c :
         {Case{0.28, 0.5, 0, true}, Case{0.26, 0.5, 0, false}, Case{0.5, 0.093, 0, true},
          Case{0.5, 0.086, 0, false}, Case{0.1, 0.5, 0.105, true}, Case{0.1, 0.5, 0.09, false},
          Case{0.0, 0.5, 0.18, true}, Case{0.0, 0.5, 0.15, false}}) {
        const Real drop = pyramid_drop(c.mu_discs, c.mu_floor, c.mu_roll);
        std::printf("mu discs %.3g, floor %.3g, mu_r %.3g: top disc fell %.3g R (%s)\n", c.mu_discs,
                    c.mu_floor, c.mu_roll, drop / r, c.stands ? "stands" : "collapses");
        if (c.stands)
            EXPECT_LT(drop, 0.01 * r) << c.mu_discs << " " << c.mu_floor << " " << c.mu_roll;
        else
            EXPECT_GT(drop, 0.2 * r) << c.mu_discs << " " << c.mu_floor << " " << c.mu_roll;
    }
}
