// The resident DEM loop on the host's memory and threads (exec.backend = "host_resident"), and
// the choice of backend for the DEM phase.
#include "debrisflow/core/error.hpp"
#include "debrisflow/coupling/resident_sph_dem.hpp"
#include "debrisflow/dem/resident_dem.hpp"
#include "debrisflow/exec/backend_choice.hpp"
#include "debrisflow/exec/host_space.hpp"

namespace debrisflow::dem {

template class ResidentDem<exec::HostSpace>;

namespace {
ResidentDemFactory cuda_factory = nullptr;
}

void set_cuda_dem_factory(ResidentDemFactory f) {
    cuda_factory = f;
}

std::string backend_words(const std::string& backend) {
    if (backend == "host") return "host, the DEM phase on the host's threads (OpenMP)";
    return backend + ", the DEM phase resident " +
           (backend == "cuda" ? "on the CUDA device"
                              : "in the host's memory and run on its threads, the device's code "
                                "path") +
           "; walls, rigid bodies and FEM solids moved on the host (a body's contact spheres and "
           "a solid's surface go there, their loads come back); grain probes evaluated there "
           "(a pressure map gets its wall's contacts, a run-out each grain's row); grains are "
           "copied to the host only for frames, checkpoints and the end (of grains that leave, "
           "only their masses, materials and faces; of a feed's region, the grains near it)";
}

std::unique_ptr<ResidentDemPhase> make_resident_dem(const std::string& backend, DemSolver& host,
                                                    const std::string& where) {
    return exec::choose_resident<ResidentDemPhase>(
        backend, host, where, [&] { return std::make_unique<ResidentDem<exec::HostSpace>>(host); },
        cuda_factory);
}

} // namespace debrisflow::dem
