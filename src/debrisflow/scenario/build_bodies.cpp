#include "debrisflow/scenario/build_bodies.hpp"
#include "debrisflow/core/error.hpp"
#include "debrisflow/dem/materials.hpp"
#include <algorithm>
#include <fmt/format.h>

namespace debrisflow::scenario {

namespace {

int material_of(const io::CaseSpec& c, const std::string& name) {
    const auto& m = c.dem.materials;
    const auto it = std::find_if(m.begin(), m.end(), [&](const auto& x) { return x.name == name; });
    if (it == m.end()) throw InputError(c.file + ": no [[material]] named \"" + name + "\"");
    return int(it - m.begin());
}

int body_of(const io::CaseSpec& c, const std::string& name) {
    if (name.empty()) return -1;
    for (std::size_t b = 0; b < c.rigid.bodies.size(); ++b)
        if (c.rigid.bodies[b].name == name) return int(b);
    throw InputError(c.file + ": no [[body]] named \"" + name + "\"");
}

} // namespace

std::vector<BuiltBody> build_body_geometry(const io::CaseSpec& c) {
    std::vector<BuiltBody> out;
    const Real dp = c.fluids.empty() ? 0 : c.dp;
    for (const auto& b : c.rigid.bodies) {
        out.push_back(build_body(b, c, b.density, dp, b.layers));
        out.back().state.material = material_of(c, b.material);
    }
    return out;
}

std::unique_ptr<rigid::BodySolver> make_body_solver(const io::CaseSpec& c,
                                                    const std::vector<BuiltBody>& built,
                                                    const dem::WallSet* walls) {
    std::vector<rigid::BodyState> states;
    std::vector<rigid::BodyModel> models;
    for (const auto& b : built) {
        states.push_back(b.state);
        models.push_back(b.model);
    }
    rigid::JointSet joints;
    for (const auto& js : c.rigid.joints) {
        rigid::Joint j;
        j.name = js.name;
        j.type = js.type == "hinge"   ? rigid::JointType::hinge
                 : js.type == "ball"  ? rigid::JointType::ball
                 : js.type == "fixed" ? rigid::JointType::fixed
                                      : rigid::JointType::spring;
        j.a = body_of(c, js.body_a);
        j.b = body_of(c, js.body_b);
        auto local = [&](int b, Vec3 p) {
            return b < 0 ? p : rigid::rotate_inverse(states[b].q, p - states[b].pos);
        };
        auto local_axis = [&](int b, Vec3 a) {
            return b < 0 ? a : rigid::rotate_inverse(states[b].q, a);
        };
        j.anchor_a = local(j.a, js.point);
        const Vec3 end_b = j.type == rigid::JointType::spring ? js.point_b : js.point;
        j.anchor_b = local(j.b, end_b);
        j.axis_a = local_axis(j.a, js.axis);
        j.axis_b = local_axis(j.b, js.axis);
        const rigid::Quat qa = j.a < 0 ? rigid::Quat{} : states[j.a].q;
        const rigid::Quat qb = j.b < 0 ? rigid::Quat{} : states[j.b].q;
        j.rel0 = rigid::conjugate(qa) * qb;
        j.stiffness = js.stiffness;
        j.damping = js.damping;
        j.rest_length = js.rest_length ? *js.rest_length : norm(end_b - js.point);
        joints.joints().push_back(j);
    }
    rigid::RigidParams p;
    p.gravity = c.dem.params.gravity;
    if (!c.fluids.empty() && !c.fluid_gravity) p.buoyancy_density = c.sph.rho0;
    p.dt = c.rigid.dt;
    p.joint_iterations = c.rigid.joint_iterations;
    p.joint_stabilization = c.rigid.joint_stabilization;
    p.dim = c.dim;
    p.domain = c.domain;
    auto table = dem::build_pair_table(c.dem.materials, c.dem.overrides, "none");
    return std::make_unique<rigid::BodySolver>(
        p, std::move(states), std::move(models), std::move(joints),
        rigid::BodyContacts(std::move(table), int(c.dem.materials.size())), walls);
}

coupling::BodyParticles body_particles(const std::vector<BuiltBody>& built, ParticleId first_id) {
    coupling::BodyParticles bp;
    bp.first_id = first_id;
    for (std::size_t b = 0; b < built.size(); ++b)
        for (const auto& sp : built[b].sph_points)
            bp.append(std::int32_t(b), built[b].state, sp.p, sp.n);
    return bp;
}

} // namespace debrisflow::scenario
