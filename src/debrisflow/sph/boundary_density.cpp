#include "debrisflow/exec/parallel.hpp"
#include "debrisflow/sph/mdbc_k.hpp"
#include "debrisflow/sph/sph_solver.hpp"

namespace debrisflow::sph {

void SphSolver::update_boundary_density() {
    auto pv = set_.view();
    const auto gv = grid_.view();
    const Real rho_min = boundary_min_density();
    Real* ghost = nullptr;
    if (params_.no_slip == "mdbc") {
        ghost_velocity_.resize(4 * std::size_t(pv.n));
        ghost = ghost_velocity_.data();
    }
    std::visit(
        [&](const auto& kernel) {
            using K = std::decay_t<decltype(kernel)>;
            exec::for_each(pv.n,
                           MdbcDensity<K>{pv, gv, kernel, params_.h, rho_min, params_.dim, ghost});
        },
        models_.kernel);
}

NoSlipWall SphSolver::no_slip_wall() const {
    const bool mirrored =
        params_.no_slip == "mdbc" && ghost_velocity_.size() == 4 * std::size_t(set_.size());
    return {mirrored ? ghost_velocity_.data() : nullptr, Real(0.5) * params_.dp};
}

} // namespace debrisflow::sph
