#pragma once
// The prescribed state of a velocity inlet's buffer zone (flow/fluid_inlet.hpp), written once
// for the host solver's particles and a resident backend's (sph/resident_sph.hpp).
#include "debrisflow/core/hd.hpp"
#include "debrisflow/models/eos_tait_k.hpp"
#include "debrisflow/particles/particle_set.hpp"
#include <type_traits>

namespace debrisflow::flow {

// The buffer box at one instant: fluid inside moves at the inflow velocity along `axis` and
// carries the hydrostatic density of its depth below the box's top (Tafuni et al. 2018 with
// prescribed state; p = rho0 g (top - z) turned into a density by the Tait equation).
struct InletBuffer {
    Vec3 lo, hi;
    int axis;
    Real velocity; // signed, along axis [m/s]
    Real g_down;   // |g_z| when the fluid carries gravity, else 0
    bool flat;     // 2D: y is not tested
    models::TaitEos eos;

    DF_HD bool contains(Vec3 x) const {
        for (int k = 0; k < 3; ++k)
            if (!(flat && k == 1) && !(x[k] >= lo[k] && x[k] <= hi[k])) return false;
        return true;
    }
    // Hydrostatic below the buffer's top, as the initial fluid blocks (build_particles).
    DF_HD Real density_at(Real z) const {
        const Real depth = hi.z - z;
        return depth > 0 ? eos.density(eos.rho0 * g_down * depth) : eos.rho0;
    }
};

// Sets the state of the fluid particles inside the buffer; `old` (the Verlet scheme's state at
// t_n-1: vx, vy, vz, rho) is set alike when it is kept, else null.
struct PrescribeBuffer {
    InletBuffer buffer;
    particles::ParticleView pv;
    Real* old_vx;
    Real* old_vy;
    Real* old_vz;
    Real* old_rho;
    DF_HD void operator()(Index i) const {
        if (!pv.is_fluid(i) || !buffer.contains(pv.pos(i))) return;
        Real* v[3] = {pv.vx, pv.vy, pv.vz};
        Real* vo[3] = {old_vx, old_vy, old_vz};
        for (int k = 0; k < 3; ++k) {
            v[k][i] = k == buffer.axis ? buffer.velocity : Real(0);
            if (old_rho) vo[k][i] = v[k][i];
        }
        pv.rho[i] = buffer.density_at(pv.z[i]);
        if (old_rho) old_rho[i] = pv.rho[i];
    }
};

static_assert(std::is_trivially_copyable_v<PrescribeBuffer>);

} // namespace debrisflow::flow
