#pragma once
#include "debrisflow/dem/grain_set.hpp"
#include "debrisflow/dem/wall_proximity.hpp"
#include "debrisflow/flow/feed_reach_k.hpp"
#include "debrisflow/flow/solid_feed.hpp"
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

namespace debrisflow::dem {
class DemSolver;
class ResidentDemPhase;
} // namespace debrisflow::dem

namespace debrisflow::flow {

// Solid feed: grains are released in the box at the target solid discharge Q_s(t): the solid
// volume owed grows by Q_s dt each step, and grains (sizes from the block's distribution) are
// placed at random positions that overlap no grain and no fixed wall (dem/wall_proximity.hpp:
// a region that cuts a wall releases only in its free part), until the debt is smaller than the
// next grain. When the region is full the debt carries over (the feed is choked; the CSV shows
// it, and the log warns once, SolidFeed::lag_note).
class GrainFeed : public SolidFeed {
public:
    GrainFeed(const io::FeedSpec& spec, const io::CaseSpec& c);

    // Inserts what is owed after a step of dt ending at t.
    void apply(dem::DemSolver& dem, Real t, Real dt);
    // The same for grains resident in a backend's memory: the grains near the region are
    // looked for there and the new ones appended there (dem/resident_dem.hpp).
    void apply(dem::ResidentDemPhase& resident, dem::DemSolver& dem, Real t, Real dt);
    // One grain of the smallest size the feed can release (for the DEM time step).
    Real smallest_diameter() const { return spec_.size.min; }

private:
    FeedReach reach() const;
    void place(std::vector<std::pair<Vec3, Real>> near, dem::GrainSet& into,
               const dem::WallProximity& walls);
    // The fixed walls, kept while the walls' layout and which of them are present stay the same.
    const dem::WallProximity& walls_near(const dem::DemSolver& dem);

    int material_;
    std::unique_ptr<dem::WallProximity> walls_near_;
    std::uint64_t walls_layout_ = 0;
    std::vector<bool> walls_active_;
};

} // namespace debrisflow::flow
