// The resident SPH loop on the host's memory and threads (exec.backend = "host_resident"), and
// the choice of backend.
#include "debrisflow/core/error.hpp"
#include "debrisflow/exec/host_space.hpp"
#include "debrisflow/sph/resident_backend.hpp"
#include "debrisflow/sph/resident_sph.hpp"

namespace debrisflow::sph {

template class ResidentSph<exec::HostSpace>;

namespace {
ResidentFactory cuda_factory = nullptr;
}

void set_cuda_factory(ResidentFactory f) {
    cuda_factory = f;
}

std::string backend_words(const std::string& backend, bool bodies) {
    if (backend == "host") return "host, every phase on the host's threads (OpenMP)";
    return backend + ", the SPH phase resident " +
           (backend == "cuda" ? "on the CUDA device"
                              : "in the host's memory and run on its threads, the device's code "
                                "path") +
           (bodies ? "; rigid bodies: fluid loads reduced and body particles moved there, the "
                     "6-DOF update on the host"
                   : "") +
           "; particles are copied to the host only for frames, checkpoints and the end";
}

std::unique_ptr<ResidentPhase> make_resident_sph(const std::string& backend, SphSolver& host,
                                                 const std::string& where) {
    if (backend == "host_resident") return std::make_unique<ResidentSph<exec::HostSpace>>(host);
    if (backend == "cuda") {
        if (!cuda_factory)
            throw InputError(where + ": this build has no CUDA backend; configure it with "
                                     "`cmake --preset cuda` (nvcc) and run build-cuda/debrisflow, "
                                     "or use \"host\" or \"host_resident\"");
        return cuda_factory(host, where);
    }
    throw InputError(where + ": unknown backend '" + backend + "'");
}

} // namespace debrisflow::sph
