#pragma once
#include "debrisflow/core/real.hpp"

namespace debrisflow::time {

// When an observer fires: every `interval` seconds of simulated time or every `steps` steps.
// The Integrator also calls every observer at the first and the last step.
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

    // True if the observer should fire at (step, t); advances the internal clock.
    bool due(long step, Real t) {
        bool fire = false;
        if (interval_ > 0 && t >= next_ - Real(1e-12) * (1 + next_)) {
            fire = true;
            while (next_ <= t + Real(1e-12) * (1 + t)) next_ += interval_;
        }
        if (steps_ > 0 && step % steps_ == 0) fire = true;
        return fire;
    }

    // Advances the clock as if the schedule had been checked at every step up to time t (a
    // resumed run): the same additions from 0 as the saved run made, so the same next time.
    void skip_through(Real t) {
        if (interval_ > 0)
            while (!(t < next_ - Real(1e-12) * (1 + next_))) next_ += interval_;
    }

private:
    Real interval_ = 0, next_ = 0;
    long steps_ = 0;
};

} // namespace debrisflow::time
