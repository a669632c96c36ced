#pragma once
#include "debrisflow/core/real.hpp"
#include "debrisflow/core/vec3_k.hpp"
#include <cstdint>
#include <type_traits>
#include <vector>

namespace debrisflow::checkpoint {
class Archive;
}

namespace debrisflow::particles {

enum class Kind : std::uint8_t { fluid = 0, boundary = 1 };

// Trivially copyable view of a ParticleSet: raw pointers only, usable in OpenMP and CUDA loops.
struct ParticleView {
    Real *x, *y, *z;
    Real *vx, *vy, *vz;
    Real *ax, *ay, *az;
    Real *rho, *drho, *p, *mass;
    Real *wnx, *wny, *wnz, *wd; // boundary: wall normal into the fluid, depth behind the wall
    Real* mu;                   // apparent dynamic viscosity [Pa s] (viscous models)
    std::uint8_t* kind;
    std::int16_t* group;
    Index n;

    DF_HD Vec3 pos(Index i) const { return {x[i], y[i], z[i]}; }
    DF_HD Vec3 vel(Index i) const { return {vx[i], vy[i], vz[i]}; }
    DF_HD bool is_fluid(Index i) const { return kind[i] == std::uint8_t(Kind::fluid); }
};
static_assert(std::is_trivially_copyable_v<ParticleView>);

// A particle about to be added (an inlet's new layer).
struct NewParticle {
    Vec3 pos, vel;
    Real rho, mass;
    Kind kind;
    std::int16_t group;
};

// Structure-of-arrays SPH particle storage. `group` is the index of the fluid body or the
// wall a particle was created from; `id` is persistent across reordering and removal.
class ParticleSet {
public:
    std::vector<Real> x, y, z, vx, vy, vz, ax, ay, az, rho, drho, p, mass;
    std::vector<Real> wnx, wny, wnz, wd; // zero for fluid particles
    std::vector<Real> mu; // apparent dynamic viscosity [Pa s]; 0 for artificial viscosity
    // State at t_(n-1), Verlet scheme only: empty after drop_previous_state().
    std::vector<Real> vx_old, vy_old, vz_old, rho_old;
    // SPS stress / rho^2 from the last force evaluation (Laminar+SPS only), 6 per particle
    // (xx, xy, xz, yy, yz, zz); zero for new particles. Empty (no memory) until the solver
    // of a Laminar+SPS case sizes it.
    std::vector<Real> sps_tau;
    std::vector<std::uint8_t> kind;
    std::vector<std::int16_t> group;
    std::vector<ParticleId> id;

    Index size() const { return Index(x.size()); }
    Index count(Kind k) const;

    void add(Vec3 pos, Vec3 vel, Real density, Real m, Kind k, std::int16_t grp);
    void add(const NewParticle& q) { add(q.pos, q.vel, q.rho, q.mass, q.kind, q.group); }
    // Hands out `count` new persistent ids (for particles added elsewhere: a resident phase's)
    // and returns the first.
    ParticleId claim_ids(Index count) {
        const ParticleId first = next_id_;
        next_id_ += ParticleId(count);
        return first;
    }
    // Wall normal (into the fluid) and depth behind the wall surface of boundary particle i.
    void set_wall(Index i, Vec3 normal, Real depth);

    // Applies new order: element i of the result is old element perm[i].
    void permute(const std::vector<Index>& perm);

    // Removes every particle for which keep[i] == 0 (order of the rest is preserved).
    void compact(const std::vector<std::uint8_t>& keep);

    // Frees the Verlet scheme's state at t_(n-1) and stops keeping it (a symplectic run: 32 B
    // per particle less).
    void drop_previous_state();
    bool keeps_previous_state() const { return previous_state_; }

    ParticleView view();
    // Bytes allocated for every array.
    std::size_t bytes() const;
    // Saves or restores every array and the next id (checkpoint/archive.hpp).
    void state(checkpoint::Archive& ar);
    // Changes whenever particles are added, reordered or removed (indices become stale).
    std::uint64_t layout_version() const { return layout_version_; }
    // Says that the arrays were replaced from elsewhere (a resident phase's copy).
    void layout_changed() { ++layout_version_; }

private:
    std::uint64_t layout_version_ = 0;
    bool previous_state_ = true;
    ParticleId next_id_ = 0;
};

} // namespace debrisflow::particles
