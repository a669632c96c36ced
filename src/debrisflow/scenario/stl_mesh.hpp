#pragma once
#include "debrisflow/core/vec3_k.hpp"
#include <string>
#include <vector>

namespace debrisflow::scenario {

struct Triangle {
    Vec3 a, b, c;
    Vec3 normal() const; // unit, from vertex order (right hand)
};

// Triangle mesh read from ASCII or binary STL, scaled then offset.
struct TriangleMesh {
    std::vector<Triangle> triangles;
    static TriangleMesh read_stl(const std::string& path, Real scale, Vec3 offset);
    void bounds(Vec3& lo, Vec3& hi) const;
    // Point-in-closed-mesh test by ray parity.
    bool contains(Vec3 p) const;
    // Number of triangles a ray from p along dir crosses.
    int crossings(Vec3 p, Vec3 dir) const;
};

} // namespace debrisflow::scenario
