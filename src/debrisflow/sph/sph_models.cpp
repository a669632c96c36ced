#include "debrisflow/sph/sph_models.hpp"

namespace debrisflow::sph {

SphModels SphModels::from_params(const SphParams& p) {
    SphModels m;
    m.kernel = kernels::make_kernel(p.kernel, p.h, p.dim);
    m.viscosity = p.viscosity_model;
    m.diffusion = DiffusionRegistry::visit_name(p.diffusion, [&]<class D>() -> Diffusion {
        D d;
        if constexpr (!std::is_same_v<D, models::NoDiffusion>) {
            d.delta = p.delta;
            d.h = p.h;
            d.c0 = p.c0;
        }
        if constexpr (std::is_same_v<D, models::Fourtakas>) {
            const Real b = p.c0 * p.c0 * p.rho0 / p.gamma;
            d.rho0 = p.rho0;
            d.inv_gamma = 1 / p.gamma;
            for (int k = 0; k < 3; ++k) d.g_over_b[k] = p.rho0 * p.gravity[k] / b;
        }
        return d;
    });
    return m;
}

} // namespace debrisflow::sph
