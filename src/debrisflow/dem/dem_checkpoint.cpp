// The DEM phase's state for checkpoints: grains and clumps, contact histories, walls, and
// what the neighbour search carries between rebuilds (the skin's drift, the grid's box).
#include "debrisflow/checkpoint/archive.hpp"
#include "debrisflow/dem/dem_solver.hpp"

namespace debrisflow::dem {

void GrainSet::state(checkpoint::Archive& ar) {
    ar.section("grains");
    ar(pos, vel, spin, force, torque, radius, mass, inv_mass, inv_inertia, material, id, next_id_);
    const std::size_t n = pos.size();
    for (const auto* v : {&vel, &spin, &force, &torque})
        if (v->size() != n) ar.fail("grain arrays of different lengths");
    for (const auto* v : {&radius, &mass, &inv_mass, &inv_inertia})
        if (v->size() != n) ar.fail("grain arrays of different lengths");
    if (material.size() != n || id.size() != n) ar.fail("grain arrays of different lengths");
    ClumpSet& c = clumps;
    ar(c.pos, c.vel, c.ang_mom, c.force, c.torque, c.orient, c.mass, c.inv_inertia, c.first,
       c.member_id, c.offset);
    if (c.first.size() != c.mass.size() + 1 || c.first.back() != c.member_id.size())
        ar.fail("clump arrays that do not match");
}

void ContactSlots::state(checkpoint::Archive& ar) {
    if (!ar.is_loading()) {
        // Slots past a grain's count hold leftovers of earlier builds that nothing reads:
        // saved as zeros, so equal states give equal files.
        std::vector<Index> partner(partner_.size(), 0);
        std::vector<std::uint32_t> key(key_.size(), 0);
        std::vector<Vec3> xi(xi_.size(), Vec3{}), mroll(mroll_.size(), Vec3{});
        for (std::size_t i = 0; i < count_.size(); ++i)
            for (std::size_t k = 0; k < std::size_t(std::min(count_[i], cap_)); ++k) {
                const std::size_t s = i * std::size_t(cap_) + k;
                partner[s] = partner_[s], key[s] = key_[s], xi[s] = xi_[s];
                if (rolling_) mroll[s] = mroll_[s];
            }
        ar(cap_, count_, partner, key, xi, mroll);
        return;
    }
    ar(cap_, count_, partner_, key_, xi_, mroll_);
    next_cap_ = std::max(cap_, Index(2)); // the rows' stride as saved, for the next build
    if (partner_.size() != count_.size() * std::size_t(cap_) || key_.size() != partner_.size() ||
        xi_.size() != partner_.size() || mroll_.size() != (rolling_ ? partner_.size() : 0))
        ar.fail("contact slots that do not match");
}

void WallSet::state(checkpoint::Archive& ar) {
    ar.section("walls");
    for (auto& w : walls_) {
        ar(w.origin, w.active, w.force, w.moment, w.impulse, w.impulse_time, w.contacts);
    }
    // Faces (FEM surfaces change with erosion), their nodal corners and the moving nodes.
    ar.columns(prims_, &WallPrimitive::a, &WallPrimitive::b, &WallPrimitive::c, &WallPrimitive::n,
               &WallPrimitive::type, &WallPrimitive::wall, &WallPrimitive::corners,
               &WallPrimitive::solid, &WallPrimitive::covered_by);
    ar.columns(corners_, &NodalCorners::node, &NodalCorners::offset);
    ar(nodes_.x, nodes_.v, nodes_.impulse, layout_);
    for (const auto& p : prims_)
        if (p.wall < 0 || std::size_t(p.wall) >= walls_.size() ||
            (p.corners >= 0 && std::size_t(p.corners) >= corners_.size()))
            ar.fail("wall faces that do not match this case's walls");
}

void DemSolver::state(checkpoint::Archive& ar) {
    grains_.state(ar);
    walls_.state(ar);
    ar.section("dem");
    grain_slots_.state(ar);
    wall_slots_.state(ar);
    obstacle_slots_.state(ar);
    ar(max_radius_, skin_, drift_, dt_, current_h_, auto_dt_.dt, auto_dt_.limiter);
    ar(stability_dt_.dt, stability_dt_.limiter, built_, bad_, evaluated_, contacts_, builds_);
    ar(sum_contact_force_, walls_seen_, grid_lo_, grid_hi_);
    std::uint64_t timed = obstacle_spheres_timed_;
    ar(obstacles_seen_, obstacle_builds_seen_, timed);
    obstacle_spheres_timed_ = std::size_t(timed);
    // The contact state of the grains as the last evaluation saw it (velocities before the
    // closing half kick): a force evaluation before the next drift (a fluid step's
    // mid-point) reads it, not the kicked velocities.
    ar.columns(hot_, &GrainState::x, &GrainState::v, &GrainState::w, &GrainState::r, &GrainState::m,
               &GrainState::material);
    if (hot_.size() != grains_.pos.size()) ar.fail("a grain contact state of another length");
    if (!ar.is_loading()) return;
    reach_ = largest_reach(table_, max_radius_); // of the restored largest grain
    map_clumps();
    if (built_ && grains_.size() > 0) {
        // the grid's box as at the last rebuild (its periodic lengths give the separations)
        grid_.configure(grid_lo_, grid_hi_, grid_cell(), params_.dim, domain_.periodic);
        const Real* p = &grains_.pos[0].x;
        grid_.build(p, p + 1, p + 2, grains_.size(), 3);
    }
}

} // namespace debrisflow::dem
