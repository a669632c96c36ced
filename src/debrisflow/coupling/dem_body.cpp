#include "debrisflow/coupling/dem_body.hpp"
#include "debrisflow/dem/dem_solver.hpp"
#include "debrisflow/rigid/body_solver.hpp"
#include <algorithm>

namespace debrisflow::coupling {

DemBodyCoupling::DemBodyCoupling(rigid::BodySolver& bodies, dem::DemSolver& grains) {
    bodies.attach_grains(this);
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

// F_b = J_b / t, T_b = L_b / t: the impulse the DEM summed over the time t since the last
// collection (the last average again when no DEM step came between).
void DemBodyCoupling::add_loads(std::vector<rigid::BodyLoads>& loads) {
    auto& o = obstacles_;
    if (o.time > 0)
        for (std::size_t b = 0; b < grain_force_.size(); ++b) {
            grain_force_[b] = (1 / o.time) * o.impulse[b];
            grain_torque_[b] = (1 / o.time) * o.angular_impulse[b];
            o.impulse[b] = o.angular_impulse[b] = {};
        }
    o.time = 0;
    for (std::size_t b = 0; b < grain_force_.size(); ++b) {
        loads[b].contact_force += grain_force_[b];
        loads[b].contact_torque += grain_torque_[b];
    }
}

// Sphere k of body b at x = X + R c_k with v = V + w x (x - X); a free body's compliances for
// the DEM's stable step: 1/m + |c|^2 / I_min (normal), 1/m + (|c| + r)^2 / I_min (tangential).
void DemBodyCoupling::follow(const std::vector<rigid::BodyState>& bodies,
                             const std::vector<rigid::BodyModel>& models) {
    auto& o = obstacles_;
    const std::size_t nb = bodies.size();
    grain_force_.resize(nb);
    grain_torque_.resize(nb);
    o.impulse.resize(nb);
    o.angular_impulse.resize(nb);
    o.spheres.clear();
    o.body_com.resize(nb);
    for (std::size_t b = 0; b < nb; ++b) {
        const rigid::BodyState& s = bodies[b];
        o.body_com[b] = s.pos;
        if (s.motion == rigid::Motion::removed) continue;
        const bool free = s.motion == rigid::Motion::free;
        const Real m = free ? s.mass : Real(1e20);
        const Vec3 w = s.omega();
        // the most compliant rotation the body may take (locked world axes left out, which for
        // a principal frame turning only about a locked axis's normal is exact, else an upper
        // bound)
        Real inv_i = 0;
        for (int k = 0; k < 3; ++k)
            if (!s.lock_rotation[std::size_t(k)]) inv_i = std::max(inv_i, s.inv_inertia[k]);
        for (const auto& sp : models[b].samples) {
            const Vec3 x = s.to_world(sp.center);
            dem::ObstacleSphere o_s{x, s.point_velocity(x), w, sp.radius, m, s.material, int(b)};
            if (free) {
                const Real c = norm(sp.center);
                o_s.normal_compliance = 1 / s.mass + c * c * inv_i;
                o_s.tangential_compliance = 1 / s.mass + (c + sp.radius) * (c + sp.radius) * inv_i;
                o_s.rotational_compliance = inv_i;
            }
            o.spheres.push_back(o_s);
        }
    }
    ++o.version;
}

} // namespace debrisflow::coupling
