#include "debrisflow/app/simulation.hpp"
#include "debrisflow/app/stop_request.hpp"
#include "debrisflow/core/error.hpp"
#include "debrisflow/exec/parallel.hpp"
#include "debrisflow/io/vtk_writer.hpp"
#include "debrisflow/probes/flow_probes.hpp"
#include "debrisflow/probes/probe_registry.hpp"
#include "debrisflow/scenario/build_bodies.hpp"
#include "debrisflow/scenario/build_fem.hpp"
#include "debrisflow/scenario/build_grains.hpp"
#include "debrisflow/scenario/build_particles.hpp"
#include "debrisflow/scenario/resource_estimate.hpp"
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>

namespace debrisflow::app {

Simulation::Simulation(io::CaseSpec spec)
    : spec_(std::move(spec)), domain_exit_(spec_.domain_exit, spec_.domain, spec_.dim) {
    // Nothing is allocated for a case that cannot fit in memory (or --max-memory).
    scenario::require_within_budget(scenario::estimate_resources(spec_));
    // The probes read their own settings: a bad one is rejected before anything is built.
    for (const auto& p : spec_.probes) probes_.push_back(probes::make_probe(p, spec_));
    std::vector<scenario::BuiltBody> bodies;
    if (spec_.has_bodies()) bodies = scenario::build_body_geometry(spec_);
    ParticleId first_body_particle = 0;
    if (spec_.has_fem()) fem_ = scenario::make_fem_solver(spec_);
    if (!spec_.fluids.empty()) {
        first_body_particle = scenario::build_particles(spec_, set_, bodies);
        if (fem_) {
            const int layers =
                spec_.fem.layers > 0 ? spec_.fem.layers : sph::kernel_layers(spec_.sph.h, spec_.dp);
            sph_fem_ = std::make_unique<coupling::SphFemCoupling>(*fem_, set_, spec_.dp, layers,
                                                                  spec_.sph.rho0, spec_.dim);
            sph_fem_->connect();
        }
        solver_ = std::make_unique<sph::SphSolver>(spec_.sph, set_, spec_.domain);
        host_fluid_ = std::make_unique<probes::HostFluidReader>(*solver_);
        if (spec_.backend != "host") {
            resident_ =
                sph::make_resident_sph(spec_.backend, *solver_, spec_.exec_origin.at("backend"));
            if (sph_fem_) resident_->couple_fem(*sph_fem_); // where the particles are
        }
    }
    if (spec_.has_dem || spec_.has_bodies()) {
        scenario::build_dem_walls(spec_, dem_walls_);
        for (const auto& p : probes_)
            if (p->contact_wall() >= 0)
                dem_walls_.walls()[std::size_t(p->contact_wall())].record_contacts = true;
    }
    if (fem_ && (spec_.has_dem || spec_.has_bodies())) couple_fem_to_contacts();
    if (spec_.has_bodies()) {
        rigid_ = scenario::make_body_solver(spec_, bodies, &dem_walls_);
        if (solver_)
            sph_body_ = std::make_unique<coupling::SphBodyCoupling>(
                *rigid_, set_, scenario::body_particles(bodies, first_body_particle));
        if (resident_ && sph_body_) resident_->couple_bodies(*rigid_, *sph_body_);
    }
    if (dem_fem_) dem_fem_->connect(rigid_.get());
    if (spec_.has_dem) {
        bed_overlap_ = scenario::build_grains(spec_, grains_, dem_walls_);
        dem_ = std::make_unique<dem::DemSolver>(spec_.dem.params, grains_, dem_walls_,
                                                spec_.dem.materials, spec_.dem.overrides,
                                                spec_.domain);
        host_grains_ = std::make_unique<probes::HostGrainReader>(*dem_);
        if (rigid_) {
            for (std::size_t b = 0; b < rigid_->models().size(); ++b)
                if (rigid_->models()[b].samples.empty())
                    throw InputError(fmt::format(
                        "{}: body '{}' has no contact spheres for the grains; set [rigid] "
                        "contact_spacing (m)",
                        spec_.rigid.bodies[b].origin.block(), rigid_->models()[b].name));
            dem_body_ = std::make_unique<coupling::DemBodyCoupling>(*rigid_, *dem_);
        }
        if (solver_ && spec_.dem.fluid_drag != "none")
            sph_dem_ =
                std::make_unique<coupling::SphDemCoupling>(*solver_, *dem_, spec_.dem.fluid_drag);
        const auto& p = spec_.dem.params;
        const auto stable = dem_->stability_dt();
        if (p.dt > 0 && p.dt > stable.dt)
            throw InputError(fmt::format("{}: dem.dt = {:.4g} s exceeds the stable step {:.4g} s "
                                         "({}); use dem.dt <= {:.4g} s",
                                         spec_.dem_origin.at("dt"), p.dt, stable.dt, stable.limiter,
                                         stable.dt));
        if (spec_.backend != "host")
            resident_dem_ =
                dem::make_resident_dem(spec_.backend, *dem_, spec_.exec_origin.at("backend"));
        if (sph_dem_ && resident_ && resident_dem_) // where the particles and grains are
            resident_sph_dem_ = resident_dem_->couple_fluid(*resident_, *sph_dem_);
    }
    wall_removed_.assign(spec_.walls.size(), 0);
    for (const auto& in : spec_.inlets) {
        inlets_.push_back(std::make_unique<flow::FluidInlet>(in, spec_));
        probes_.push_back(
            std::make_unique<probes::InletProbe>(*inlets_.back(), in.every, spec_.dim == 2));
    }
    for (const auto& f : spec_.dem.feeds) {
        feeds_.push_back(std::make_unique<flow::GrainFeed>(f, spec_));
        probes_.push_back(std::make_unique<probes::FeedProbe>(*feeds_.back(), f.every, "grains"));
        // The DEM step must hold for the smallest grain the feed can release.
        dem::GrainSet prototype;
        for (Real d : {f.size.max, f.size.min})
            scenario::add_grain(spec_, prototype, {}, {}, {}, d,
                                scenario::material_index(spec_, f.material));
        dem_->include_sizes(prototype);
        scenario::require_feed_within_contact(spec_, f, prototype); // its largest grain first
    }
    for (const auto& f : spec_.rigid.feeds) {
        rock_feeds_.push_back(std::make_unique<flow::RockFeed>(f, spec_));
        probes_.push_back(
            std::make_unique<probes::FeedProbe>(*rock_feeds_.back(), f.every, "rocks"));
    }
    for (const auto& out : spec_.outlets) {
        outlets_.push_back(std::make_unique<flow::Outlet>(out, spec_.sph.rho0));
        probes_.push_back(std::make_unique<probes::OutletProbe>(
            *outlets_.back(), out.every, spec_.dim == 2, spec_.has_bodies()));
    }
}

void Simulation::couple_fem_to_contacts() {
    std::vector<int> materials;
    for (const auto& s : spec_.fem.solids)
        materials.push_back(
            s.dem_material.empty() ? -1 : scenario::material_index(spec_, s.dem_material));
    dem_fem_ = std::make_unique<coupling::DemFemCoupling>(*fem_, dem_walls_, materials);
}

std::vector<const coupling::Coupling*> Simulation::couplings() const {
    std::vector<const coupling::Coupling*> out;
    for (const coupling::Coupling* c : std::initializer_list<const coupling::Coupling*>{
             sph_body_.get(), sph_dem_.get(), dem_body_.get(), sph_fem_.get(), dem_fem_.get()})
        if (c) out.push_back(c);
    return out;
}

probes::Probe& Simulation::probe(const std::string& name) {
    for (auto& p : probes_)
        if (p->name() == name) return *p;
    throw std::out_of_range("no probe named " + name);
}

std::size_t Simulation::memory_bytes() const {
    const double grains = double(grains_.size()) * scenario::bytes_per_grain(spec_);
    if (!solver_) return std::size_t(grains);
    const double particle = scenario::sph_bytes_per_particle(
        spec_.dim, solver_->support() / spec_.dp,
        sph::diffusion_needs_density_gradient(spec_.sph.diffusion));
    return std::size_t(grains + double(set_.size()) * particle);
}

RunReport Simulation::run(const RunOptions& opt) {
    exec::set_threads(opt.threads);
    RunReport report;
    report.threads = exec::max_threads();
    report.fluid = set_.count(particles::Kind::fluid);
    report.boundary = set_.count(particles::Kind::boundary);
    report.grains = grains_.size();
    report.bodies = rigid_ ? long(rigid_->bodies().size()) : 0;
    if (solver_) report.initial_dt = solver_->initial_dt();
    if (dem_) {
        report.dem_dt = {dem_->dt(),
                         spec_.dem.params.dt > 0 ? "user dt" : dem_->automatic_dt().limiter};
        if (!solver_) report.initial_dt = report.dem_dt;
    }
    if (rigid_ && !solver_ && !dem_) report.initial_dt = {spec_.rigid.dt, "rigid dt"};
    const bool files = !opt.out_dir.empty();
    log_.set_quiet(opt.quiet);
    open_output(opt);
    auto& vtk = vtk_;
    auto& vtk_grains = vtk_grains_;
    auto& vtk_bodies = vtk_bodies_;
    auto& vtk_fem = vtk_fem_;
    if (fem_) {
        long elements = 0;
        for (const auto& s : fem_->solids()) elements += long(s.volume.size());
        report.fem_nodes = long(fem_->nodes());
        report.fem_elements = elements;
        report.fem_dt = fem_->critical_dt();
        if (!solver_ && !dem_ && !rigid_)
            report.initial_dt = {fem_->critical_dt(), "fem element CFL"};
    }
    log_case(report);
    if (dem_ && spec_.dem.settle && !settled_ && t_ == 0 && !resume_.active) {
        try {
            settle_grains();
        } catch (const RunStopped& e) {
            const bool asked = dynamic_cast<const InterruptedError*>(&e) != nullptr;
            log_.line(asked ? std::string(e.what())
                            : std::string("ERROR: settling stopped: ") + e.what());
            throw;
        }
        if (files && grains_.clumps.empty()) {
            scenario::write_grain_state(opt.out_dir + "/grains_settled.csv", grains_,
                                        spec_.dem.materials);
            log_.line("settled state: " + opt.out_dir +
                      "/grains_settled.csv (reuse with packing = \"file\")");
        } else if (files) {
            log_.line("settled state not written: a saved grain state holds spheres only, and "
                      "this case has clumps");
        }
    }

    time::Integrator integ;
    // in the order coupling/step_order.cpp states
    time::Phase* sph_phase = resident_ ? static_cast<time::Phase*>(resident_.get()) : solver_.get();
    time::Phase* dem_phase =
        resident_dem_ ? static_cast<time::Phase*>(resident_dem_.get()) : dem_.get();
    time::Phase* sph_dem_phase =
        resident_sph_dem_ ? resident_sph_dem_.get() : static_cast<time::Phase*>(sph_dem_.get());
    for (time::Phase* p :
         coupling::force_order({sph_phase, dem_phase, sph_dem_phase, rigid_.get(), fem_.get()}))
        integ.add_phase(p);
    integ.set_reorder_every(solver_ ? spec_.sph.reorder_every : 1);
    // Cases without fluid take one force evaluation per step (velocity Verlet in the DEM and
    // the rigid bodies).
    integ.set_scheme(spec_.scheme == "verlet" || !solver_ ? time::Scheme::verlet
                                                          : time::Scheme::symplectic,
                     spec_.verlet_euler_every);
    // The symplectic scheme keeps its own copy of the state at t_n; the Verlet scheme's
    // state at t_(n-1) is not needed.
    if (solver_ && spec_.scheme != "verlet") set_.drop_previous_state();
    if (resume_.active) integ.resume(resume_.step, resume_.first_dt);
    resume_.active = false;
    for (std::size_t w = 0; w < spec_.walls.size(); ++w) {
        if (!spec_.walls[w].remove_at) continue;
        const Real at = *spec_.walls[w].remove_at;
        integ.add_hook(time::Hook::step_begin, [this, w, at](const time::StepInfo& s) {
            if (wall_removed_[w] || s.t < at) return;
            if (resident_)
                resident_->remove_group(std::int16_t(w)); // where the particles are
            else if (solver_)
                solver_->remove_group(std::int16_t(w));
            if (dem_) dem_->remove_wall(int(w));
            if (!dem_ && rigid_) dem_walls_.walls()[w].active = false;
            wall_removed_[w] = 1;
            log_.line(fmt::format("t = {:.6g} s: wall '{}' removed", s.t, spec_.walls[w].name));
        });
    }
    // Eroded elements take their SPH boundary particles with them, between steps, and the
    // surfaces they expose get boundary particles of their own (where the particles are with a
    // resident backend: the coupling removes and appends them there itself).
    if (sph_fem_)
        integ.add_hook(time::Hook::after_integration, [this](const time::StepInfo& s) {
            const std::string note =
                sph_fem_->erode(s.t, [this](const std::vector<std::uint8_t>& keep) {
                    solver_->remove_particles(keep);
                });
            if (!note.empty()) log_.line(note);
        });
    // Open boundaries act between the integration and the neighbour search of each step.
    if (!inlets_.empty() || !outlets_.empty() || !feeds_.empty() || !rock_feeds_.empty())
        integ.add_hook(time::Hook::after_integration, [this](const time::StepInfo& s) {
            for (auto& in : inlets_) {
                if (resident_) { // where the particles are
                    resident_->prescribe(in->buffer(s.t));
                    resident_->append(in->new_layers(s.t, s.dt));
                } else {
                    in->apply(set_, s.t, s.dt);
                }
            }
            for (auto& f : feeds_) {
                if (resident_dem_)
                    f->apply(*resident_dem_, *dem_, s.t, s.dt); // where the grains are
                else
                    f->apply(*dem_, s.t, s.dt);
                if (const auto note = f->lag_note(s.t); !note.empty()) log_.line(note);
            }
            for (auto& f : rock_feeds_) {
                // the grains near the feed's region, wherever they are
                flow::RockFeed::GrainsNear near;
                if (resident_dem_)
                    near = [this](const flow::FeedReach& r) {
                        return resident_dem_->grains_near(r);
                    };
                else if (dem_)
                    near = flow::RockFeed::near_in(grains_);
                f->apply(*rigid_, near, probe_context().fluid, s.t, s.dt);
                if (const auto note = f->lag_note(s.t); !note.empty()) log_.line(note);
            }
            for (auto& out : outlets_) {
                const long before = out->bodies_removed();
                if (resident_ || resident_dem_) {
                    // the fluid and the grains inside removed where they are, then the bodies
                    // on the host, their particles released where they are
                    // (sph/resident_bodies.hpp)
                    if (resident_)
                        out->tally_fluid(resident_->remove_fluid_inside(out->box()).mass);
                    if (resident_dem_) {
                        const auto left = resident_dem_->remove_inside(out->box());
                        out->tally_grains(left.mass, left.material, dem_->materials());
                    }
                    out->apply(nullptr, nullptr, rigid_.get());
                } else
                    out->apply(solver_.get(), dem_.get(), rigid_.get());
                if (out->bodies_removed() > before)
                    log_.line(fmt::format("t = {:.6g} s: {} rigid bod{} left through outlet '{}' "
                                          "({} in all, {:.4g} kg)",
                                          s.t, out->bodies_removed() - before,
                                          out->bodies_removed() - before == 1 ? "y" : "ies",
                                          out->name(), out->bodies_removed(), out->body_mass()));
            }
        });
    // Fluid particles and grains that left the domain go (domain.exit = "remove"), after the
    // outlets and before the neighbour search and the health checks.
    if (domain_exit_.removes())
        integ.add_hook(time::Hook::after_integration, [this](const time::StepInfo& s) {
            // a resident phase finds and removes its leavers where its particles are
            if (resident_ || resident_dem_) {
                if (resident_) {
                    const auto left = resident_->remove_fluid_outside(domain_exit_.faces());
                    if (!left.face.empty()) {
                        const std::string note = domain_exit_.tally_fluid(
                            flow::DomainExit::leavers(left.face, left.mass), left.mass_in_set, s.t);
                        if (!note.empty()) log_.line(note);
                    }
                }
                // the drift flags a step after which a grain may be outside: then the leavers
                // are removed where they are
                if (resident_dem_ && dem_->may_have_left()) {
                    const auto left = resident_dem_->remove_outside(domain_exit_.faces());
                    if (!left.mass.empty()) {
                        const std::string note = domain_exit_.tally_grains(
                            flow::DomainExit::leavers(left.face, left.mass), left.mass_in_set, s.t);
                        if (!note.empty()) log_.line(note);
                    }
                }
                return;
            }
            const std::string note = domain_exit_.apply(solver_.get(), dem_.get(), s.t);
            if (!note.empty()) log_.line(note);
        });
    for (auto& p : probes_) {
        probes::Probe* raw = p.get();
        // the grain probes read the grains where they are (ctx.grains); one that reads a wall's
        // grain contacts brings back those contacts only (publish_wall_contacts)
        const bool contacts = resident_dem_ && raw->contact_wall() >= 0;
        integ.add_observer(
            time::Schedule::every_time(p->every()),
            [this, raw, contacts](const time::StepInfo& s) {
                if (contacts) resident_dem_->publish_wall_contacts();
                raw->record(s.t, probe_context());
            },
            raw->reads_particles());
    }
    const auto frames = spec_.vtk_every > 0 ? time::Schedule::every_time(spec_.vtk_every)
                                            : time::Schedule::every_steps(0);
    if (vtk)
        integ.add_observer(frames,
                           [this, &vtk](const time::StepInfo& s) { vtk->write(set_, s.t); });
    if (vtk_grains)
        integ.add_observer(frames, [this, &vtk_grains](const time::StepInfo& s) {
            vtk_grains->write(grains_, s.t);
        });
    if (vtk_bodies)
        integ.add_observer(frames, [this, &vtk_bodies](const time::StepInfo& s) {
            write_bodies(*vtk_bodies, s.t);
        });
    if (vtk_fem)
        integ.add_observer(
            frames, [this, &vtk_fem](const time::StepInfo& s) { vtk_fem->write(*fem_, s.t); });
    // Particle-steps counted step by step: inlets, feeds and outlets change the count.
    double particle_steps = 0;
    integ.add_observer(
        time::Schedule::every_steps(1),
        [&](const time::StepInfo& s) {
            if (s.step > 0)
                particle_steps += double((resident_ ? resident_->size() : set_.size()) +
                                         (resident_dem_ ? resident_dem_->size() : grains_.size()) +
                                         (fem_ ? fem_->nodes() : 0));
        },
        false);
    const auto wall0 = std::chrono::steady_clock::now();
    auto last_report = wall0;
    integ.add_observer(
        time::Schedule::every_steps(1),
        [&](const time::StepInfo& s) {
            const auto now = std::chrono::steady_clock::now();
            if (!s.last &&
                std::chrono::duration<double>(now - last_report).count() < spec_.progress_seconds)
                return;
            last_report = now;
            const double wall = std::chrono::duration<double>(now - wall0).count();
            const double pss = wall > 0 ? particle_steps / wall : 0;
            const double eta = s.t > 0 ? wall * (spec_.t_end - s.t) / s.t : 0;
            log_.line(fmt::format("t = {:.5f} s  step {}  dt = {:.3e} s ({})  {:.3g} "
                                  "particle-steps/s  wall {:.1f} s  ETA {:.0f} s{}",
                                  s.t, s.step, s.dt, s.limiter, pss, wall, eta,
                                  dem_ ? fmt::format("  contacts {}", dem_->contacts()) : ""));
            for (auto& p : probes_) p->flush();
        },
        false);
    // Checkpoints, after the observers have seen the step: every checkpoint_every simulated
    // seconds, every checkpoint_wall minutes, at the end, and on a stop request. Ctrl-C or
    // SIGTERM stops after this step and keeps the output (app/stop_request.hpp).
    auto every = time::Schedule::every_time(spec_.checkpoint_every);
    every.skip_through(t_);
    auto last_checkpoint = std::chrono::steady_clock::now();
    integ.add_hook(time::Hook::after_output, [&, this](const time::StepInfo& s) {
        const int sig = stop_signal();
        const auto now = std::chrono::steady_clock::now();
        const bool due = (spec_.checkpoint_every > 0 && every.due(s.step, s.t)) ||
                         (spec_.checkpoint_wall > 0 &&
                          std::chrono::duration<double>(now - last_checkpoint).count() >=
                              60 * spec_.checkpoint_wall) ||
                         (s.last && (spec_.checkpoint_every > 0 || spec_.checkpoint_wall > 0));
        if (files && (due || sig)) {
            integ.publish(s.step);
            write_checkpoint(opt.out_dir, s.step, s.t, integ.first_dt());
            last_checkpoint = std::chrono::steady_clock::now();
        }
        if (sig)
            throw InterruptedError(fmt::format("stopped on request (signal {}) at t = {:.6g} s "
                                               "(step {})",
                                               sig, s.t, s.step));
    });

    auto finish_stats = [&]() {
        report.particle_steps = particle_steps;
        if (rigid_) report.bodies = long(rigid_->bodies().size()); // rock feeds add bodies
        report.fluid_end = set_.count(particles::Kind::fluid);
        report.grains_end = grains_.size();
        report.fluid_exit = domain_exit_.fluid();
        report.grain_exit = domain_exit_.grains();
        if (solver_) {
            report.pair_list_builds = resident_ ? resident_->sorts() : solver_->list_builds();
            report.pairs = solver_->pair_list().pairs();
            report.sph_bytes = resident_ ? resident_->memory_bytes() : solver_->memory_bytes();
            if (resident_) report.sph_copies_to_host = resident_->copies_to_host();
            report.sph_particles = set_.size();
        }
        if (rigid_) report.body_contacts = rigid_->contacts();
        if (fem_) {
            report.fem_eroded = fem_->eroded_elements();
            report.fem_substeps = fem_->substeps();
        }
        if (dem_) {
            report.dem_contacts = dem_->contacts();
            report.dem_list_builds = dem_->list_builds();
        }
        if (resident_dem_) {
            report.dem_bytes = resident_dem_->memory_bytes();
            report.dem_copies_to_host = resident_dem_->copies_to_host();
            report.dem_copies_from_host = resident_dem_->copies_from_host();
        }
    };
    try {
        report.result = integ.run(t_, opt.until > 0 ? opt.until : spec_.t_end);
        t_ = report.result.t;
        finish_stats();
    } catch (const RunStopped& e) {
        const bool asked = dynamic_cast<const InterruptedError*>(&e) != nullptr;
        const bool memory = dynamic_cast<const OutOfMemoryError*>(&e) != nullptr;
        report.status = asked ? "interrupted" : memory ? "out_of_memory" : "unstable";
        report.message = e.what();
        report.result = integ.result();
        finish_stats();
        log_.line(std::string(asked ? "run " : "ERROR: run stopped: ") + e.what());
        if (files) {
            write_summary(opt.out_dir + "/summary.json", spec_, report, probes_);
            log_.line("output so far kept in " + opt.out_dir);
        }
        throw;
    }
    const auto& r = report.result;
    report.particle_steps = particle_steps;
    if (rigid_) report.bodies = long(rigid_->bodies().size()); // rock feeds add bodies
    const double pss = r.wall_seconds > 0 ? particle_steps / r.wall_seconds : 0;
    log_.line(fmt::format("finished: {} steps to t = {:.6g} s in {:.2f} s wall, {:.3g} "
                          "particle-steps/s (neighbours {:.2f} s, forces {:.2f} s, integration "
                          "{:.2f} s, output {:.2f} s)",
                          r.steps, r.t, r.wall_seconds, pss, r.timings.neighbors, r.timings.forces,
                          r.timings.integration, r.timings.output));
    std::vector<probes::BodyInfo> body_info;
    if (rigid_)
        for (std::size_t b = 0; b < rigid_->bodies().size(); ++b)
            body_info.push_back({rigid_->models()[b].name, rigid_->bodies()[b].mass,
                                 rigid_->models()[b].volume, rigid_->bodies()[b].material});
    const auto design = probes::design_checks(spec_, probes_, body_info);
    log_design(design);
    if (files) {
        if (dem_ && grains_.clumps.empty())
            scenario::write_grain_state(opt.out_dir + "/grains_final.csv", grains_,
                                        spec_.dem.materials);
        write_summary(opt.out_dir + "/summary.json", spec_, report, probes_, design);
        log_.line("output: " + opt.out_dir +
                  " (vtk/*.pvd for ParaView, probes/*.csv, summary.json, log.txt)");
    }
    return report;
}

} // namespace debrisflow::app
