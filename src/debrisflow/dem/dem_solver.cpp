#include "debrisflow/dem/dem_solver.hpp"
#include "debrisflow/core/error.hpp"
#include "debrisflow/core/stopwatch.hpp"
#include "debrisflow/dem/critical_dt.hpp"
#include "debrisflow/dem/grain_contact_k.hpp"
#include "debrisflow/dem/grain_kick_drift_k.hpp"
#include "debrisflow/dem/resident_dem_k.hpp"
#include "debrisflow/dem/rolling_models_k.hpp"
#include "debrisflow/dem/slot_candidates_k.hpp"
#include "debrisflow/exec/parallel.hpp"
#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <limits>
#include <unordered_map>

namespace debrisflow::dem {

DemSolver::DemSolver(const DemParams& params, GrainSet& grains, WallSet& walls,
                     std::vector<Material> materials, const std::vector<PairOverride>& overrides,
                     const Domain& domain)
    : params_(params), grains_(grains), walls_(walls), materials_(std::move(materials)),
      table_(build_pair_table(materials_, overrides, params.rolling)), domain_(domain) {
    map_clumps();
    // Contact slots keep a rolling moment only for the elastic-plastic rolling model.
    const bool epsd = std::any_of(table_.begin(), table_.end(), [](const PairParams& p) {
        return RollingRegistry::visit_index(p.rolling, []<class M>() { return M::keeps_moment; });
    });
    for (auto* slots : {&grain_slots_, &wall_slots_, &obstacle_slots_}) slots->keep_rolling(epsd);
    for (Real r : grains_.radius) max_radius_ = std::max(max_radius_, r);
    size_search_margin();
    auto_dt_ = critical_dt(grains_, wall_materials(), materials_, table_, params_, domain_,
                           params_.safety);
    stability_dt_ = critical_dt(grains_, wall_materials(), materials_, table_, params_, domain_,
                                stability_fraction);
    dt_ = params_.dt > 0 ? params_.dt : auto_dt_.dt;
}

time::DtLimit DemSolver::stable_dt() const {
    if (params_.subcycle) return {std::numeric_limits<Real>::max(), "sub-cycled"};
    if (drag_dt() < dt_) return {drag_dt(), "fluid drag"};
    return {dt_, params_.dt > 0 ? "user dt" : auto_dt_.limiter};
}

Real DemSolver::drag_dt() const {
    // Forward drag dv/dt = -(beta/m) v is stable for h beta/m < 2; half of that keeps the
    // relaxation monotone.
    if (!fluid_ || fluid_->max_rate <= 0) return std::numeric_limits<Real>::max();
    return Real(0.5) / fluid_->max_rate;
}

GrainContactInputs DemSolver::grain_contact_inputs() {
    refresh_hot();
    return contact_inputs(current_h_);
}

GrainContactInputs DemSolver::contact_inputs(Real h) {
    return {hot_.data(),
            grains_.size(),
            grain_slots_.partners(),
            grain_slots_.counts(),
            grain_slots_.tangential(),
            grain_slots_.rolling(),
            grain_slots_.capacity(),
            pair_table(),
            grid_.view(),
            h};
}

void DemSolver::update_neighbors(bool) {
    if (!built_) rebuild();
}

void DemSolver::compute_forces() {
    // The step just taken ended with a force evaluation that the grains were kicked with and
    // that the FEM nodes received as impulse; evaluating the same state again would hand the
    // grains a force nobody else felt. Evaluate again only for a new wall layout or when bodies
    // moved their contact spheres after the step (then the bodies take this reaction too,
    // averaged with the step's over the time both cover).
    const bool bodies_moved = obstacles_ && obstacles_->version != obstacles_seen_;
    if (evaluated_ && !bodies_moved && walls_.layout() == walls_seen_) {
        evaluated_ = false;
        return;
    }
    evaluated_ = false;
    if (!built_ || walls_.layout() != walls_seen_) rebuild();
    ScopedTimer timer(t_forces_);
    forces(0, bodies_moved);
}

void DemSolver::rebuild() {
    ScopedTimer timer(t_neighbors_);
    const Index n = grains_.size();
    built_ = true;
    drift_ = 0;
    walls_seen_ = walls_.layout();
    ++builds_;
    if (n == 0) return;
    configure_grid();
    const auto build_grid = [&] {
        const Real* p = &grains_.pos[0].x;
        grid_.build(p, p + 1, p + 2, n, 3);
    };
    build_grid();
    if (params_.reorder) {
        const std::vector<Index> perm = grid_.order();
        grains_.permute(perm);
        grain_slots_.permute(perm);
        wall_slots_.permute(perm);
        obstacle_slots_.permute(perm);
        if (fluid_) fluid_->permute(perm);
        map_clumps();
        build_grid();
    }
    const GrainView g = grains_.view();
    refresh_hot();
    const Real skin = search_margin();
    const std::int32_t* clump_of = clump_of_id_.empty() ? nullptr : clump_of_id_.data();
    grain_slots_.build(n, GrainCandidates{grid_.view(), g.pos, g.radius, g.id, clump_of, skin});
    const auto& prims = walls_.primitives();
    const auto& wl = walls_.walls();
    // Active primitives with their boxes.
    active_prims_.clear();
    active_bounds_.clear();
    for (std::size_t k = 0; k < prims.size(); ++k)
        if (wl[std::size_t(prims[k].wall)].active) {
            active_prims_.push_back(Index(k));
            active_bounds_.push_back(PrimitiveBounds::of(prims[k]));
        }
    wall_bins_.build(active_bounds_, max_radius_ + skin, params_.dim);
    wall_slots_.build(n, WallCandidatesOf{prims.data(), active_prims_.data(), active_bounds_.data(),
                                          Index(active_prims_.size()), g.pos, g.radius, skin,
                                          wall_bins_.view()});
}

void DemSolver::configure_grid() {
    // Cells of one search radius over the grains' bounding box (the whole length in periodic
    // directions), so that sparse grains in a large domain do not pay for empty cells.
    const Bounds box = exec::reduce(grains_.size(), Bounds{domain_.hi, domain_.lo},
                                    GrainBounds{grains_.pos.data()}, Bounds::combine,
                                    exec::serial_below(parallel_min + 1));
    set_grid_box(box);
    grid_.configure(grid_lo_, grid_hi_, grid_cell(), params_.dim, domain_.periodic);
}

void DemSolver::set_grid_box(Bounds b) {
    Vec3 lo = b.lo, hi = b.hi;
    const Real radius = grid_cell();
    for (int d = 0; d < 3; ++d) {
        if (domain_.periodic[d] || !(hi[d] >= lo[d])) {
            lo[d] = domain_.lo[d], hi[d] = domain_.hi[d];
        } else {
            lo[d] -= radius, hi[d] += radius;
        }
    }
    grid_lo_ = lo, grid_hi_ = hi;
}

void DemSolver::kick_drift(Real h) {
    ScopedTimer timer(t_integration_);
    GrainView g = grains_.view();
    const bool plane = params_.dim == 2;
    const Domain dom = domain_;
    GrainState* hot = hot_.data();
    const std::int32_t* clump_of = clump_of_id_.empty() ? nullptr : clump_of_id_.data();
    const GrainKickDrift move_grain{g, hot, clump_of, h, plane, dom};
    const DriftReport moved = exec::reduce(g.n, DriftReport{}, move_grain, DriftReport::combine,
                                           exec::serial_below(parallel_min + 1));
    Real vmax2 = moved.vmax2;
    if (clump_of) vmax2 = std::max(vmax2, clump_kick_drift(h));
    if (moved.outside > 0 || !std::isfinite(vmax2)) bad_ = true;
    drift_ += h * (std::sqrt(vmax2) + walls_.max_speed());
}

void DemSolver::step(Real h) {
    current_h_ = h;
    kick_drift(h);
    advance_walls(h);
    if (drift_ > Real(0.5) * skin_ || walls_.layout() != walls_seen_) rebuild();
    if (obstacles_ && (obstacles_->version != obstacles_seen_ || builds_ != obstacle_builds_seen_))
        build_obstacle_slots();
    {
        ScopedTimer timer(t_forces_);
        forces(Real(0.5) * h);
    }
    evaluated_ = true;
}

void DemSolver::advance_walls(Real h) {
    walls_.advance(h);
    for (auto& w : walls_.walls()) {
        w.impulse += h * w.force; // force of the previous evaluation, held over the step
        w.impulse_time += h;
    }
}

void DemSolver::build_obstacle_slots() {
    if (obstacles_->spheres.size() != obstacle_spheres_timed_) include_bodies();
    obstacles_seen_ = obstacles_->version;
    obstacle_builds_seen_ = builds_;
    const auto& sph = obstacles_->spheres;
    configure_obstacle_grid(obstacle_grid_);
    if (!sph.empty()) {
        const Real* c = &sph[0].x.x;
        obstacle_grid_.build(c, c + 1, c + 2, Index(sph.size()), ObstacleCandidates::stride);
    }
    const GrainView g = grains_.view();
    obstacle_slots_.build(grains_.size(),
                          ObstacleCandidates{obstacle_grid_.view(), sph.data(), Index(sph.size()),
                                             g.pos, g.radius, search_margin()});
}

void DemSolver::configure_obstacle_grid(neighbors::CellGrid& grid) const {
    const auto& sph = obstacles_->spheres;
    Real rmax = 0;
    Vec3 lo{}, hi{};
    for (std::size_t s = 0; s < sph.size(); ++s) {
        rmax = std::max(rmax, sph[s].r);
        for (int d = 0; d < 3; ++d) {
            lo[d] = s == 0 ? sph[s].x[d] : std::min(lo[d], sph[s].x[d]);
            hi[d] = s == 0 ? sph[s].x[d] : std::max(hi[d], sph[s].x[d]);
        }
    }
    // Cells of one reach over the spheres' box widened by a cell (never empty): every sphere
    // a grain may touch lies in the grain's 3 x 3 (x 3) stencil; a grain beyond the box is
    // placed in its edge cells.
    const Real cell = std::max(max_radius_ + rmax + search_margin(), Real(1e-9));
    for (int d = 0; d < 3; ++d) lo[d] -= cell, hi[d] += cell;
    grid.configure(lo, hi, cell, params_.dim, {false, false, false});
}

void DemSolver::size_search_margin() {
    skin_ = params_.skin * 2 * max_radius_;
    // every effective radius of a contact is at most the largest grain's
    reach_ = largest_reach(table_, max_radius_);
}

void DemSolver::advance(Real dt) {
    if (!params_.subcycle) {
        step(dt);
        return;
    }
    const long n = std::max(1L, long(std::ceil(dt / std::min(dt_, drag_dt()) - 1e-9)));
    for (long s = 0; s < n; ++s) step(dt / Real(n));
}

std::vector<int> DemSolver::wall_materials() const {
    std::vector<int> m;
    for (const auto& w : walls_.walls()) m.push_back(w.material);
    return m;
}

void DemSolver::refresh_hot() {
    const GrainView g = grains_.view();
    hot_.resize(std::size_t(g.n));
    GrainState* hot = hot_.data();
    // below parallel_min on one thread, as the other grain loops (a 400-disc column on 2
    // threads: 4 % less wall time than a parallel region per neighbour rebuild)
    if (g.n > parallel_min) {
        exec::for_each(g.n, [=](Index i) { hot[i] = GrainState::load(g, i); });
    } else {
        for (Index i = 0; i < g.n; ++i) hot[i] = GrainState::load(g, i);
    }
}

Real DemSolver::unbalanced_ratio() const {
    const Index n = grains_.size();
    // A packing is only judged once it is one (on average a contact per grain): early on a
    // few hard collisions among falling grains would make the ratio small.
    if (n == 0 || 2 * contacts_ < long(n)) return std::numeric_limits<Real>::max();
    // a clump counts once, with its net force
    Real sum = 0;
    long bodies = 0;
    for (Index i = 0; i < n; ++i) {
        if (!clump_of_id_.empty() && clump_of_id_[grains_.id[std::size_t(i)]] >= 0) continue;
        sum += norm(grains_.force[std::size_t(i)]);
        ++bodies;
    }
    for (const Vec3& f : grains_.clumps.force) sum += norm(f);
    bodies += long(grains_.clumps.size());
    return (sum / Real(bodies)) / mean_contact_force();
}

bool DemSolver::escaped(Index i) const {
    return GrainEscaped{grains_.pos.data(), grains_.vel.data(), domain_, params_.dim == 2}(i);
}

void DemSolver::check_health(Real t) const {
    if (!bad_) return;
    for (Index i = 0; i < grains_.size(); ++i) {
        const std::size_t k = std::size_t(i);
        const Vec3 p = grains_.pos[k], v = grains_.vel[k];
        const bool nan = !std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z) ||
                         !std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z);
        if (escaped(i))
            throw InstabilityError(fmt::format(
                "grain {} {} at t = {:.6g} s: position ({:.4g}, {:.4g}, {:.4g}) m, velocity "
                "({:.4g}, {:.4g}, {:.4g}) m/s; domain [{:.4g}, {:.4g}, {:.4g}]-[{:.4g}, {:.4g}, "
                "{:.4g}] m. Check the time step (dem.dt, dem.safety) and the walls{}",
                grains_.id[k], nan ? "has a non-finite state" : "left the domain", t, p.x, p.y, p.z,
                v.x, v.y, v.z, domain_.lo.x, domain_.lo.y, domain_.lo.z, domain_.hi.x, domain_.hi.y,
                domain_.hi.z,
                nan ? "" : " (domain.exit = \"remove\" takes grains that leave out of the run)"));
    }
    throw InstabilityError(fmt::format("DEM state became non-finite at t = {:.6g} s", t));
}

void DemSolver::add_timings(time::Timings& t) const {
    t.neighbors += t_neighbors_;
    t.forces += t_forces_;
    t.integration += t_integration_;
}

} // namespace debrisflow::dem
