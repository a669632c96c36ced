#pragma once
#include "debrisflow/coupling/coupling.hpp"
#include "debrisflow/particles/particle_set.hpp"
#include "debrisflow/rigid/fluid_side.hpp"
#include <unordered_map>
#include <vector>

namespace debrisflow::checkpoint {
class Archive;
}
namespace debrisflow::rigid {
class BodySolver;
}

namespace debrisflow::coupling {

// SPH boundary particles that move with the bodies, addressed by persistent particle id:
// particle id first_id + k belongs to body owner[k] at body-frame offset offset[k], with the
// body-frame wall normal normal[k] (for the no-slip extrapolation). Bodies added during the run
// append rows, found through extra_rows.
struct BodyParticles {
    ParticleId first_id = 0;
    std::vector<std::int32_t> owner;
    std::vector<Vec3> offset, normal;
    std::unordered_map<ParticleId, std::uint32_t> extra_rows; // id -> row, for added bodies
    // A row for body b's particle at world position p with outward normal n, kept in the
    // body's frame (state: the body's current pose).
    void append(std::int32_t b, const rigid::BodyState& state, Vec3 p, Vec3 n) {
        owner.push_back(b);
        offset.push_back(rigid::rotate_inverse(state.q, p - state.pos));
        normal.push_back(rigid::rotate_inverse(state.q, n));
    }
    // Row of particle id, or -1 when it belongs to no body (`initial`: rows built before the run).
    long row(ParticleId id, std::size_t initial) const {
        if (id >= first_id && id < first_id + initial) return long(id - first_id);
        const auto it = extra_rows.find(id);
        return it == extra_rows.end() ? -1 : long(it->second);
    }
};

// Two-way fluid <-> rigid-body coupling through the bodies' SPH boundary particles. The fluid
// loads are the summed SPH accelerations of a body's boundary particles, F = sum m_k a_k,
// T = sum (x_k - X) x m_k a_k (DualSPHysics floating bodies, Dominguez et al. 2022 eqs.
// 31-32), read after the SPH force evaluation; after every update of the bodies the particles
// take the rigid motion x_k = X + R o_k, v_k = V + w x (x_k - X), with their wall normals.
class SphBodyCoupling : public Coupling, public rigid::FluidSide {
public:
    // Attaches itself to the bodies (they keep a pointer to it: this object must not move,
    // hold it by pointer).
    SphBodyCoupling(rigid::BodySolver& bodies, particles::ParticleSet& set, BodyParticles rows);
    SphBodyCoupling(const SphBodyCoupling&) = delete;
    SphBodyCoupling& operator=(const SphBodyCoupling&) = delete;

    const char* coupling_name() const override { return "sph-rigid"; }
    std::vector<Exchange> exchanges() const override;

    void add_loads(const std::vector<rigid::BodyState>& bodies,
                   std::vector<rigid::BodyLoads>& loads) override;
    void follow(const std::vector<rigid::BodyState>& bodies, bool positions) override;
    void add_shell(int b, const rigid::BodyState& state,
                   const std::vector<rigid::ShellPoint>& shell, Real rho, Real m_particle) override;
    void release(int b, std::vector<std::uint8_t>& keep) override;
    std::size_t particles_of(int b) const override;
    // The rows of body b's shell points, whose particles were given the ids first_id,
    // first_id + 1, ... (here by add_shell; by a resident backend where its particles are).
    void add_rows(int b, const rigid::BodyState& state, const std::vector<rigid::ShellPoint>& shell,
                  ParticleId first_id);

    // The body particles' rows (a resident backend takes them over: sph/resident_bodies.hpp).
    const BodyParticles& rows() const { return rows_; }
    std::size_t initial_rows() const { return initial_rows_; }

    // Saves or restores the rows (those of bodies added during the run included)
    // (coupling/coupling_checkpoint.cpp).
    void state(checkpoint::Archive& ar);

private:
    // The particle index and row of every body particle, found again after the particle set
    // was reordered, grown or shrunk.
    void refresh();

    particles::ParticleSet& set_;
    BodyParticles rows_;
    std::size_t initial_rows_ = 0;           // rows of the bodies built before the run
    std::vector<Index> members_;             // particle index of each body particle
    std::vector<std::uint32_t> member_rows_; // its row in rows_
    std::uint64_t layout_seen_ = ~std::uint64_t(0);
};

} // namespace debrisflow::coupling
