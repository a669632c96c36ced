#pragma once
#include "debrisflow/core/domain.hpp"
#include "debrisflow/rigid/body_contacts.hpp"
#include "debrisflow/rigid/fluid_side.hpp"
#include "debrisflow/rigid/grain_side.hpp"
#include "debrisflow/rigid/joints.hpp"
#include "debrisflow/time/phase.hpp"
#include <memory>
#include <vector>

namespace debrisflow::checkpoint {
class Archive;
}

namespace debrisflow::rigid {

struct RigidParams {
    Vec3 gravity{0, 0, -9.81};
    Real dt = 0; // user step (0: limited by contacts and springs only)
    int joint_iterations = 30;
    Real joint_stabilization = 0.2;
    int dim = 3;
    Domain domain;
    // > 0 when the fluid carries no gravity: bodies get the buoyancy -rho V g analytically.
    Real buoyancy_density = 0;
};

// Six-degree-of-freedom rigid bodies as a phase of the time loop. Newton-Euler with the
// translation as in the SPH scheme, the rotation by kick / torque-free split rotation / kick
// (Dullweber et al. 1997) on the world angular momentum and a unit quaternion. Fluid loads
// come from the attached FluidSide (coupling::SphBodyCoupling), read in the force
// evaluation, so the phase is added after the SPH phase; after every update the fluid side
// moves the bodies' boundary particles. Contacts and springs add their loads; joints
// constrain velocities after every velocity update.
class BodySolver : public time::Phase {
public:
    BodySolver(RigidParams params, std::vector<BodyState> bodies, std::vector<BodyModel> models,
               JointSet joints, BodyContacts contacts, const dem::WallSet* walls);
    // Couples the bodies to a fluid (it must outlive the solver).
    void attach_fluid(FluidSide* fluid);
    // Couples the bodies to grains (it must outlive the solver): their contact samples become
    // the grains' obstacle spheres, the grains' reaction a contact load.
    void attach_grains(GrainSide* grains);

    const char* name() const override { return "rigid"; }
    void update_neighbors(bool reorder) override;
    void compute_forces() override;
    void predictor(Real dt) override;
    void corrector(Real dt) override;
    void verlet_step(Real dt, bool euler) override;
    time::DtLimit stable_dt() const override;
    void check_health(Real t) const override;
    std::string diagnose() const override; // the fastest body and its recent peak loads
    void add_timings(time::Timings& t) const override;

    // Adds a body during the run (a rock feed); with a fluid attached, its shell points become
    // SPH boundary particles of density rho and mass m_particle (FluidSide::add_shell).
    // Returns the body's index.
    int add_body(BodyState state, BodyModel model, const std::vector<ShellPoint>& shell, Real rho,
                 Real m_particle);

    // Removes free, unjointed body b from the model (an outlet took it): it is parked at rest
    // where it is (Motion::removed) and leaves the contacts, the grains' obstacles, the health
    // check and the output. Returns false (nothing done) for any other body. Its SPH boundary
    // particles, with a fluid attached, are marked 0 in `keep` (sized to the particle set),
    // for the caller to remove with SphSolver::remove_particles.
    bool remove_body(int b, std::vector<std::uint8_t>& keep);
    bool removed(int b) const { return bodies_[std::size_t(b)].motion == Motion::removed; }
    // Number of SPH boundary particles of body b (0 without a fluid).
    std::size_t particles_of(int b) const { return fluid_ ? fluid_->particles_of(b) : 0; }

    // A velocity-Verlet step on the bodies alone (tests, body-only runs).
    void step(Real dt);

    const std::vector<BodyState>& bodies() const { return bodies_; }
    std::vector<BodyState>& bodies() { return bodies_; }
    const std::vector<BodyModel>& models() const { return models_; }
    const std::vector<BodyLoads>& loads() const { return loads_; }
    const JointSet& joints() const { return joints_; }
    int find(const std::string& name) const; // -1 if absent
    long contacts() const { return contacts_.contacts(); }
    // Force of the bodies on the moving nodes of nodal walls (FEM surfaces), last evaluation.
    const std::vector<Vec3>& node_forces() const { return contacts_.node_forces(); }
    // Force of all bodies on geometric wall w in the last evaluation [N].
    Vec3 wall_force(int w) const {
        const auto& f = contacts_.wall_forces();
        return std::size_t(w) < f.size() ? f[std::size_t(w)] : Vec3{};
    }
    // Each body contact's load on wall w (a wall with record_contacts), last evaluation.
    const std::vector<dem::ContactLoad>& wall_contacts(int w) const {
        static const std::vector<dem::ContactLoad> none;
        const auto& c = contacts_.wall_contacts();
        return std::size_t(w) < c.size() ? c[std::size_t(w)] : none;
    }
    Real time() const { return t_; }
    // Kinetic energy and world angular momentum of body b (about its centre of mass).
    Real kinetic_energy(int b) const;
    // Saves or restores the bodies, their loads, joints' impulses, contact memory and the
    // step's bookkeeping (rigid/rigid_checkpoint.cpp), bodies added during the run (rock
    // feeds) with their models included (their boundary particles are the fluid side's).
    void state(checkpoint::Archive& ar);

private:
    // The grains' obstacle spheres follow the bodies.
    void update_obstacles() {
        if (grains_) grains_->follow(bodies_, models_);
    }
    // The fluid's boundary particles follow the bodies (positions too when asked).
    void move_particles(bool positions) {
        if (fluid_) fluid_->follow(bodies_, positions);
    }
    void kick(Real h);              // v += h F/m, L += h T (free bodies)
    void drift(Real h, Real t_mid); // x += h v, free rotation over h; prescribed motion
    // Prescribed body over h with its table velocities at t_mid (midpoint rule).
    static void move_prescribed(BodyState& s, const BodyModel& m, Real h, Real t_mid);
    void constrain(Real dt); // joints and locks
    Vec3 total_force(int b) const;
    std::string describe_loads(std::size_t b) const; // recent peak loads of body b
    Vec3 total_torque(int b) const;

    RigidParams params_;
    std::vector<BodyState> bodies_, saved_;
    std::vector<BodyModel> models_;
    std::vector<BodyLoads> loads_;
    JointSet joints_;
    BodyContacts contacts_;
    const dem::WallSet* walls_;
    std::size_t initial_bodies_ = 0; // bodies of the case; rock feeds add more
    FluidSide* fluid_ = nullptr;
    GrainSide* grains_ = nullptr;
    Real t_ = 0, saved_t_ = 0;
    Real elapsed_ = 0;        // time since the contact history was committed
    bool commit_next_ = true; // the next force evaluation ends a step
    Real pending_kick_ = 0;   // velocity Verlet: second half kick still to apply
    Real max_contact_rate_ = 0;
    Real last_dt_ = 0; // size of the last step taken
    double t_forces_ = 0, t_integrate_ = 0;
    // Recent peak loads, for the failure message: 0.5 s covers a rock thrown across a flume
    // (2 m at 8 m/s) between the throw and its leaving the domain.
    LoadRecorder recorder_{Real(0.5)};
};

} // namespace debrisflow::rigid
