// What the BodySolver says about its bodies' state: the health check, the loads behind an
// instability, kinetic energy.
#include "debrisflow/core/error.hpp"
#include "debrisflow/rigid/body_solver.hpp"
#include <cmath>
#include <fmt/format.h>

namespace debrisflow::rigid {

void BodySolver::check_health(Real t) const {
    const auto& d = params_.domain;
    for (std::size_t b = 0; b < bodies_.size(); ++b) {
        const BodyState& s = bodies_[b];
        if (s.motion == Motion::removed) continue;
        const Real vals[] = {s.pos.x, s.pos.y,     s.pos.z,     s.vel.x,     s.vel.y,
                             s.vel.z, s.ang_mom.x, s.ang_mom.y, s.ang_mom.z, s.q.w};
        bool finite = true;
        for (Real v : vals) finite = finite && std::isfinite(v);
        bool inside = true;
        int wrapped = -1;
        for (int k = 0; k < 3 && finite; ++k)
            if (!(params_.dim == 2 && k == 1) && (s.pos[k] < d.lo[k] || s.pos[k] > d.hi[k])) {
                if (d.periodic[k])
                    wrapped = k;
                else
                    inside = false;
            }
        if (finite && inside && wrapped >= 0)
            throw InstabilityError(fmt::format(
                "at t = {:.6g} s: body '{}' crossed the periodic boundary in {} (at {:.4g} m); "
                "rigid bodies do not wrap through periodic directions yet: keep them inside "
                "with walls, or remove them with an outlet before the boundary",
                t, models_[b].name, "xyz"[wrapped], s.pos[wrapped]));
        if (finite && inside) continue;
        throw InstabilityError(fmt::format(
            "{} at t = {:.6g} s: body '{}' ({:.3g} kg) at ({:.4g}, {:.4g}, {:.4g}) m, velocity "
            "({:.4g}, {:.4g}, {:.4g}) m/s; {}",
            finite ? "body left the domain" : "non-finite body state (NaN/Inf)", t, models_[b].name,
            s.mass, s.pos.x, s.pos.y, s.pos.z, s.vel.x, s.vel.y, s.vel.z, describe_loads(b)));
    }
}

std::string BodySolver::describe_loads(std::size_t b) const {
    std::vector<std::string> wall_names, body_names;
    if (walls_)
        for (const auto& w : walls_->walls()) wall_names.push_back(w.name);
    for (const auto& m : models_) body_names.push_back(m.name);
    return recorder_.describe(b, bodies_[b].mass * norm(params_.gravity), wall_names, body_names);
}

std::string BodySolver::diagnose() const {
    std::size_t fastest = bodies_.size();
    Real v2 = -1;
    for (std::size_t b = 0; b < bodies_.size(); ++b)
        if (bodies_[b].motion == Motion::free && dot(bodies_[b].vel, bodies_[b].vel) > v2)
            fastest = b, v2 = dot(bodies_[b].vel, bodies_[b].vel);
    if (fastest == bodies_.size()) return {};
    const BodyState& s = bodies_[fastest];
    return fmt::format("fastest body '{}' ({:.3g} kg) at ({:.4g}, {:.4g}, {:.4g}) m, velocity "
                       "({:.4g}, {:.4g}, {:.4g}) m/s; {}",
                       models_[fastest].name, s.mass, s.pos.x, s.pos.y, s.pos.z, s.vel.x, s.vel.y,
                       s.vel.z, describe_loads(fastest));
}

Real BodySolver::kinetic_energy(int b) const {
    const BodyState& s = bodies_[b];
    const Vec3 w = s.omega();
    return Real(0.5) * s.mass * dot(s.vel, s.vel) + Real(0.5) * dot(w, s.ang_mom);
}

} // namespace debrisflow::rigid
