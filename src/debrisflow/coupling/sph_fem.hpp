#pragma once
#include "debrisflow/coupling/coupling.hpp"
#include "debrisflow/coupling/sph_fem_k.hpp"
#include "debrisflow/fem/fem_solver.hpp"
#include "debrisflow/fem/fem_surface.hpp"
#include "debrisflow/particles/particle_set.hpp"
#include "debrisflow/rigid/fluid_side.hpp"
#include <unordered_map>
#include <vector>

namespace debrisflow::checkpoint {
class Archive;
}

namespace debrisflow::coupling {

// The carried particles where a resident backend holds them (sph/resident_fem.hpp): what the
// coupling asks of them. Without one, the coupling works on the host's ParticleSet itself.
class FemParticles {
public:
    virtual ~FemParticles() = default;
    // The carriers (SphFemCoupling::carriers) changed: rows were added or facets reassigned.
    virtual void carriers_changed() = 0;
    // Every carried particle takes its element's motion (FollowElements).
    virtual void move(const std::vector<Vec3>& x, const std::vector<Vec3>& v,
                      const std::vector<Vec3>& facet_normal, Real ahead) = 0;
    // Each carried particle's row and fluid load m a, in index order.
    virtual std::vector<CarriedLoad> loads() = 0;
    // Removes the particles of the rows with dead[row] = 1 (their elements eroded).
    virtual void remove_rows(const std::vector<std::uint8_t>& dead) = 0;
    // After the surface changed: each carried particle's normal (its facet's) and depth[row].
    virtual void resurface(const std::vector<Vec3>& facet_normal,
                           const std::vector<Real>& depth) = 0;
    // Appends carried particles (wall normal and depth, row each) with ids claimed from the
    // host's set; returns the first id (the others follow it).
    virtual ParticleId append(const std::vector<particles::NewParticle>& fresh,
                              const std::vector<rigid::ShellPoint>& walls,
                              const std::vector<std::int32_t>& rows) = 0;
};

// Two-way SPH <-> FEM coupling through boundary particles that move with the elements
// (as DualSPHysics couples Chrono/FEA bodies: DBC particles carried by the structure). Each
// particle sits at fixed natural coordinates xi of its element: x = sum N_a(xi) x_a,
// v = sum N_a(xi) v_a; the fluid force on it, m_k a_k (the SPH pair forces are antisymmetric,
// so this is exactly the reaction of the fluid), returns to the element's nodes with the same
// weights, F_a += N_a(xi) m_k a_k: sum_a N_a = 1 conserves momentum across the interface and
// the virtual work of the load is consistent with the shape functions.
class SphFemCoupling : public Coupling {
public:
    // Samples every solid on the fluid's lattice spacing dp: points inside the solid within
    // `layers` x dp of its surface become boundary particles of density rho (mass rho dp^dim);
    // fluid particles inside a solid are removed. Call before the SPH solver is built.
    SphFemCoupling(fem::FemSolver& fem, particles::ParticleSet& set, Real dp, int layers, Real rho,
                   int dim);

    const char* coupling_name() const override { return "sph-fem"; }
    std::vector<Exchange> exchanges() const override;
    // Registers the fluid load (a load source) and the particles' motion (a surface mover)
    // with the FEM solver.
    void connect();
    // The carried particles live where a resident backend holds them from now on (before
    // the run); the coupling keeps the rows and the id -> row map (which its checkpoint saves).
    void attach(FemParticles* particles);
    // Between steps: eroded elements' particles leave (on the host through `remove`, the SPH
    // solver's keep-mask removal; where the particles are with a resident backend) and the
    // exposed surface gets particles of its own. Returns a log line when something changed.
    template <class Remove> std::string erode(Real t, const Remove& remove) {
        const std::size_t before = particles();
        if (resident_) {
            const auto dead = newly_dead_rows();
            if (!dead.empty()) resident_->remove_rows(dead);
        } else {
            const auto keep = eroded_keep_mask();
            if (!keep.empty()) remove(keep);
        }
        const std::size_t removed = before - particles();
        return erosion_note(t, removed, expose_new_surface());
    }
    // Places the particles from the nodes, `ahead` seconds extrapolated along the node velocity.
    void move_particles(Real ahead);
    // Adds the fluid forces on the particles to the nodes [N].
    void collect_forces(std::vector<Vec3>& f);
    Vec3 last_force() const { return last_force_; } // total fluid force on the solids [N]
    // Particles of eroded elements leave with their element: a keep-mask over the particle set
    // (1 = keep) when some must go, else empty. Apply it between steps
    // (SphSolver::remove_particles), then call expose_new_surface().
    std::vector<std::uint8_t> eroded_keep_mask();
    // After erosion the surface is rebuilt from the live elements: lattice samples of live
    // elements that now lie within `layers` dp of it become boundary particles (appended to the
    // set at their current positions), so the fluid meets what remains; every particle's wall
    // normal and depth follow the new surface. Returns the number of particles added.
    std::size_t expose_new_surface();
    std::size_t particles() const { return row_of_id_.size(); } // live boundary particles
    // Row of the particle with persistent id `id`, or -1 when no element carries it.
    std::int32_t row_of(ParticleId id) const {
        const auto it = row_of_id_.find(id);
        return it == row_of_id_.end() ? -1 : std::int32_t(it->second);
    }
    // Each row's place in its element (index = row).
    const std::vector<FemCarrier>& carriers() const { return carriers_; }

    // Saves or restores what the coupling keeps between steps (coupling/coupling_checkpoint.cpp).
    void state(checkpoint::Archive& ar);

private:
    std::string erosion_note(Real t, std::size_t removed, std::size_t added) const;
    // With a resident backend: when elements eroded since the last call, marks the surface
    // stale, drops the eroded rows' ids from the map and returns dead[row] = 1 for them (empty
    // when no carried particle goes).
    std::vector<std::uint8_t> newly_dead_rows();
    // The outward normal of every facet at the nodes' current positions.
    std::vector<Vec3> facet_normals() const;
    struct Row {
        std::int32_t solid, element;
        std::array<Real, 10> n; // shape-function values at xi
        std::int32_t facet;     // nearest boundary facet (wall normal)
        Vec3 X;                 // reference position
    };
    // Nearest facet of facets_ to a reference position and its distance.
    std::int32_t nearest_facet(Vec3 X, Real& depth) const;
    FemCarrier carrier_of(const Row& r) const;
    // The particle that row r places now, with its wall normal and depth.
    particles::NewParticle new_particle(const Row& r, Real depth, rigid::ShellPoint& wall) const;
    void add_particle(const Row& r, Real depth);
    void refresh_members();

    fem::FemSolver& fem_;
    particles::ParticleSet& set_;
    int dim_;
    Real thickness_, rho_, mass_;
    std::vector<Row> rows_;
    std::vector<FemCarrier> carriers_; // rows_' places, as the per-particle rules read them
    std::vector<Row> hidden_;          // samples deeper than the boundary layer, exposed by erosion
    bool surface_stale_ = false;
    std::vector<fem::SurfaceFacet> facets_;
    std::unordered_map<ParticleId, std::uint32_t> row_of_id_;
    std::vector<Index> members_;
    std::vector<std::uint32_t> member_rows_;
    std::uint64_t layout_seen_ = ~std::uint64_t(0);
    long eroded_seen_ = 0;
    Vec3 last_force_;
    FemParticles* resident_ = nullptr;
};

} // namespace debrisflow::coupling
