#pragma once
// The grains' bounding box, which the DEM's cell grid spans (DemSolver::configure_grid on the
// host, ResidentDem's through Space::fold): host/device functors.
#include "debrisflow/core/real.hpp"
#include "debrisflow/core/vec3_k.hpp"
#include <type_traits>

namespace debrisflow::dem {

// The box around a set of points (empty by default: the fold's identity).
struct Bounds {
    Vec3 lo{Real(1e300), Real(1e300), Real(1e300)}, hi{-Real(1e300), -Real(1e300), -Real(1e300)};
    DF_HD static void combine(Bounds& a, const Bounds& b) {
        for (int d = 0; d < 3; ++d) {
            a.lo[d] = b.lo[d] < a.lo[d] ? b.lo[d] : a.lo[d];
            a.hi[d] = b.hi[d] > a.hi[d] ? b.hi[d] : a.hi[d];
        }
    }
};

// Adds grain i's centre to the box (the grid's extent, DemSolver::configure_grid).
struct GrainBounds {
    const Vec3* pos;
    DF_HD void operator()(Index i, Bounds& b) const { Bounds::combine(b, Bounds{pos[i], pos[i]}); }
};

static_assert(std::is_trivially_copyable_v<GrainBounds>);

} // namespace debrisflow::dem
