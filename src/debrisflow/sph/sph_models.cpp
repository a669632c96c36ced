#include "debrisflow/sph/sph_models.hpp"

namespace debrisflow::sph {

SphModels SphModels::from_params(const SphParams& p) {
    SphModels m;
    m.kernel = kernels::make_kernel(p.kernel, p.h, p.dim);
    m.viscosity = p.viscosity_model;
    const models::DiffusionContext ctx{p.delta, p.h, p.c0, p.rho0, p.gamma, p.gravity};
    m.diffusion = DiffusionRegistry::visit_name(
        p.diffusion, [&]<class D>() -> Diffusion { return D::configure(ctx); });
    return m;
}

bool diffusion_needs_density_gradient(const std::string& name) {
    return DiffusionRegistry::visit_name(name, []<class D>() { return D::needs_density_gradient; });
}

} // namespace debrisflow::sph
