// The resident SPH loop on the host's memory and threads (exec.backend = "host_resident"), and
// the choice of backend.
#include "debrisflow/core/error.hpp"
#include "debrisflow/exec/backend_choice.hpp"
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

std::string backend_words(const std::string& backend, bool bodies, bool fem) {
    if (backend == "host") return "host, every phase on the host's threads (OpenMP)";
    return backend + ", the SPH phase resident " +
           (backend == "cuda" ? "on the CUDA device"
                              : "in the host's memory and run on its threads, the device's code "
                                "path") +
           (bodies ? "; rigid bodies: fluid loads reduced and body particles moved there, the "
                     "6-DOF update on the host"
                   : "") +
           (fem ? "; FEM solids: their boundary particles moved from the nodes and their loads "
                  "compacted there, the FEM stepped on the host"
                : "") +
           "; particles are copied to the host only for frames, checkpoints and the end";
}

std::unique_ptr<ResidentPhase> make_resident_sph(const std::string& backend, SphSolver& host,
                                                 const std::string& where) {
    return exec::choose_resident<ResidentPhase>(
        backend, host, where, [&] { return std::make_unique<ResidentSph<exec::HostSpace>>(host); },
        cuda_factory);
}

} // namespace debrisflow::sph
