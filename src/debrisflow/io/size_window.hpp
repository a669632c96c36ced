#pragma once
#include "debrisflow/io/case_spec.hpp"

namespace debrisflow::io {

// Standard normal lower and upper tails, Phi(x) = erfc(-x/sqrt2)/2 and Q(x) = erfc(x/sqrt2)/2,
// each accurate where it is small.
Real normal_lower_tail(Real x);
Real normal_upper_tail(Real x);

// A lognormal size window [min, max] in standard-normal units, a = ln(min/d50)/sigma and
// b = ln(max/d50)/sigma, clamped to [-40, 40] where both tails are 0 in double.
void lognormal_window(const SizeSpec& s, Real& a, Real& b);

// Probability that a lognormal(d50, sigma) diameter lies within [min, max]: Phi(b) - Phi(a),
// computed in the tail the window lies in.
Real lognormal_window_probability(const SizeSpec& s);

// Mass fraction of a sieve curve (mass passing, linear between sieves) within [min, max];
// 0 when the window misses every rising segment of the curve.
Real sieve_window_mass_fraction(const SizeSpec& s);

} // namespace debrisflow::io
