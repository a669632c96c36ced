#pragma once
#include "debrisflow/core/vec3_k.hpp"
#include <string>

namespace debrisflow::io {

// Largest coordinate magnitude of a wall or structure [m]: beyond any real structure, and it
// keeps products of extents (face normals, areas) finite.
inline constexpr Real max_wall_coordinate = 1e9;

// Most boxes all [[structure]] blocks of a case may expand into: every solid face is checked
// against every other solid once at set-up (WallSet::cover_faces).
inline constexpr long max_structure_boxes = 2000;

// Why the box lo..hi cannot be a wall (empty when it can): a coordinate beyond
// max_wall_coordinate, or an extent (x, z and in 3D y) that is not above 1e-9 (1 m + |lo| + |hi|),
// which round-off would turn into faces without a normal. In 2D the y extent is not checked.
std::string unresolvable_box(Vec3 lo, Vec3 hi, int dim);

} // namespace debrisflow::io
