#pragma once
#include "debrisflow/dem/grain_set.hpp"
#include "debrisflow/dem/wall_proximity.hpp"
#include "debrisflow/dem/wall_set.hpp"
#include "debrisflow/io/case_spec.hpp"
#include "debrisflow/scenario/grain_bed_load.hpp"

namespace debrisflow::scenario {

// Creates the grains of every [[grains]] block (sizes drawn from the block's distribution,
// placed by random non-overlapping insertion, on a lattice, singly, or read from a saved
// state). Masses: spheres rho 4/3 pi r^3 (I = 2/5 m r^2); in 2D discs rho pi r^2 t of the
// case's thickness t (I = 1/2 m r^2), as PFC2D. Refuses a block too soft to rest on its
// contacts (grain_bed_load.hpp) or whose grains start inside one of `walls` (more than
// max_bed_overlap of a grain's radius into a wall, or the centre in a solid or behind a plane),
// and returns the deepest bed overlap of the blocks.
BedOverlap build_grains(const io::CaseSpec& spec, dem::GrainSet& grains, const dem::WallSet& walls);

// Appends one grain of diameter d and material index mat (masses as above).
void add_grain(const io::CaseSpec& c, dem::GrainSet& g, Vec3 x, Vec3 v, Vec3 w, Real d, int mat);
// Index of the [[material]] called `name`.
int material_index(const io::CaseSpec& c, const std::string& name);

// The walls near which grains are placed (`walls` built from c by build_dem_walls), with the
// "box" walls as solid blocks: WallProximity's search for a grain that starts inside a wall.
dem::WallProximity wall_proximity(const io::CaseSpec& c, const dem::WallSet& walls, Real reach,
                                  bool fixed_only);

// Geometric walls (planes and triangles) of every [[wall]] block.
void build_dem_walls(const io::CaseSpec& spec, dem::WallSet& walls);

// Saved grain state (CSV: x, y, z, vx, vy, vz, wx, wy, wz, diameter, material name), readable
// by a [[grains]] block with packing = "file".
void write_grain_state(const std::string& path, const dem::GrainSet& grains,
                       const std::vector<dem::Material>& materials);

} // namespace debrisflow::scenario
