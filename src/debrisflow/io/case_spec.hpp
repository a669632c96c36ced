#pragma once
#include "debrisflow/dem/dem_params.hpp"
#include "debrisflow/dem/materials.hpp"
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
    std::string material; // DEM: contact material ("" = the grain's own)
    Vec3 velocity;        // DEM: prescribed translation velocity [m/s]
};

// Grain sizes: "mono" (diameter), "lognormal" (median d50, log-standard deviation sigma) or
// "sieve" (sizes [m] with cumulative % passing), cut to [min, max].
struct SizeSpec {
    std::string distribution = "mono";
    Real diameter = 0, d50 = 0, sigma = 0, min = 0, max = 0;
    std::vector<Real> sieve_sizes, sieve_passing;
};

// A body of grains: "random" (non-overlapping random insertion in a region to a count or
// mass), "lattice" (simple cubic in a region), "single" (one grain at a position) or "file"
// (a saved state, e.g. a settled packing written by a previous run).
struct GrainsSpec {
    std::string name, material, packing = "random";
    SizeSpec size;
    ShapeSpec region;
    long count = 0;
    Real mass = 0;
    Real gap = 0; // lattice: clearance between neighbours as a fraction of the diameter
    Vec3 position, velocity, angular_velocity;
    unsigned seed = 1;
    std::string file;
};

struct DemSpec {
    dem::DemParams params;
    std::vector<dem::Material> materials;
    std::vector<dem::PairOverride> overrides;
    Real thickness = 0;       // 2D: disc thickness [m] (mass of a disc, as PFC2D)
    bool settle = false;      // settle under gravity before t = 0
    Real settle_ratio = 0.01; // stop when mean unbalanced / mean contact force < this
    Real settle_max_time = 2; // [s] of settling before giving up
    std::vector<GrainsSpec> grains;
};

struct ProbeSpec {
    std::string name;
    std::string type; // pressure, gauge, velocity, front, wall_force, section,
                      // kinetic_energy, runup, mass_flux
    Vec3 position;
    std::string wall;
    int axis = 0;
    Real every = 0;
    Vec3 normal;   // wall_force: direction of the normal component; mass_flux: plane normal
    Vec3 min, max; // kinetic_energy: box; section: window
    Real bed = 0;  // section, runup: bed elevation z [m]
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
    bool has_dem = false;
    DemSpec dem;
    std::vector<WallSpec> walls;
    std::vector<ProbeSpec> probes;
    std::string resolved_toml; // the case after --set overrides, for the output folder
};

// Reads and validates a case file; `overrides` are "key=value" strings from --set.
CaseSpec read_case(const std::string& path, const std::vector<std::string>& overrides);

} // namespace debrisflow::io
