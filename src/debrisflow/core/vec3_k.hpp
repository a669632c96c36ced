#pragma once
#include "debrisflow/core/hd.hpp"
#include "debrisflow/core/real.hpp"
#include <cmath>

namespace debrisflow {

// Small 3-vector used in per-pair functors (host and device). 2D cases live in the x-z plane.
struct Vec3 {
    Real x = 0, y = 0, z = 0;
    DF_HD constexpr Real& operator[](int i) { return i == 0 ? x : (i == 1 ? y : z); }
    DF_HD constexpr Real operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }
};

DF_HD constexpr Vec3 operator+(Vec3 a, Vec3 b) {
    return {a.x + b.x, a.y + b.y, a.z + b.z};
}
DF_HD constexpr Vec3 operator-(Vec3 a, Vec3 b) {
    return {a.x - b.x, a.y - b.y, a.z - b.z};
}
DF_HD constexpr Vec3 operator-(Vec3 a) {
    return {-a.x, -a.y, -a.z};
}
DF_HD constexpr Vec3 operator*(Real s, Vec3 a) {
    return {s * a.x, s * a.y, s * a.z};
}
DF_HD constexpr Vec3 operator*(Vec3 a, Real s) {
    return {s * a.x, s * a.y, s * a.z};
}
DF_HD constexpr Vec3& operator+=(Vec3& a, Vec3 b) {
    a.x += b.x;
    a.y += b.y;
    a.z += b.z;
    return a;
}
DF_HD constexpr Vec3& operator-=(Vec3& a, Vec3 b) {
    a.x -= b.x;
    a.y -= b.y;
    a.z -= b.z;
    return a;
}
DF_HD constexpr Real dot(Vec3 a, Vec3 b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}
DF_HD constexpr Vec3 cross(Vec3 a, Vec3 b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
DF_HD inline Real norm(Vec3 a) {
    return std::sqrt(dot(a, a));
}

} // namespace debrisflow
