#pragma once
#include "debrisflow/dem/grain_set.hpp"
#include "debrisflow/io/case_spec.hpp"
#include <random>

namespace debrisflow::scenario {

// The shape of a [[grains]] block's clumps at unit volume-equivalent diameter: the member
// spheres in the principal frame (centre of mass at the origin), the union's volume (2D: area)
// and principal moments per unit density (lattice integration of the union, as for a [[body]]
// clump). A grain of size d is this shape scaled by d.
struct ClumpTemplate {
    std::vector<Vec3> centers; // principal frame, unit size
    std::vector<Real> radii;
    Real volume = 0; // of the union at unit size (2D: area)
    Vec3 inertia;    // principal moments per unit density at unit size (2D: per unit thickness)
    Real reach = 0;  // largest |centre| + radius at unit size: the bounding sphere
    int dim = 3;

    // Built from the block's spheres (any unit); throws InputError naming the block.
    static ClumpTemplate from(const io::GrainsSpec& b, const io::CaseSpec& c);
    // Bounding radius of a clump of volume-equivalent diameter d.
    Real bounding_radius(Real d) const { return reach * d; }
};

// Appends a clump of volume-equivalent diameter d centred (centre of mass) at x: its member
// grains and its rigid body. Mass rho V (2D: rho A t); each member carries a share of it in
// proportion to r^3 (2D: r^2), so the grains' masses sum to the clump's.
void add_clump(const io::CaseSpec& c, dem::GrainSet& g, const ClumpTemplate& shape, Vec3 x, Vec3 v,
               Vec3 w, Real d, int mat, rigid::Quat q);

// A uniformly random orientation (2D: a random angle about y).
rigid::Quat random_orientation(std::mt19937_64& rng, int dim);

} // namespace debrisflow::scenario
