#include "debrisflow/app/simulation.hpp"
#include "debrisflow/core/error.hpp"
#include "debrisflow/exec/parallel.hpp"
#include "debrisflow/io/vtk_writer.hpp"
#include "debrisflow/scenario/build_particles.hpp"
#include <chrono>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>

namespace debrisflow::app {

Simulation::Simulation(io::CaseSpec spec) : spec_(std::move(spec)) {
    scenario::build_particles(spec_, set_);
    solver_ = std::make_unique<sph::SphSolver>(spec_.sph, set_, spec_.domain);
    for (const auto& p : spec_.probes) probes_.push_back(probes::make_probe(p, spec_));
}

probes::Probe& Simulation::probe(const std::string& name) {
    for (auto& p : probes_)
        if (p->name() == name) return *p;
    throw std::out_of_range("no probe named " + name);
}

std::size_t Simulation::memory_bytes() const {
    const std::size_t n = std::size_t(set_.size());
    // Particle fields (21 Real + kind + group + id), doubled while reordering; integrator
    // copies (7 Real); grid arrays; half pair list: half the neighbours within support + skin
    // (1.1 support) plus 25 % capacity slack, 4 bytes each.
    const double pi = 3.14159265358979, reach = 1.1 * solver_->support() / spec_.dp;
    const double neighbours =
        spec_.dim == 3 ? 4.0 / 3.0 * pi * reach * reach * reach : pi * reach * reach;
    const std::size_t list = std::size_t(0.5 * neighbours * 1.25) * sizeof(Index);
    return n * (2 * (21 * sizeof(Real) + 1 + 2 + 8) + 7 * sizeof(Real) + 3 * sizeof(Index) + list +
                4 * sizeof(Real) * 2);
}

io::RunReport Simulation::run(const RunOptions& opt) {
    exec::set_threads(opt.threads);
    io::RunReport report;
    report.threads = exec::max_threads();
    report.fluid = set_.count(particles::Kind::fluid);
    report.boundary = set_.count(particles::Kind::boundary);
    report.initial_dt = solver_->initial_dt();
    const bool files = !opt.out_dir.empty();
    log_.set_quiet(opt.quiet);
    std::unique_ptr<io::VtkSeries> vtk;
    if (files) {
        std::filesystem::create_directories(opt.out_dir);
        log_.open(opt.out_dir + "/log.txt");
        std::ofstream(opt.out_dir + "/case.toml") << spec_.resolved_toml << "\n";
        for (auto& p : probes_) p->open(opt.out_dir + "/probes");
        if (spec_.vtk) vtk = std::make_unique<io::VtkSeries>(opt.out_dir + "/vtk");
    }
    log_.line(fmt::format("debrisflow: case '{}' ({}), {}D, dp = {} m, end time {} s", spec_.name,
                          spec_.file, spec_.dim, spec_.dp, spec_.t_end));
    log_.line(fmt::format("particles: {} fluid, {} boundary; threads: {}", report.fluid,
                          report.boundary, report.threads));
    log_.line(fmt::format("sph: kernel {}, h = {:.4g} m, c0 = {:.4g} m/s, viscosity {}, "
                          "diffusion {}; initial dt = {:.3g} s (limited by {})",
                          spec_.sph.kernel, spec_.sph.h, spec_.sph.c0, spec_.sph.viscosity,
                          spec_.sph.diffusion, report.initial_dt.dt, report.initial_dt.limiter));

    time::Integrator integ;
    integ.add_phase(solver_.get());
    integ.set_reorder_every(spec_.sph.reorder_every);
    integ.set_scheme(spec_.scheme == "verlet" ? time::Scheme::verlet : time::Scheme::symplectic,
                     spec_.verlet_euler_every);
    for (std::size_t w = 0; w < spec_.walls.size(); ++w) {
        if (!spec_.walls[w].remove_at) continue;
        const Real at = *spec_.walls[w].remove_at;
        auto removed = std::make_shared<bool>(false);
        integ.add_hook(time::Hook::step_begin, [this, w, at, removed](const time::StepInfo& s) {
            if (*removed || s.t < at) return;
            solver_->remove_group(std::int16_t(w));
            *removed = true;
            log_.line(fmt::format("t = {:.6g} s: wall '{}' removed", s.t, spec_.walls[w].name));
        });
    }
    for (auto& p : probes_) {
        probes::Probe* raw = p.get();
        integ.add_observer(time::Schedule::every_time(p->every()),
                           [this, raw](const time::StepInfo& s) { raw->record(s.t, *solver_); });
    }
    if (vtk)
        integ.add_observer(spec_.vtk_every > 0 ? time::Schedule::every_time(spec_.vtk_every)
                                               : time::Schedule::every_steps(0),
                           [this, &vtk](const time::StepInfo& s) { vtk->write(set_, s.t); });
    const auto wall0 = std::chrono::steady_clock::now();
    auto last_report = wall0;
    integ.add_observer(time::Schedule::every_steps(1), [&](const time::StepInfo& s) {
        const auto now = std::chrono::steady_clock::now();
        if (!s.last &&
            std::chrono::duration<double>(now - last_report).count() < spec_.progress_seconds)
            return;
        last_report = now;
        const double wall = std::chrono::duration<double>(now - wall0).count();
        const double pss = wall > 0 ? double(set_.size()) * double(s.step) / wall : 0;
        const double eta = s.t > 0 ? wall * (spec_.t_end - s.t) / s.t : 0;
        log_.line(fmt::format("t = {:.5f} s  step {}  dt = {:.3e} s ({})  {:.3g} "
                              "particle-steps/s  wall {:.1f} s  ETA {:.0f} s",
                              s.t, s.step, s.dt, s.limiter, pss, wall, eta));
    });

    try {
        report.result = integ.run(t_, opt.until > 0 ? opt.until : spec_.t_end);
        t_ = report.result.t;
        report.pair_list_builds = solver_->list_builds();
        report.pairs = solver_->pair_list().pairs();
    } catch (const InstabilityError& e) {
        report.status = "unstable";
        report.message = e.what();
        report.result = integ.result();
        log_.line(std::string("ERROR: run stopped: ") + e.what());
        if (files) {
            io::write_summary(opt.out_dir + "/summary.json", spec_, report, probes_);
            log_.line("output so far kept in " + opt.out_dir);
        }
        throw;
    }
    const auto& r = report.result;
    const double pss = r.wall_seconds > 0 ? double(set_.size()) * r.steps / r.wall_seconds : 0;
    log_.line(fmt::format("finished: {} steps to t = {:.6g} s in {:.2f} s wall, {:.3g} "
                          "particle-steps/s (neighbours {:.2f} s, forces {:.2f} s, integration "
                          "{:.2f} s, output {:.2f} s)",
                          r.steps, r.t, r.wall_seconds, pss, r.timings.neighbors, r.timings.forces,
                          r.timings.integration, r.timings.output));
    if (files) {
        io::write_summary(opt.out_dir + "/summary.json", spec_, report, probes_);
        log_.line("output: " + opt.out_dir +
                  " (vtk/particles.pvd for ParaView, probes/*.csv, "
                  "summary.json, log.txt)");
    }
    return report;
}

} // namespace debrisflow::app
