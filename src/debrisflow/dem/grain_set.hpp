#pragma once
#include "debrisflow/core/real.hpp"
#include "debrisflow/core/vec3_k.hpp"
#include "debrisflow/dem/clump_set.hpp"
#include <cstdint>
#include <type_traits>
#include <vector>

namespace debrisflow::checkpoint {
class Archive;
}

namespace debrisflow::dem {

// Trivially copyable view of a GrainSet: raw pointers only, usable in OpenMP and CUDA loops.
struct GrainView {
    Vec3 *pos, *vel, *spin; // position [m], velocity [m/s], angular velocity [rad/s]
    Vec3 *force, *torque;   // [N], [N m]
    Real *radius, *mass, *inv_mass, *inv_inertia;
    std::uint8_t* material;
    std::uint32_t* id;
    Index n;
};
static_assert(std::is_trivially_copyable_v<GrainView>);

// Structure-of-arrays storage of spherical grains (discs in 2D, which live in the x-z plane and
// spin about y); vector quantities are stored as arrays of 3-vectors (one memory stream each,
// which is what the bandwidth-bound DEM loops need). `id` is persistent across reordering;
// contact history is keyed by it.
class GrainSet {
public:
    std::vector<Vec3> pos, vel, spin, force, torque;
    std::vector<Real> radius, mass, inv_mass, inv_inertia;
    std::vector<std::uint8_t> material;
    std::vector<std::uint32_t> id;
    // Rigid clumps whose members are grains of this set (empty: every grain is free).
    ClumpSet clumps;

    Index size() const { return Index(pos.size()); }
    // Adds a grain of the given mass and moment of inertia (solid sphere 2/5 m r^2, disc
    // 1/2 m r^2); returns its index.
    Index add(Vec3 pos, Vec3 vel, Real r, Real m, Real inertia, std::uint8_t mat);
    void set_spin(Index i, Vec3 w);
    // Applies a new order: element i of the result is old element perm[i].
    void permute(const std::vector<Index>& perm);
    // Keeps the grains listed in `kept` (old indices, in order); the others are removed.
    void select(const std::vector<Index>& kept);
    GrainView view();
    Real total_mass() const;
    // The id the next grain added will get (ids are 0, 1, 2 ... in order of addition).
    std::uint32_t next_id() const { return next_id_; }
    // An empty set whose grains get the ids that `from` would give next (grains added for a
    // resident loop, which holds the set's grains elsewhere).
    static GrainSet continuing(const GrainSet& from) {
        GrainSet s;
        s.next_id_ = from.next_id_;
        return s;
    }
    // Ids below `next` are taken (given by a set made with continuing()).
    void reserve_ids(std::uint32_t next) { next_id_ = next_id_ < next ? next : next_id_; }
    // Saves or restores every array, the clumps and the next id (dem/dem_checkpoint.cpp).
    void state(checkpoint::Archive& ar);

private:
    std::uint32_t next_id_ = 0;
};

} // namespace debrisflow::dem
