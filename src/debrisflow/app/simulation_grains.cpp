// The grains' settling before a run, and the rigid bodies' VTK frames.
#include "debrisflow/app/simulation.hpp"
#include "debrisflow/app/stop_request.hpp"
#include "debrisflow/core/error.hpp"
#include <fmt/format.h>

namespace debrisflow::app {

void Simulation::settle_grains() {
    dem::DemSolver& d = *dem_;
    const bool measuring = d.measuring_contact_force();
    d.measure_contact_force(true);
    d.update_neighbors(true);
    d.compute_forces();
    const Real dt = d.dt();
    const long check_every = 200;
    long steps = 0;
    Real ratio = d.unbalanced_ratio();
    while (ratio >= spec_.dem.settle_ratio) {
        if (Real(steps) * dt > spec_.dem.settle_max_time)
            throw InstabilityError(fmt::format(
                "grains did not settle within dem.settle_max_time = {} s (mean unbalanced / "
                "mean contact force = {:.3g}, target {})",
                spec_.dem.settle_max_time, ratio, spec_.dem.settle_ratio));
        for (long k = 0; k < check_every; ++k, ++steps) {
            if (const int sig = stop_signal()) // Ctrl-C or SIGTERM: before the next step
                throw InterruptedError(fmt::format("stopped on request (signal {}) while settling "
                                                   "the grains, after {:.4g} s of settling (mean "
                                                   "unbalanced / mean contact force {:.3g})",
                                                   sig, Real(steps) * dt, ratio));
            d.step(dt);
        }
        d.check_health(Real(steps) * dt);
        ratio = d.unbalanced_ratio();
    }
    d.measure_contact_force(measuring);
    d.stop_grains();
    for (auto& w : dem_walls_.walls()) w.impulse = {}, w.impulse_time = 0;
    log_.line(fmt::format("grains settled: {} steps ({:.4g} s), mean unbalanced / mean contact "
                          "force = {:.3g} (< {}), {} contacts",
                          steps, Real(steps) * dt, ratio, spec_.dem.settle_ratio, d.contacts()));
    settled_ = true;
}

void Simulation::write_bodies(io::VtkSeries& vtk, Real t) const {
    std::vector<Vec3> x, v;
    std::vector<float> r;
    std::vector<std::int32_t> body;
    const auto& states = rigid_->bodies();
    const auto& models = rigid_->models();
    for (std::size_t b = 0; b < states.size(); ++b) {
        const auto& s = states[b];
        if (s.motion == rigid::Motion::removed) continue; // left through an outlet
        auto add = [&](Vec3 local, Real radius) {
            const Vec3 p = s.to_world(local);
            x.push_back(p);
            v.push_back(s.point_velocity(p));
            r.push_back(float(radius));
            body.push_back(std::int32_t(b));
        };
        for (const auto& sp : models[b].samples) add(sp.center, sp.radius);
        if (models[b].samples.empty())
            for (const auto& vx : models[b].vertices) add(vx, 0);
        add({}, 0); // the centre of mass
    }
    vtk.write(x, v, r, body, t);
}

} // namespace debrisflow::app
