#pragma once
#include "debrisflow/core/hd.hpp"
#include "debrisflow/dem/contact_params.hpp"
#include "debrisflow/dem/rolling/constant_torque_rolling_k.hpp"
#include "debrisflow/dem/rolling/epsd_rolling_k.hpp"
#include "debrisflow/dem/rolling/no_rolling_k.hpp"
#include "debrisflow/models/registry.hpp"

namespace debrisflow::dem {

// The rolling-resistance models, selectable by name (`dem.rolling`). A model is a type in
// dem/rolling/ with its name, its moment, whether it carries the moment between steps and its
// mode for the stable step; adding one is its file and a line here. A pair's
// PairParams::rolling is the model's position in this list.
using RollingRegistry = models::Registry<NoRolling, ConstantTorqueRolling, EpsdRolling>;

// Dispatch on a pair's rolling index, the same code on the host and a GPU.
template <class Registry> struct RollingModels;
template <class... Models> struct RollingModels<models::Registry<Models...>> {
    DF_HD DF_HOT_INLINE static Vec3 moment(const PairParams& p, const RollingInput& in,
                                           Vec3* memory) {
        Vec3 m{};
        std::uint8_t k = 0;
        (void)((p.rolling == k++ ? (m = Models::moment(p, in, memory), true) : false) || ...);
        return m;
    }
};
using Rolling = RollingModels<RollingRegistry>;

} // namespace debrisflow::dem
