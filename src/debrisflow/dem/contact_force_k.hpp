#pragma once
#include "debrisflow/core/vec3_k.hpp"
#include "debrisflow/dem/contact_frame_k.hpp"
#include "debrisflow/dem/contact_laws_k.hpp"
#include "debrisflow/dem/rolling_models_k.hpp"

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

// One contact: the pair's normal law (dem/laws/), incremental tangential spring-dashpot with
// Coulomb limit |F_t| <= mu F_n (x the law's factor, tanh(8 |v_t|) for DCDEM), and the pair's
// rolling resistance model (dem/rolling/) while the contact is compressive.
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
    if (ft2 > limit * limit) {
        // sliding: |F_t| = limit, and the spring alone holds it, xi = -F_t / k_t (Cundall &
        // Strack 1979; as LIGGGHTS). Storing the dashpot's share too, xi = -(F_t + g_t v_t) / k_t,
        // turns the spring against the slip once g_t |v_t| > mu F_n, and it then pushes the grain
        // along its old slip when the contact sticks: with e = 0.1 the discs of a settled column
        // kept spinning (rotational energy growing, settling stalled at a ratio of 0.12).
        // limit / |F_t| as limit sqrt(ft2) / ft2: the division runs beside the square root
        ft = (limit * std::sqrt(ft2) * (Real(1) / ft2)) * ft;
        xi = r.kt > 0 ? (Real(-1) / r.kt) * ft : Vec3{};
    }
    *h.xi = xi;
    // (a slot without rolling memory, h.mroll null, starts from zero moment every step)
    const Vec3 mroll =
        r.fn > 0 ? Rolling::moment(p, RollingInput{wrel, n, r.fn, r.kn_tangent, r_eff, dt}, h.mroll)
                 : Vec3{};
    return {r.fn * n + ft, ft, mroll, r.fn};
}

DF_HD DF_HOT_INLINE ContactResult resolve_contact(const PairParams& p, Real delta, Vec3 n,
                                                  Vec3 vrel, Vec3 wrel, Real r_eff, Real m_eff,
                                                  Real dt, ContactHistory& h) {
    return resolve_contact(p, delta, n, vrel, wrel, r_eff, m_eff, dt, HistoryRef::of(h));
}

} // namespace debrisflow::dem
