#pragma once
#include "debrisflow/time/phase.hpp"
#include "debrisflow/time/schedule.hpp"
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace debrisflow::time {

// Where a hook runs inside a step.
// after_output runs once the observers have seen the step (a checkpoint there holds the
// probes' rows of the step).
enum class Hook {
    step_begin,
    after_neighbors,
    after_forces,
    after_integration,
    step_end,
    after_output
};

// What observers and hooks see of the current step.
struct StepInfo {
    long step = 0;
    Real t = 0;
    Real dt = 0;
    std::string limiter;
    bool last = false; // final call of the run (end time reached or run stopped)
};

struct RunResult {
    long steps = 0;
    Real t = 0;
    double wall_seconds = 0;
    Timings timings;
};

// The one time loop: the symplectic position-Verlet scheme of DualSPHysics (Leimkuhler et al.
// 1996; Dominguez et al. 2022, eqs. 20-22), a predictor to t_n + dt/2 with the derivatives at
// t_n and a corrector with those at t_n + dt/2 (two force evaluations per step):
//   predictor: x, v, rho advanced by dt/2;   forces at t_n+1/2
//   corrector: v_n+1 = v_n + dt a_n+1/2, x_n+1 = x_n + dt (v_n + v_n+1)/2,
//              rho_n+1 = rho_n (2 - eps)/(2 + eps), eps = -dt drho_n+1/2 / rho_n+1/2
// The alternative `verlet` scheme (one force evaluation per step, as DualSPHysics's examples
// use) is available for speed comparisons; the validation suite runs the symplectic scheme.
// dt is the minimum over phases of their stable step; the limiting criterion is reported.
enum class Scheme { symplectic, verlet };

class Integrator {
public:
    using Callback = std::function<void(const StepInfo&)>;

    void add_phase(Phase* p) { phases_.push_back(p); }
    void add_hook(Hook where, Callback f) { hooks_.push_back({where, std::move(f)}); }
    // An observer that reads the particles' state; `reads_state = false` for those that read
    // only counts and clocks, so that a resident phase is not copied back for them.
    void add_observer(Schedule when, Callback f, bool reads_state = true) {
        observers_.push_back({when, std::move(f), reads_state});
    }
    // Brings every phase's state to the host (Phase::publish) once per step.
    void publish(long step);
    void set_scheme(Scheme s, int euler_every = 40) {
        scheme_ = s;
        euler_every_ = euler_every;
    }
    // Particles are sorted by cell every n steps (0: never).
    void set_reorder_every(int n) { reorder_every_ = n; }

    // Runs from t0 to t_end. On instability the observers get a final call (last = true)
    // and the InstabilityError propagates.
    RunResult run(Real t0, Real t_end);
    // The next run continues a saved run after `step` steps whose first step was `first_dt`
    // (the dt-collapse watchdog's reference): no observer is called at t0 (the saved run
    // called those that were due), time schedules resume after t0, and the phases' saved
    // derivatives are used as they are (no force evaluation at t0).
    void resume(long step, Real first_dt) {
        resume_step_ = step;
        resume_first_dt_ = first_dt;
    }
    // The first step's dt of the current (or resumed) run.
    Real first_dt() const { return first_dt_; }
    DtLimit stable_dt() const;
    // Steps, time and timings of the last run, also after it stopped on an instability.
    const RunResult& result() const { return result_; }

private:
    void call_hooks(Hook where, const StepInfo& info);
    void notify_observers(const StepInfo& info, bool force);
    struct HookEntry {
        Hook where;
        Callback f;
    };
    struct ObserverEntry {
        Schedule when;
        Callback f;
        bool reads_state = true;
        long fired_step = -1; // the step it was last called at
    };
    std::vector<Phase*> phases_;
    std::vector<HookEntry> hooks_;
    std::vector<ObserverEntry> observers_;
    // dt below this fraction of the first step's dt stops the run (dt collapse watchdog).
    static constexpr Real min_dt_fraction_ = 1e-3;
    int reorder_every_ = 1;
    Scheme scheme_ = Scheme::symplectic;
    int euler_every_ = 40;
    double t_output_ = 0;
    long resume_step_ = -1;
    long published_step_ = -1;
    Real resume_first_dt_ = 0, first_dt_ = 0;
    RunResult result_;
};

} // namespace debrisflow::time
