#pragma once
#include "debrisflow/core/real.hpp"

namespace debrisflow::dem {

// Damping coefficients that give a contact law a requested coefficient of restitution e.

// Damping ratio of the linear spring-dashpot for restitution e:
// zeta = -ln e / sqrt(pi^2 + ln^2 e) (exact for the linear oscillator).
Real linear_damping_ratio(Real e);

// Tsuji coefficient alpha such that F = k d^1.5 + alpha sqrt(m k) d^0.25 d' (force clamped
// >= 0) rebounds with restitution e. The dimensionless oscillator X'' = -X^1.5 - alpha X^0.25 X'
// shows that e depends on alpha only (Tsuji et al. 1992; Antypov & Elliott 2011); it is
// integrated accurately and inverted by bisection.
Real tsuji_alpha(Real e);
// The least restitution tsuji_alpha accepts (alpha = 22); below it the contact is overdamped
// and the map from e to alpha is ill-conditioned. Case files are checked against it.
inline constexpr Real hertz_min_restitution = 0.01;
// Restitution of that oscillator for a given alpha (the forward map used by tsuji_alpha).
Real tsuji_restitution(Real alpha);

} // namespace debrisflow::dem
