#pragma once
#include "debrisflow/core/domain.hpp"
#include "debrisflow/dem/obstacles.hpp"
#include "debrisflow/particles/particle_set.hpp"
#include "debrisflow/rigid/body_contacts.hpp"
#include "debrisflow/rigid/joints.hpp"
#include "debrisflow/time/phase.hpp"
#include <memory>
#include <unordered_map>
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

// SPH boundary particles that move with the bodies, addressed by persistent particle id:
// particle id first_id + k belongs to body owner[k] at body-frame offset offset[k], with the
// body-frame wall normal normal[k] (for the no-slip extrapolation). Bodies added during the run
// append rows whose ids are listed in extra_ids (row owner.size() - extra_ids.size() + j).
struct BodyParticles {
    ParticleId first_id = 0;
    std::vector<std::int32_t> owner;
    std::vector<Vec3> offset, normal;
    std::unordered_map<ParticleId, std::uint32_t> extra_rows; // id -> row, for added bodies
    // Row of particle id, or -1 when it belongs to no body.
    long row(ParticleId id, std::size_t initial) const {
        if (id >= first_id && id < first_id + initial) return long(id - first_id);
        const auto it = extra_rows.find(id);
        return it == extra_rows.end() ? -1 : long(it->second);
    }
};

// A surface point of a body added during the run: world position and outward unit normal.
struct ShellPoint {
    Vec3 p, n;
    Real depth;
};

// Six-degree-of-freedom rigid bodies as a phase of the time loop. Newton-Euler with the
// translation as in the SPH scheme, the rotation by kick / torque-free split rotation / kick
// (Dullweber et al. 1997) on the world angular momentum and a unit quaternion. Fluid loads
// are the summed SPH accelerations of the bodies' boundary particles, F = sum m_k a_k,
// T = sum (x_k - X) x m_k a_k (DualSPHysics floating bodies, Dominguez et al. 2022 eqs.
// 31-32); the phase must be added after the SPH phase. Contacts and springs add their loads;
// joints constrain velocities after every velocity update.
class BodySolver : public time::Phase {
public:
    BodySolver(RigidParams params, std::vector<BodyState> bodies, std::vector<BodyModel> models,
               JointSet joints, BodyContacts contacts, const dem::WallSet* walls);
    // Couples the bodies to the fluid through their boundary particles in `set`.
    void attach_particles(particles::ParticleSet* set, BodyParticles particles);
    // Couples the bodies to the grains: their contact samples become DEM obstacle spheres;
    // the grains' reaction (averaged over the DEM steps since the last collection) is added
    // to the contact loads, so the momentum exchanged is the same on both sides.
    void attach_grains(dem::ObstacleSet* obstacles);

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
    // SPH boundary particles of density rho and mass m_particle. Returns the body's index.
    int add_body(BodyState state, BodyModel model, const std::vector<ShellPoint>& shell, Real rho,
                 Real m_particle);

    // Removes free, unjointed body b from the model (an outlet took it): it is parked at rest
    // where it is (Motion::removed) and leaves the contacts, the grains' obstacles, the health
    // check and the output. Returns false (nothing done) for any other body. Its SPH boundary
    // particles are marked 0 in `keep` (sized to the attached particle set, when there is one),
    // for the caller to remove with SphSolver::remove_particles.
    bool remove_body(int b, std::vector<std::uint8_t>& keep);
    bool removed(int b) const { return bodies_[std::size_t(b)].motion == Motion::removed; }
    // Number of SPH boundary particles of body b in the attached set (0 without one).
    std::size_t particles_of(int b) const;

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
    // feeds) with their models and boundary particles included.
    void state(checkpoint::Archive& ar);

private:
    void refresh_members();
    void update_obstacles();
    void move_particles(bool positions);
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
    particles::ParticleSet* set_ = nullptr;
    BodyParticles particles_;
    std::size_t initial_rows_ = 0;    // rows of the bodies built before the run
    std::vector<Index> members_;      // particle index of each body particle
    std::vector<std::uint32_t> rows_; // its row in particles_
    dem::ObstacleSet* obstacles_ = nullptr;
    std::vector<Vec3> grain_force_, grain_torque_; // last collected grain reaction
    std::uint64_t layout_seen_ = ~std::uint64_t(0);
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
