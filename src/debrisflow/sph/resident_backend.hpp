#pragma once
// Which backend runs the SPH phase's time loop (exec.backend, --backend):
// - "host": the SphSolver's own loops on the host's threads (OpenMP; the default);
// - "host_resident": the resident loop (sph/resident_sph.hpp) in the host's memory, on its
//   threads: the device's code path, run where there is no GPU (CI);
// - "cuda": the resident loop in a CUDA device's memory (a build configured with
//   DEBRISFLOW_CUDA; exec/cuda_space.cuh).
#include "debrisflow/flow/exit_faces_k.hpp"
#include "debrisflow/flow/inlet_buffer_k.hpp"
#include "debrisflow/flow/outlet_box_k.hpp"
#include "debrisflow/time/phase.hpp"
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

namespace debrisflow::coupling {
class SphBodyCoupling;
class SphFemCoupling;
} // namespace debrisflow::coupling
namespace debrisflow::rigid {
class BodySolver;
}
namespace debrisflow::probes {
class FluidReader;
}

namespace debrisflow::sph {

class SphSolver;

// The SPH phase of a resident backend, as the Simulation sees it.
class ResidentPhase : public time::Phase {
public:
    // Bytes held in the backend's memory (particles, grid, scratch).
    virtual std::size_t memory_bytes() const = 0;
    // Times the particles were sorted by cell.
    virtual long sorts() const = 0;
    // Times the particles were copied to the host's set (publish).
    virtual long copies_to_host() const = 0;
    // Particles held now (the host's set is brought up to date only by publish()).
    virtual Index size() const = 0;
    // Removes the boundary particles of wall group `group` (a gate lifting), where they are.
    virtual void remove_group(std::int16_t group) = 0;
    // Removes the fluid particles whose centre left the domain, where they are, and says which
    // left (index order): the faces they crossed, their masses, and the fluid mass held before.
    struct Leaving {
        std::vector<int> face;
        std::vector<Real> mass;
        Real mass_in_set = 0;
    };
    virtual Leaving remove_fluid_outside(const flow::ExitFaces& faces) = 0;
    // Removes the fluid particles inside an outlet's box, where they are; says which left
    // (index order: their masses; no faces, no mass held).
    virtual Leaving remove_fluid_inside(const flow::OutletBox& box) = 0;
    // Prescribes the state of the fluid inside an inlet's buffer, where the particles are.
    virtual void prescribe(const flow::InletBuffer& buffer) = 0;
    // Appends particles (an inlet's new layers) after the last, with ids claimed from the
    // host's set, as ParticleSet::add would.
    virtual void append(const std::vector<particles::NewParticle>& fresh) = 0;
    // Becomes the bodies' fluid side (before the run): their fluid loads reduced and their
    // particles moved, added (rock feeds) and removed (outlets) where the particles are
    // (sph/resident_bodies.hpp); the host's coupling keeps the rows.
    virtual void couple_bodies(rigid::BodySolver& bodies, coupling::SphBodyCoupling& coupling) = 0;
    // Holds the FEM solids' carried boundary particles (before the run): moved from the nodes,
    // their loads compacted, eroded and exposed where the particles are (sph/resident_fem.hpp);
    // the host's coupling keeps the rows and the FEM.
    virtual void couple_fem(coupling::SphFemCoupling& coupling) = 0;
    // The probes' point samples and reductions, evaluated where the particles are.
    virtual const probes::FluidReader& fluid_reader() const = 0;
    // The host's ParticleSet was replaced (a checkpoint restored): take it over again now.
    virtual void reload() = 0;
};

// How `check` and the log name where each phase runs on `backend` (`bodies`: the case has
// rigid bodies; `fem`: FEM solids in the fluid).
std::string backend_words(const std::string& backend, bool bodies, bool fem);

// The resident phase for `backend` ("host_resident" or "cuda") on the host solver's particles.
// Throws InputError (naming `where`) when this build has no such backend.
std::unique_ptr<ResidentPhase> make_resident_sph(const std::string& backend, SphSolver& host,
                                                 const std::string& where);

// Set by a build with the CUDA backend (exec/cuda_instantiations.cu: cuda::register_backend).
// It throws InputError (naming `where`) when the machine has no CUDA device.
using ResidentFactory = std::unique_ptr<ResidentPhase> (*)(SphSolver&, const std::string& where);
void set_cuda_factory(ResidentFactory f);

} // namespace debrisflow::sph
