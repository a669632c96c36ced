// Compiles the host/device SPH functors with nvcc and launches them from a CUDA kernel, so
// that every per-pair rule stays device-callable. No GPU is needed to compile this file.
#include "debrisflow/kernels/cubic_spline_k.hpp"
#include "debrisflow/kernels/wendland_c2_k.hpp"
#include "debrisflow/models/density_diffusion_k.hpp"
#include "debrisflow/models/viscosity_k.hpp"
#include "debrisflow/sph/interaction_k.hpp"

namespace debrisflow::cuda {

template <class F> __global__ void for_each_kernel(Index n, F f) {
    const Index i = Index(blockIdx.x) * Index(blockDim.x) + Index(threadIdx.x);
    if (i < n) f(i);
}

template <class F> void launch(Index n, const F& f) {
    const int block = 128;
    for_each_kernel<<<(n + block - 1) / block, block>>>(n, f);
}

template <class K, class V, class D> void instantiate_interaction() {
    launch(0, sph::FluidInteraction<K, V, D>{});
}

template <class K> void instantiate_kernel() {
    instantiate_interaction<K, models::ArtificialViscosity, models::NoDiffusion>();
    instantiate_interaction<K, models::ArtificialViscosity, models::MolteniColagrossi>();
    instantiate_interaction<K, models::ArtificialViscosity, models::Fourtakas>();
    instantiate_interaction<K, models::LaminarViscosity, models::NoDiffusion>();
    instantiate_interaction<K, models::LaminarViscosity, models::Fourtakas>();
    instantiate_interaction<K, models::LaminarSpsViscosity, models::Fourtakas>();
    launch(0, sph::SpsStress<K>{});
}

void instantiate_all() {
    instantiate_kernel<kernels::WendlandC2>();
    instantiate_kernel<kernels::CubicSpline>();
}

} // namespace debrisflow::cuda
