#include "debrisflow/exec/parallel.hpp"
#include "debrisflow/sph/mdbc_k.hpp"
#include "debrisflow/sph/sph_solver.hpp"

namespace debrisflow::sph {

void SphSolver::update_boundary_density() {
    auto pv = set_.view();
    const auto gv = grid_.view();
    const Real rho_min = boundary_min_density();
    const Real rho_air = eos_.density(0);
    const bool no_slip = params_.no_slip == "mdbc";
    // The half list's path visits only the boundary particles whose ghost node may see fluid
    // (refresh_mdbc_rows); the others keep their density, and zero ghost velocities. The
    // cells path visits every particle, and MdbcDensity writes every ghost record it visits.
    const bool rows = !params_.gathers();
    if (rows) refresh_mdbc_rows();
    if (no_slip && ghost_velocity_.size() != 4 * std::size_t(pv.n))
        ghost_velocity_.assign(4 * std::size_t(pv.n), Real(0));
    Real* ghost = no_slip ? ghost_velocity_.data() : nullptr;
    std::visit(
        [&](const auto& kernel) {
            using K = std::decay_t<decltype(kernel)>;
            const MdbcDensity<K> mdbc{pv,      gv,         kernel,      params_.h, rho_min,
                                      rho_air, params_.dp, params_.dim, ghost};
            if (!rows) {
                exec::for_each(pv.n, mdbc);
                return;
            }
            const Index* row = mdbc_rows_.data();
            exec::for_each(Index(mdbc_rows_.size()), [=](Index k) { mdbc(row[k]); });
        },
        models_.kernel);
}

// At each list build (and whenever particles are added, removed or reordered): the boundary
// particles with wall geometry whose ghost node x_b + 2 d n has a fluid particle within
// support + skin (the list grid's reach). Until the next build no particle moves more than
// skin / 2, so every other ghost node sees no fluid within the kernel's support, where
// MdbcDensity would keep the particle's density and give it no ghost velocity: leaving them
// out changes no result. Dry walls (most of a long flume before the flow arrives) cost nothing.
void SphSolver::refresh_mdbc_rows() {
    if (mdbc_rows_builds_ == list_builds_ && mdbc_rows_layout_ == set_.layout_version()) return;
    mdbc_rows_builds_ = list_builds_;
    mdbc_rows_layout_ = set_.layout_version();
    const auto pv = set_.view();
    const auto gv = grid_.view();
    std::vector<std::uint8_t> wet(std::size_t(pv.n), 0);
    std::uint8_t* w = wet.data();
    exec::for_each(pv.n, [=](Index b) {
        if (pv.is_fluid(b) || !(pv.wd[b] > 0)) return;
        const Vec3 xg = pv.pos(b) + (2 * pv.wd[b]) * Vec3{pv.wnx[b], pv.wny[b], pv.wnz[b]};
        bool seen = false;
        gv.for_each_class0_neighbor(-1, xg, pv.x, pv.y, pv.z,
                                    [&](Index j, Vec3, Real) { seen = seen || pv.is_fluid(j); });
        w[b] = seen;
    });
    mdbc_rows_.clear();
    for (Index b = 0; b < pv.n; ++b)
        if (wet[std::size_t(b)]) mdbc_rows_.push_back(b);
    // ghost velocities are written for these rows only; the others must read zero
    if (params_.no_slip == "mdbc") ghost_velocity_.assign(4 * std::size_t(pv.n), Real(0));
}

NoSlipWall SphSolver::no_slip_wall() const {
    const bool mirrored =
        params_.no_slip == "mdbc" && ghost_velocity_.size() == 4 * std::size_t(set_.size());
    return {mirrored ? ghost_velocity_.data() : nullptr, Real(0.5) * params_.dp};
}

} // namespace debrisflow::sph
