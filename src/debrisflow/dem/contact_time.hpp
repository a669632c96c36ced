#pragma once
#include "debrisflow/dem/contact_laws_k.hpp"

namespace debrisflow::dem {

// How long a normal impact of a material pair lasts, as the pair's law gives it: the time
// scale that bounds the DEM step (critical_dt.cpp) and the sub-step horizon of rigid bodies'
// contacts (body_contacts.cpp). v: the approach speed (Hertz-type laws depend on it).

// Undamped duration (e.g. pi sqrt(m*/k_n) for the linear spring, 2.868 (m*^2 / (E*^2 R* v))^(1/5)
// for the Hertz-type laws, Johnson 1985 eq. 11.24).
inline Real undamped_contact_time(const PairParams& p, Real m_eff, Real r_eff, Real v) {
    return ContactLawRegistry::visit_index(
        p.law, [&]<class L>() { return L::undamped_contact_time(p, m_eff, r_eff, v); });
}

// Duration with the law's damping where it has a closed form (the damped linear oscillator);
// the others keep their undamped time.
inline Real contact_time(const PairParams& p, Real m_eff, Real r_eff, Real v) {
    return ContactLawRegistry::visit_index(
        p.law, [&]<class L>() { return L::contact_time(p, m_eff, r_eff, v); });
}

} // namespace debrisflow::dem
