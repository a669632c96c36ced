#pragma once
#include "debrisflow/core/domain.hpp"
#include "debrisflow/dem/dem_params.hpp"
#include "debrisflow/dem/grain_set.hpp"
#include "debrisflow/dem/materials.hpp"
#include "debrisflow/dem/obstacles.hpp"
#include "debrisflow/time/phase.hpp"
#include <vector>

namespace debrisflow::dem {

// The DEM time step: safety x the shortest contact duration over every material pair that can
// meet (grain-grain, and grain-wall with each wall's material; -1 = the grain's own), taken
// with the smallest grain of each material: linear pi / (w0 sqrt(1 - zeta^2)); Hertz-type
// 2.868 (m*^2 / (E*^2 R* v))^(1/5) at the reference velocity (Johnson 1985), and at most
// 0.2 x the Rayleigh time pi r sqrt(rho/G) / (0.1631 nu + 0.8766). The contact's faster modes
// shorten it: the tangential spring on the contact point's compliance sum(1/m + r^2/I) (sqrt(3.5)
// times the normal frequency for spheres, sqrt(3) for discs, when k_t = k_n) and the EPSD
// rolling spring on sum(1/I). With `obstacles`, the spheres of free rigid bodies are partners
// too, with the body's compliance at the sphere (mass, and inertia with the lever arm) in place
// of a second grain's. Returns the step and the criterion (mode and pair) that limits it.
time::DtLimit critical_dt(const GrainSet& grains, const std::vector<int>& wall_materials,
                          const std::vector<Material>& materials,
                          const std::vector<PairParams>& table, const DemParams& params,
                          const Domain& domain, Real safety,
                          const ObstacleSet* obstacles = nullptr);

} // namespace debrisflow::dem
