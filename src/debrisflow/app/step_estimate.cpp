#include "debrisflow/app/step_estimate.hpp"
#include "debrisflow/core/error.hpp"
#include <cmath>
#include <fmt/format.h>

namespace debrisflow::app {

StepEstimate estimate_step(Simulation& sim) {
    const io::CaseSpec& spec = sim.spec();
    StepEstimate e;
    if (sim.has_fluid()) {
        const auto d = sim.solver().initial_dt();
        e = {d.dt, "sph/" + d.limiter};
    }
    if (sim.has_grains() && !spec.dem.params.subcycle && sim.grains().dt() < e.dt)
        e = {sim.grains().dt(), "dem"};
    if (sim.has_bodies() && spec.rigid.dt > 0 && spec.rigid.dt < e.dt)
        e = {spec.rigid.dt, "rigid dt"};
    const bool fem_alone = !sim.has_fluid() && !sim.has_grains() && !sim.has_bodies();
    if (sim.has_fem() && fem_alone && sim.fem().critical_dt() < e.dt)
        e = {sim.fem().critical_dt(), "fem element CFL"};
    return e;
}

void require_feasible_steps(Simulation& sim) {
    const StepEstimate e = estimate_step(sim);
    const io::CaseSpec& spec = sim.spec();
    if (!(e.dt > 0) || !std::isfinite(e.dt))
        throw InputError(fmt::format("{}: the time step is {} s ({}); check the material and "
                                     "fluid parameters",
                                     spec.time_origin.at("end"), e.dt, e.limiter));
    const double steps = double(spec.t_end) / double(e.dt);
    if (steps > 1e10)
        throw InputError(fmt::format(
            "{}: time.end = {} s needs about {:.3g} steps of {:.3g} s (limited by {}): more than "
            "1e10 steps cannot finish; shorten time.end, or coarsen what limits the step (dp, "
            "the smallest grain, the stiffness)",
            spec.time_origin.at("end"), spec.t_end, steps, e.dt, e.limiter));
}

} // namespace debrisflow::app
