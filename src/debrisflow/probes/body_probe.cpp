#include "debrisflow/probes/body_probe.hpp"
#include "debrisflow/core/error.hpp"
#include "debrisflow/rigid/body_solver.hpp"
#include <algorithm>

namespace debrisflow::probes {

std::unique_ptr<Probe> BodyProbe::from_config(const ProbeSetup& s) {
    const std::string body = s.t.string("body");
    if (std::none_of(s.c.rigid.bodies.begin(), s.c.rigid.bodies.end(),
                     [&](const auto& b) { return b.name == body; }))
        s.t.fail("body", "no [[body]] named \"" + body + "\"");
    return std::make_unique<BodyProbe>(s.name(), s.every(), body);
}

std::vector<std::string> BodyProbe::columns() const {
    return {"x [m]",        "y [m]",        "z [m]",          "point_x [m]",    "point_y [m]",
            "point_z [m]",  "vx [m/s]",     "vy [m/s]",       "vz [m/s]",       "wx [rad/s]",
            "wy [rad/s]",   "wz [rad/s]",   "qw [-]",         "qx [-]",         "qy [-]",
            "qz [-]",       "roll [deg]",   "pitch [deg]",    "yaw [deg]",      "fluid_fx [N]",
            "fluid_fy [N]", "fluid_fz [N]", "contact_fx [N]", "contact_fy [N]", "contact_fz [N]"};
}

std::vector<Real> BodyProbe::sample(Real, const ProbeContext& ctx) {
    if (!ctx.rigid) throw InputError("probe '" + name() + "': the case has no bodies");
    if (index_ < 0) index_ = ctx.rigid->find(body_);
    const auto& s = ctx.rigid->bodies()[index_];
    const auto& m = ctx.rigid->models()[index_];
    const auto& l = ctx.rigid->loads()[index_];
    const Vec3 p = m.has_track_point ? s.to_world(m.track_point) : s.pos;
    const Vec3 v = s.vel, w = s.omega();
    const rigid::Quat q = rigid::normalized(s.q * rigid::conjugate(s.q_user));
    const Vec3 e = (180 / Real(3.14159265358979323846)) * rigid::euler_zyx(q);
    return {s.pos.x,
            s.pos.y,
            s.pos.z,
            p.x,
            p.y,
            p.z,
            v.x,
            v.y,
            v.z,
            w.x,
            w.y,
            w.z,
            q.w,
            q.x,
            q.y,
            q.z,
            e.x,
            e.y,
            e.z,
            l.fluid_force.x,
            l.fluid_force.y,
            l.fluid_force.z,
            l.contact_force.x,
            l.contact_force.y,
            l.contact_force.z};
}

} // namespace debrisflow::probes
