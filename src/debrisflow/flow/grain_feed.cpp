#include "debrisflow/flow/grain_feed.hpp"
#include "debrisflow/dem/dem_solver.hpp"
#include "debrisflow/dem/resident_dem_backend.hpp"
#include "debrisflow/scenario/build_grains.hpp"
#include <cmath>

namespace debrisflow::flow {

GrainFeed::GrainFeed(const io::FeedSpec& spec, const io::CaseSpec& c)
    : SolidFeed(spec, c), material_(scenario::material_index(c, spec.material)) {}

FeedReach GrainFeed::reach() const {
    return {spec_.min, spec_.max, spec_.size.max, case_.dim == 2};
}

void GrainFeed::apply(dem::DemSolver& dem, Real t, Real dt) {
    accrue(t, dt);
    if (owed_ < piece_volume(next_d_)) return;
    auto& g = dem.grains();
    const Index before = g.size();
    // Grains near the region (possible overlaps), gathered once per batch.
    const FeedReach region = reach();
    std::vector<std::pair<Vec3, Real>> near;
    for (Index i = 0; i < g.size(); ++i)
        if (region.near(g.pos[std::size_t(i)], g.radius[std::size_t(i)]))
            near.push_back({g.pos[std::size_t(i)], g.radius[std::size_t(i)]});
    place(std::move(near), g, walls_near(dem));
    if (g.size() > before) dem.grains_added(before);
}

void GrainFeed::apply(dem::ResidentDemPhase& resident, dem::DemSolver& dem, Real t, Real dt) {
    accrue(t, dt);
    if (owed_ < piece_volume(next_d_)) return;
    // the few grains near the region come from where the grains are; the new ones go there
    dem::GrainSet fresh = dem::GrainSet::continuing(dem.grains());
    place(resident.grains_near(reach()), fresh, walls_near(dem));
    dem.grains().reserve_ids(fresh.next_id());
    if (fresh.size() > 0) resident.append(fresh);
}

const dem::WallProximity& GrainFeed::walls_near(const dem::DemSolver& dem) {
    std::vector<bool> active;
    for (const auto& w : dem.walls().walls()) active.push_back(w.active);
    if (!walls_near_ || dem.walls().layout() != walls_layout_ || active != walls_active_) {
        walls_near_ = std::make_unique<dem::WallProximity>(
            scenario::wall_proximity(case_, dem.walls(), spec_.size.max / 2, true));
        walls_layout_ = dem.walls().layout();
        walls_active_ = std::move(active);
    }
    return *walls_near_;
}

// Random positions in the region clear of `near`, of each other and of the fixed walls, while a
// grain is owed.
void GrainFeed::place(std::vector<std::pair<Vec3, Real>> near, dem::GrainSet& g,
                      const dem::WallProximity& walls) {
    std::uniform_real_distribution<Real> u(0, 1);
    auto& rng = sizes_.rng();
    constexpr int tries_per_grain = 200;
    while (owed_ >= piece_volume(next_d_)) {
        const Real r = next_d_ / 2;
        bool placed = false;
        for (int k = 0; k < tries_per_grain && !placed; ++k) {
            Vec3 p;
            for (int a = 0; a < 3; ++a)
                p[a] = case_.dim == 2 && a == 1
                           ? 0
                           : spec_.min[a] + r + u(rng) * (spec_.max[a] - spec_.min[a] - 2 * r);
            bool free = true;
            for (const auto& [q, rq] : near) {
                const Vec3 s = p - q;
                if (dot(s, s) < (r + rq) * (r + rq)) {
                    free = false;
                    break;
                }
            }
            // touching a wall is free; round-off of a region that ends on a wall's face too
            if (!free || walls.deepest(p, r).overlap > Real(1e-6) * r) continue;
            scenario::add_grain(case_, g, p, spec_.velocity, {}, next_d_, material_);
            near.push_back({p, r});
            placed = true;
        }
        if (!placed) break; // region full: the debt waits for the next step
        released(piece_volume(next_d_), g.mass.back());
    }
}

} // namespace debrisflow::flow
