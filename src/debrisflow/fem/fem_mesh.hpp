#pragma once
#include "debrisflow/core/vec3_k.hpp"
#include "debrisflow/fem/element_type.hpp"
#include <array>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace debrisflow::fem {

// A solid mesh of one element type: node coordinates (2D meshes lie in the x-z plane, y = 0),
// connectivity (nodes_of(type) per element, VTK order) and named node sets (fixed supports,
// monitoring points, loaded faces).
struct FemMesh {
    ElementType type = ElementType::hex8;
    std::vector<Vec3> nodes;
    std::vector<std::int32_t> conn;
    std::map<std::string, std::vector<std::int32_t>> node_sets;

    std::size_t elements() const { return conn.size() / std::size_t(nodes_of(type)); }
    // Nodes inside the box [lo, hi] (inclusive within tol).
    std::vector<std::int32_t> nodes_in(Vec3 lo, Vec3 hi, Real tol) const;
};

// Structured box [lo, hi] with n = (nx, ny, nz) divisions: hex8, tet4 or tet10 (each hex cut
// into six tetrahedra about its main diagonal, conforming across faces) in 3D; quad4 in the
// x-z plane in 2D (ny ignored). Node sets: xmin, xmax, ymin, ymax, zmin, zmax (faces).
FemMesh box_mesh(ElementType t, Vec3 lo, Vec3 hi, std::array<int, 3> n);

// Trapezoidal dam cross-section in the x-z plane extruded along y: base from x0 to
// x0 + base_width at z = z0, crest of crest_width at z0 + height whose upstream edge is
// x0 + upstream_offset (0: vertical upstream face), across y0 .. y0 + length. n = (nx across
// the section, ny along the dam, nz up). 2D (quad4): the section alone. Node sets: base, crest,
// upstream, downstream, left (y0), right (y0 + length).
struct TrapezoidSpec {
    Real x0 = 0, z0 = 0, y0 = 0;
    Real base_width = 1, crest_width = 0.5, height = 1, upstream_offset = 0, length = 1;
};
FemMesh trapezoid_mesh(ElementType t, const TrapezoidSpec& s, std::array<int, 3> n);

// Gmsh MSH 4.1 ASCII file: the elements of the requested type (hex8, tet4, tet10 or quad4;
// quad4 meshes are read in the x-y plane of the file and placed in the x-z plane). Physical
// groups become node sets of all their entities' nodes. Throws InputError naming the file.
FemMesh read_gmsh(const std::string& path, ElementType t);

} // namespace debrisflow::fem
