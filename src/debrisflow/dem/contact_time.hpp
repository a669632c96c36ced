#pragma once
#include "debrisflow/dem/contact_params.hpp"
#include <cmath>

namespace debrisflow::dem {

// How long a normal impact of a material pair lasts: the time scale that bounds the DEM step
// (critical_dt.cpp) and the sub-step horizon of rigid bodies' contacts (body_contacts.cpp).

// Undamped duration: linear spring pi sqrt(m*/k_n); Hertz-type laws (hertz_mindlin, dcdem)
// 2.868 (m*^2 / (E*^2 R* v))^(1/5) at approach speed v (Johnson 1985, eq. 11.24).
inline Real undamped_contact_time(const PairParams& p, Real m_eff, Real r_eff, Real v) {
    constexpr Real pi = Real(3.14159265358979323846);
    if (p.law == LawId::linear) return pi * std::sqrt(m_eff / p.kn);
    return Real(2.868) * std::pow(m_eff * m_eff / (p.e_star * p.e_star * r_eff * v), Real(0.2));
}

// Duration with the law's damping where it has a closed form: the damped linear oscillator
// lasts pi / (w0 sqrt(1 - zeta^2)); the Hertz-type laws keep their undamped time.
inline Real contact_time(const PairParams& p, Real m_eff, Real r_eff, Real v) {
    const Real t = undamped_contact_time(p, m_eff, r_eff, v);
    return p.law == LawId::linear ? t / std::sqrt(1 - p.damping * p.damping) : t;
}

} // namespace debrisflow::dem
