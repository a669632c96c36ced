#pragma once
// The DEM's opening kick and drift of one grain, written once for the host loop
// (DemSolver::kick_drift, an exec::reduce) and a device loop (exec/cuda_instantiations.cu).
#include "debrisflow/core/domain.hpp"
#include "debrisflow/dem/grain_contact_k.hpp"
#include <cstdint>
#include <type_traits>

namespace debrisflow::dem {

// What a drift reports: the largest squared speed (the neighbour list's skin budget) and how
// many coordinates left a closed side of the domain or are not finite.
struct DriftReport {
    Real vmax2 = 0;
    int outside = 0;
    DF_HD static void combine(DriftReport& a, const DriftReport& b) {
        a.vmax2 = a.vmax2 < b.vmax2 ? b.vmax2 : a.vmax2; // std::max, on a device too
        a.outside += b.outside;
    }
};

// Velocity Verlet with the dashpots' velocity predicted to the positions' time:
//   v_n+1/2 = v_n + (h/2) F_n / m,  x_n+1 = x_n + h v_n+1/2,  w_n+1 = w_n + h T_n / I;
// the stored velocity is then v* = v_n+1/2 + (h/2) F_n / m, and the closing kick of the force
// pass adds (h/2) (F_n+1 - F_n) / m. Clump members are moved with their clump instead.
struct GrainKickDrift {
    GrainView g;
    GrainState* hot;              // the contact pass's interleaved copy, refreshed here
    const std::int32_t* clump_of; // clump of each grain id (< 0: none), or null
    Real h;
    bool plane; // 2D: motion in the x-z plane, spin about y only
    Domain dom;
    DF_HD void operator()(Index i, DriftReport& out) const {
        if (clump_of && clump_of[g.id[i]] >= 0) return; // moved with its clump
        const Real half = Real(0.5) * h;
        const Real im = g.inv_mass[i], ii = g.inv_inertia[i];
        Vec3 dv = (half * im) * g.force[i];
        Vec3 v = g.vel[i] + dv, w = g.spin[i] + (h * ii) * g.torque[i];
        if (plane) dv.y = 0, v.y = 0, w.x = 0, w.z = 0;
        const Real vel[3] = {v.x, v.y, v.z};
        g.vel[i] = v + dv;
        g.spin[i] = w;
        Vec3 p = g.pos[i];
        for (int d = 0; d < 3; ++d) {
            Real x = p[d] + h * vel[d];
            if (dom.periodic[d]) {
                const Real len = dom.hi[d] - dom.lo[d];
                if (x >= dom.hi[d]) x -= len;
                if (x < dom.lo[d]) x += len;
            } else if (!(plane && d == 1) && !(x >= dom.lo[d] && x <= dom.hi[d])) {
                ++out.outside; // outside the domain, or NaN
            }
            p[d] = x;
        }
        g.pos[i] = p;
        GrainState& hs = hot[i];
        hs.x = p;
        hs.v = g.vel[i];
        hs.w = w;
        const Real v2 = vel[0] * vel[0] + vel[1] * vel[1] + vel[2] * vel[2];
        out.vmax2 = out.vmax2 < v2 ? v2 : out.vmax2;
    }
};
static_assert(std::is_trivially_copyable_v<GrainKickDrift>);

} // namespace debrisflow::dem
