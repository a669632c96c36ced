#pragma once
#include "debrisflow/rigid/quaternion_k.hpp"

namespace debrisflow::rigid {

// Torque-free rotation of a rigid body over dt by the symplectic splitting of Dullweber,
// Leimkuhler & McLachlan 1997 (J. Chem. Phys. 107, 5840, eq. 4.4): the kinetic energy
// sum_k L_k^2 / (2 I_k) (body-frame angular momentum L, principal moments I) is split into
// its three terms, each an exact rotation about one principal axis by (L_k / I_k) h, composed
// as R1(dt/2) R2(dt/2) R3(dt) R2(dt/2) R1(dt/2). The world angular momentum and |L| are
// conserved to round-off; the energy error is bounded, O(dt^2), without drift.
// q: body -> world orientation (updated); l_world: angular momentum in the world frame.
DF_HD inline void free_rotation(Quat& q, Vec3 l_world, Vec3 inv_inertia, Real dt) {
    Vec3 l = rotate_inverse(q, l_world);
    auto sub = [&](int k, Real h) {
        const Real phi = l[k] * inv_inertia[k] * h;
        if (phi == 0) return;
        Vec3 axis{};
        axis[k] = 1;
        q = q * axis_angle(axis, phi);
        // The body frame turns by phi about axis k: body components of L turn by -phi.
        const int a = (k + 1) % 3, b = (k + 2) % 3;
        const Real c = std::cos(phi), s = std::sin(phi);
        const Real la = l[a], lb = l[b];
        l[a] = c * la + s * lb;
        l[b] = -s * la + c * lb;
    };
    const Real half = Real(0.5) * dt;
    sub(0, half);
    sub(1, half);
    sub(2, dt);
    sub(1, half);
    sub(0, half);
    q = normalized(q);
}

// Angular velocity in the world frame from the world angular momentum.
DF_HD inline Vec3 angular_velocity(Quat q, Vec3 l_world, Vec3 inv_inertia) {
    const Vec3 l = rotate_inverse(q, l_world);
    return rotate(q, {l.x * inv_inertia.x, l.y * inv_inertia.y, l.z * inv_inertia.z});
}

// World angular momentum of a body turning with world angular velocity w.
DF_HD inline Vec3 angular_momentum(Quat q, Vec3 w, Vec3 inv_inertia) {
    const Vec3 wb = rotate_inverse(q, w);
    auto inv = [](Real v) { return v > 0 ? 1 / v : Real(0); };
    return rotate(
        q, {wb.x * inv(inv_inertia.x), wb.y * inv(inv_inertia.y), wb.z * inv(inv_inertia.z)});
}

} // namespace debrisflow::rigid
