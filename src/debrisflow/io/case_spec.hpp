#pragma once
#include "debrisflow/sph/sph_params.hpp"
#include "debrisflow/sph/sph_solver.hpp"
#include <optional>
#include <string>
#include <vector>

namespace debrisflow::io {

// A solid region: box (min, max), cylinder (base centre, axis, radius, length; a disc in
// 2D) or closed triangle mesh from STL (scaled, then offset).
struct ShapeSpec {
    std::string type = "box";
    Vec3 min, max;
    Vec3 center, axis{0, 0, 1};
    Real radius = 0, length = 0;
    std::string file;
    Real scale = 1;
    Vec3 offset;
};

struct FluidSpec {
    std::string name;
    ShapeSpec shape;
    Vec3 velocity;
    bool hydrostatic = true;
};

// Fixed boundary built from dynamic boundary particles. Types: "box" (solid block),
// "open_tank" (bottom and side walls around an inner box), "plane" (half-space behind a
// plane, clipped to the domain), "stl" (surface mesh, normals pointing into the fluid).
struct WallSpec {
    std::string name;
    std::string type;
    ShapeSpec shape;
    Vec3 point, normal;
    int layers = 0;
    std::optional<Real> remove_at;
};

struct ProbeSpec {
    std::string name;
    std::string type; // pressure, gauge, velocity, front, wall_force
    Vec3 position;
    std::string wall;
    int axis = 0;
    Real every = 0;
};

struct CaseSpec {
    std::string file;
    std::string name;
    int dim = 2;
    Real dp = 0;
    Real t_end = 0;
    std::string scheme = "symplectic"; // time.scheme: symplectic | verlet
    int verlet_euler_every = 40;
    Real vtk_every = 0; // 0: first and last frame only
    bool vtk = true;
    Real progress_seconds = 2;
    sph::SphParams sph;
    sph::Domain domain;
    Real c0_coefficient = 0, reference_depth = 0; // when c0 = coefficient * sqrt(g H)
    std::vector<FluidSpec> fluids;
    std::vector<WallSpec> walls;
    std::vector<ProbeSpec> probes;
    std::string resolved_toml; // the case after --set overrides, for the output folder
};

// Reads and validates a case file; `overrides` are "key=value" strings from --set.
CaseSpec read_case(const std::string& path, const std::vector<std::string>& overrides);

} // namespace debrisflow::io
