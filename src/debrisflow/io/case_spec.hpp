#pragma once
#include "debrisflow/core/domain.hpp"
#include "debrisflow/dem/dem_params.hpp"
#include "debrisflow/dem/materials.hpp"
#include "debrisflow/fem/fem_material.hpp"
#include "debrisflow/fem/fem_mesh.hpp"
#include "debrisflow/fem/fem_params.hpp"
#include "debrisflow/io/origin.hpp"
#include "debrisflow/sph/sph_params.hpp"
#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace debrisflow::io {

class ConfigTable;

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
    Origin origin; // where the block is in the case file
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
    Vec3 velocity;        // prescribed translation velocity [m/s] (grains' wall, fluid's particles)
    // type "boxes": a union of solid boxes {min, max} forming one named wall (structures)
    std::vector<std::array<Vec3, 2>> boxes;
    std::string structure; // the [[structure]] type that produced it ("" for [[wall]])
    Real slit_density = 0; // slit dams: sum of openings / dam width
    Origin origin;         // where the block is in the case file
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
    // Non-spherical grains: a rigid clump of spheres (discs in 2D), given as (x, y, z, r) in
    // any unit and scaled so that its volume-equivalent diameter (2D: area-equivalent) is the
    // grain's size; empty: spheres. Random orientation unless `aligned`.
    std::vector<Vec3> clump_centers;
    std::vector<Real> clump_radii;
    bool clump_aligned = false;
    // packing = "file": which of material, velocity, angular_velocity and region the block
    // gives to override the saved state (region: keep the grains whose centre is inside).
    struct FileOverrides {
        bool material = false, velocity = false, angular_velocity = false, region = false;
    } file_overrides;
    Origin origin; // where the block is in the case file
};

// Solid feed (a hopper outlet or an insertion region): grains of `size` released at random
// non-overlapping places in the box `min`-`max` at a solid discharge Q_s(t) [m^3/s of solid;
// 2D: m^2/s], piecewise linear in `times` (one value: constant), with `velocity`.
// A solid feed: grains, or rigid rocks when `rocks` lists a library of closed STL shapes (each
// rock: a random shape, stretched along its axes with the sphericity kept within
// +-sphericity_tolerance of the shape's, randomly oriented, scaled to a sampled
// equivalent-sphere diameter).
struct FeedSpec {
    std::string name, material;
    SizeSpec size;
    Vec3 min, max, velocity;
    std::vector<Real> times, discharge;
    unsigned seed = 1;
    Real every = 0.01;
    std::vector<std::string> rocks; // STL files (resolved paths); empty: a grain feed
    Real sphericity_tolerance = Real(0.15);
    int layers = 0; // SPH boundary layers of each rock (0: automatic)
    Origin origin;  // where the block is in the case file
};

struct DemSpec {
    dem::DemParams params;
    std::vector<dem::Material> materials;
    std::vector<Origin> material_origins; // where each [[material]] is in the case file
    std::vector<dem::PairOverride> overrides;
    Real thickness = 0;              // 2D: disc thickness [m] (mass of a disc, as PFC2D)
    bool settle = false;             // settle under gravity before t = 0
    Real settle_ratio = 0.01;        // stop when mean unbalanced / mean contact force < this
    Real settle_max_time = 2;        // [s] of settling before giving up
    std::string fluid_drag = "none"; // drag law of the SPH-DEM coupling (none: no coupling)
    std::vector<GrainsSpec> grains;
    std::vector<FeedSpec> feeds;
};

// A rigid body: shape (box, sphere, cylinder, stl, clump of spheres), material (a DEM
// [[material]] name: density and contact parameters), mass properties from the geometry or
// prescribed, motion (free, fixed, prescribed velocity tables), locked world DOFs.
struct BodySpec {
    std::string name, material;
    std::string motion = "free"; // free | fixed | prescribed
    ShapeSpec shape;             // type box | sphere | cylinder | stl | clump
    std::vector<Vec3> clump_centers;
    std::vector<Real> clump_radii;
    Real density = 0;                           // [kg/m^3]; 0: the material's
    std::optional<Real> mass;                   // [kg] (2D: per metre of thickness)
    std::optional<Vec3> com_offset;             // centre of mass minus geometric centroid [m]
    std::optional<std::array<Real, 6>> inertia; // about the CoM: xx, yy, zz, xy, xz, yz
    Vec3 velocity, angular_velocity;            // initial (free) or constant (prescribed)
    std::vector<Real> motion_times;             // prescribed: piecewise-linear tables
    std::vector<Vec3> motion_velocity, motion_angular_velocity;
    std::array<bool, 3> lock_translation{false, false, false};
    std::array<bool, 3> lock_rotation{false, false, false};
    std::optional<Vec3> track_point; // a named point reported by the body probe (world, t=0)
    Real contact_radius = 0;         // Hertz curvature radius at vertices [m] (0: automatic)
    int layers = 0;                  // SPH boundary layers sampled inside the surface
    Origin origin;                   // where the block is in the case file
};

// A constraint between two bodies, or a body and the ground (body_b empty): hinge (revolute
// about axis through point), ball (spherical joint at point), fixed (welded at point) or spring
// (linear spring-damper between point on a and point_b on b).
struct JointSpec {
    std::string name, type, body_a, body_b;
    Vec3 point, point_b, axis{0, 1, 0};
    Real stiffness = 0, damping = 0;
    std::optional<Real> rest_length;
};

struct RigidSpec {
    Real dt = 0;                    // time step when the case has neither fluid nor grains
    Real contact_spacing = 0;       // distributed-contact sphere spacing (default dp)
    int joint_iterations = 30;      // Gauss-Seidel sweeps over the joints
    Real joint_stabilization = 0.2; // Baumgarte factor of the position error fed back per step
    std::vector<BodySpec> bodies;
    std::vector<JointSpec> joints;
    std::vector<FeedSpec> feeds; // rock feeds (bodies released during the run)
};

// A [[probe]] block: its name, type and sampling interval; the rest of the block belongs to
// the probe's type, which reads it when the probe is made (probes/probe_registry.hpp).
struct ProbeSpec {
    std::string name;
    std::string type;
    Real every = 0;
    std::shared_ptr<const ConfigTable> table; // the block (keeps the parsed case file alive)
    Origin origin;                            // where the block is in the case file
};

// Fluid entering through the downstream face of a buffer box (`min`-`max`) along `axis`
// (sign +1 or -1): discharge Q(t) [m^3/s; 2D: m^2/s] piecewise linear in `times` (one value:
// constant). The buffer is also a [[fluid]] block (index `fluid`) filled at t = 0.
struct InletSpec {
    std::string name;
    Vec3 min, max;
    int axis = 0, sign = 1;
    std::vector<Real> times, discharge;
    Real every = 0.01; // sampling interval of its CSV [s]
    std::size_t fluid = 0;
    Origin origin; // where the block is in the case file
    // Cross-section normal to the flow [m^2] (2D: its height x 1 m).
    Real area(int dim) const {
        Real a = 1;
        for (int k = 0; k < 3; ++k)
            if (k != axis && !(dim == 2 && k == 1)) a *= max[k] - min[k];
        return a;
    }
};

// Sink: fluid particles and grains inside the box `min`-`max` are removed and counted.
struct OutletSpec {
    std::string name;
    Vec3 min, max;
    Real every = 0.01;
    Origin origin; // where the block is in the case file
};

// A deformable solid (explicit FEM): a built-in mesh ("box": min, max, divisions; "trapezoid":
// a dam section extruded across the channel) or a Gmsh file, of one element type, with node
// sets fixed in all directions.
struct FemSolidSpec {
    std::string name, material, mesh = "box", element = "hex8", file;
    std::string dem_material; // DEM material grains and bodies meet on its surface ("": theirs)
    Vec3 min, max;
    std::array<int, 3> divisions{4, 4, 4};
    fem::TrapezoidSpec trapezoid;
    std::vector<std::string> fixed;
    Origin origin; // where the block is in the case file
};

// A named node set: the nodes of `solid` inside the box min-max.
struct FemNodeSetSpec {
    std::string name, solid;
    Vec3 min, max;
};

// A force [N] (2D: N/m) shared by the nodes of a set, scaled by a table of time.
struct FemLoadSpec {
    std::string set;
    Vec3 force;
    std::vector<Real> times, scale;
};

struct FemSpec {
    fem::FemParams params;
    int layers = 0; // SPH boundary layers inside the solids' surface (0: ceil(2h/dp))
    std::vector<fem::FemMaterial> materials;
    std::vector<FemSolidSpec> solids;
    std::vector<FemNodeSetSpec> node_sets;
    std::vector<FemLoadSpec> loads;
};

// What happens to a fluid particle or a grain whose centre leaves the (non-periodic) domain:
// "remove" takes it out of the run and counts it by phase and by the face it crossed (as
// DualSPHysics does with its excluded particles); "stop" ends the run with the particle's
// state. A non-finite state always stops the run (flow/domain_exit.hpp).
struct DomainExitSpec {
    std::string policy = "remove";
    // Warn once when the mass a phase lost exceeds this fraction of all it ever held.
    Real warn_fraction = 0.01;
};

struct CaseSpec {
    std::string file;
    std::string name;
    int dim = 2;
    Real dp = 0;
    Real t_end = 0;
    std::string scheme = "symplectic"; // time.scheme: symplectic | verlet
    int verlet_euler_every = 40;
    // exec.backend: which backend runs the SPH phase's time loop, "host" (the default),
    // "host_resident" or "cuda" (sph/resident_backend.hpp).
    std::string backend = "host";
    Real vtk_every = 0; // 0: first and last frame only
    bool vtk = true;
    Real progress_seconds = 2;
    // output.checkpoint_every [s simulated] and output.checkpoint_wall [min wall clock]: when
    // to write OUT/checkpoint/ (0: never; a stop by SIGINT/SIGTERM writes one either way).
    Real checkpoint_every = 0, checkpoint_wall = 0;
    sph::SphParams sph;
    bool fluid_gravity = true; // [sph] fluid_gravity: false = no hydrostatic field in the fluid
    Domain domain;
    DomainExitSpec domain_exit;
    Real c0_coefficient = 0, reference_depth = 0; // when c0 = coefficient * sqrt(g H)
    std::vector<FluidSpec> fluids;
    bool has_dem = false;
    DemSpec dem;
    std::vector<WallSpec> walls;
    RigidSpec rigid;
    bool has_bodies() const { return !rigid.bodies.empty() || !rigid.feeds.empty(); }
    FemSpec fem;
    bool has_fem() const { return !fem.solids.empty(); }
    std::vector<ProbeSpec> probes;
    std::vector<InletSpec> inlets;
    std::vector<OutletSpec> outlets;
    std::string resolved_toml; // the case after --set overrides, for the output folder
    // The case less [output] and time.end: what a checkpoint must match to be restarted
    // (output settings may change, and a finished run may be extended).
    std::string physics_toml;
    // Where the top level and the [time], [domain], [sph] and [dem] tables are in the file.
    Origin origin, time_origin, domain_origin, sph_origin, dem_origin, exec_origin;
};

// Reads and validates a case file; `overrides` are "key=value" strings from --set.
CaseSpec read_case(const std::string& path, const std::vector<std::string>& overrides);
// The same from the text of a case; `path` names it in messages and anchors relative mesh
// and state files (the fuzz harness reads its inputs this way).
CaseSpec read_case_text(const std::string& text, const std::string& path,
                        const std::vector<std::string>& overrides);

} // namespace debrisflow::io
