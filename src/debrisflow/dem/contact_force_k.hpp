#pragma once
#include "debrisflow/core/vec3_k.hpp"
#include "debrisflow/dem/contact_laws_k.hpp"

namespace debrisflow::dem {

// History carried by a contact from step to step: the tangential spring displacement xi and
// the elastic-plastic rolling moment.
struct ContactHistory {
    Vec3 xi;
    Vec3 mroll;
};

// Where a contact's history is stored: its tangential spring, and its rolling moment when the
// elastic-plastic rolling model is on (null otherwise: the contact slots of a case without it
// keep only the spring, half the memory traffic of the contact loop).
struct HistoryRef {
    Vec3* xi;
    Vec3* mroll;
    DF_HD static HistoryRef of(ContactHistory& h) { return {&h.xi, &h.mroll}; }
    DF_HD void clear() const {
        *xi = Vec3{};
        if (mroll) *mroll = Vec3{};
    }
};

struct ContactResult {
    Vec3 force; // on grain i (the grain on the +n side), total
    Vec3 ft;    // tangential part of it
    Vec3 mroll; // rolling resistance moment on grain i (j receives -mroll)
    Real fn;    // normal force magnitude
};

// Keeps the tangential spring in the current tangent plane with its length unchanged
// (rigid rotation of the contact frame, as LIGGGHTS does): t = v - (v.n) n scaled by
// |v|/|t| = (1 - q)^(-1/2), q = (v.n)^2/|v|^2. Between two steps the normal turns by a tiny
// angle, so q ~ 1e-10 and the series 1 + q/2 + 3q^2/8 is exact to round-off (q < 1e-4: error
// below 3e-13); larger turns take the square root.
DF_HD DF_HOT_INLINE Vec3 rotate_into_plane(Vec3 v, Vec3 n) {
    const Real m2 = dot(v, v);
    if (m2 == 0) return v;
    const Real vn = dot(v, n);
    const Vec3 t = v - vn * n;
    const Real q = vn * vn / m2;
    if (q < Real(1e-4)) return (1 + q * (Real(0.5) + Real(0.375) * q)) * t;
    const Real t2 = dot(t, t);
    return t2 > 0 ? std::sqrt(m2 / t2) * t : Vec3{};
}

// One contact: normal law by name, incremental tangential spring-dashpot with Coulomb limit
// |F_t| <= mu F_n (x tanh(8 |v_t|) for DCDEM), and optional rolling resistance:
// constant torque M_r = -mu_r R* F_n w_r/|w_r| (Zhou et al. 1999) or the elastic-plastic
// spring M_r += -k_r w_r dt, k_r = 2.25 k_n mu_r^2 R*^2, |M_r| <= mu_r R* F_n (Ai et al. 2011).
// n points from j (or the wall) to i; vrel is the contact-point velocity of i relative to j;
// wrel = w_i - w_j.
DF_HD DF_HOT_INLINE ContactResult resolve_contact(const PairParams& p, Real delta, Vec3 n,
                                                  Vec3 vrel, Vec3 wrel, Real r_eff, Real m_eff,
                                                  Real dt, HistoryRef h) {
    const Real vn = dot(vrel, n);
    const Vec3 vt = vrel - vn * n;
    Real factor = 1;
    const NormalResponse r = normal_response(
        p, ContactInput{delta, -vn, r_eff, m_eff, std::sqrt(m_eff)}, dot(vt, vt), factor);
    Vec3 xi = rotate_into_plane(*h.xi, n);
    xi += dt * vt;
    Vec3 ft = -r.kt * xi - r.gt * vt;
    const Real limit = r.friction * factor;
    const Real ft2 = dot(ft, ft);
    if (ft2 > limit * limit) { // sliding: |F_t| = limit, spring length from it
        const Real ft_mag = std::sqrt(ft2);
        ft = (limit / ft_mag) * ft;
        xi = r.kt > 0 ? (Real(-1) / r.kt) * (ft + r.gt * vt) : Vec3{};
    }
    *h.xi = xi;
    Vec3 mroll{};
    if (p.rolling != RollingId::none && r.fn > 0) {
        const Vec3 wr = wrel - dot(wrel, n) * n;
        const Real mmax = p.mu_roll * r_eff * r.fn;
        if (p.rolling == RollingId::constant_torque) {
            const Real w = norm(wr);
            if (w > 0) mroll = (-mmax / w) * wr;
        } else {
            const Real kr = Real(2.25) * r.kn_tangent * p.mu_roll * p.mu_roll * r_eff * r_eff;
            // (a slot without rolling memory starts from zero moment every step)
            mroll = (h.mroll ? rotate_into_plane(*h.mroll, n) : Vec3{}) - (kr * dt) * wr;
            const Real m = norm(mroll);
            if (m > mmax) mroll = (mmax / m) * mroll;
            if (h.mroll) *h.mroll = mroll;
        }
    }
    return {r.fn * n + ft, ft, mroll, r.fn};
}

DF_HD DF_HOT_INLINE ContactResult resolve_contact(const PairParams& p, Real delta, Vec3 n,
                                                  Vec3 vrel, Vec3 wrel, Real r_eff, Real m_eff,
                                                  Real dt, ContactHistory& h) {
    return resolve_contact(p, delta, n, vrel, wrel, r_eff, m_eff, dt, HistoryRef::of(h));
}

} // namespace debrisflow::dem
