#pragma once
#include "debrisflow/io/case_spec.hpp"
#include "debrisflow/rigid/body_model.hpp"
#include "debrisflow/rigid/body_state.hpp"
#include "debrisflow/scenario/stl_mesh.hpp"
#include <functional>

namespace debrisflow::scenario {

// A boundary particle sampled inside a body's surface: position, outward unit normal and
// depth below the surface (at t = 0, world frame).
struct BodySurfacePoint {
    Vec3 p, n;
    Real depth;
};

struct BuiltBody {
    rigid::BodyState state;
    rigid::BodyModel model;
    std::vector<BodySurfacePoint> sph_points; // empty when the case has no fluid
    Real volume = 0;                          // geometric volume [m^3] (2D: per metre)
    std::function<bool(Vec3)> inside;         // point inside the shape at t = 0
};

// Mass properties, principal frame, contact features and SPH samples of a body. Mass and
// inertia come from the geometry and density (box, sphere, cylinder exactly; STL by signed
// tetrahedra, Tonon 2004; clumps by lattice integration of the union), then the prescribed
// mass (inertia scaled), centre-of-mass offset (parallel-axis theorem) or full inertia tensor
// replace them. In 2D the body is 1 m thick along y and turns about y only. An "stl" body takes
// `mesh` (world coordinates at t = 0) when given instead of reading spec.shape.file.
BuiltBody build_body(const io::BodySpec& spec, const io::CaseSpec& c, Real density, Real sph_dp,
                     int layers, const TriangleMesh* mesh = nullptr);

} // namespace debrisflow::scenario
