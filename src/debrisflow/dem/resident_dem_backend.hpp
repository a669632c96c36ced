#pragma once
// Which backend runs the DEM phase's time loop (exec.backend, --backend), as for the SPH phase
// (sph/resident_backend.hpp): "host" is the DemSolver's own loops; "host_resident" the resident
// loop (dem/resident_dem.hpp) in the host's memory, the device's code path run where there is
// no GPU (CI); "cuda" the same loop in a CUDA device's memory.
#include "debrisflow/dem/grain_set.hpp"
#include "debrisflow/flow/exit_faces_k.hpp"
#include "debrisflow/flow/feed_reach_k.hpp"
#include "debrisflow/flow/outlet_box_k.hpp"
#include "debrisflow/time/phase.hpp"
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace debrisflow::coupling {
class SphDemCoupling;
}
namespace debrisflow::sph {
class ResidentPhase;
}
namespace debrisflow::probes {
class GrainReader;
}

namespace debrisflow::dem {

class DemSolver;

// The DEM phase of a resident backend, as the Simulation sees it. The host's DemSolver keeps
// the parameters, the walls, the step and the counters; the grains and their contact slots
// live in the backend's memory and are copied to the host's GrainSet and slots by publish().
class ResidentDemPhase : public time::Phase {
public:
    // Bytes held in the backend's memory (grains, contact slots, grid, scratch).
    virtual std::size_t memory_bytes() const = 0;
    // Times the grains were copied to the host (publish) and from it (reload).
    virtual long copies_to_host() const = 0;
    virtual long copies_from_host() const = 0;
    // The grain contacts of the last evaluation on the walls that record them (a pressure map
    // reads them) to those walls, and nothing else.
    virtual void publish_wall_contacts() = 0;
    // The grain probes' sums, maxima and rows, evaluated where the grains are
    // (dem/resident_grain_reader.hpp).
    virtual probes::GrainReader& grain_reader() = 0;
    // The host's DemSolver changed the grains or their slots (a checkpoint restored): take its
    // state over again.
    virtual void reload() = 0;
    // Grains held now (the host's GrainSet is brought up to date only by publish()).
    virtual Index size() const = 0;
    // Grains that left, removed where they are (index order): their masses and materials, the
    // faces they crossed (the domain exit only) and the mass held before (the same).
    struct Leaving {
        std::vector<int> face;
        std::vector<Real> mass;
        std::vector<std::uint8_t> material;
        Real mass_in_set = 0;
    };
    // Removes the grains whose finite centre left the domain (domain.exit = "remove").
    virtual Leaving remove_outside(const flow::ExitFaces& faces) = 0;
    // Removes the grains whose centre is inside an outlet's box.
    virtual Leaving remove_inside(const flow::OutletBox& box) = 0;
    // The positions and radii of the grains near a feed's region (FeedReach::near), in index
    // order: the few a new grain must keep clear of.
    virtual std::vector<std::pair<Vec3, Real>> grains_near(const flow::FeedReach& region) = 0;
    // Appends grains (a feed's, ids from GrainSet::continuing) after the last, as
    // DemSolver::grains_added: empty slot rows, the search margin and step widened for their
    // sizes, a neighbour rebuild.
    virtual void append(const GrainSet& fresh) = 0;
    // The unresolved SPH-DEM coupling of these grains with the resident `fluid` (of the same
    // backend), as a phase that replaces the host's `coupling` in the time loop and works
    // where the grains and particles are; the host's coupling keeps the drag law and the
    // scalars (coupling/resident_sph_dem.hpp).
    virtual std::unique_ptr<time::Phase> couple_fluid(sph::ResidentPhase& fluid,
                                                      coupling::SphDemCoupling& coupling) = 0;
};

// How `check` and the log name where the DEM phase runs on `backend`.
std::string backend_words(const std::string& backend);

// The resident DEM phase for `backend` ("host_resident" or "cuda") on the host solver's
// grains. Throws InputError (naming `where`) when this build has no such backend.
std::unique_ptr<ResidentDemPhase> make_resident_dem(const std::string& backend, DemSolver& host,
                                                    const std::string& where);

// Set by a build with the CUDA backend (exec/cuda_instantiations.cu).
using ResidentDemFactory = std::unique_ptr<ResidentDemPhase> (*)(DemSolver&,
                                                                 const std::string& where);
void set_cuda_dem_factory(ResidentDemFactory f);

} // namespace debrisflow::dem
