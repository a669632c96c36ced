#pragma once
#include "debrisflow/kernels/kernel.hpp"
#include "debrisflow/models/density_diffusion_k.hpp"
#include "debrisflow/sph/sph_params.hpp"

namespace debrisflow::sph {

// Model families of the WCSPH solver, each selectable by name in the case file (viscosity:
// sph/viscosity_registry.hpp).
using DiffusionRegistry = models::Registry<models::NoDiffusion, models::MolteniColagrossi,
                                           models::Fourtakas, models::Antuono>;
using Diffusion = DiffusionRegistry::Variant;

// The concrete models for a parameter set (names are validated when the case is read).
struct SphModels {
    kernels::Kernel kernel;
    Viscosity viscosity;
    Diffusion diffusion;

    static SphModels from_params(const SphParams& p);
};

// Whether the diffusion model of that name reads renormalised density gradients (one more pass
// over the pairs and 3 reals per particle; the memory estimate counts them).
bool diffusion_needs_density_gradient(const std::string& name);

} // namespace debrisflow::sph
