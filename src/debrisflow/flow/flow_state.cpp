// Open boundaries' state for checkpoints: what they have let in, taken out or counted.
#include "debrisflow/checkpoint/archive.hpp"
#include "debrisflow/flow/domain_exit.hpp"
#include "debrisflow/flow/fluid_inlet.hpp"
#include "debrisflow/flow/outlet.hpp"
#include "debrisflow/flow/solid_feed.hpp"
#include <sstream>

namespace debrisflow::flow {

void FluidInlet::state(checkpoint::Archive& ar) {
    ar.section("inlet " + spec_.name);
    ar(advance_, mass_in_, volume_in_);
}

void Outlet::state(checkpoint::Archive& ar) {
    ar.section("outlet " + spec_.name);
    ar(fluid_mass_, fluid_volume_, grain_mass_, grain_volume_, body_mass_, grains_removed_,
       bodies_removed_);
}

void SolidFeed::state(checkpoint::Archive& ar) {
    ar.section("feed " + spec_.name);
    std::ostringstream rng;
    rng << sizes_.rng();
    std::string engine = rng.str();
    ar(next_d_, owed_, volume_in_, mass_in_, count_, engine);
    if (!ar.is_loading()) return;
    std::istringstream in(engine);
    in >> sizes_.rng();
    if (!in) ar.fail("a feed's random generator state cannot be read");
}

void DomainExit::state(checkpoint::Archive& ar) {
    ar.section("domain exit");
    ar(fluid_, grains_, fluid_warned_, grains_warned_);
}

} // namespace debrisflow::flow
