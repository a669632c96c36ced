#pragma once
#include "debrisflow/particles/particle_set.hpp"

namespace debrisflow::sph {

// How the viscous terms see a wall particle b: the velocity difference v_fluid - v_b that a
// fluid particle at x_fluid feels across it, given the plain difference dv = v_fluid - v_b.
// Two ways to put the no-slip condition on the wall surface:
// - "morris" (Morris, Fox & Zhu 1997, eq. 30): per pair, b carries v_B = -(d_B/d_A) v_A
//   relative to the wall, so dv -> (1 + d_B/d_A) dv, with d_A the fluid particle's and d_B
//   the wall particle's distance to the wall surface; d_A is bounded below by dp/2 (Morris
//   caps the factor at 1.5 for particles closer than the lattice allows).
// - "mdbc" (English et al. 2022, the no-slip variant of mDBC): b carries the velocity of the
//   fluid at its ghost node x_g = x_b + 2 d_B n mirrored across the wall surface,
//   v_b' = 2 v_b - v_g, the same for every partner, so dv -> dv + (v_g - v_b). ghost holds
//   (v_g - v_b, known) per particle, 4 per particle (MdbcDensity); where the ghost node sees
//   no fluid (known = 0: a film thinner than the kernel, a free surface) Morris's rule is used.
// Particles without wall geometry (depth 0) keep the plain difference.
struct NoSlipWall {
    const Real* ghost = nullptr; // nullptr: Morris everywhere
    Real half_dp = 0;

    DF_HD DF_HOT_INLINE Vec3 difference(const particles::ParticleView& pv, Index b, Vec3 x_fluid,
                                        Vec3 dv) const {
        if (!(pv.wd[b] > 0)) return dv;
        if (ghost && ghost[4 * b + 3] > 0)
            return dv + Vec3{ghost[4 * b], ghost[4 * b + 1], ghost[4 * b + 2]};
        const Vec3 n{pv.wnx[b], pv.wny[b], pv.wnz[b]};
        const Real d_fluid = dot(x_fluid - pv.pos(b), n) - pv.wd[b];
        const Real beta = 1 + pv.wd[b] / (d_fluid > half_dp ? d_fluid : half_dp);
        return beta * dv;
    }
};

} // namespace debrisflow::sph
