#pragma once
#include "debrisflow/dem/wall_geometry_k.hpp"
#include <cstdint>
#include <vector>

namespace debrisflow::dem {

// Which faces of an axis-aligned box to build.
struct BoxFaceSet {
    bool bottom = true, top = true, xsides = true, ysides = true;
};

// The faces of the box [lo, hi] as pairs of triangles with normals pointing into the box:
// bottom, top, then the sides x-, x+, y-, y+ (those asked for). With solid >= 0 the triangles
// bound convex solid `solid` (numbered within the list handed to WallSet::add), which must then
// be closed in 3D (every face) or a prism across y (no y sides: the slice of a 2D case).
void box_faces(std::vector<WallPrimitive>& out, Vec3 lo, Vec3 hi, BoxFaceSet faces,
               std::int32_t solid = -1);

// A triangle with corners a, b, c and unit normal (b - a) x (c - a) / |...|.
WallPrimitive wall_triangle(Vec3 a, Vec3 b, Vec3 c);

} // namespace debrisflow::dem
