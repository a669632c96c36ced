#include "debrisflow/sph/sph_solver.hpp"
#include "debrisflow/core/error.hpp"
#include "debrisflow/core/stopwatch.hpp"
#include "debrisflow/exec/parallel.hpp"
#include "debrisflow/sph/apparent_viscosity_k.hpp"
#include "debrisflow/sph/density_gradient_k.hpp"
#include "debrisflow/sph/interaction_k.hpp"
#include "debrisflow/sph/sph_solver_gather.hpp"
#include "debrisflow/sph/time_schemes_k.hpp"
#include <cmath>
#include <fmt/format.h>
#include <numeric>

namespace debrisflow::sph {

using particles::Kind;

namespace {
// Particle i's data for the velocity-gradient pair loops, loaded once per row.
struct GradientSide {
    Vec3 x, v;
    Real vol; // m / rho
    bool fluid;
    static GradientSide of(const particles::ParticleView& pv, const Real* vol, Index i) {
        return {pv.pos(i), pv.vel(i), vol[i], pv.is_fluid(i)};
    }
};
// Particle i's data for the density-gradient pair loop.
struct DensitySide {
    Vec3 x;
    Real rho, vol;
    bool fluid;
    static DensitySide of(const particles::ParticleView& pv, const Real* vol, Index i) {
        return {pv.pos(i), pv.rho[i], vol[i], pv.is_fluid(i)};
    }
};
} // namespace

SphSolver::SphSolver(const SphParams& params, particles::ParticleSet& set, const Domain& domain)
    : params_(params), set_(set), domain_(domain), eos_(params.rho0, params.c0, params.gamma),
      models_(SphModels::from_params(params)) {
    support_ = std::visit([](const auto& k) { return k.support(); }, models_.kernel);
    // The pair list holds pairs up to support + skin and is rebuilt once a particle has moved
    // skin/2; 10 % of the support keeps the list ~1.3x the true pairs in 3D.
    skin_ = Real(0.1) * support_;
    // The gather loop reads a grid rebuilt every step: cells of the support, no skin.
    const Real cell = params.gathers() ? support_ : support_ + skin_;
    grid_.configure(domain.lo, domain.hi, cell, params.dim, domain.periodic);
}

Real SphSolver::max_displacement() const {
    const auto& s = set_;
    const auto g = grid_.view();
    const Real *xr = xref_.data(), *yr = yref_.data(), *zr = zref_.data();
    auto pv = const_cast<particles::ParticleSet&>(s).view();
    return exec::max_of(pv.n, [=](Index i) {
        const Vec3 d = g.separation(pv.pos(i), {xr[i], yr[i], zr[i]});
        return dot(d, d);
    });
}

void SphSolver::build_grid() {
    // The gather loop's grid lists each cell's fluid before its walls (GridView::classes), so
    // that a wall particle's row visits only fluid partners: boundary-boundary pairs add nothing.
    const std::uint8_t* cls = params_.gathers() ? set_.kind.data() : nullptr;
    grid_.build(set_.x.data(), set_.y.data(), set_.z.data(), set_.size(), 1, cls);
}

void SphSolver::update_neighbors(bool allow_reorder) {
    ScopedTimer timer(t_neighbors_);
    build_grid();
    if (params_.gathers()) {
        // The gather reads the grid built above, every step. As a device does, it sorts the
        // particles by cell whenever the step allows, so it keeps no reference positions.
        if (allow_reorder && params_.reorder_every > 0 && !grid_.in_order()) {
            set_.permute(grid_.order());
            build_grid();
            ++list_builds_;
        }
        return;
    }
    const bool stale = !list_valid_ || xref_.size() != std::size_t(set_.size()) ||
                       4 * max_displacement() > skin_ * skin_;
    if (!stale) return;
    if (allow_reorder && params_.reorder_every > 0) {
        set_.permute(grid_.order());
        build_grid();
    }
    list_.build(grid_.view(), set_.view());
    xref_ = set_.x;
    yref_ = set_.y;
    zref_ = set_.z;
    list_valid_ = true;
    ++list_builds_;
}

SphSolver::SpsConstants SphSolver::sps_constants() const {
    const auto* v = std::get_if<models::LaminarSpsViscosity>(&models_.viscosity);
    if (!v) return {};
    const Real dp2 = params_.dp * params_.dp;
    return {v->smagorinsky * v->smagorinsky * dp2, Real(2) / 3 * v->blin * dp2};
}

void SphSolver::update_pressure(bool arrays) {
    auto pv = set_.view();
    if (!arrays) { // the gather computes p / rho^2, c and m / rho where it needs them
        for (auto* v : {&prho_, &cs_, &vol_}) std::vector<Real>().swap(*v);
        exec::for_each(pv.n, TaitPressure{pv, eos_});
        return;
    }
    prho_.resize(std::size_t(pv.n));
    cs_.resize(std::size_t(pv.n));
    vol_.resize(std::size_t(pv.n));
    exec::for_each(pv.n, TaitPressureArrays{pv, eos_, prho_.data(), cs_.data(), vol_.data()});
}

void SphSolver::update_viscosity(bool pairs) {
    auto pv = set_.view();
    const auto gv = grid_.view();
    const NoSlipWall wall = no_slip_wall();
    std::visit(
        [&](const auto& kernel, const auto& visc) {
            using K = std::decay_t<decltype(kernel)>;
            using V = std::decay_t<decltype(visc)>;
            if constexpr (V::needs_apparent_viscosity) {
                if (!pairs) {
                    exec::for_each(pv.n, ApparentViscosity<K, V>{pv, gv, kernel, visc, wall});
                    return;
                }
                // Half pair list: each pair adds vol_j (v_j - v_i) (x) grad W_ij to i and the
                // mirror term vol_i (v_i - v_j) (x) grad W_ji = vol_i (v_j - v_i) (x) grad W_ij
                // to j (fluid particles only; wall partners with their no-slip velocity).
                const Real support2 = support_ * support_;
                const Real* vol = vol_.data(); // m / rho, from update_pressure()
                exec::for_each_pair_w<6>(
                    list_, pv.n, buffers_, [=](Index i) { return GradientSide::of(pv, vol, i); },
                    [=](const GradientSide& a, Index i, Index j, Real* di, Real* dj) {
                        const bool fj = pv.is_fluid(j);
                        if (!a.fluid && !fj) return;
                        const Vec3 xj = pv.pos(j);
                        const Vec3 r = gv.separation(a.x, xj);
                        const Real r2 = dot(r, r);
                        if (r2 >= support2) return;
                        const Vec3 gw = kernel.grad_over_r(std::sqrt(r2)) * r;
                        if (a.fluid)
                            add_symmetric_gradient(
                                di, vol[j], gradient_velocity_difference(pv, wall, j, a.x, a.v),
                                gw);
                        if (fj)
                            add_symmetric_gradient(
                                dj, a.vol,
                                -1 * gradient_velocity_difference(pv, wall, i, xj, pv.vel(j)), gw);
                    },
                    [=](Index i, const Real* d) {
                        pv.mu[i] = pv.is_fluid(i)
                                       ? visc.apparent_viscosity(strain_rate_of(d), pv.p[i])
                                       : Real(0);
                    });
            } else {
                exec::for_each(pv.n, FluidViscosity{pv, params_.rho0 * visc.kinematic_viscosity()});
            }
        },
        models_.kernel, models_.viscosity);
}

void SphSolver::update_density_gradient(bool pairs) {
    grad_rho_.resize(3 * std::size_t(set_.size()));
    if (!pairs) {
        std::visit(
            [&](const auto& kernel) {
                using K = std::decay_t<decltype(kernel)>;
                exec::for_each(set_.size(),
                               RenormalisedDensityGradient<K>{set_.view(), grid_.view(), kernel,
                                                              grad_rho_.data(), params_.dim});
            },
            models_.kernel);
        return;
    }
    // Half pair list: fluid pair (i, j) adds (rho_j - rho_i) V_j f r and -V_j f r (x) r to i,
    // and with r -> -r, rho_j - rho_i -> rho_i - rho_j the same products with V_i to j.
    std::visit(
        [&](const auto& kernel) {
            if (params_.dim == 2)
                density_gradient_over_pairs<2>(kernel);
            else
                density_gradient_over_pairs<3>(kernel);
        },
        models_.kernel);
}

template <int Dim, class K> void SphSolver::density_gradient_over_pairs(const K& kernel) {
    auto pv = set_.view();
    const auto gv = grid_.view();
    const Real support2 = support_ * support_;
    const Real* vol = vol_.data(); // m / rho, from update_pressure()
    Real* out = grad_rho_.data();
    exec::for_each_pair_w<density_gradient_sums<Dim>>(
        list_, pv.n, buffers_, [=](Index i) { return DensitySide::of(pv, vol, i); },
        [=](const DensitySide& a, Index, Index j, Real* di, Real* dj) {
            if (!a.fluid || !pv.is_fluid(j)) return;
            const Vec3 r = gv.separation(a.x, pv.pos(j));
            const Real r2 = dot(r, r);
            if (r2 >= support2) return;
            const Real f = kernel.grad_over_r(std::sqrt(r2));
            const Real drho = pv.rho[j] - a.rho;
            add_density_gradient_pair<Dim>(di, drho, vol[j] * f, r);
            add_density_gradient_pair<Dim>(dj, drho, a.vol * f, r);
        },
        [=](Index i, const Real* acc) {
            const Vec3 g = pv.is_fluid(i) ? renormalised_gradient<Dim>(acc) : Vec3{};
            out[3 * i] = g.x;
            out[3 * i + 1] = g.y;
            out[3 * i + 2] = g.z;
        });
}

Real SphSolver::max_kinematic_viscosity() const {
    const bool apparent = std::visit(
        [](const auto& v) { return std::decay_t<decltype(v)>::needs_apparent_viscosity; },
        models_.viscosity);
    if (!apparent)
        return std::visit([](const auto& v) { return v.kinematic_viscosity(); }, models_.viscosity);
    auto pv = const_cast<particles::ParticleSet&>(set_).view();
    return exec::max_of(pv.n, FluidKinematicViscosity{pv});
}

void SphSolver::compute_forces() {
    if (params_.gathers()) {
        compute_forces_gather();
        return;
    }
    ScopedTimer timer(t_forces_);
    auto pv = set_.view();
    const auto gv = grid_.view();
    const Real support2 = support_ * support_;
    const Vec3 gravity = params_.gravity;
    const SpsConstants sps = sps_constants();
    with_pair_terms(
        [&](const auto& terms) {
            using Terms = std::decay_t<decltype(terms)>;
            using Side = typename Terms::Side;
            // a (3), drho, and for Laminar+SPS the symmetric velocity gradient (6)
            constexpr bool gradient = Terms::viscosity_type::needs_velocity_gradient;
            constexpr int W = gradient ? 10 : 4;
            Real* tau = set_.sps_tau.data(); // sized by with_pair_terms
            exec::for_each_pair_w<W>(
                list_, pv.n, buffers_, [=](Index i) { return terms.side(i); },
                [=](const Side& a, Index i, Index j, Real* acc_i, Real* out_j) {
                    const Side b = terms.side(j);
                    const Vec3 r = gv.separation(a.x, b.x);
                    const Real r2 = dot(r, r);
                    if (r2 >= support2) return;
                    const auto t = terms(a, i, b, j, r, r2);
                    acc_i[0] += b.m * t.g.x;
                    acc_i[1] += b.m * t.g.y;
                    acc_i[2] += b.m * t.g.z;
                    acc_i[3] += b.m * t.cont + t.d.i;
                    out_j[0] -= a.m * t.g.x;
                    out_j[1] -= a.m * t.g.y;
                    out_j[2] -= a.m * t.g.z;
                    out_j[3] += a.m * t.cont + t.d.j;
                    if constexpr (gradient) {
                        // i gains vol_j (v_j - v_i) (x) grad W_ij, j the mirror term
                        // vol_i (v_j - v_i) (x) grad W_ij (fluid particles only)
                        const Vec3 dv = b.v - a.v;
                        if (a.fluid) add_symmetric_gradient(acc_i + 4, b.vol, dv, t.grad_w);
                        if (b.fluid) add_symmetric_gradient(out_j + 4, a.vol, dv, t.grad_w);
                    }
                },
                // Runs after every pair is summed: the stress read above can be replaced.
                [=](Index i, const Real* total) {
                    const bool fluid = pv.is_fluid(i);
                    pv.ax[i] = total[0] + (fluid ? gravity.x : 0);
                    pv.ay[i] = total[1] + (fluid ? gravity.y : 0);
                    pv.az[i] = total[2] + (fluid ? gravity.z : 0);
                    pv.drho[i] = total[3];
                    if constexpr (gradient) {
                        Real* t = tau + 6 * i;
                        for (int k = 0; k < 6; ++k) t[k] = 0;
                        if (fluid) sps_tau(total + 4, sps.smag, sps.blin, 1 / pv.rho[i], t);
                    }
                });
        },
        true);
}

void SphSolver::compute_forces_gather() {
    ScopedTimer timer(t_forces_);
    with_gather([&](const auto& body) { exec::for_each(set_.size(), body); });
}

Real SphSolver::boundary_min_density() const {
    return eos_.density(params_.boundary_min_pressure);
}

StepStart SphSolver::step_start() {
    return {x0_.data(),  y0_.data(),  z0_.data(),  vx0_.data(),
            vy0_.data(), vz0_.data(), rho0_.data()};
}

void SphSolver::predictor(Real dt) {
    ScopedTimer timer(t_integrate_);
    const Index n = set_.size();
    for (auto* v : {&x0_, &y0_, &z0_, &vx0_, &vy0_, &vz0_, &rho0_}) v->resize(n);
    exec::for_each(n, SymplecticPredictor{set_.view(), step_start(), Real(0.5) * dt,
                                          boundary_min_density(), domain_});
}

void SphSolver::corrector(Real dt) {
    ScopedTimer timer(t_integrate_);
    exec::for_each(set_.size(), SymplecticCorrector{set_.view(), step_start(), dt,
                                                    boundary_min_density(), domain_});
}

void SphSolver::verlet_step(Real dt, bool euler) {
    ScopedTimer timer(t_integrate_);
    const PreviousState old{set_.vx_old.data(), set_.vy_old.data(), set_.vz_old.data(),
                            set_.rho_old.data()};
    exec::for_each(set_.size(),
                   VerletUpdate{set_.view(), old, dt, boundary_min_density(), euler, domain_});
}

std::size_t SphSolver::memory_bytes() const {
    std::size_t b = set_.bytes() + grid_.bytes() + list_.bytes();
    for (const auto& t : buffers_.per_thread) b += bytes_of(t);
    return b + bytes_of(prho_, cs_, vol_, tau_next_, grad_rho_, ghost_velocity_, mdbc_rows_, xref_,
                        yref_, zref_, x0_, y0_, z0_, vx0_, vy0_, vz0_, rho0_);
}

void SphSolver::add_timings(time::Timings& t) const {
    t.neighbors += t_neighbors_;
    t.forces += t_forces_;
    t.integration += t_integrate_;
}

void SphSolver::remove_particles(const std::vector<std::uint8_t>& keep) {
    const bool list_current =
        list_valid_ && list_.particles() == set_.size() && xref_.size() == std::size_t(set_.size());
    set_.compact(keep);
    if (!list_current) {
        list_valid_ = false;
        return;
    }
    // The remaining pairs and reference positions stay valid (Verlet criterion unchanged).
    ScopedTimer timer(t_neighbors_);
    list_.compact(keep);
    for (auto* ref : {&xref_, &yref_, &zref_}) {
        std::size_t w = 0;
        for (std::size_t i = 0; i < keep.size(); ++i)
            if (keep[i]) (*ref)[w++] = (*ref)[i];
        ref->resize(w);
    }
}

void SphSolver::remove_group(std::int16_t group) {
    std::vector<std::uint8_t> keep(set_.size());
    for (Index i = 0; i < set_.size(); ++i)
        keep[i] = !(set_.kind[i] == std::uint8_t(Kind::boundary) && set_.group[i] == group);
    set_.compact(keep);
    list_valid_ = false;
}

} // namespace debrisflow::sph
