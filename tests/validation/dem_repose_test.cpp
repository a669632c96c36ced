// The smallest heap: a disc resting in the pocket of two touching fixed discs of its size,
// under gravity tilted by beta. Closed form (statics of the top disc): the two contact normals
// lie 30 deg either side of the vertical, so without rolling resistance the disc stays while
// gravity points between them (beta <= 30 deg, whatever the sliding friction) and rolls out
// over the downhill disc beyond. With rolling resistance the moment at that contact carries
// the torque of the friction force, F R = m g R sin(phi), up to mu_r R* F_n =
// mu_r R* m g cos(phi), so the disc stays up to beta = 30 deg + atan(mu_r R* / R)
// = 30 deg + atan(mu_r / 2) for equal discs (R* = R / 2), as long as atan(mu) exceeds that
// (rolling, not sliding). A heap on two-grain clumps, which needs no friction between the
// grains, is DemClump.GrainOnDimersStandsWithoutGrainFrictionAtTheClosedFormFloorFriction.
#include "dem_rig.hpp"
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fmt/format.h>
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
    const Index top = rig.add_disc({0, 0, std::sqrt(3.0) * r}, r, rho, thickness, 0);
    const Real mass = rig.grains.mass[std::size_t(top)];
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

// The next heap up: three equal discs, two touching on a floor and one resting on both (in 3D
// four spheres, three touching on the floor and one on top). Closed form (statics; each of the
// k bottom grains (k = 2 discs, 3 spheres) carries the top one's contact force N along the line
// of centres, beta from the vertical (30 deg for discs, asin(1/sqrt(3)) = 35.26 deg for spheres),
// and a tangential F, the floor N_f and f, no force between the bottom grains): the top grain's
// weight W gives N cos(beta) - F sin(beta) = W/k and N_f = (k + 1) W/k; the moment about a
// bottom grain's centre, R f - R F + M = 0, with M the rolling moments of its two contacts; its
// horizontal balance, N sin(beta) + F cos(beta) + f = 0.
// - Without rolling resistance (M = 0): f = F, so F/N = tan(beta/2) and f/N_f =
//   tan(beta/2)/(k + 1): the pyramid stands if and only if mu between the grains is at least
//   tan(beta/2) (discs 0.268, spheres 0.318) and mu on the floor at least tan(beta/2)/(k + 1)
//   (0.0893, 0.0795).
// - With rolling resistance (EPSD, |M| <= mu_r R* F_n; R* = R/2 between grains, R on the
//   floor) and sliding between the grains (F = -mu N, s = -mu): it stands only if
//   sin(beta) + s (1 + cos(beta)) <= mu_r (1/2 + (k + 1)(cos(beta) - s sin(beta))), and the
//   floor holds f: |sin(beta) + s cos(beta)| <= (k + 1) mu_f (cos(beta) - s sin(beta)).
//   Below the bound no equilibrium exists, so the pyramid must collapse; above it one exists,
//   which the elastic-plastic springs must find (friction is not associated, so that half is
//   not a theorem; it holds here).
namespace {

struct Pyramid {
    int dim;
    Real beta() const { return dim == 2 ? pi / 6 : std::asin(1 / std::sqrt(3.0)); }
    int bottom() const { return dim == 2 ? 2 : 3; }
    Real mu_grains() const { return std::tan(beta() / 2); }
    Real mu_floor() const { return mu_grains() / (bottom() + 1); }
    // the least mu_r with sliding friction mu between the grains
    Real mu_roll(Real mu) const {
        const Real sb = std::sin(beta()), cb = std::cos(beta());
        return (sb - mu * (1 + cb)) / (Real(0.5) + (bottom() + 1) * (cb + mu * sb));
    }
    // the floor friction that state needs
    Real mu_floor_rolling(Real mu) const {
        const Real sb = std::sin(beta()), cb = std::cos(beta());
        return std::abs(sb - mu * cb) / ((bottom() + 1) * (cb + mu * sb));
    }
};

// How far the top grain's centre has fallen [m] after 0.5 s, gravity on at t = 0.
Real pyramid_drop(const Pyramid& pyr, Real mu_grains, Real mu_floor, Real mu_roll) {
    const Real r = 0.005, thickness = 0.005, rho = 2500;
    dem::Material grain;
    grain.name = "grain";
    grain.density = rho;
    grain.kn = grain.kt = 1e5;
    grain.restitution = 0.3;
    grain.friction = mu_grains;
    grain.rolling_friction = mu_roll;
    dem::Material floor = grain;
    floor.name = "floor";
    dem::PairOverride on_floor;
    on_floor.a = "grain", on_floor.b = "floor";
    on_floor.friction = mu_floor;
    on_floor.rolling_friction = mu_roll;
    DemRig rig;
    // a disc of the quasi-2D layer (thickness `thickness`) or a sphere, at rest at x
    const auto add_grain = [&](Vec3 x) {
        return pyr.dim == 3 ? rig.add_sphere(x, {}, r, rho, 0)
                            : rig.add_disc(x, r, rho, thickness, 0);
    };
    const Real base = r / std::sin(pi / Real(pyr.bottom())); // bottom centres from the axis
    for (int b = 0; b < pyr.bottom(); ++b) {
        const Real a = 2 * pi * b / pyr.bottom();
        add_grain({base * std::cos(a), pyr.dim == 2 ? 0 : base * std::sin(a), r});
    }
    const Vec3 top{0, 0, r + std::sqrt(4 * r * r - base * base)};
    add_grain(top);
    rig.add_plane("floor", {0, 0, 0}, {0, 0, 1}, 1);
    dem::DemParams p;
    p.dim = pyr.dim;
    p.rolling = mu_roll > 0 ? "epsd" : "none";
    p.reorder = false; // the last grain stays the top one
    p.safety = 0.05;
    rig.start(p, {grain, floor}, {-0.1, pyr.dim == 2 ? 0 : -0.1, -0.01},
              {0.1, pyr.dim == 2 ? 0 : 0.1, 0.1}, {on_floor});
    for (Real t = 0; t < 0.5; t += rig.solver->dt()) rig.solver->advance(rig.solver->dt());
    return top.z - rig.grains.pos[std::size_t(pyr.bottom())].z;
}

} // namespace

// Each threshold approached from both sides: 4 % above (stands) and below (collapses) without
// rolling resistance, 10 % above and 7 % below with it: "stands" is a fall of the top grain
// below 0.01 R in 0.5 s (the contacts' elastic overlap is ~2e-5 R), "collapses" beyond 0.2 R.
TEST(DemRepose, PyramidOfThreeDiscsOrFourSpheresStandsAtTheClosedFormFriction) {
    const Real r = 0.005;
    for (const int dim : {2, 3}) {
        const Pyramid pyr{dim};
        struct Case {
            Real mu_grains, mu_floor, mu_roll;
            bool stands;
        };
        const Real mu = pyr.mu_grains(), muf = pyr.mu_floor();
        const Real mr1 = pyr.mu_roll(0.1), mr0 = pyr.mu_roll(0);
        std::printf("%dD: closed form mu %.4f, floor %.4f, mu_r %.4f (mu = 0.1), %.4f (mu = 0)\n",
                    dim, mu, muf, mr1, mr0);
        // the rolling cases' floor (mu 0.5) holds the state the bound assumes
        ASSERT_LT(std::max(pyr.mu_floor_rolling(0.1), pyr.mu_floor_rolling(0)), 0.5);
        for (const Case c : {Case{1.04 * mu, 0.5, 0, true}, Case{0.96 * mu, 0.5, 0, false},
                             Case{0.5, 1.04 * muf, 0, true}, Case{0.5, 0.96 * muf, 0, false},
                             Case{0.1, 0.5, 1.10 * mr1, true}, Case{0.1, 0.5, 0.93 * mr1, false},
                             Case{0, 0.5, 1.10 * mr0, true}, Case{0, 0.5, 0.93 * mr0, false}}) {
            const Real drop = pyramid_drop(pyr, c.mu_grains, c.mu_floor, c.mu_roll);
            std::printf("%dD mu %.4f, floor %.4f, mu_r %.4f: top grain fell %.3g R (%s)\n", dim,
                        c.mu_grains, c.mu_floor, c.mu_roll, drop / r,
                        c.stands ? "stands" : "collapses");
            const auto what =
                fmt::format("{}D mu {} floor {} mu_r {}", dim, c.mu_grains, c.mu_floor, c.mu_roll);
            if (c.stands)
                EXPECT_LT(drop, 0.01 * r) << what;
            else
                EXPECT_GT(drop, 0.2 * r) << what;
        }
    }
}
