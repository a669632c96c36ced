#pragma once
#include "debrisflow/dem/grain_set.hpp"
#include "debrisflow/flow/solid_feed.hpp"

namespace debrisflow::dem {
class DemSolver;
}

namespace debrisflow::flow {

// Solid feed: grains are released in the box at the target solid discharge Q_s(t): the solid
// volume owed grows by Q_s dt each step, and grains (sizes from the block's distribution) are
// placed at random positions that overlap no grain, until the debt is smaller than the next
// grain. When the region is full the debt carries over (the feed is choked; the CSV shows it).
class GrainFeed : public SolidFeed {
public:
    GrainFeed(const io::FeedSpec& spec, const io::CaseSpec& c);

    // Inserts what is owed after a step of dt ending at t.
    void apply(dem::DemSolver& dem, Real t, Real dt);
    // Whether the step of dt ending at t leaves at least the next grain owed, i.e. whether
    // apply() would place grains (and read the grains' positions) rather than only add to the
    // debt: what a resident DEM loop asks before it copies its grains to the host.
    bool due(Real t, Real dt) const { return owed() + q_.at(t) * dt >= volume_of(next_d_); }

    // One grain of the smallest size the feed can release (for the DEM time step).
    Real smallest_diameter() const { return spec_.size.min; }

private:
    Real volume_of(Real d) const;

    int material_;
};

} // namespace debrisflow::flow
