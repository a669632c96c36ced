#pragma once
#include "debrisflow/core/vec3_k.hpp"
#include <array>

namespace debrisflow {

// The simulation box [lo, hi], shared by every physics: the neighbour grids span it, and each
// direction is either closed or periodic.
struct Domain {
    Vec3 lo, hi;
    std::array<bool, 3> periodic{false, false, false};
};

} // namespace debrisflow
