// Closed-form checks of the DCDEM normal law and of rolling resistance.
#include "dem_rig.hpp"
#include <cmath>
#include <cstdio>
#include <gtest/gtest.h>

using namespace debrisflow;
using test::DemRig;

namespace {

// Normal impact of a sphere on a rigid plane at v; returns the rebound speed / v.
Real rebound_ratio(const dem::Material& m, Real r, Real v) {
    dem::Material rigid = m;
    rigid.name = "rigid";
    rigid.rigid = true;
    DemRig rig;
    rig.add_sphere({0, 0, r * 1.001}, {0, 0, -v}, r, m.density, 0);
    rig.add_plane("floor", {0, 0, 0}, {0, 0, 1}, 1);
    dem::DemParams p;
    p.gravity = {0, 0, 0};
    p.safety = 0.001;
    rig.start(p, {m, rigid}, {-1, -1, -1}, {1, 1, 1});
    bool touched = false;
    for (long s = 0; s < 1000000; ++s) {
        rig.solver->advance(rig.solver->dt());
        const bool touching = rig.grains.pos[0].z < r;
        touched = touched || touching;
        if (touched && !touching) break;
    }
    return rig.grains.vel[0].z / v;
}

} // namespace

// DCDEM (Canelas et al. 2017, Lemieux et al. 2008): F = k_n d^1.5 - g_n d^0.25 v_n with
// k_n = 4/3 E* sqrt(R*), g_n = C_n sqrt(6 m* E* sqrt(R*)) is Tsuji's oscillator with
// alpha = g_n / sqrt(m* k_n) = C_n sqrt(4.5), so its restitution is velocity-independent and
// equals tsuji_restitution(C_n sqrt(4.5)). Tolerance 0.5 % (time integration at t_c/1000).
TEST(DemLaws, DcdemRestitutionFollowsFromCn) {
    dem::Material m;
    m.name = "rock";
    m.law = "dcdem";
    m.density = 2650;
    m.youngs_modulus = 4.5e10; // the slit-check-dam paper's sediment: E 45 GPa, nu 0.35
    m.poisson = 0.35;
    m.friction = 0.35;
    for (Real cn : {1e-5, 0.05, 0.2}) {
        m.keys<dem::DcdemLaw>().damping_cn = cn;
        const Real expected = dem::tsuji_restitution(cn * std::sqrt(4.5));
        for (Real v : {0.5, 3.0}) {
            const Real e = rebound_ratio(m, 0.01, v);
            EXPECT_NEAR(e / expected, 1, 0.005) << "C_n " << cn << " v " << v;
            std::printf("dcdem C_n %.0e v %.1f m/s: e = %.4f (expected %.4f)\n", cn, v, e,
                        expected);
        }
    }
}

// Constant-torque rolling resistance M = mu_r R* F_n (Zhou et al. 1999): a solid sphere
// rolling on a level plane decelerates at a = 5/7 mu_r g (from m a = -F, I w' = F r - M with
// rolling without slip). Tolerance 0.5 %.
TEST(DemLaws, ConstantTorqueRollingDecelerates) {
    dem::Material m;
    m.name = "glass";
    m.density = 2500;
    m.kn = m.kt = 1e5;
    m.restitution = 0.3;
    m.friction = 0.5;
    m.rolling_friction = 0.1;
    const Real r = 0.01, v0 = 1.0, g = 9.81;
    DemRig rig;
    const Real mass = DemRig::sphere_mass(m.density, r);
    const Real sink = mass * g / m.kn; // start at the static overlap
    rig.add_sphere({0, 0, r - sink}, {v0, 0, 0}, r, m.density, 0);
    rig.grains.set_spin(0, {0, v0 / r, 0});
    rig.add_plane("floor", {0, 0, 0}, {0, 0, 1}, -1);
    dem::DemParams p;
    p.rolling = "constant_torque";
    rig.start(p, {m}, {-1, -1, -1}, {10, 1, 1});
    const Real a = rig.fitted_acceleration(0.05, 0.5), expected = -5.0 / 7.0 * 0.1 * g;
    std::printf("constant-torque rolling: a = %.5f m/s2 (expected %.5f)\n", a, expected);
    EXPECT_NEAR(a / expected, 1, 0.005);
}

namespace {

// The automatic DEM step of one grain of inertia factor `beta` (I = beta m r^2) on a plane,
// linear law with kt = ratio * kn.
time::DtLimit linear_step(Real beta, Real ratio, Real restitution = 0.5) {
    dem::Material m;
    m.name = "glass";
    m.density = 2500;
    m.kn = 1e5;
    m.kt = ratio * m.kn;
    m.restitution = restitution;
    DemRig rig;
    const Real r = 0.005, mass = DemRig::sphere_mass(m.density, r);
    rig.grains.add({0, 0, r}, {}, r, mass, beta * mass * r * r, 0);
    rig.add_plane("floor", {0, 0, 0}, {0, 0, 1}, 0);
    dem::DemParams p;
    p.safety = 0.1;
    rig.start(p, {m}, {-1, -1, -1}, {1, 1, 1});
    return rig.solver->automatic_dt();
}

} // namespace

// The stable step covers every mode of a contact, not only the normal one: with k_t = k_n the
// tangential spring acts on the contact point's compliance 1/m + r^2/I, so its frequency is
// sqrt(1 + 1/beta) times the normal one: sqrt(3.5) for a sphere (beta = 2/5), sqrt(3) for a
// disc (beta = 1/2) (closed form of the two-mode oscillator). The step is then
// safety x pi / omega_t (undamped), taken for two such grains meeting (m* = m/2, the stiffest
// pair; the wall pair is sqrt(2) slower). With k_t = 2/7 k_n (sphere) the tangential frequency
// equals the normal one (undamped time pi / omega_n still limits); with k_t = k_n / 10 the damped
// normal contact time does. Tolerance 1e-12 (exact formulas).
TEST(DemLaws, StableStepCoversTheTangentialRotationalMode) {
    const Real pi = 3.14159265358979323846, kn = 1e5;
    const Real mass = DemRig::sphere_mass(2500, 0.005);
    for (const auto& [beta, factor] : {std::pair{0.4, 3.5}, std::pair{0.5, 3.0}}) {
        const auto lim = linear_step(beta, 1);
        const Real expected = 0.1 * pi / std::sqrt(factor * kn / (mass / 2));
        EXPECT_NEAR(lim.dt / expected, 1, 1e-12) << "beta " << beta << ": " << lim.limiter;
        EXPECT_NE(lim.limiter.find("tangential-rotational"), std::string::npos) << lim.limiter;
    }
    const auto equal = linear_step(0.4, 2.0 / 7.0);
    EXPECT_NEAR(equal.dt / (0.1 * pi / std::sqrt(kn / (mass / 2))), 1, 1e-12) << equal.limiter;
    const auto normal = linear_step(0.4, 0.1);
    const Real zeta = dem::linear_damping_ratio(0.5);
    EXPECT_NEAR(normal.dt / (0.1 * pi / (std::sqrt(kn / (mass / 2)) * std::sqrt(1 - zeta * zeta))),
                1, 1e-12)
        << normal.limiter;
    EXPECT_NE(normal.limiter.find("linear contact time"), std::string::npos) << normal.limiter;
}

// The dashpots' explicit bound: a dashpot of damping ratio zeta on a mode of frequency w is
// stable for dt < 1 / (zeta w) per contact, and gets the springs' margin, dt <= safety x t_c /
// (2 zeta), t_c = pi / w undamped. With e = 0.1 (zeta 0.591) and k_t = k_n, a sphere's
// tangential dashpot on the contact point's mass m*/3.5 has zeta sqrt(3.5) at sqrt(3.5) w_n:
// dt = 0.1 pi / (7 zeta w_n). With e = 0.01 (zeta 0.826) and k_t = k_n / 100 the normal dashpot
// limits: dt = 0.1 pi / (2 zeta w_n). Closed forms, 1e-12.
TEST(DemLaws, StableStepCoversTheDashpots) {
    const Real pi = 3.14159265358979323846, kn = 1e5;
    const Real mass = DemRig::sphere_mass(2500, 0.005), wn = std::sqrt(kn / (mass / 2));
    const auto tangential = linear_step(0.4, 1, 0.1);
    const Real z1 = dem::linear_damping_ratio(0.1);
    EXPECT_NEAR(tangential.dt / (0.1 * pi / (7 * z1 * wn)), 1, 1e-12) << tangential.limiter;
    EXPECT_NE(tangential.limiter.find("tangential-rotational dashpot"), std::string::npos)
        << tangential.limiter;
    const auto normal = linear_step(0.4, 0.01, 0.01);
    const Real z2 = dem::linear_damping_ratio(0.01);
    EXPECT_NEAR(normal.dt / (0.1 * pi / (2 * z2 * wn)), 1, 1e-12) << normal.limiter;
    EXPECT_NE(normal.limiter.find("normal dashpot"), std::string::npos) << normal.limiter;
    // e = 0.5 (zeta 0.215): the springs limit, as before
    EXPECT_EQ(linear_step(0.4, 1).limiter.find("dashpot"), std::string::npos);
}

// A free rigid body's contact sphere takes a second grain's place in the stable step, with the
// body's compliance at the sphere: a body of a quarter of the grain's mass (one sphere of the
// grain's radius at its centre of mass, I = 2/5 M r^2) gives m* = m/5 and the tangential
// compliance 3.5/m + 14/m = 17.5/m, so with k_t = k_n the step is safety x pi /
// sqrt(17.5 k_n / m), shorter than the grain pair's (sqrt(7 k_n / m)). Closed form as above;
// 1e-12.
TEST(DemLaws, StableStepCoversARigidBodysMassAndInertia) {
    const Real pi = 3.14159265358979323846, kn = 1e5, r = 0.005;
    dem::Material m;
    m.name = "glass";
    m.density = 2500;
    m.kn = m.kt = kn;
    m.restitution = 0.5;
    DemRig rig;
    const Real mass = DemRig::sphere_mass(m.density, r);
    rig.grains.add({0, 0, 0.5}, {}, r, mass, 0.4 * mass * r * r, 0);
    dem::DemParams p;
    p.safety = 0.1;
    p.gravity = {0, 0, 0};
    rig.start(p, {m}, {-1, -1, -1}, {1, 1, 1});
    const Real grains_only = rig.solver->automatic_dt().dt;
    EXPECT_NEAR(grains_only / (0.1 * pi / std::sqrt(7 * kn / mass)), 1, 1e-12);
    const Real body_mass = mass / 4, inv_i = 1 / (0.4 * body_mass * r * r);
    dem::ObstacleSet body;
    dem::ObstacleSphere s{{0, 0, 0}, {}, {}, r, body_mass, 0, 0};
    s.normal_compliance = 1 / body_mass;
    s.tangential_compliance = 1 / body_mass + r * r * inv_i;
    s.rotational_compliance = inv_i;
    body.spheres = {s};
    body.body_com = {{0, 0, 0}};
    rig.solver->attach_obstacles(&body);
    const auto lim = rig.solver->automatic_dt();
    EXPECT_NEAR(lim.dt / (0.1 * pi / std::sqrt(17.5 * kn / mass)), 1, 1e-12) << lim.limiter;
    EXPECT_NE(lim.limiter.find("body"), std::string::npos) << lim.limiter;
    EXPECT_NEAR(rig.solver->dt(), lim.dt, 0);
}
