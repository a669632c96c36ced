#pragma once
#include "debrisflow/dem/grain_set.hpp"
#include "debrisflow/flow/hydrograph.hpp"
#include "debrisflow/flow/solid_feed.hpp"
#include "debrisflow/io/case_spec.hpp"
#include "debrisflow/scenario/size_sampler.hpp"

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

    const std::string& name() const override { return spec_.name; }
    Real discharge(Real t) const override { return q_.at(t); }
    Real volume_in() const override { return volume_in_; }
    Real mass_in() const override { return mass_in_; }
    Real owed() const override { return owed_; }
    long pieces_in() const override { return count_; }
    // One grain of the smallest size the feed can release (for the DEM time step).
    Real smallest_diameter() const { return spec_.size.min; }

private:
    Real volume_of(Real d) const;

    io::FeedSpec spec_;
    const io::CaseSpec& case_;
    Hydrograph q_;
    scenario::SizeSampler sizes_;
    int material_;
    Real next_d_;
    Real owed_ = 0, volume_in_ = 0, mass_in_ = 0;
    long count_ = 0;
};

} // namespace debrisflow::flow
