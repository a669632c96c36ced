#pragma once
#include "debrisflow/io/case_spec.hpp"
#include <cmath>
#include <random>

namespace debrisflow::scenario {

// Draws diameters from the block's distribution. Sieve curves give mass passing, so sizes
// drawn from that curve are kept with probability (d_min/d)^dim to turn mass into number.
class SizeSampler {
public:
    SizeSampler(const io::SizeSpec& s, int dim, unsigned seed) : s_(s), dim_(dim), rng_(seed) {}
    Real operator()() {
        if (s_.distribution == "mono") return s_.diameter;
        std::uniform_real_distribution<Real> u(0, 1);
        for (;;) {
            Real d;
            if (s_.distribution == "lognormal") {
                std::normal_distribution<Real> z(0, 1);
                d = s_.d50 * std::exp(s_.sigma * z(rng_));
            } else {
                const Real p = u(rng_) * (s_.sieve_passing.back() - s_.sieve_passing.front()) +
                               s_.sieve_passing.front();
                std::size_t k = 1;
                while (k + 1 < s_.sieve_passing.size() && s_.sieve_passing[k] < p) ++k;
                const Real p0 = s_.sieve_passing[k - 1], p1 = s_.sieve_passing[k];
                const Real f = p1 > p0 ? (p - p0) / (p1 - p0) : 0;
                d = s_.sieve_sizes[k - 1] + f * (s_.sieve_sizes[k] - s_.sieve_sizes[k - 1]);
                if (u(rng_) > std::pow(s_.min / d, Real(dim_))) continue;
            }
            if (d >= s_.min && d <= s_.max) return d;
        }
    }
    std::mt19937_64& rng() { return rng_; }

private:
    io::SizeSpec s_;
    int dim_;
    std::mt19937_64 rng_;
};

} // namespace debrisflow::scenario
