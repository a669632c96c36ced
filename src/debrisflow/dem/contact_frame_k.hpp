#pragma once
#include "debrisflow/core/hd.hpp"
#include "debrisflow/core/vec3_k.hpp"
#include <cmath>

namespace debrisflow::dem {

// Keeps the tangential spring in the current tangent plane with its length unchanged
// (rigid rotation of the contact frame, as LIGGGHTS does): t = v - (v.n) n scaled by
// |v|/|t| = (1 - q)^(-1/2), q = (v.n)^2/|v|^2. Between two steps the normal turns by a tiny
// angle, so q ~ 1e-10 and the series 1 + q/2 + 3q^2/8 is exact to round-off (q < 1e-4: error
// below 3e-13); larger turns take the square root.
DF_HD DF_HOT_INLINE Vec3 rotate_into_plane(Vec3 v, Vec3 n) {
    const Real m2 = dot(v, v);
    if (m2 == 0) return v;
    const Real inv_m2 = Real(1) / m2; // of the stored spring: ready before n is
    const Real vn = dot(v, n);
    const Vec3 t = v - vn * n;
    const Real q = vn * vn * inv_m2;
    if (q < Real(1e-4)) return (1 + q * (Real(0.5) + Real(0.375) * q)) * t;
    const Real t2 = dot(t, t);
    return t2 > 0 ? std::sqrt(m2 / t2) * t : Vec3{};
}

} // namespace debrisflow::dem
