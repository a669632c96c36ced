#pragma once
// The grains a grain feed (flow/grain_feed.hpp) must keep new grains clear of, written once for
// the host and a resident DEM loop (dem/resident_dem.hpp finds them where the grains are).
#include "debrisflow/core/hd.hpp"
#include "debrisflow/core/real.hpp"
#include "debrisflow/core/vec3_k.hpp"

namespace debrisflow::flow {

struct FeedReach {
    Vec3 lo, hi; // the feed's region
    Real reach;  // the largest diameter the feed releases (a margin beyond the largest radius)
    bool plane;  // 2D: y does not count
    // Whether a grain at p of radius r could overlap a new grain: its centre within the region
    // grown by `reach` and its own radius.
    DF_HD bool near(Vec3 p, Real r) const {
        bool in = true;
        for (int k = 0; k < 3; ++k)
            if (!(plane && k == 1)) in = in && p[k] > lo[k] - reach - r && p[k] < hi[k] + reach + r;
        return in;
    }
};

} // namespace debrisflow::flow
