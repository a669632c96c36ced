#pragma once
#include "debrisflow/core/hd.hpp"
#include "debrisflow/core/vec3_k.hpp"
#include <array>
#include <cmath>
#include <cstdint>
#include <type_traits>

namespace debrisflow::dem {

enum class PrimitiveType : std::uint8_t { plane = 0, triangle = 1 };

// One piece of a geometric wall: a half-space (plane through a with unit normal n, grains on
// the +n side) or a triangle (a, b, c; n its unit normal), touched from either side.
// A triangle may be a face of a convex solid (a structure's box, WallSet::solids()): then n
// points into the solid, and a face lying on another solid of the same motion (a post's foot
// on the bed, its side against the flume wall) is covered by it: inside the structure, no
// way in or out.
struct WallPrimitive {
    Vec3 a, b, c, n;
    PrimitiveType type;
    std::int16_t wall;            // index of the named wall it belongs to
    std::int32_t corners = -1;    // row of WallSet::corners() for a triangle on moving nodes
    std::int32_t solid = -1;      // convex solid it bounds; -1: an open surface
    std::int32_t covered_by = -1; // solid holding this face; -1: exposed
};
static_assert(std::is_trivially_copyable_v<WallPrimitive>);

// Closest point of triangle abc to p (Ericson 2005, Real-Time Collision Detection, 5.1.5).
DF_HD inline Vec3 closest_on_triangle(Vec3 p, Vec3 a, Vec3 b, Vec3 c) {
    const Vec3 ab = b - a, ac = c - a, ap = p - a;
    const Real d1 = dot(ab, ap), d2 = dot(ac, ap);
    if (d1 <= 0 && d2 <= 0) return a;
    const Vec3 bp = p - b;
    const Real d3 = dot(ab, bp), d4 = dot(ac, bp);
    if (d3 >= 0 && d4 <= d3) return b;
    const Real vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + (d1 / (d1 - d3)) * ab;
    const Vec3 cp = p - c;
    const Real d5 = dot(ab, cp), d6 = dot(ac, cp);
    if (d6 >= 0 && d5 <= d6) return c;
    const Real vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + (d2 / (d2 - d6)) * ac;
    const Real va = d3 * d6 - d5 * d4;
    if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
        return b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b);
    const Real denom = 1 / (va + vb + vc);
    return a + (vb * denom) * ab + (vc * denom) * ac;
}

// Barycentric weights of q (a point of triangle abc) in a, b, c, clamped to [0, 1] and summing
// to 1 (Ericson 2005, 3.4): the split of a contact force onto the corners.
DF_HD inline Vec3 barycentric(Vec3 q, Vec3 a, Vec3 b, Vec3 c) {
    const Vec3 v0 = b - a, v1 = c - a, v2 = q - a;
    const Real d00 = dot(v0, v0), d01 = dot(v0, v1), d11 = dot(v1, v1);
    const Real d20 = dot(v2, v0), d21 = dot(v2, v1);
    const Real den = d00 * d11 - d01 * d01;
    if (!(den > 0)) return {Real(1) / 3, Real(1) / 3, Real(1) / 3};
    Real v = (d11 * d20 - d01 * d21) / den, w = (d00 * d21 - d01 * d20) / den;
    v = v < 0 ? 0 : (v > 1 ? 1 : v);
    w = w < 0 ? 0 : (w > 1 ? 1 : w);
    Real u = 1 - v - w;
    if (u < 0) {
        const Real s = v + w;
        v /= s, w /= s, u = 0;
    }
    return {u, v, w};
}

// Corner k of a triangle that follows moving nodes (a deforming FEM surface) sits at
// node[k] + offset[k] (the offset extrudes a 2D edge across the y = 0 plane).
struct NodalCorners {
    std::array<std::int32_t, 3> node;
    std::array<Vec3, 3> offset;
};

// Velocity of a point of a nodal triangle with barycentric weights w: sum_k w_k v[node_k].
DF_HD inline Vec3 blend(const NodalCorners& c, const Vec3* v, Vec3 w) {
    return w.x * v[c.node[0]] + w.y * v[c.node[1]] + w.z * v[c.node[2]];
}

// Contact point of a sphere centre p with a primitive: returns the point on the primitive
// closest to p (for a plane, the foot of the perpendicular).
DF_HD inline Vec3 closest_point(const WallPrimitive& w, Vec3 p) {
    if (w.type == PrimitiveType::plane) return p - dot(p - w.a, w.n) * w.n;
    return closest_on_triangle(p, w.a, w.b, w.c);
}

// Signed distance used for the overlap: along the normal for a plane (negative behind it),
// Euclidean for a triangle.
DF_HD inline Real wall_distance(const WallPrimitive& w, Vec3 p, Vec3 q) {
    if (w.type == PrimitiveType::plane) return dot(p - w.a, w.n);
    return norm(p - q);
}

// Axis-aligned box around a primitive (a plane: unbounded); the neighbour search skips a
// primitive whose box, grown by the reach, does not hold the grain centre. Exact as a filter:
// the closest point lies in the box, so a centre within reach of it lies in the grown box.
struct PrimitiveBounds {
    Vec3 lo, hi;
    bool bounded = false;
    DF_HD static PrimitiveBounds of(const WallPrimitive& w) {
        if (w.type == PrimitiveType::plane) return {};
        PrimitiveBounds b;
        b.bounded = true;
        for (int d = 0; d < 3; ++d) {
            b.lo[d] = std::fmin(w.a[d], std::fmin(w.b[d], w.c[d]));
            b.hi[d] = std::fmax(w.a[d], std::fmax(w.b[d], w.c[d]));
        }
        return b;
    }
    DF_HD bool may_reach(Vec3 p, Real reach) const {
        if (!bounded) return true;
        for (int d = 0; d < 3; ++d)
            if (p[d] < lo[d] - reach || p[d] > hi[d] + reach) return false;
        return true;
    }
};

// Whether q lies on triangle w (within tol): a contact whose closest point lies on a triangle
// already in contact is the same contact seen from a neighbouring triangle (shared edge or
// vertex), and is skipped so that flat and convex meshes push once.
DF_HD inline bool lies_on_triangle(const WallPrimitive& w, Vec3 q, Real tol) {
    if (w.type != PrimitiveType::triangle) return false;
    if (std::fabs(dot(q - w.a, w.n)) > tol) return false;
    const Vec3 c = closest_on_triangle(q, w.a, w.b, w.c);
    const Vec3 d = c - q;
    return dot(d, d) <= tol * tol;
}

} // namespace debrisflow::dem
