#pragma once
#include "debrisflow/core/vec3_k.hpp"
#include <string>
#include <vector>

namespace debrisflow::rigid {

// A sphere fixed to a body, in the body (principal) frame.
struct BodySphere {
    Vec3 center;
    Real radius;
};

// Geometry a body carries through the run, in its body frame: smooth-contact features
// (vertices with the Hertz radius, exact spheres), the distributed-contact spheres for
// body-body contact, the tracked point, and prescribed-motion tables.
struct BodyModel {
    std::string name;
    std::vector<Vec3> vertices;      // box corners, cylinder rims, mesh vertices
    std::vector<BodySphere> spheres; // sphere and clump members (exact contact)
    std::vector<BodySphere> samples; // surface samples for distributed body-body contact
    Vec3 track_point;                // body frame
    bool has_track_point = false;
    std::vector<Real> times; // prescribed motion: piecewise-linear in time
    std::vector<Vec3> velocity, angular_velocity;
    Vec3 bound_radius; // x: largest distance of any feature from the CoM
    Real volume = 0;   // [m^3] (2D: per metre), for the analytic buoyancy
};

// Piecewise-linear interpolation of a table (constant beyond its ends).
Vec3 interpolate(const std::vector<Real>& t, const std::vector<Vec3>& v, Real at);

} // namespace debrisflow::rigid
