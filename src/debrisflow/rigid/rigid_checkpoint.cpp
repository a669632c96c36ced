// The rigid-body phase's state for checkpoints: bodies, loads, joints' impulses, contact
// memory (tangential springs, the side of each vertex near an open surface) and the load
// recorder's windows.
#include "debrisflow/checkpoint/archive.hpp"
#include "debrisflow/rigid/body_solver.hpp"
#include <algorithm>
#include <tuple>

namespace debrisflow::rigid {

void BodyContacts::state(checkpoint::Archive& ar) {
    ar.section("body contacts");
    ar(wall_hist_, body_hist_);
    // side_ by (body, vertex, primitive): sorted, so equal memories give equal files
    std::vector<std::uint32_t> body, vertex;
    std::vector<std::uint64_t> primitive;
    std::vector<std::int8_t> side;
    if (!ar.is_loading()) {
        std::vector<std::pair<SideKey, std::int8_t>> rows(side_.begin(), side_.end());
        std::sort(rows.begin(), rows.end(), [](const auto& a, const auto& b) {
            return std::tie(a.first.body, a.first.vertex, a.first.primitive) <
                   std::tie(b.first.body, b.first.vertex, b.first.primitive);
        });
        for (const auto& [k, v] : rows)
            body.push_back(k.body), vertex.push_back(k.vertex), primitive.push_back(k.primitive),
                side.push_back(v);
    }
    ar(body, vertex, primitive, side);
    if (ar.is_loading()) {
        if (vertex.size() != body.size() || primitive.size() != body.size() ||
            side.size() != body.size())
            ar.fail("a contact side table of mismatched lengths");
        side_.clear();
        for (std::size_t i = 0; i < body.size(); ++i)
            side_[SideKey{body[i], vertex[i], std::size_t(primitive[i])}] = side[i];
    }
    ar(contacts_, max_rate_, rate_, imminent_dt_, wall_force_, node_force_, wall_contacts_,
       strongest_);
}

void LoadRecorder::state(checkpoint::Archive& ar) {
    ar(start_, current_, previous_);
}

namespace {
// A body's geometry and prescribed motion (bodies a rock feed added).
void model_state(checkpoint::Archive& ar, BodyModel& m) {
    ar(m.name, m.vertices, m.track_point, m.has_track_point, m.times, m.velocity);
    ar(m.angular_velocity, m.bound_radius, m.volume);
    for (auto* spheres : {&m.spheres, &m.samples})
        ar.columns(*spheres, &BodySphere::center, &BodySphere::radius);
}
} // namespace

void BodySolver::state(checkpoint::Archive& ar) {
    ar.section("bodies");
    std::uint64_t count = bodies_.size();
    ar(count);
    if (count < initial_bodies_ || count > initial_bodies_ + (1u << 24))
        ar.fail("its body count does not fit this case");
    models_.resize(std::size_t(count));
    for (std::size_t b = initial_bodies_; b < models_.size(); ++b) model_state(ar, models_[b]);
    std::vector<BodyState> bodies = bodies_;
    ar.columns(bodies, &BodyState::pos, &BodyState::q, &BodyState::vel, &BodyState::ang_mom,
               &BodyState::mass, &BodyState::inv_mass, &BodyState::inv_inertia, &BodyState::q_user,
               &BodyState::motion, &BodyState::lock_translation, &BodyState::lock_rotation,
               &BodyState::material, &BodyState::contact_radius, &BodyState::prescribed_omega);
    if (bodies.size() != count) ar.fail("its body count does not match its models");
    bodies_ = std::move(bodies);
    ar(loads_, t_, saved_t_, elapsed_, commit_next_);
    ar(pending_kick_, max_contact_rate_, last_dt_);
    std::vector<Vec3> impulse;
    for (const auto& j : joints_.joints()) impulse.push_back(j.impulse);
    ar(impulse);
    if (impulse.size() != joints_.joints().size()) ar.fail("its joint count differs");
    for (std::size_t k = 0; k < impulse.size(); ++k) joints_.joints()[k].impulse = impulse[k];
    contacts_.state(ar);
    recorder_.state(ar);
    if (ar.is_loading() && loads_.size() != count)
        ar.fail("body loads that do not match its bodies");
}

} // namespace debrisflow::rigid
