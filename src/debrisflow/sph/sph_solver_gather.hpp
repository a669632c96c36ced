#pragma once
// SphSolver's template members that hand its pair terms and its gather loop body to a caller:
// included by sph_solver.cpp and by backends that run the loop elsewhere (bench/gpu).
#include "debrisflow/sph/interaction_k.hpp"
#include "debrisflow/sph/sph_solver.hpp"
#include <variant>

namespace debrisflow::sph {

template <class K, class V, class D>
PairTerms<K, V, D> SphSolver::pair_terms(const particles::ParticleView& pv, const K& kernel,
                                         const V& visc, const D& diff, const Real* prho,
                                         const Real* cs, const Real* vol, const Real* tau) const {
    // eta2 = 0.01 h^2 regularises 1 / r^2 (Monaghan 1992)
    return {pv,  kernel, visc, diff,           prho,
            cs,  vol,    tau,  no_slip_wall(), Real(0.01) * params_.h * params_.h,
            eos_};
}

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
            // The half list reads p / rho^2, c and m / rho from arrays; the gather computes
            // them where it loads a particle (no arrays: less memory, as on a device).
            const bool arrays = pairs;
            auto terms = pair_terms(pv, kernel, visc, diff, arrays ? prho_.data() : nullptr,
                                    arrays ? cs_.data() : nullptr, arrays ? vol_.data() : nullptr,
                                    sps ? set_.sps_tau.data() : nullptr);
            if constexpr (std::decay_t<decltype(diff)>::needs_density_gradient) {
                update_density_gradient(pairs);
                terms.grad_rho = grad_rho_.data();
            }
            f(terms);
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
