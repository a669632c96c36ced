#include "debrisflow/rigid/body_solver.hpp"
#include "debrisflow/core/stopwatch.hpp"
#include <cmath>
#include <limits>

namespace debrisflow::rigid {

BodySolver::BodySolver(RigidParams params, std::vector<BodyState> bodies,
                       std::vector<BodyModel> models, JointSet joints, BodyContacts contacts,
                       const dem::WallSet* walls)
    : params_(params), bodies_(std::move(bodies)), models_(std::move(models)),
      loads_(bodies_.size()), joints_(std::move(joints)), contacts_(std::move(contacts)),
      walls_(walls), initial_bodies_(bodies_.size()) {
    for (auto& b : bodies_) apply_locks(b);
}

void BodySolver::attach_fluid(FluidSide* fluid) {
    fluid_ = fluid;
}

void BodySolver::attach_grains(GrainSide* grains) {
    grains_ = grains;
    update_obstacles();
}

int BodySolver::find(const std::string& name) const {
    for (std::size_t b = 0; b < models_.size(); ++b)
        if (models_[b].name == name) return int(b);
    return -1;
}

bool BodySolver::remove_body(int b, std::vector<std::uint8_t>& keep) {
    BodyState& s = bodies_[std::size_t(b)];
    if (s.motion != Motion::free || joints_.involves(b)) return false;
    s.motion = Motion::removed;
    s.vel = s.ang_mom = s.prescribed_omega = {};
    s.inv_mass = 0;
    if (fluid_) fluid_->release(b, keep);
    update_obstacles();
    return true;
}

int BodySolver::add_body(BodyState state, BodyModel model, const std::vector<ShellPoint>& shell,
                         Real rho, Real m_particle) {
    apply_locks(state);
    const int b = int(bodies_.size());
    bodies_.push_back(state);
    models_.push_back(std::move(model));
    loads_.emplace_back();
    update_obstacles();
    if (fluid_) fluid_->add_shell(b, state, shell, rho, m_particle);
    return b;
}

void BodySolver::update_neighbors(bool) {}

Vec3 BodySolver::total_force(int b) const {
    const BodyLoads& l = loads_[b];
    const Real buoyant = params_.buoyancy_density * models_[b].volume;
    return l.fluid_force + l.contact_force + l.joint_force +
           (bodies_[b].mass - buoyant) * params_.gravity;
}

Vec3 BodySolver::total_torque(int b) const {
    const BodyLoads& l = loads_[b];
    return l.fluid_torque + l.contact_torque + l.joint_torque;
}

void BodySolver::compute_forces() {
    ScopedTimer timer(t_forces_);
    for (auto& l : loads_) l = {};
    if (fluid_) fluid_->add_loads(bodies_, loads_);
    if (grains_) grains_->add_loads(loads_);
    // Look ahead three steps of the current size (the first evaluation: a millisecond).
    const Real horizon = 3 * (last_dt_ > 0 ? last_dt_ : Real(1e-3));
    max_contact_rate_ =
        contacts_.compute(bodies_, models_, walls_, loads_, elapsed_, commit_next_, horizon);
    joints_.add_spring_loads(bodies_, loads_);
    recorder_.record(t_, loads_, contacts_.strongest());
    if (pending_kick_ > 0) {
        const Real h = pending_kick_;
        pending_kick_ = 0;
        kick(Real(0.5) * h);
        constrain(h);
        move_particles(false);
    }
}

void BodySolver::kick(Real h) {
    for (std::size_t b = 0; b < bodies_.size(); ++b) {
        BodyState& s = bodies_[b];
        if (s.motion != Motion::free) continue;
        s.vel += (h * s.inv_mass) * total_force(int(b));
        s.ang_mom += h * total_torque(int(b));
        apply_locks(s);
    }
}

void BodySolver::move_prescribed(BodyState& s, const BodyModel& m, Real h, Real t_mid) {
    if (!m.times.empty()) {
        s.vel = interpolate(m.times, m.velocity, t_mid);
        s.prescribed_omega = interpolate(m.times, m.angular_velocity, t_mid);
    }
    s.pos += h * s.vel;
    s.q = normalized(from_rotation_vector(h * s.prescribed_omega) * s.q);
}

void BodySolver::drift(Real h, Real t_mid) {
    for (std::size_t b = 0; b < bodies_.size(); ++b) {
        BodyState& s = bodies_[b];
        if (s.motion == Motion::fixed || s.motion == Motion::removed) continue;
        if (s.motion == Motion::prescribed) {
            move_prescribed(s, models_[b], h, t_mid);
            continue;
        }
        s.pos += h * s.vel;
        free_rotation(s.q, s.ang_mom, s.inv_inertia, h);
    }
}

void BodySolver::constrain(Real dt) {
    if (!joints_.empty())
        joints_.project(bodies_, dt, params_.joint_iterations, params_.joint_stabilization);
    for (auto& b : bodies_) apply_locks(b);
}

void BodySolver::predictor(Real dt) {
    ScopedTimer timer(t_integrate_);
    saved_ = bodies_;
    saved_t_ = t_;
    last_dt_ = dt;
    // x_n+1/2 = x_n + dt/2 v_n, v_n+1/2 = v_n + dt/2 a_n (as the SPH predictor)
    drift(Real(0.5) * dt, t_ + Real(0.25) * dt);
    kick(Real(0.5) * dt);
    constrain(Real(0.5) * dt);
    move_particles(true);
    update_obstacles();
    elapsed_ = Real(0.5) * dt;
    commit_next_ = false;
}

void BodySolver::corrector(Real dt) {
    ScopedTimer timer(t_integrate_);
    // Kick (dt/2), free rotation (dt), kick (dt/2) with the mid-step loads, from the state at
    // t_n; x_n+1 = x_n + dt (v_n + v_n+1)/2.
    bodies_ = saved_;
    for (std::size_t b = 0; b < bodies_.size(); ++b) {
        BodyState& s = bodies_[b];
        if (s.motion == Motion::fixed || s.motion == Motion::removed) continue;
        if (s.motion == Motion::prescribed) { // moves with its mid-step velocity
            move_prescribed(s, models_[b], dt, t_ + Real(0.5) * dt);
            continue;
        }
        const Vec3 v0 = s.vel;
        s.ang_mom += (Real(0.5) * dt) * total_torque(int(b));
        apply_locks(s);
        free_rotation(s.q, s.ang_mom, s.inv_inertia, dt);
        s.ang_mom += (Real(0.5) * dt) * total_torque(int(b));
        s.vel += (dt * s.inv_mass) * total_force(int(b));
        apply_locks(s);
        s.pos += (Real(0.5) * dt) * (v0 + s.vel);
    }
    constrain(dt);
    t_ = saved_t_ + dt;
    move_particles(true);
    update_obstacles();
    elapsed_ = dt;
    commit_next_ = true;
}

void BodySolver::verlet_step(Real dt, bool) {
    ScopedTimer timer(t_integrate_);
    last_dt_ = dt;
    kick(Real(0.5) * dt);
    constrain(dt);
    drift(dt, t_ + Real(0.5) * dt);
    t_ += dt;
    pending_kick_ = dt;
    move_particles(true);
    update_obstacles();
    elapsed_ = dt;
    commit_next_ = true;
}

void BodySolver::step(Real dt) {
    verlet_step(dt, false);
    compute_forces();
}

time::DtLimit BodySolver::stable_dt() const {
    time::DtLimit lim{std::numeric_limits<Real>::max(), "none"};
    if (params_.dt > 0) lim = {params_.dt, "user dt"};
    if (contacts_.imminent_dt() < lim.dt) lim = {contacts_.imminent_dt(), "impact"};
    if (max_contact_rate_ > 0) {
        const Real dtc = Real(0.2) * 3.14159265358979 / std::sqrt(max_contact_rate_);
        if (dtc < lim.dt) lim = {dtc, "contact"};
    }
    const Real dts = joints_.stable_dt(bodies_);
    if (dts < lim.dt) lim = {dts, "spring"};
    return lim;
}

void BodySolver::add_timings(time::Timings& t) const {
    t.forces += t_forces_;
    t.integration += t_integrate_;
}

} // namespace debrisflow::rigid
