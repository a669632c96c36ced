#pragma once
#include "debrisflow/core/real.hpp"
#include <vector>

namespace debrisflow::time {

// When an observer fires: every `interval` seconds of simulated time, every `steps` steps,
// and/or at listed times. Always fires at the first and the last step.
class Schedule {
public:
    static Schedule every_time(Real interval) {
        Schedule s;
        s.interval_ = interval;
        return s;
    }
    static Schedule every_steps(long n) {
        Schedule s;
        s.steps_ = n;
        return s;
    }
    void add_time(Real t) { times_.push_back(t); }

    // True if the observer should fire at (step, t); advances the internal clock.
    bool due(long step, Real t) {
        bool fire = false;
        if (interval_ > 0 && t >= next_ - Real(1e-12) * (1 + next_)) {
            fire = true;
            while (next_ <= t + Real(1e-12) * (1 + t)) next_ += interval_;
        }
        if (steps_ > 0 && step % steps_ == 0) fire = true;
        for (Real& at : times_)
            if (at >= 0 && t >= at) {
                fire = true;
                at = -1;
            }
        return fire;
    }

private:
    Real interval_ = 0, next_ = 0;
    long steps_ = 0;
    std::vector<Real> times_;
};

} // namespace debrisflow::time
