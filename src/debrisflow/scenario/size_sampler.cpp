#include "debrisflow/scenario/size_sampler.hpp"
#include "debrisflow/io/size_window.hpp"

#include <algorithm>
#include <cmath>

namespace debrisflow::scenario {
SizeSampler::SizeSampler(const io::SizeSpec& s, int dim, unsigned seed)
    : s_(s), dim_(dim), rng_(seed) {
    if (s_.distribution == "lognormal") {
        io::lognormal_window(s_, alpha_, beta_);
        reject_ = io::lognormal_window_probability(s_) >= Real(0.5);
    } else if (s_.distribution == "sieve") {
        // Number of grains in [lo, hi] of segment k: slope_k ∫ d^-dim dd, with slope_k the
        // mass passing per metre; scaled by the smallest lower end so that no power overflows.
        const auto& d = s_.sieve_sizes;
        const auto& p = s_.sieve_passing;
        const Real n1 = Real(dim_ - 1);
        Real ref = 0;
        for (std::size_t k = 1; k < d.size(); ++k) {
            const Real lo = std::max(d[k - 1], s_.min), hi = std::min(d[k], s_.max);
            if (!(hi > lo) || !(p[k] > p[k - 1])) continue;
            if (ref == 0) ref = lo;
            const Real slope = (p[k] - p[k - 1]) / (d[k] / ref - d[k - 1] / ref);
            // ∫_lo^hi (d/ref)^-dim d(d/ref) = (lo/ref)^(1-dim) (1 - (lo/hi)^(dim-1)) / (dim-1)
            const Real n = slope * std::pow(ref / lo, n1) * (1 - std::pow(lo / hi, n1)) / n1;
            seg_lo_.push_back(lo);
            seg_hi_.push_back(hi);
            seg_cum_.push_back((seg_cum_.empty() ? 0 : seg_cum_.back()) + n);
        }
    }
}

Real SizeSampler::operator()() {
    if (s_.distribution == "lognormal") return lognormal();
    if (s_.distribution == "sieve") return sieve();
    return s_.diameter;
}

Real SizeSampler::lognormal() {
    if (reject_) {
        for (;;) {
            // a fresh distribution per draw (it would otherwise hand out the cached second
            // value of its pair): the seeded streams of earlier versions, grain for grain
            std::normal_distribution<Real> z(0, 1);
            const Real d = s_.d50 * std::exp(s_.sigma * z(rng_));
            if (d >= s_.min && d <= s_.max) return d;
        }
    }
    // Inverse CDF by bisection on the tail the window lies in (monotone, 200 halvings at most
    // reach the resolution of double over [-40, 40]).
    std::uniform_real_distribution<Real> u(0, 1);
    const Real v = u(rng_);
    const bool upper = alpha_ >= 0;
    auto tail = [&](Real x) { return upper ? io::normal_upper_tail(x) : io::normal_lower_tail(x); };
    // target tail value between the window's ends
    const Real ta = tail(alpha_), tb = tail(beta_);
    const Real target = ta + v * (tb - ta);
    Real lo = alpha_, hi = beta_;
    for (int i = 0; i < 200 && hi - lo > 1e-14 * (1 + std::abs(lo)); ++i) {
        const Real mid = Real(0.5) * (lo + hi);
        // lower_tail increases with x, upper_tail decreases: compare along the window
        const bool below = upper ? tail(mid) > target : tail(mid) < target;
        (below ? lo : hi) = mid;
    }
    return std::clamp(s_.d50 * std::exp(s_.sigma * Real(0.5) * (lo + hi)), s_.min, s_.max);
}

Real SizeSampler::sieve() {
    std::uniform_real_distribution<Real> u(0, 1);
    const Real pick = u(rng_) * seg_cum_.back();
    const std::size_t k = std::size_t(std::upper_bound(seg_cum_.begin(), seg_cum_.end() - 1, pick) -
                                      seg_cum_.begin());
    const Real lo = seg_lo_[k], hi = seg_hi_[k], n1 = Real(dim_ - 1);
    // F(d) = (1 - (lo/d)^(dim-1)) / (1 - (lo/hi)^(dim-1)) inverted
    const Real r = std::pow(lo / hi, n1);
    const Real d = lo * std::pow(1 - u(rng_) * (1 - r), -1 / n1);
    return std::clamp(d, lo, hi);
}

} // namespace debrisflow::scenario
