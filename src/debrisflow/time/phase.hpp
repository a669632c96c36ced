#pragma once
#include "debrisflow/core/real.hpp"
#include <string>

namespace debrisflow::time {

// A stable time step and the criterion that limited it.
struct DtLimit {
    Real dt;
    std::string limiter;
};

// Wall-clock seconds spent per part of the step, for profiling output.
struct Timings {
    double neighbors = 0, forces = 0, integration = 0, output = 0;
};

// One physics phase attached to the Integrator (SPH today; DEM, rigid bodies and FEM attach
// the same way). Virtual calls happen once per step, never inside a particle loop.
class Phase {
public:
    virtual ~Phase() = default;
    virtual const char* name() const = 0;
    // Rebuilds neighbour structures; `reorder` also sorts particles by cell for locality.
    virtual void update_neighbors(bool reorder) = 0;
    virtual void compute_forces() = 0;
    // Saves the state at t_n and advances it to t_n + dt/2 with the current derivatives.
    virtual void predictor(Real dt) = 0;
    // Completes the step from the saved state with the derivatives at t_n + dt/2.
    virtual void corrector(Real dt) = 0;
    // One Verlet step (Verlet 1967 as in DualSPHysics) with the derivatives at t_n; `euler`
    // replaces the leapfrog over two steps by a forward step (decouples odd and even steps).
    virtual void verlet_step(Real dt, bool euler) = 0;
    virtual DtLimit stable_dt() const = 0;
    // Throws InstabilityError when the state is no longer physical.
    virtual void check_health(Real t) const = 0;
    // What this phase saw recently, appended to an instability raised by any phase (a rigid
    // body's shell particle leaving the domain is caught by the SPH phase; the rigid phase
    // says which body moves fastest and what pushed it). Empty: nothing to add.
    virtual std::string diagnose() const { return {}; }
    virtual void add_timings(Timings& t) const = 0;
    // A phase whose state lives elsewhere (a device) copies it to the host's containers, which
    // observers and checkpoints read; called only when one of them is due.
    virtual void publish() {}
};

} // namespace debrisflow::time
