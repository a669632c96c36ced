#include "debrisflow/dem/wall_proximity.hpp"
#include <cmath>

namespace debrisflow::dem {

namespace {
bool tested(const Wall& w, bool fixed_only) {
    if (fixed_only) return w.active && !(norm(w.velocity) > 0);
    return !(w.remove_at && *w.remove_at <= 0);
}
} // namespace

WallProximity::WallProximity(const WallSet& walls, Real reach, int dim, bool fixed_only)
    : walls_(walls), fixed_only_(fixed_only) {
    const auto& prims = walls.primitives();
    for (std::size_t k = 0; k < prims.size(); ++k) {
        const WallPrimitive& p = prims[k];
        if (p.corners >= 0 || !tested(walls.walls()[std::size_t(p.wall)], fixed_only)) continue;
        active_.push_back(Index(k));
        bounds_.push_back(PrimitiveBounds::of(p));
    }
    const auto& solids = walls.solids();
    for (std::size_t s = 0; s < solids.size(); ++s)
        if (tested(walls.walls()[std::size_t(solids[s].wall)], fixed_only))
            solids_.push_back(int(s));
    bins_.build(bounds_, reach, dim);
}

void WallProximity::add_solid_box(Vec3 lo, Vec3 hi, int wall) {
    if (tested(walls_.walls()[std::size_t(wall)], fixed_only_)) boxes_.push_back({lo, hi, wall});
}

WallOverlap WallProximity::deepest(Vec3 p, Real r) const {
    WallOverlap out;
    const auto& prims = walls_.primitives();
    const WallBinsView bins = bins_.view();
    bins.for_each_candidate(p, Index(active_.size()), [&](Index a) {
        if (!bounds_[std::size_t(a)].may_reach(p, r)) return;
        const WallPrimitive& w = prims[std::size_t(active_[std::size_t(a)])];
        const Real overlap = r - wall_distance(w, p, closest_point(w, p));
        if (overlap > out.overlap) out = {overlap, w.wall, false};
    });
    for (int s : solids_)
        if (walls_.inside(s, p) && !out.in_solid)
            out = {std::fmax(out.overlap, r), walls_.solids()[std::size_t(s)].wall, true};
    for (const Box& b : boxes_)
        if (!out.in_solid && p.x > b.lo.x && p.x < b.hi.x && p.y > b.lo.y && p.y < b.hi.y &&
            p.z > b.lo.z && p.z < b.hi.z)
            out = {std::fmax(out.overlap, r), b.wall, true};
    return out;
}

} // namespace debrisflow::dem
