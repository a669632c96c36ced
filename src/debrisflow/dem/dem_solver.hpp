#pragma once
#include "debrisflow/core/domain.hpp"
#include "debrisflow/dem/clump_step_k.hpp"
#include "debrisflow/dem/contact_slots.hpp"
#include "debrisflow/dem/dem_params.hpp"
#include "debrisflow/dem/fluid_load.hpp"
#include "debrisflow/dem/grain_bounds_k.hpp"
#include "debrisflow/dem/grain_contact_k.hpp"
#include "debrisflow/dem/grain_own_pass_k.hpp"
#include "debrisflow/dem/grain_set.hpp"
#include "debrisflow/dem/grain_slot_contact_k.hpp"
#include "debrisflow/dem/grain_slot_pass_k.hpp"
#include "debrisflow/dem/materials.hpp"
#include "debrisflow/dem/obstacles.hpp"
#include "debrisflow/dem/wall_bins.hpp"
#include "debrisflow/dem/wall_set.hpp"
#include "debrisflow/neighbors/cell_grid.hpp"
#include "debrisflow/time/phase.hpp"
#include <algorithm>
#include <vector>

namespace debrisflow::dem {

// Discrete element phase: spherical grains (discs in 2D) with contact laws chosen per
// material pair, exact geometric walls, and velocity-Verlet stepping (kick, drift, forces,
// kick) at its own stable step. When sub-cycling inside an SPH step, advance(dt) takes as
// many DEM steps as dt needs; otherwise the DEM step limits the Integrator's dt.
class DemSolver : public time::Phase {
public:
    DemSolver(const DemParams& params, GrainSet& grains, WallSet& walls,
              std::vector<Material> materials, const std::vector<PairOverride>& overrides,
              const Domain& domain);

    const char* name() const override { return "dem"; }
    void update_neighbors(bool reorder) override;
    void compute_forces() override;
    void predictor(Real) override {}
    void corrector(Real dt) override { advance(dt); }
    void verlet_step(Real dt, bool) override { advance(dt); }
    time::DtLimit stable_dt() const override;
    void check_health(Real t) const override;
    void add_timings(time::Timings& t) const override;

    // Advances by dt (in sub-steps of at most the DEM step when sub-cycling).
    void advance(Real dt);
    // One velocity-Verlet step of size h.
    void step(Real h);
    // The automatic step (safety x shortest contact time, <= 0.2 Rayleigh time) and its reason.
    time::DtLimit automatic_dt() const { return auto_dt_; }
    // The largest step accepted from the user (0.2 x shortest contact time, 0.2 Rayleigh time).
    time::DtLimit stability_dt() const { return stability_dt_; }
    Real dt() const { return dt_; }
    // Rebuilds neighbour lists now (reordering grains by cell when params.reorder), keeping
    // the contact history; normally triggered by the accumulated drift.
    void rebuild_now() { rebuild(); }
    // Removes a wall (a gate opening): its contacts end at the next step.
    void remove_wall(int wall);
    // The clump grain i belongs to (-1: a free grain), and where the grain of a given id is
    // now (valid while the case has clumps).
    std::int32_t clump_of(Index i) const {
        return clump_of_id_.empty() ? -1 : clump_of_id_[grains_.id[std::size_t(i)]];
    }
    Index index_of_id(std::uint32_t id) const { return index_of_id_[id]; }
    // Each grain id's clump (< 0: free), empty without clumps.
    const std::vector<std::int32_t>& clump_of_ids() const { return clump_of_id_; }
    // Clears keep[i] for every member of a clump that has a member with keep[i] == 0: a clump
    // leaves whole. Call before counting what remove_grains will take.
    void expand_to_clumps(std::vector<std::uint8_t>& keep) const;
    // face[i] (the domain face grain i crossed, or -1) for the members of a clump that crossed
    // one: its members still inside count at the furthest-numbered face a member crossed.
    void spread_clump_faces(std::vector<int>& face) const;
    // Removes the grains with keep[i] == 0 (an outlet), with their whole clumps; contact
    // history of the rest is kept.
    void remove_grains(std::vector<std::uint8_t> keep);
    // True when a step left a grain outside the domain or with a non-finite state (then
    // check_health stops the run unless such grains are removed first).
    bool may_have_left() const { return bad_; }
    // Call after grains were appended to the GrainSet (a feed): they join the contact search.
    void grains_added(Index old_count);
    // Lowers the automatic step so that it also holds for the grains in `prototypes` (sizes a
    // feed will release later).
    void include_sizes(const GrainSet& prototypes);
    // Grains also collide with the spheres of rigid bodies in `o` (null: none).
    // The automatic step then covers their mass and inertia too.
    void attach_obstacles(ObstacleSet* o) {
        obstacles_ = o;
        if (o && !o->spheres.empty()) include_bodies();
    }
    // Grains also feel the fluid loads in `f` (null: none); the DEM keeps its arrays sized and
    // ordered with the grains and limits its sub-step to 0.5 m / beta (explicit drag).
    void attach_fluid(FluidLoad* f) {
        fluid_ = f;
        if (f) f->resize(std::size_t(grains_.size()));
    }
    // Changes gravity from the next step on (a tilting table; the step is not recomputed).
    void set_gravity(Vec3 g) { params_.gravity = g; }
    // Sets every grain's velocity and spin to zero (end of settling).
    void stop_grains();
    // Saves or restores grains, contact histories, walls and the neighbour search's state
    // (dem/dem_checkpoint.cpp).
    void state(checkpoint::Archive& ar);

    // Contacts in the last force evaluation and the mean contact force magnitude [N].
    long contacts() const { return contacts_; }
    Real mean_contact_force() const { return contacts_ > 0 ? sum_contact_force_ / contacts_ : 0; }
    // PFC's equilibrium ratio: mean unbalanced force / mean contact force (infinite while
    // there are fewer contacts than half the grains).
    // The ratio needs the contact forces' magnitudes (a square root per contact), which a
    // force evaluation sums only while measuring: settling turns it on; a caller that wants
    // the ratio after a run turns it on before.
    Real unbalanced_ratio() const;
    void measure_contact_force(bool on) { measure_contact_force_ = on; }
    bool measuring_contact_force() const { return measure_contact_force_; }
    long list_builds() const { return builds_; }

    // What the grain-grain contact loop reads, for a backend that evaluates it elsewhere
    // (bench/gpu) or a check of it (GrainSlotContact evaluates one slot as the loop does).
    GrainContactInputs grain_contact_inputs();

    GrainSet& grains() { return grains_; }
    const GrainSet& grains() const { return grains_; }
    WallSet& walls() { return walls_; }
    const WallSet& walls() const { return walls_; }
    const std::vector<Material>& materials() const { return materials_; }
    const DemParams& params() const { return params_; }
    const Domain& domain() const { return domain_; }
    // A grain's contact load on a wall that keeps them (a pressure map reads them).
    struct RecordedLoad {
        Index grain;
        std::size_t wall;
        ContactLoad load;
    };

private:
    // The resident loop (dem/resident_dem.hpp) steps this solver's state in its own memory:
    // it keeps the parameters, walls, step and counters here and copies grains and slots.
    template <class> friend class ResidentDem;
    // Below this many grains the loops run on one thread (OpenMP start-up would dominate).
    static constexpr Index parallel_min = 4096;
    // Largest step accepted from the user: a fifth of the shortest contact time (about 0.6 / w,
    // inside the 2 / w stability bound of velocity Verlet with room for several contacts).
    static constexpr Real stability_fraction = 0.2;
    void rebuild();
    // The active wall primitives and their boxes at the last rebuild (WallCandidatesOf).
    std::vector<Index> active_prims_;
    std::vector<PrimitiveBounds> active_bounds_;
    WallBins wall_bins_; // of the active primitives, at each rebuild
    void configure_grid();
    // The grid's box around the grains' box b: one search radius beyond it, the domain's
    // length in periodic or empty directions (into grid_lo_, grid_hi_); and its cell edge.
    void set_grid_box(Bounds b);
    Real grid_cell() const { return 2 * max_radius_ + search_margin(); }
    // Copies positions, velocities, spins, radii, masses and materials into hot_.
    void refresh_hot();
    void kick_drift(Real h);
    // One force evaluation (and the closing half kick when half_kick > 0): the host's pass
    // (own_ranges) or the device's layout (slot_contacts, then own_slots).
    void forces(Real half_kick, bool collect_obstacles = false);
    // What the per-grain pass reads (GrainOwnPass), as the state stands.
    GrainOwnInputs own_inputs(Real half_kick);
    struct ThreadReport {
        long touching = 0;
        Real force_sum = 0;
    };
    // The host's pass: grain-grain contacts and the per-grain pass on contiguous thread ranges;
    // adds the walls' and bodies' loads to wall_sum_ and body_sum_ (dem_forces.cpp).
    ThreadReport own_ranges(Real half_kick, bool measure);
    // The per-grain pass in the device's layout after slot_contacts filled acc_: reactions kept
    // per wall and obstacle slot, then summed per wall and per body (dem_slot_pass.cpp).
    SlotReport own_slots(Real half_kick, bool measure);
    std::vector<WallState> wall_states_;
    // The walls' states as the per-grain pass reads them, refreshed from the WallSet.
    const std::vector<WallState>& refresh_wall_states();
    // Moves the walls by a step h and adds the force of the last evaluation, held over the
    // step, to each wall's impulse.
    void advance_walls(Real h);
    std::vector<Real> wall_out_, obstacle_out_;
    std::vector<std::uint8_t> wall_touching_, obstacle_touching_;
    // Candidate grain-obstacle pairs within reach (rebuilt when either side moved).
    void build_obstacle_slots();
    // The cell grid of the obstacle spheres' box, cells of one reach (configured, not built).
    void configure_obstacle_grid(neighbors::CellGrid& grid) const;
    neighbors::CellGrid obstacle_grid_;
    // Each wall's contact material (-1: the grain's own), for the stable step.
    std::vector<int> wall_materials() const;
    // Lowers the automatic step for the rigid bodies' contact spheres (their mass and inertia);
    // run when their number changes.
    void include_bodies();
    std::size_t obstacle_spheres_timed_ = 0;
    // Whether grain i is outside the (non-periodic) domain or not finite.
    bool escaped(Index i) const;
    // Clumps (grains_.clumps): which clump each grain id belongs to (-1: a free grain) and
    // where each id is now; rebuilt whenever grains are reordered, removed or added.
    void map_clumps();
    // The first half kick and the drift of every clump, and its members placed and moved
    // with it (velocity and spin predicted to the end of the step, as the grains'). Returns
    // the largest member speed squared; flags a member outside the domain in bad_.
    Real clump_kick_drift(Real h);
    // Sums the members' forces and torques (and gravity) on each clump, gives the clump its
    // closing half kick (half > 0) and moves the members' velocities and spins with it.
    void clump_forces(Real half);
    // The clumps' arrays as the clump functors read them (dem/clump_step_k.hpp).
    ClumpView clump_view();
    std::vector<std::int32_t> clump_of_id_;
    std::vector<Index> index_of_id_;

    DemParams params_;
    GrainSet& grains_;
    WallSet& walls_;
    std::vector<Material> materials_;
    std::vector<PairParams> table_;
    Domain domain_;
    neighbors::CellGrid grid_;
    Vec3 grid_lo_{}, grid_hi_{}; // the grid's box at the last rebuild
    ContactSlots grain_slots_, wall_slots_, obstacle_slots_;
    ObstacleSet* obstacles_ = nullptr;
    FluidLoad* fluid_ = nullptr;
    // Largest step the explicit fluid drag allows (infinite without a fluid).
    Real drag_dt() const;
    std::uint64_t obstacles_seen_ = ~std::uint64_t(0);
    std::uint64_t walls_seen_ = ~std::uint64_t(0); // WallSet::layout() of the last rebuild
    long obstacle_builds_seen_ = -1;
    // Grain-grain loop: each thread's contiguous range of grains (ranges_[t], ranges_[t+1]),
    // balanced on contact slots at each rebuild (balance_threads); per grain the sum of its
    // contact forces and torques (acc_, 6 reals); reactions on grains of another thread's
    // range set aside per thread (spills_).
    struct Spill {
        Index j;
        Vec3 force, torque;
    };
    void balance_threads(int threads);
    std::vector<Index> ranges_;
    long ranges_balanced_ = -1;
    std::vector<Real> acc_;
    std::vector<std::vector<Spill>> spills_;
    // dem.contact_pass = "slots" (the device's layout, dem_slot_pass.cpp): fills acc_ from one
    // evaluation per candidate slot (slot_out_, 9 reals; slot_touching_) gathered per grain
    // through the reverse index (the slots naming each grain as partner, rebuilt with the
    // list); returns the touching contacts and their summed |F| (with `measure`).
    SlotReport slot_contacts(Real h_contact, bool measure);
    // What the contact functors read, as the grain state stands (hot_ current), with spring
    // increment h.
    GrainContactInputs contact_inputs(Real h);
    std::vector<Real> slot_out_;
    std::vector<std::uint8_t> slot_touching_;
    std::vector<Index> reverse_start_, reverse_;
    long reverse_builds_ = -1;
    // What each thread of the per-grain pass sums, kept between steps (no allocation in a
    // step once the sizes are reached): wall and body loads (6 reals each), the contact loads
    // a pressure map reads, touching contacts and the summed |F| for the settling ratio.
    struct ThreadSums {
        std::vector<Real> wall, body;
        std::vector<RecordedLoad> loads;
        long touching = 0;
        Real force_sum = 0;
    };
    std::vector<ThreadSums> thread_sums_;
    std::vector<Real> wall_sum_, body_sum_;
    // Interleaved copy of the state the contact loop reads (one 96-byte record per grain
    // instead of twelve arrays), written by the drift; the GrainSet stays the master copy.
    std::vector<GrainState> hot_;
    // skin_: the neighbour lists' margin for motion between rebuilds; reach_: the farthest an
    // adhesive law acts beyond touch (largest_reach), added to the search radius.
    Real max_radius_ = 0, skin_ = 0, reach_ = 0, drift_ = 0, dt_ = 0;
    void size_search_margin();
    Real search_margin() const { return skin_ + reach_; }
    PairTable pair_table() const { return {table_.data(), int(materials_.size()), reach_ > 0}; }
    Real current_h_ = 0; // size of the step being taken (tangential spring increment)
    time::DtLimit auto_dt_{0, ""}, stability_dt_{0, ""};
    bool built_ = false, bad_ = false;
    bool evaluated_ = false; // the last step's closing force evaluation is still current
    long contacts_ = 0, builds_ = 0;
    Real sum_contact_force_ = 0;
    bool measure_contact_force_ = false;
    double t_neighbors_ = 0, t_forces_ = 0, t_integration_ = 0;
};

} // namespace debrisflow::dem
