#pragma once
#include "debrisflow/core/hd.hpp"
#include "debrisflow/core/vec3_k.hpp"
#include <cmath>

namespace debrisflow::rigid {

// Unit quaternion q = (w, x, y, z) for a rotation body -> world: v_world = q v_body q*.
struct Quat {
    Real w = 1, x = 0, y = 0, z = 0;
};

// Hamilton product a b (rotation b first, then a).
DF_HD constexpr Quat operator*(Quat a, Quat b) {
    return {a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z,
            a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y,
            a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x,
            a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w};
}

DF_HD constexpr Quat conjugate(Quat q) {
    return {q.w, -q.x, -q.y, -q.z};
}

DF_HD inline Quat normalized(Quat q) {
    const Real s = 1 / std::sqrt(q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z);
    return {s * q.w, s * q.x, s * q.y, s * q.z};
}

// Rotation by `angle` [rad] about the unit axis `a`.
DF_HD inline Quat axis_angle(Vec3 a, Real angle) {
    const Real s = std::sin(Real(0.5) * angle);
    return {std::cos(Real(0.5) * angle), s * a.x, s * a.y, s * a.z};
}

// Rotation vector phi (axis * angle) as a quaternion, exact for any |phi|.
DF_HD inline Quat from_rotation_vector(Vec3 phi) {
    const Real angle = norm(phi);
    if (angle < Real(1e-300)) return {};
    return axis_angle((1 / angle) * phi, angle);
}

// q v q* (v_body -> v_world): v + 2 w (u x v) + 2 u x (u x v), u = (x, y, z).
DF_HD constexpr Vec3 rotate(Quat q, Vec3 v) {
    const Vec3 u{q.x, q.y, q.z};
    const Vec3 t = 2 * cross(u, v);
    return v + q.w * t + cross(u, t);
}

// q* v q (v_world -> v_body).
DF_HD constexpr Vec3 rotate_inverse(Quat q, Vec3 v) {
    return rotate(conjugate(q), v);
}

// Intrinsic Z-Y'-X'' (yaw, pitch, roll) angles of q, returned as (roll, pitch, yaw) [rad].
DF_HD inline Vec3 euler_zyx(Quat q) {
    const Real sinp = 2 * (q.w * q.y - q.z * q.x);
    const Real pitch =
        std::fabs(sinp) >= 1 ? std::copysign(Real(1.5707963267948966), sinp) : std::asin(sinp);
    const Real roll = std::atan2(2 * (q.w * q.x + q.y * q.z), 1 - 2 * (q.x * q.x + q.y * q.y));
    const Real yaw = std::atan2(2 * (q.w * q.z + q.x * q.y), 1 - 2 * (q.y * q.y + q.z * q.z));
    return {roll, pitch, yaw};
}

// Quaternion of intrinsic Z-Y'-X'' angles (roll, pitch, yaw) [rad].
DF_HD inline Quat from_euler_zyx(Vec3 rpy) {
    return axis_angle({0, 0, 1}, rpy.z) * axis_angle({0, 1, 0}, rpy.y) *
           axis_angle({1, 0, 0}, rpy.x);
}

} // namespace debrisflow::rigid
