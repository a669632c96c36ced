#include "debrisflow/time/integrator.hpp"
#include "debrisflow/core/error.hpp"
#include "debrisflow/core/stopwatch.hpp"
#include <chrono>
#include <fmt/format.h>

namespace debrisflow::time {

DtLimit Integrator::stable_dt() const {
    DtLimit best{std::numeric_limits<Real>::max(), "none"};
    for (const Phase* p : phases_) {
        DtLimit d = p->stable_dt();
        if (d.dt < best.dt) best = {d.dt, std::string(p->name()) + "/" + d.limiter};
    }
    return best;
}

void Integrator::call_hooks(Hook where, const StepInfo& info) {
    for (auto& h : hooks_)
        if (h.where == where) h.f(info);
}

void Integrator::publish(long step) {
    if (published_step_ == step) return;
    for (Phase* p : phases_) p->publish();
    published_step_ = step;
}

void Integrator::notify_observers(const StepInfo& info, bool force) {
    ScopedTimer timer(t_output_);
    for (auto& o : observers_) {
        const bool due = o.when.due(info.step, info.t);
        // Forced (a run's first or last call): once per step, also after the due calls.
        if (due || (force && o.fired_step != info.step)) {
            o.fired_step = info.step;
            if (o.reads_state) publish(info.step);
            o.f(info);
        }
    }
}

RunResult Integrator::run(Real t0, Real t_end) {
    const auto wall0 = std::chrono::steady_clock::now();
    StepInfo info;
    info.t = t0;
    published_step_ = -1;
    const bool resumed = resume_step_ >= 0;
    if (resumed) info.step = resume_step_;
    resume_step_ = -1;
    // A resumed run keeps the saved derivatives: evaluating the forces again would differ
    // where a model carries state between evaluations (Laminar+SPS's lagged stress).
    for (Phase* p : phases_) {
        p->update_neighbors(reorder_every_ > 0);
        if (!resumed) p->compute_forces();
    }
    DtLimit first = stable_dt();
    info.dt = first.dt;
    info.limiter = first.limiter;
    if (resumed) {
        first.dt = resume_first_dt_;
        for (auto& o : observers_) o.when.skip_through(t0), o.fired_step = info.step;
    } else {
        notify_observers(info, true);
    }
    first_dt_ = first.dt;
    const Real dt_floor = min_dt_fraction_ * first.dt;
    auto finish = [&]() {
        RunResult r;
        r.steps = info.step;
        r.t = info.t;
        r.wall_seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
        for (const Phase* p : phases_) p->add_timings(r.timings);
        r.timings.output = t_output_;
        return r;
    };
    try {
        while (info.t < t_end - Real(1e-12) * (1 + t_end)) {
            call_hooks(Hook::step_begin, info);
            DtLimit lim = stable_dt();
            if (lim.dt < dt_floor)
                throw InstabilityError(fmt::format(
                    "time step collapsed at t = {:.6g} s: dt = {:.3g} s ({}) is below {:.3g} x "
                    "the initial {:.3g} s",
                    info.t, lim.dt, lim.limiter, min_dt_fraction_, first.dt));
            if (info.t + lim.dt > t_end) lim.dt = t_end - info.t;
            info.dt = lim.dt;
            info.limiter = lim.limiter;
            if (scheme_ == Scheme::symplectic) {
                for (Phase* p : phases_) p->predictor(lim.dt);
                for (Phase* p : phases_) p->update_neighbors(false);
                for (Phase* p : phases_) p->compute_forces();
                for (Phase* p : phases_) p->corrector(lim.dt);
            } else {
                const bool euler = euler_every_ > 0 && (info.step + 1) % euler_every_ == 0;
                for (Phase* p : phases_) p->verlet_step(lim.dt, euler);
            }
            info.t += lim.dt;
            ++info.step;
            call_hooks(Hook::after_integration, info);
            const bool reorder = reorder_every_ > 0 && info.step % reorder_every_ == 0;
            for (Phase* p : phases_) p->update_neighbors(reorder);
            call_hooks(Hook::after_neighbors, info);
            for (Phase* p : phases_) p->compute_forces();
            call_hooks(Hook::after_forces, info);
            try {
                for (Phase* p : phases_) p->check_health(info.t);
            } catch (const InstabilityError& e) {
                std::string message = e.what();
                for (const Phase* p : phases_)
                    if (const std::string d = p->diagnose(); !d.empty())
                        message += fmt::format("\n  {}: {}", p->name(), d);
                throw InstabilityError(message);
            }
            call_hooks(Hook::step_end, info);
            info.last = !(info.t < t_end - Real(1e-12) * (1 + t_end));
            notify_observers(info, info.last);
            call_hooks(Hook::after_output, info);
        }
    } catch (const RunStopped&) {
        info.last = true;
        result_ = finish();
        notify_observers(info, true);
        publish(info.step); // the final state on the host, whatever the observers read
        throw;
    }
    result_ = finish();
    publish(info.step);
    return result_;
}

} // namespace debrisflow::time
