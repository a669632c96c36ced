#pragma once
#include "debrisflow/core/vec3_k.hpp"
#include "debrisflow/fem/element_type.hpp"
#include <array>
#include <cstdint>
#include <vector>

namespace debrisflow::fem {

class FemSolver;

// A boundary facet of the live elements: a triangle (3D; element quads are split in two, tet10
// faces in four through their edge nodes) or an edge (2D, nodes[2] = -1), with global node ids
// ordered so that the right-hand normal (3D) or (dz, 0, -dx) (2D) points out of the solid.
struct SurfaceFacet {
    std::int32_t solid, element;
    std::array<std::int32_t, 3> nodes;
};

// Facets that belong to exactly one live (not eroded) element.
std::vector<SurfaceFacet> boundary_facets(const FemSolver& fem);

// Outward unit normal of a facet at the current node positions.
Vec3 facet_normal(const SurfaceFacet& f, const std::vector<Vec3>& x);
// Distance from p to a facet and the closest point's outward normal (current positions).
Real facet_distance(const SurfaceFacet& f, const std::vector<Vec3>& x, Vec3 p);

// Shape-function values of element type t at natural coordinates xi.
std::vector<Real> shape_values(ElementType t, const std::array<Real, 3>& xi);
// Natural coordinates of point p in element e of solid s (reference configuration); false when
// p lies outside the element.
bool locate(const FemSolver& fem, std::size_t s, std::size_t e, Vec3 p, std::array<Real, 3>& xi);

} // namespace debrisflow::fem
