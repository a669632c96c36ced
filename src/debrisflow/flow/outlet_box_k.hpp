#pragma once
// An outlet's sink box (flow/outlet.hpp), written once for the host and a resident backend
// (sph/resident_sph.hpp finds the fluid inside it where its particles are).
#include "debrisflow/core/hd.hpp"
#include "debrisflow/core/vec3_k.hpp"

namespace debrisflow::flow {

struct OutletBox {
    Vec3 lo, hi;
    // Closed box, every coordinate tested (2D cases sit at y = 0 inside it).
    DF_HD bool contains(Vec3 p) const {
        return p.x >= lo.x && p.x <= hi.x && p.y >= lo.y && p.y <= hi.y && p.z >= lo.z &&
               p.z <= hi.z;
    }
};

} // namespace debrisflow::flow
