// Grain-size sampling: truncated lognormal and sieve curves drawn exactly and in bounded time,
// whatever the window [min, max]; checked against the distributions' own CDFs.
#include "debrisflow/io/size_window.hpp"
#include "debrisflow/scenario/size_sampler.hpp"
#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <vector>

using namespace debrisflow;

namespace {

io::SizeSpec lognormal(Real d50, Real sigma, Real min, Real max) {
    io::SizeSpec s;
    s.distribution = "lognormal";
    s.d50 = d50, s.sigma = sigma, s.min = min, s.max = max;
    return s;
}

std::vector<Real> draw(const io::SizeSpec& s, int dim, int n) {
    scenario::SizeSampler sizes(s, dim, 11);
    std::vector<Real> d(static_cast<std::size_t>(n));
    for (auto& x : d) x = sizes();
    return d;
}

Real fraction_below(const std::vector<Real>& d, Real x) {
    return Real(std::count_if(d.begin(), d.end(), [&](Real v) { return v <= x; })) / Real(d.size());
}

// Truncated normal CDF at z for the window [a, b] in standard-normal units.
Real truncated_cdf(Real z, Real a, Real b) {
    auto phi = [](Real x) { return io::normal_lower_tail(x); };
    return (phi(z) - phi(a)) / (phi(b) - phi(a));
}

} // namespace

// Window probability: Phi(b) - Phi(a); Phi(1) = 0.841345, Phi(6) = 1 - 9.866e-10
// (Abramowitz & Stegun table 26.1).
TEST(SizeSampler, LognormalWindowProbabilityMatchesTables) {
    EXPECT_NEAR(io::lognormal_window_probability(lognormal(1, 1, std::exp(-1.0), std::exp(1.0))),
                2 * 0.841345 - 1, 1e-6);
    EXPECT_NEAR(io::lognormal_window_probability(lognormal(1, 1, std::exp(6.0), 1e30)) / 9.866e-10,
                1, 1e-3);
}

// A window far in the upper tail (3 to 5 sigma, 0.13 % of the distribution) is drawn by
// inverse CDF: every size inside the window, and the truncated CDF at the window's 1/3 point
// reproduced within 3 standard errors of 4000 draws (0.024).
TEST(SizeSampler, LognormalTailWindowIsDrawnExactly) {
    const auto s = lognormal(0.01, 0.3, 0.01 * std::exp(0.9), 0.01 * std::exp(1.5));
    const auto d = draw(s, 3, 4000);
    for (Real x : d) {
        ASSERT_GE(x, s.min);
        ASSERT_LE(x, s.max);
    }
    const Real z = 3 + 2.0 / 3;
    EXPECT_NEAR(fraction_below(d, 0.01 * std::exp(0.3 * z)), truncated_cdf(z, 3, 5), 0.024);
}

// Same in the lower tail, below -4 sigma (3e-5 of the distribution).
TEST(SizeSampler, LognormalLowerTailWindowIsDrawnExactly) {
    const auto s = lognormal(0.05, 0.5, 0.05 * std::exp(-3.0), 0.05 * std::exp(-2.0));
    const auto d = draw(s, 2, 4000);
    const Real z = -5.5;
    EXPECT_NEAR(fraction_below(d, 0.05 * std::exp(0.5 * z)), truncated_cdf(z, -6, -4), 0.024);
    EXPECT_GE(*std::min_element(d.begin(), d.end()), s.min);
    EXPECT_LE(*std::max_element(d.begin(), d.end()), s.max);
}

// A wide sieve curve (1 mm to 1 m, mass passing linear in d) in 3D: by number the grains
// follow n(d) ∝ d^-3 on each segment. For a single segment [a, b] the number fraction below x
// is (1 - (a/x)^2) / (1 - (a/b)^2); at x = 2a that is 0.75 within 3 standard errors (0.02).
// Rejection from the mass curve would need ~1e9 draws per grain here.
TEST(SizeSampler, WideSieveCurveIsDrawnByNumberExactly) {
    io::SizeSpec s;
    s.distribution = "sieve";
    s.sieve_sizes = {0.001, 1.0};
    s.sieve_passing = {0, 100};
    s.min = 0.001, s.max = 1.0;
    const auto d = draw(s, 3, 4000);
    EXPECT_NEAR(fraction_below(d, 0.002), (1 - 0.25) / (1 - 1e-6), 0.02);
    EXPECT_GE(*std::min_element(d.begin(), d.end()), s.min);
}

// A window cutting a sieve curve keeps the curve's shape inside it: 2D discs (number ∝ d^-2),
// sizes 2-4-6 mm at 0-50-100 % passing, window [3, 5] mm. Number weights: segment
// [3, 4] mm: 25 (1/3 - 1/4) = 2.0833, segment [4, 5] mm: 25 (1/4 - 1/5) = 1.25; so 0.625 of
// the grains are 4 mm or finer (3 standard errors of 4000 draws: 0.023).
TEST(SizeSampler, SieveWindowKeepsTheCurveInside) {
    io::SizeSpec s;
    s.distribution = "sieve";
    s.sieve_sizes = {0.002, 0.004, 0.006};
    s.sieve_passing = {0, 50, 100};
    s.min = 0.003, s.max = 0.005;
    EXPECT_NEAR(io::sieve_window_mass_fraction(s), 0.5, 1e-12);
    const auto d = draw(s, 2, 4000);
    EXPECT_NEAR(fraction_below(d, 0.004), 2.0833 / (2.0833 + 1.25), 0.023);
    EXPECT_GE(*std::min_element(d.begin(), d.end()), s.min);
    EXPECT_LE(*std::max_element(d.begin(), d.end()), s.max);
}
