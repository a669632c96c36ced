#include "debrisflow/exec/parallel.hpp"
#include "debrisflow/sph/mdbc_k.hpp"
#include "debrisflow/sph/sph_solver.hpp"

namespace debrisflow::sph {

void SphSolver::update_boundary_density() {
    auto pv = set_.view();
    const auto gv = grid_.view();
    const Real rho_min = boundary_min_density();
    std::visit(
        [&](const auto& kernel) {
            using K = std::decay_t<decltype(kernel)>;
            exec::for_each(pv.n, MdbcDensity<K>{pv, gv, kernel, params_.h, rho_min, params_.dim});
        },
        models_.kernel);
}

} // namespace debrisflow::sph
