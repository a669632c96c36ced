#pragma once
#include "debrisflow/coupling/coupling.hpp"
#include "debrisflow/dem/obstacles.hpp"
#include "debrisflow/rigid/grain_side.hpp"

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
// after every update of the bodies the spheres take their positions and velocities (and the
// masses and compliances the DEM's contact laws and stable step need); the DEM evaluates each
// grain-sphere contact with the grain pair laws at every sub-step and sums the reaction
// impulse per body (force and torque about its centre of mass); the bodies take that impulse
// over their own step, divided by the time it covers, F = J / t.
class DemBodyCoupling : public Coupling, public rigid::GrainSide {
public:
    // Attaches the shared sphere set to both solvers (they keep a pointer to it: this object
    // must not move, hold it by pointer).
    DemBodyCoupling(rigid::BodySolver& bodies, dem::DemSolver& grains);
    DemBodyCoupling(const DemBodyCoupling&) = delete;
    DemBodyCoupling& operator=(const DemBodyCoupling&) = delete;

    const char* coupling_name() const override { return "dem-rigid"; }
    std::vector<Exchange> exchanges() const override;

    void add_loads(std::vector<rigid::BodyLoads>& loads) override;
    void follow(const std::vector<rigid::BodyState>& bodies,
                const std::vector<rigid::BodyModel>& models) override;

    // Saves or restores the spheres, the impulse not yet collected and the last reaction
    // (coupling/coupling_checkpoint.cpp).
    void state(checkpoint::Archive& ar);

private:
    dem::ObstacleSet obstacles_;
    std::vector<Vec3> grain_force_, grain_torque_; // last collected reaction per body
};

} // namespace debrisflow::coupling
