#pragma once
#include <cstdint>

namespace debrisflow {

// Floating-point precision is a build choice; validation runs in double.
#if defined(DEBRISFLOW_SINGLE_PRECISION)
using Real = float;
#else
using Real = double;
#endif

using Index = std::int32_t;       // local particle index (changes when a set is reordered)
using ParticleId = std::uint64_t; // persistent id (survives reordering)

} // namespace debrisflow
