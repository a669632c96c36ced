// Clumps of grains (multi-sphere particles) against closed forms: a torque-free tumbling clump
// keeps its angular momentum and energy; a dimer of two touching discs on a tilting table
// slides at atan(mu) or tips over its downhill disc at 45 deg, whichever comes first, where a
// single disc rolls away at any tilt; a grain on dimers stands without friction between the
// grains, where the same heap of round grains needs it.
#include "debrisflow/rigid/quaternion_k.hpp"
#include "dem_rig.hpp"
#include "run_case.hpp"
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <gtest/gtest.h>

using namespace debrisflow;
using test::DemRig;

namespace {

constexpr Real pi = 3.14159265358979323846;

dem::Material glass(Real mu) {
    dem::Material m;
    m.name = "glass";
    m.density = 2500;
    m.kn = m.kt = 1e5;
    m.restitution = 0.3;
    m.friction = mu;
    return m;
}

// Two touching discs of radius r (2D, thickness t) lying along x on a floor, as one clump:
// A = 2 pi r^2, M = rho t A, I_y = 2 (1/2 m r^2 + m r^2) = 3 m r^2 per disc mass m.
void add_dimer(DemRig& rig, Real r, Real t, Real rho) {
    const Real m = rho * t * pi * r * r, z = r * (1 - 1e-4);
    std::vector<std::uint32_t> ids;
    for (Real x : {-r, r}) {
        ids.push_back(rig.grains.next_id());
        rig.grains.add({x, 0, z}, {}, r, m, 3 * m * r * r, 0);
    }
    rig.grains.clumps.add({0, 0, z}, {}, {}, rigid::Quat{}, 2 * m, {0, 1 / (3 * m * r * r), 0}, ids,
                          {{-r, 0, 0}, {r, 0, 0}});
}

// Tilts gravity from beta0 at `rate` deg/s (after 0.05 s at rest at beta0); returns the tilt
// [deg] at which the body has moved half a disc radius along the floor (90: never by 60 deg).
Real departure_angle(bool dimer, Real mu, Real beta0, Real rate) {
    const Real r = 0.005, t = 0.005, rho = 2500, g = 9.81;
    DemRig rig;
    if (dimer) {
        add_dimer(rig, r, t, rho);
    } else {
        const Real m = rho * t * pi * r * r;
        rig.grains.add({0, 0, r * (1 - 1e-4)}, {}, r, m, 0.5 * m * r * r, 0);
    }
    rig.add_plane("floor", {0, 0, 0}, {0, 0, 1}, -1);
    dem::DemParams p;
    p.dim = 2;
    p.safety = 0.05;
    rig.start(p, {glass(mu)}, {-1, 0, -1}, {1, 0, 1});
    // the clump's centre of mass, or the disc's centre
    return rig.tilt_until_moved(g, beta0, rate, 0.05, 0.5 * r, [&] {
        return dimer ? rig.grains.clumps.pos[0] : rig.grains.pos[0];
    });
}

} // namespace

// Tilted at 2.5 deg/s from 4 deg below the closed form (the disc: from 0): a dimer with mu = 0.5
// slides at atan(0.5) = 26.57 deg; with mu = 1.2 (sliding would wait for 50.19 deg) it tips over
// its downhill disc when gravity through the centre of mass passes the downhill contact, tan(beta)
// = r / r, 45 deg. Not before, at most 1 deg after (the ramp's lag, as in DemRepose). A single disc
// rolls away within 1 deg.
TEST(DemClump, DimerOnATiltingTableSlidesOrTipsAtTheClosedFormAngle) {
    const Real slide_expected = std::atan(0.5) * 180 / pi;
    const Real slide = departure_angle(true, 0.5, slide_expected - 4, 2.5);
    const Real tip = departure_angle(true, 1.2, 41, 2.5),
               disc = departure_angle(false, 0.5, 0, 2.5);
    std::printf("dimer mu 0.5 leaves at %.2f deg (slides at %.2f); mu 1.2 at %.2f deg (tips at "
                "45); single disc at %.2f deg\n",
                slide, slide_expected, tip, disc);
    EXPECT_GE(slide, slide_expected);
    EXPECT_LE(slide, slide_expected + 1);
    EXPECT_GE(tip, 45);
    EXPECT_LE(tip, 46);
    EXPECT_LE(disc, 1);
}

// An asymmetric clump (three unequal spheres, not in a plane of symmetry) tumbling with no
// gravity and no contact: the world angular momentum is conserved to round-off by the split
// rotation (rigid::free_rotation, Dullweber et al. 1997) and the rotational energy to its
// bounded O(dt^2) error (1e-6 relative over about 4 turns); the centre of mass moves uniformly
// and the members keep their distances.
TEST(DemClump, TorqueFreeTumblingConservesAngularMomentumAndEnergy) {
    const char* text = R"(
name = "tumbling"
dimensions = 3
[time]
end = 0.5
[output]
vtk = false
[physics]
gravity = [0, 0, 0]
[domain]
min = [-1, -1, -1]
max = [1, 1, 1]
[dem]
safety = 0.05
[[material]]
name = "rock"
density = 2650
kn = 1e5
restitution = 0.5
friction = 0.5
[[grains]]
name = "rock"
material = "rock"
packing = "single"
position = [0, 0, 0]
diameter = 0.02
velocity = [0.1, 0.05, 0]
angular_velocity = [40, 25, -30]
clump = [[0, 0, 0, 1], [1.2, 0, 0, 0.7], [0.3, 1.0, 0.4, 0.5]]
)";
    app::Simulation sim(test::case_from_toml("tumbling", text));
    const auto& cl = sim.grains().grains().clumps;
    ASSERT_EQ(cl.size(), 1);
    const Vec3 l0 = cl.ang_mom[0], x0 = cl.pos[0], v0 = cl.vel[0];
    const Real e0 = dot(cl.spin(0), cl.ang_mom[0]);
    const auto& g = sim.grains().grains();
    auto distances = [&] {
        std::vector<Real> d = {norm(g.pos[0] - g.pos[1]), norm(g.pos[1] - g.pos[2]),
                               norm(g.pos[0] - g.pos[2])};
        std::sort(d.begin(), d.end());
        return d;
    };
    const auto d0 = distances();
    app::RunOptions opt;
    opt.quiet = true;
    sim.run(opt);
    const Vec3 l = cl.ang_mom[0];
    const Real e = dot(cl.spin(0), cl.ang_mom[0]);
    std::printf("|dL|/|L| %.3g, dE/E %.3g, turns %.1f\n", norm(l - l0) / norm(l0), e / e0 - 1,
                0.5 * norm(cl.spin(0)) / (2 * pi));
    EXPECT_LT(norm(l - l0) / norm(l0), 1e-12);
    EXPECT_LT(std::abs(e / e0 - 1), 1e-6);
    EXPECT_LT(norm(cl.pos[0] - (x0 + 0.5 * v0)), 1e-12);
    const auto d1 = distances();
    for (std::size_t k = 0; k < 3; ++k) EXPECT_NEAR(d1[k] / d0[k], 1, 1e-12);
}

// The smallest heap on clumps: k dimers (two touching grains of radius r as one clump; k = 2
// discs in 2D, 3 spheres in 3D) lie on a floor, pointing away from the axis, their inner grains
// touching in a ring; a grain of the same size rests on the inner ones. Closed form (statics):
// each contact with the top grain lies beta from the vertical (30 deg in 2D, asin(1/sqrt(3)) =
// 35.26 deg in 3D) and needs no friction: the top grain sits in the pocket as long as the
// dimers stay, and a dimer cannot turn out of the way (its two floor contacts stop it rolling;
// the push, inward of the outer contact and pointing down, cannot tip it: both floor normals
// stay positive). Each frictionless contact carries N = m g / (k cos(beta)); its horizontal
// part m g tan(beta) / k pushes the dimer (mass 2 m) outward along its axis, against the floor
// friction mu_f (2 m g + m g / k). So the heap stands iff mu_f >= tan(beta) / (2 k + 1) (2D:
// 0.1155, 3D: 0.1010), whatever the friction between the grains, zero included. The same heap
// of round grains (the k inner grains alone, as in DemRepose's pyramid) needs mu >= tan(beta/2)
// between the grains or rolling resistance: with mu = 0 and no rolling resistance it collapses.
namespace {

// A dimer of two touching grains of radius r centred at c, its axis horizontal at angle a from
// x (a clump of two discs of thickness t in 2D, two spheres in 3D); member inertia is unused.
void add_dimer(DemRig& rig, int dim, Vec3 c, Real a, Real r, Real t, Real rho) {
    const Real m = dim == 2 ? rho * t * pi * r * r : DemRig::sphere_mass(rho, r);
    const Vec3 u{std::cos(a), std::sin(a), 0};
    std::vector<std::uint32_t> ids;
    for (Real s : {-1.0, 1.0}) {
        ids.push_back(rig.grains.next_id());
        rig.grains.add(c + (s * r) * u, {}, r, m, m * r * r, 0);
    }
    // body frame along the axis: 2D I_y = 2 (m r^2 / 2 + m r^2); 3D I_x = 2 (2/5 m r^2),
    // I_y = I_z = 2 (2/5 m r^2 + m r^2)
    const Vec3 inv_i =
        dim == 2 ? Vec3{0, 1 / (3 * m * r * r), 0}
                 : Vec3{1 / (0.8 * m * r * r), 1 / (2.8 * m * r * r), 1 / (2.8 * m * r * r)};
    rig.grains.clumps.add(c, {}, {}, rigid::axis_angle({0, 0, 1}, a), 2 * m, inv_i, ids,
                          {{-r, 0, 0}, {r, 0, 0}});
}

// How far the top grain's centre has fallen [m] after 0.5 s, gravity on at t = 0: on dimers,
// or on single grains where the dimers' inner grains are.
Real heap_on_dimers_drop(int dim, bool dimers, Real mu_grains, Real mu_floor) {
    const Real r = 0.005, t = 0.005, rho = 2500;
    dem::Material grain = glass(mu_grains);
    dem::Material floor = grain;
    floor.name = "floor";
    dem::PairOverride on_floor;
    on_floor.a = "glass", on_floor.b = "floor";
    on_floor.friction = mu_floor;
    DemRig rig;
    const int k = dim == 2 ? 2 : 3;
    const Real base = r / std::sin(pi / k); // inner grains' centres from the axis
    for (int b = 0; b < k; ++b) {
        const Real a = 2 * pi * b / k;
        const Vec3 u{std::cos(a), std::sin(a), 0};
        if (dimers)
            add_dimer(rig, dim, Vec3{0, 0, r} + (base + r) * u, a, r, t, rho);
        else if (dim == 2)
            rig.add_disc(Vec3{0, 0, r} + base * u, r, rho, t, 0);
        else
            rig.add_sphere(Vec3{0, 0, r} + base * u, {}, r, rho, 0);
    }
    const Vec3 top{0, 0, r + std::sqrt(4 * r * r - base * base)};
    const Index top_id =
        dim == 2 ? rig.add_disc(top, r, rho, t, 0) : rig.add_sphere(top, {}, r, rho, 0);
    rig.add_plane("floor", {0, 0, 0}, {0, 0, 1}, 1);
    dem::DemParams p;
    p.dim = dim;
    p.reorder = false; // the top grain keeps its index
    p.safety = 0.05;
    rig.start(p, {grain, floor}, {-0.1, dim == 2 ? 0 : -0.1, -0.01}, {0.1, dim == 2 ? 0 : 0.1, 0.1},
              {on_floor});
    for (Real time = 0; time < 0.5; time += rig.solver->dt()) rig.solver->advance(rig.solver->dt());
    return top.z - rig.grains.pos[std::size_t(top_id)].z;
}

} // namespace

// The floor's threshold from both sides, 4 % above (stands: the top grain falls less than
// 0.01 r in 0.5 s; the contacts' elastic overlap is ~1e-6 r) and below (collapses: more than
// 0.2 r), with no friction between the grains; and the round grains' heap at the floor
// friction that holds the dimers, which collapses.
TEST(DemClump, GrainOnDimersStandsWithoutGrainFrictionAtTheClosedFormFloorFriction) {
    const Real r = 0.005;
    for (const int dim : {2, 3}) {
        const int k = dim == 2 ? 2 : 3;
        const Real beta = dim == 2 ? pi / 6 : std::asin(1 / std::sqrt(3.0));
        const Real mu_f = std::tan(beta) / (2 * k + 1);
        struct Case {
            bool dimers;
            Real mu_floor;
            bool stands;
        };
        for (const Case c : {Case{true, 1.04 * mu_f, true}, Case{true, 0.96 * mu_f, false},
                             Case{false, 1.04 * mu_f, false}}) {
            const Real drop = heap_on_dimers_drop(dim, c.dimers, 0, c.mu_floor);
            std::printf("%dD %s, mu 0, floor %.4f (closed form %.4f): top grain fell %.3g r (%s)\n",
                        dim, c.dimers ? "on dimers" : "on round grains", c.mu_floor, mu_f, drop / r,
                        c.stands ? "stands" : "collapses");
            if (c.stands)
                EXPECT_LT(drop, 0.01 * r) << dim << "D floor " << c.mu_floor;
            else
                EXPECT_GT(drop, 0.2 * r)
                    << dim << "D floor " << c.mu_floor << " dimers " << c.dimers;
        }
    }
}
