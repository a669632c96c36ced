#pragma once
#include "debrisflow/core/real.hpp"
#include <string>

namespace debrisflow::flow {

// What every solid feed (grains or rigid rocks) reports: the target solid discharge Q_s(t),
// what it has released and what it still owes (a growing debt: the region is full, choked).
class SolidFeed {
public:
    virtual ~SolidFeed() = default;
    virtual const std::string& name() const = 0;
    virtual Real discharge(Real t) const = 0; // target [m^3/s of solid]
    virtual Real volume_in() const = 0;       // solid volume released [m^3]
    virtual Real mass_in() const = 0;         // [kg]
    virtual Real owed() const = 0;            // solid volume not yet placed [m^3]
    virtual long pieces_in() const = 0;       // grains or rocks released
};

} // namespace debrisflow::flow
