#pragma once
// SphSolver's template members that hand its pair terms and its gather loop body to a caller:
// included by sph_solver.cpp and by backends that run the loop elsewhere (bench/gpu).
#include "debrisflow/sph/interaction_k.hpp"
#include "debrisflow/sph/sph_solver.hpp"
#include <variant>

namespace debrisflow::sph {

template <class F> void SphSolver::with_pair_terms(F&& f, bool pairs) {
    if (params_.boundary == "mdbc") update_boundary_density();
    update_pressure(pairs);
    update_viscosity(pairs);
    const bool sps = std::holds_alternative<models::LaminarSpsViscosity>(models_.viscosity);
    if (sps && set_.sps_tau.size() != 6 * std::size_t(set_.size()))
        set_.sps_tau.assign(6 * std::size_t(set_.size()), Real(0)); // first evaluation
    auto pv = set_.view();
    std::visit(
        [&](const auto& kernel, const auto& visc, const auto& diff) {
            using K = std::decay_t<decltype(kernel)>;
            using V = std::decay_t<decltype(visc)>;
            using D = std::decay_t<decltype(diff)>;
            // The half list reads p / rho^2, c and m / rho from arrays; the gather computes
            // them where it loads a particle (no arrays: less memory, as on a device).
            const bool arrays = pairs;
            f(PairTerms<K, V, D>{pv, kernel, visc, diff, arrays ? prho_.data() : nullptr,
                                 arrays ? cs_.data() : nullptr, arrays ? vol_.data() : nullptr,
                                 sps ? set_.sps_tau.data() : nullptr, no_slip_wall(),
                                 Real(0.01) * params_.h * params_.h, eos_});
        },
        models_.kernel, models_.viscosity, models_.diffusion);
}

template <class F> void SphSolver::with_gather(F&& f) {
    const auto gv = grid_.view();
    const SpsConstants sps = sps_constants();
    const bool gradient = std::holds_alternative<models::LaminarSpsViscosity>(models_.viscosity);
    tau_next_.assign(gradient ? 6 * std::size_t(set_.size()) : 0, Real(0));
    with_pair_terms(
        [&](const auto& terms) {
            f(make_gather(terms, gv, params_.gravity, sps.smag, sps.blin, tau_next_.data()));
        },
        false);
    if (gradient) set_.sps_tau.swap(tau_next_);
}

} // namespace debrisflow::sph
