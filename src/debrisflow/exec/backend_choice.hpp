#pragma once
// The resident phase a backend name selects, shared by the SPH and DEM phases
// (sph/resident_sph_host.cpp, dem/resident_dem_host.cpp): "host_resident" makes the host
// space's loop, "cuda" asks the factory a CUDA build registered (exec/cuda_instantiations.cu).
#include "debrisflow/core/error.hpp"
#include <memory>
#include <string>

namespace debrisflow::exec {

// make_host(): the loop on the host's space; cuda: the CUDA build's factory (null in a build
// without it: an InputError naming `where`).
template <class Phase, class Solver, class MakeHost>
std::unique_ptr<Phase> choose_resident(const std::string& backend, Solver& host,
                                       const std::string& where, const MakeHost& make_host,
                                       std::unique_ptr<Phase> (*cuda)(Solver&,
                                                                      const std::string&)) {
    if (backend == "host_resident") return make_host();
    if (backend == "cuda") {
        if (!cuda)
            throw InputError(where + ": this build has no CUDA backend; configure it with "
                                     "`cmake --preset cuda` (nvcc) and run build-cuda/debrisflow, "
                                     "or use \"host\" or \"host_resident\"");
        return cuda(host, where);
    }
    throw InputError(where + ": unknown backend '" + backend + "'");
}

} // namespace debrisflow::exec
