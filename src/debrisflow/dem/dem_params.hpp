#pragma once
#include "debrisflow/core/vec3_k.hpp"
#include <string>

namespace debrisflow::dem {

struct DemParams {
    int dim = 3;
    Vec3 gravity{0, 0, -9.81};
    Real dt = 0;        // user time step [s] (0: automatic)
    Real safety = 0.02; // dt = safety x shortest contact duration (and <= 0.2 Rayleigh time)
    Real skin = 0.1;    // neighbour search margin as a fraction of the largest diameter
    Real reference_velocity = 0;  // impact speed for the Hertz contact time (0: from gravity)
    std::string rolling = "none"; // none | constant_torque | epsd
    bool subcycle = false;        // advance(dt) splits dt into stable sub-steps (with SPH)
    bool reorder = true;          // sort grains by cell at every neighbour rebuild
    // grain-grain contacts: false, contiguous thread ranges with Newton's third law (the
    // host's pass); true, one evaluation per candidate slot then a gather per grain (the
    // device's layout, dem.contact_pass = "slots")
    bool slot_contacts = false;
};

} // namespace debrisflow::dem
