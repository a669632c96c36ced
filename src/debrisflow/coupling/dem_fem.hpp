#pragma once
#include "debrisflow/coupling/coupling.hpp"
#include "debrisflow/dem/wall_set.hpp"
#include "debrisflow/fem/fem_solver.hpp"
#include <string>
#include <vector>

namespace debrisflow::checkpoint {
class Archive;
}

namespace debrisflow::rigid {
class BodySolver;
}

namespace debrisflow::coupling {

// Two-way DEM <-> FEM contact: the boundary facets of every solid become the triangles of one
// DEM wall named after the solid (dem::WallSet::add_nodal), whose corners follow the FEM
// nodes. Grains and rigid bodies touch them with the DEM contact laws against the solid's DEM
// material; the contact point moves with the barycentric blend of the corner velocities and
// the reaction returns to the corners with the same weights (sum 1: momentum is conserved).
// The grains' reaction is gathered as an impulse over the DEM sub-steps of a global step and
// handed to the FEM as impulse / dt for that step's advance; the bodies' reaction is a force of
// the body evaluation. Eroded elements leave the surface: the triangles are rebuilt from the
// remaining facets.
class DemFemCoupling : public Coupling {
public:
    // dem_material[s]: DEM material index of solid s (-1: the grain's own material).
    DemFemCoupling(fem::FemSolver& fem, dem::WallSet& walls, const std::vector<int>& dem_material);

    const char* coupling_name() const override { return "dem-fem"; }
    std::vector<Exchange> exchanges() const override;
    // Registers the grains' reaction (a step source), the bodies' contact forces when there
    // are bodies (a load source) and the walls' motion (a surface mover) with the FEM solver.
    void connect(const rigid::BodySolver* bodies);
    // Copies the node positions and velocities into the walls and replaces the triangles when
    // elements were eroded. Call after every FEM advance.
    void sync();
    // Adds the grains' reaction impulse gathered since the last call, divided by dt [N].
    void collect_grain_forces(std::vector<Vec3>& f, Real dt);
    // Adds body contact forces on the nodes [N].
    static void add_body_forces(const std::vector<Vec3>& node_forces, std::vector<Vec3>& f);
    Vec3 last_grain_force() const { return last_grain_force_; } // total, last step [N]
    // Index of the DEM wall of solid s.
    int wall_of(std::size_t s) const { return walls_of_[s]; }
    std::size_t triangles() const;

    // Saves or restores what the coupling keeps between steps (coupling/coupling_checkpoint.cpp).
    void state(checkpoint::Archive& ar);

private:
    std::vector<std::vector<dem::NodalCorners>> triangles_per_solid() const;

    const rigid::BodySolver* bodies_ = nullptr;
    fem::FemSolver& fem_;
    dem::WallSet& walls_;
    std::vector<int> walls_of_;
    long eroded_seen_ = 0;
    Vec3 last_grain_force_;
};

} // namespace debrisflow::coupling
