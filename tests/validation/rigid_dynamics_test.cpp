// Rigid-body dynamics against analytic mechanics: torque-free tumbling (conservation and the
// intermediate-axis instability), a hinged compound pendulum and a spring-damper pair.
#include "rigid_rig.hpp"
#include <cmath>
#include <gtest/gtest.h>

namespace debrisflow {
namespace {

constexpr Real pi = 3.14159265358979323846;

// Complete elliptic integral of the first kind K(k) by the arithmetic-geometric mean.
Real elliptic_k(Real k) {
    Real a = 1, b = std::sqrt(1 - k * k);
    for (int i = 0; i < 30; ++i) {
        const Real an = Real(0.5) * (a + b);
        b = std::sqrt(a * b);
        a = an;
    }
    return pi / (2 * a);
}

TEST(RigidDynamics, TorqueFreeTumblingConservesEnergyAndAngularMomentum) {
    // A 0.3 x 0.2 x 0.1 m brick spun about its intermediate (y) axis with a 1e-3 perturbation:
    // the spin axis flips periodically (Dzhanibekov effect) while the kinetic energy and the
    // world angular momentum stay constant. Tolerance 1e-6 relative over 1e5 steps (issue 4).
    test::RigidRig rig;
    rig.add(test::RigidRig::box("brick", {-0.15, -0.1, -0.05}, {0.15, 0.1, 0.05}), 700);
    rig.bodies[0].ang_mom =
        rigid::angular_momentum(rig.bodies[0].q, {1e-2, 10, 1e-2}, rig.bodies[0].inv_inertia);
    rig.start({0, 0, 0});
    auto& s = rig.solver->bodies()[0];
    const Real e0 = rig.solver->kinetic_energy(0);
    const Vec3 l0 = s.ang_mom;
    Real worst_e = 0, worst_l = 0, min_wy = 1e9;
    const Real dt = 1e-4;
    for (long k = 0; k < 100000; ++k) {
        rig.solver->step(dt);
        worst_e = std::max(worst_e, std::fabs(rig.solver->kinetic_energy(0) / e0 - 1));
        worst_l = std::max(worst_l, norm(s.ang_mom - l0) / norm(l0));
        // body-frame angular velocity about the intermediate axis (world y at t = 0)
        const Vec3 wb = rigid::rotate_inverse(s.q, s.omega());
        const Vec3 yb = rigid::rotate_inverse(rig.bodies[0].q, {0, 1, 0});
        min_wy = std::min(min_wy, dot(wb, yb));
    }
    std::printf("tumbling: max |dE/E| = %.3g, max |dL|/|L| = %.3g, min body w_y = %.3f rad/s\n",
                worst_e, worst_l, min_wy);
    EXPECT_LT(worst_e, 1e-6);
    EXPECT_LT(worst_l, 1e-6);
    EXPECT_LT(min_wy, -9.0); // the spin flipped to the opposite direction
}

TEST(RigidDynamics, HingedPendulumPeriod) {
    // A 1 m bar (0.04 x 0.04 section) hinged to the ground about y at its top end, released
    // from 20 deg: T = 4 sqrt(I_p / (m g d)) K(sin(theta0/2)) (exact compound pendulum).
    // Tolerance 0.5 % (issue 4).
    test::RigidRig rig;
    const Real L = 1, a = 0.04, th0 = 20 * pi / 180, g = 9.81;
    const int b =
        rig.add(test::RigidRig::box("bar", {-a / 2, -a / 2, -L}, {a / 2, a / 2, 0}), 2700);
    auto& s = rig.bodies[b];
    const rigid::Quat turn = rigid::axis_angle({0, 1, 0}, th0);
    s.pos = rigid::rotate(turn, s.pos);
    s.q = turn * s.q;
    rigid::Joint hinge;
    hinge.type = rigid::JointType::hinge;
    hinge.a = b;
    hinge.anchor_a = rigid::rotate_inverse(s.q, Vec3{} - s.pos);
    hinge.anchor_b = {};
    hinge.axis_a = rigid::rotate_inverse(s.q, {0, 1, 0});
    hinge.axis_b = {0, 1, 0};
    rig.joints.joints().push_back(hinge);
    rig.start({0, 0, -g});
    const Real m = s.mass, d = L / 2, ip = m * (a * a + L * L) / 12 + m * d * d;
    const Real t_exact = 4 * std::sqrt(ip / (m * g * d)) * elliptic_k(std::sin(th0 / 2));
    // zero crossings of x (the bar's CoM passes under the pivot) moving in +x direction
    const Real dt = 1e-4;
    Real t = 0, prev = rig.body(0).pos.x;
    std::vector<Real> up;
    Real drift = 0;
    while (t < 5.5 * t_exact) {
        rig.solver->step(dt);
        t += dt;
        const Real x = rig.body(0).pos.x;
        if (prev < 0 && x >= 0) up.push_back(t - dt + dt * (-prev) / (x - prev));
        prev = x;
        const Vec3 tip = rig.body(0).to_world(hinge.anchor_a);
        drift = std::max(drift, norm(tip));
    }
    ASSERT_GE(up.size(), 5u);
    const Real period = (up.back() - up.front()) / Real(up.size() - 1);
    std::printf("pendulum: T = %.6f s, exact %.6f s (%+.4f %%), pivot drift %.2e m\n", period,
                t_exact, 100 * (period / t_exact - 1), drift);
    EXPECT_NEAR(period / t_exact, 1, 0.005);
    EXPECT_LT(drift, 1e-3 * L);
}

TEST(RigidDynamics, SpringDamperPairPeriodAndDecay) {
    // Two spheres joined by a spring-damper (k, c) oscillate about the rest length with the
    // reduced mass mu: w_d = sqrt(k/mu - (c/2mu)^2), amplitude ~ exp(-c t / (2 mu)).
    // Tolerance 0.5 % on the period and on the decay rate (issue 4).
    test::RigidRig rig;
    const int a = rig.add(test::RigidRig::sphere("a", {0, 0, 0}, 0.1), 1000);
    const int b = rig.add(test::RigidRig::sphere("b", {0.6, 0, 0}, 0.08), 1000);
    const Real k = 2000, c = 6, rest = 0.5;
    rigid::Joint spring;
    spring.type = rigid::JointType::spring;
    spring.a = a;
    spring.b = b;
    spring.stiffness = k;
    spring.damping = c;
    spring.rest_length = rest;
    rig.joints.joints().push_back(spring);
    rig.start({0, 0, 0});
    const Real ma = rig.body(a).mass, mb = rig.body(b).mass, mu = ma * mb / (ma + mb);
    const Real wd = std::sqrt(k / mu - std::pow(c / (2 * mu), 2)), rate = c / (2 * mu);
    const Real dt = 2e-5;
    Real t = 0;
    std::vector<Real> tmax, xmax;
    Real x_prev2 = 0.1, x_prev = 0.1;
    while (t < 8 * 2 * pi / wd) {
        rig.solver->step(dt);
        t += dt;
        const Real x = rig.body(b).pos.x - rig.body(a).pos.x - rest;
        if (x_prev > x_prev2 && x_prev >= x && t > dt * 2) {
            tmax.push_back(t - dt);
            xmax.push_back(x_prev);
        }
        x_prev2 = x_prev;
        x_prev = x;
    }
    ASSERT_GE(tmax.size(), 4u);
    const std::size_t n = tmax.size() - 1;
    const Real period = (tmax[n] - tmax[0]) / Real(n);
    const Real decay = std::log(xmax[0] / xmax[n]) / (tmax[n] - tmax[0]);
    std::printf("spring-damper: T = %.6f s (exact %.6f, %+.3f %%), decay %.5f 1/s (exact %.5f, "
                "%+.3f %%)\n",
                period, 2 * pi / wd, 100 * (period * wd / (2 * pi) - 1), decay, rate,
                100 * (decay / rate - 1));
    EXPECT_NEAR(period * wd / (2 * pi), 1, 0.005);
    EXPECT_NEAR(decay / rate, 1, 0.005);
    // momentum of the pair stays zero (internal forces only)
    const Vec3 p = ma * rig.body(a).vel + mb * rig.body(b).vel;
    EXPECT_LT(norm(p), 1e-9);
}

} // namespace
} // namespace debrisflow
