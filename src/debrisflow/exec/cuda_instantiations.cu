// Compiles the host/device SPH and DEM functors with nvcc and launches them from a CUDA
// kernel, so that every per-pair rule stays device-callable, and the resident SPH and DEM loops
// on the device (exec.backend = "cuda"). No GPU is needed to compile this file.
#include "debrisflow/core/error.hpp"
#include "debrisflow/coupling/resident_sph_dem.hpp"
#include "debrisflow/dem/contact_slots.hpp"
#include "debrisflow/dem/grain_kick_drift_k.hpp"
#include "debrisflow/dem/grain_own_pass_k.hpp"
#include "debrisflow/dem/grain_slot_contact_k.hpp"
#include "debrisflow/dem/grain_slot_pass_k.hpp"
#include "debrisflow/dem/resident_dem.hpp"
#include "debrisflow/dem/slot_candidates_k.hpp"
#include "debrisflow/exec/cuda_backend.hpp"
#include "debrisflow/exec/cuda_space.cuh"
#include "debrisflow/kernels/cubic_spline_k.hpp"
#include "debrisflow/kernels/wendland_c2_k.hpp"
#include "debrisflow/kernels/wendland_c4_k.hpp"
#include "debrisflow/models/density_diffusion_k.hpp"
#include "debrisflow/models/viscosity_k.hpp"
#include "debrisflow/neighbors/cell_keys_k.hpp"
#include "debrisflow/probes/fluid_samples_k.hpp"
#include "debrisflow/sph/density_gradient_k.hpp"
#include "debrisflow/sph/interaction_k.hpp"
#include "debrisflow/sph/resident_sph.hpp"
#include "debrisflow/sph/time_schemes_k.hpp"
#include "debrisflow/sph/viscosity_registry.hpp"

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

// Every viscosity model of the registry (with Fourtakas diffusion), and every diffusion model
// (with artificial viscosity): a model added to sph/viscosity_registry.hpp is compiled for the
// device here without another line.
template <class K, class... V> void instantiate_viscosities(models::Registry<V...>*) {
    (instantiate_interaction<K, V, models::Fourtakas>(), ...);
}

template <class K> void instantiate_kernel() {
    // a probe's point samples, one point per thread (the resident backend's FluidReader)
    launch(0, probes::AtPoints<probes::ShepardSample<K>, probes::PointSample>{});
    launch(0, probes::AtPoints<probes::FilledFraction<K>, Real>{});
    instantiate_viscosities<K>(static_cast<sph::ViscosityRegistry*>(nullptr));
    instantiate_interaction<K, models::ArtificialViscosity, models::NoDiffusion>();
    instantiate_interaction<K, models::ArtificialViscosity, models::MolteniColagrossi>();
    instantiate_interaction<K, models::ArtificialViscosity, models::Antuono>();
    launch(0, sph::RenormalisedDensityGradient<K>{}); // the gradients Antuono's model reads
}

// A per-particle quantity that a loop reduces over (the stable step, the health check),
// evaluated on the device into an array.
template <class F> struct Evaluate {
    F f;
    decltype(f(Index(0)))* out;
    DF_HD void operator()(Index i) const { out[i] = f(i); }
};
template <class F> void launch_evaluate() {
    launch(0, Evaluate<F>{});
}

// A per-grain step that also folds a report (the DEM's kick and drift), each thread into its
// own slot of `out` (a device reduction combines them).
template <class F, class Report> struct Folded {
    F f;
    Report* out;
    DF_HD void operator()(Index i) const { f(i, out[i]); }
};

void instantiate_all() {
    launch(0, Folded<dem::GrainKickDrift, dem::DriftReport>{});
    // the grain-grain contacts in the device's layout (dem.contact_pass = "slots")
    launch(0, dem::GrainSlotForces{});
    launch(0, Folded<dem::GrainSlotGather, dem::SlotReport>{});
    // the per-grain pass in the same layout (walls, bodies, fluid, closing kick) and the
    // loads it leaves per wall and per body (dem/grain_own_pass_k.hpp)
    launch(0, Folded<dem::GrainOwnSlots, dem::SlotReport>{});
    launch(0, Folded<dem::WallSlotLoad, dem::LoadSum>{});
    launch(0, Folded<dem::BodySlotLoad, dem::LoadSum>{});
    // a neighbour rebuild's rows: grain and wall candidates with their carried history
    launch_evaluate<dem::SlotRowFill<dem::GrainCandidates>>();
    launch_evaluate<dem::SlotRowFill<dem::WallCandidatesOf>>();
    // the SPH phase's per-particle steps (sph/time_schemes_k.hpp) and the grid's sort keys
    launch(0, neighbors::CellKeys{});
    launch(0, sph::TaitPressure{});
    launch(0, sph::TaitPressureArrays{});
    launch(0, sph::SymplecticPredictor{});
    launch(0, sph::SymplecticCorrector{});
    launch(0, sph::VerletUpdate{});
    launch_evaluate<sph::SignalSpeed>();
    launch_evaluate<sph::AccelerationNorm>();
    launch_evaluate<sph::ParticleHealthy>();
    // what the SPH probes reduce over (probes/fluid_samples_k.hpp)
    launch_evaluate<probes::FrontCoordinate>();
    launch_evaluate<probes::WallParticleLoad>();
    // the grain-grain contact of one slot as bench/gpu/gpu_dem_contacts launches it
    launch(0, dem::GrainSlotContact{});
    instantiate_kernel<kernels::WendlandC2>();
    instantiate_kernel<kernels::CubicSpline>();
    instantiate_kernel<kernels::WendlandC4>();
}

// Throws InputError (naming `where`) when this machine has no CUDA device.
void require_device(const std::string& where) {
    int count = 0;
    const cudaError_t e = cudaGetDeviceCount(&count);
    if (e != cudaSuccess || count == 0)
        throw InputError(where +
                         ": exec.backend = \"cuda\" needs a CUDA device; this "
                         "machine has none (" +
                         std::string(e != cudaSuccess ? cudaGetErrorString(e) : "0 devices") +
                         "); use \"host\" or \"host_resident\"");
}

void register_backend() {
    sph::set_cuda_factory(
        [](sph::SphSolver& host, const std::string& where) -> std::unique_ptr<sph::ResidentPhase> {
            require_device(where);
            return std::make_unique<sph::ResidentSph<exec::CudaSpace>>(host);
        });
    dem::set_cuda_dem_factory(
        [](dem::DemSolver& host,
           const std::string& where) -> std::unique_ptr<dem::ResidentDemPhase> {
            require_device(where);
            return std::make_unique<dem::ResidentDem<exec::CudaSpace>>(host);
        });
}

} // namespace debrisflow::cuda

// The SPH and DEM phases' time loops resident on the device (sph/resident_sph.hpp,
// dem/resident_dem.hpp), and with them their SPH-DEM coupling (coupling/resident_sph_dem.hpp).
template class debrisflow::sph::ResidentSph<debrisflow::exec::CudaSpace>;
template class debrisflow::dem::ResidentDem<debrisflow::exec::CudaSpace>;
