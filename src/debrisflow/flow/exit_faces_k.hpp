#pragma once
// The face of the domain a point outside it crossed (the domain exit's tally), written once
// for the host and a device (the resident SPH loop finds its leavers where the particles are).
#include "debrisflow/core/domain.hpp"
#include "debrisflow/core/hd.hpp"
#include <cmath>

namespace debrisflow::flow {

struct ExitFaces {
    Domain domain;
    int dim;
    // The face crossed furthest, relative to the domain's extent in that direction (index into
    // face_names: x-, x+, y-, y+, z-, z+), or -1 inside (periodic directions and y in 2D never
    // count).
    DF_HD int operator()(Vec3 p) const {
        int face = -1;
        Real worst = 0;
        for (int d = 0; d < 3; ++d) {
            if (domain.periodic[std::size_t(d)] || (dim == 2 && d == 1)) continue;
            const Real extent = domain.hi[d] - domain.lo[d];
            const Real below = (domain.lo[d] - p[d]) / extent,
                       above = (p[d] - domain.hi[d]) / extent;
            if (below > worst) worst = below, face = 2 * d;
            if (above > worst) worst = above, face = 2 * d + 1;
        }
        return face;
    }
    // The face a fluid particle's centre crossed, or -1 (inside, or not finite: the health
    // check stops those).
    DF_HD int of_finite(Vec3 p) const {
        if (!(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z))) return -1;
        return (*this)(p);
    }
};

} // namespace debrisflow::flow
