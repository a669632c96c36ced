#include "debrisflow/coupling/dem_body.hpp"
#include "debrisflow/dem/dem_solver.hpp"
#include "debrisflow/rigid/body_solver.hpp"

namespace debrisflow::coupling {

DemBodyCoupling::DemBodyCoupling(rigid::BodySolver& bodies, dem::DemSolver& grains) {
    bodies.attach_grains(&obstacles_);
    grains.attach_obstacles(&obstacles_);
}

std::vector<Exchange> DemBodyCoupling::exchanges() const {
    return {{"rigid", "dem",
             "contact spheres' positions, velocities, masses and compliances (ObstacleSet "
             "spheres)",
             When::body_motion},
            {"dem", "rigid",
             "grains' contact impulse and angular impulse per body over the time they cover "
             "(ObstacleSet impulse)",
             When::force_evaluation}};
}

} // namespace debrisflow::coupling
