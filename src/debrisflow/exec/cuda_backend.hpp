#pragma once
// The CUDA backend of a build configured with DEBRISFLOW_CUDA (exec/cuda_instantiations.cu).

namespace debrisflow::cuda {

// Makes exec.backend = "cuda" (--backend cuda) create the resident SPH and DEM loops on the
// device.
void register_backend();

} // namespace debrisflow::cuda
