#pragma once
#include "debrisflow/flow/hydrograph.hpp"
#include "debrisflow/io/case_spec.hpp"
#include "debrisflow/scenario/size_sampler.hpp"
#include <string>

namespace debrisflow::checkpoint {
class Archive;
}

namespace debrisflow::flow {

// What every solid feed (grains or rigid rocks) shares: the target solid discharge Q_s(t), the
// solid volume owed (grows by Q_s dt each step, paid by each piece placed), the size of the next
// piece, and what has been released. A growing debt means the region is full: the feed is choked.
class SolidFeed {
public:
    SolidFeed(const io::FeedSpec& spec, const io::CaseSpec& c)
        : spec_(spec), case_(c), q_{spec.times, spec.discharge},
          sizes_(spec.size, c.dim, spec.seed), next_d_(sizes_()) {}

    const std::string& name() const { return spec_.name; }
    Real discharge(Real t) const { return q_.at(t); } // target [m^3/s of solid]
    Real volume_in() const { return volume_in_; }     // solid volume released [m^3]
    Real mass_in() const { return mass_in_; }         // [kg]
    Real owed() const { return owed_; }               // solid volume not yet placed [m^3]
    long pieces_in() const { return count_; }         // grains or rocks released
    // Once, when the feed has fallen behind its discharge (its region full: new pieces are
    // placed only clear of the others), a warning for the log; "" otherwise.
    std::string lag_note(Real t);
    // Saves or restores the debt, the totals, the next size and the random generator
    // (flow/flow_state.cpp).
    void state(checkpoint::Archive& ar);

protected:
    // Adds Q_s(t) dt to the debt.
    void accrue(Real t, Real dt) { owed_ += q_.at(t) * dt; }
    // Volume of a piece of size d: a sphere (2D: a disc of the case's thickness); a rock of
    // equivalent diameter d has it too.
    Real piece_volume(Real d) const;
    // Books a piece of `volume` and `mass` as released and draws the next size.
    void released(Real volume, Real mass) {
        owed_ -= volume;
        volume_in_ += volume;
        mass_in_ += mass;
        ++count_;
        next_d_ = sizes_();
    }

    io::FeedSpec spec_;
    const io::CaseSpec& case_;
    Hydrograph q_;
    scenario::SizeSampler sizes_;
    Real next_d_; // diameter of the next piece [m]
    Real owed_ = 0, volume_in_ = 0, mass_in_ = 0;
    long count_ = 0;
    bool lag_warned_ = false;
};

} // namespace debrisflow::flow
