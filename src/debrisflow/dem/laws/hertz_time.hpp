#pragma once
#include "debrisflow/dem/contact_params.hpp"
#include <cmath>

namespace debrisflow::dem {

// Duration of a Hertzian impact at approach speed v: 2.868 (m*^2 / (E*^2 R* v))^(1/5)
// (Johnson 1985, eq. 11.24); the laws built on the Hertz spring share it.
inline Real hertz_contact_time(const PairParams& p, Real m_eff, Real r_eff, Real v) {
    return Real(2.868) * std::pow(m_eff * m_eff / (p.e_star * p.e_star * r_eff * v), Real(0.2));
}

} // namespace debrisflow::dem
