#pragma once
#include "debrisflow/io/case_spec.hpp"
#include <random>
#include <vector>

namespace debrisflow::scenario {

// Draws diameters from the block's distribution, exactly and in bounded time:
// - lognormal truncated to [min, max]: rejection while the window holds at least half of the
//   distribution (the seeded streams of the shipped cases), inverse CDF otherwise;
// - sieve (mass passing, linear between sieves): a segment drawn by its number of grains, then
//   d within it from the number density ∝ d^-dim (mass per grain ∝ d^dim), by inverse CDF.
class SizeSampler {
public:
    SizeSampler(const io::SizeSpec& s, int dim, unsigned seed);
    Real operator()();
    std::mt19937_64& rng() { return rng_; }

private:
    Real lognormal();
    Real sieve();
    io::SizeSpec s_;
    int dim_;
    std::mt19937_64 rng_;
    Real alpha_ = 0, beta_ = 0; // lognormal window in standard-normal units
    bool reject_ = true;        // lognormal: rejection (window probability >= 1/2)
    // sieve segments clipped to [min, max]: ends and cumulative number weights
    std::vector<Real> seg_lo_, seg_hi_, seg_cum_;
};

} // namespace debrisflow::scenario
