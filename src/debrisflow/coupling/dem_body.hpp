#pragma once
#include "debrisflow/coupling/coupling.hpp"
#include "debrisflow/dem/obstacles.hpp"

namespace debrisflow::checkpoint {
class Archive;
}
namespace debrisflow::dem {
class DemSolver;
}
namespace debrisflow::rigid {
class BodySolver;
}

namespace debrisflow::coupling {

// Two-way DEM <-> rigid-body contact through the bodies' contact spheres (dem::ObstacleSet):
// the bodies write their spheres' positions and velocities after every update; the DEM
// evaluates each grain-sphere contact with the grain pair laws at every sub-step and sums the
// reaction impulse per body (force and torque about its centre of mass); the bodies collect
// that impulse over their own step, divided by the time it covers.
class DemBodyCoupling : public Coupling {
public:
    // Attaches the shared sphere set to both solvers (they keep a pointer to it: this object
    // must not move, hold it by pointer).
    DemBodyCoupling(rigid::BodySolver& bodies, dem::DemSolver& grains);
    DemBodyCoupling(const DemBodyCoupling&) = delete;
    DemBodyCoupling& operator=(const DemBodyCoupling&) = delete;

    const char* coupling_name() const override { return "dem-rigid"; }
    std::vector<Exchange> exchanges() const override;

    // Saves or restores the spheres and the impulse not yet collected
    // (coupling/coupling_checkpoint.cpp).
    void state(checkpoint::Archive& ar);

private:
    dem::ObstacleSet obstacles_;
};

} // namespace debrisflow::coupling
