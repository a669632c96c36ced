#pragma once
#include "debrisflow/dem/contact_params.hpp"
#include "debrisflow/dem/rolling/rolling_types_k.hpp"

namespace debrisflow::dem {

// No rolling resistance: spheres roll freely (only the tangential force resists rotation).
struct NoRolling {
    static constexpr const char* name = "none";
    static constexpr bool keeps_moment = false; // carries no moment from step to step
    DF_HD static Vec3 moment(const PairParams&, const RollingInput&, Vec3*) { return {}; }
    // Frequency of the model's own mode relative to the normal one (for the stable step).
    static Real mode_ratio(const PairParams&, Real /*r_eff*/, Real /*c_r*/, Real /*m_eff*/) {
        return 0;
    }
};

} // namespace debrisflow::dem
