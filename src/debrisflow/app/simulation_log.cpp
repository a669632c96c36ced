// A run's output folder (log, resolved case, probe files, VTK series, continued on a restart)
// and what it writes to its log before the first step (the case, its models and couplings) and
// after the last (the design-formula companions of the measured peaks).
#include "debrisflow/app/simulation.hpp"
#include "debrisflow/exec/parallel.hpp"
#include "debrisflow/probes/pressure_notes.hpp"
#include <filesystem>
#include <fmt/format.h>
#include <fstream>

namespace debrisflow::app {

void Simulation::open_output(const RunOptions& opt) {
    auto& vtk = vtk_;
    auto& vtk_grains = vtk_grains_;
    auto& vtk_bodies = vtk_bodies_;
    auto& vtk_fem = vtk_fem_;
    if (!opt.out_dir.empty()) {
        std::filesystem::create_directories(opt.out_dir);
        log_.open(opt.out_dir + "/log.txt", resume_.active);
        std::ofstream(opt.out_dir + "/case.toml") << spec_.resolved_toml << "\n";
        for (auto& p : probes_) p->open(opt.out_dir + "/probes");
        if (spec_.vtk && solver_) vtk = std::make_unique<io::VtkSeries>(opt.out_dir + "/vtk");
        if (spec_.vtk && dem_)
            vtk_grains = std::make_unique<io::VtkSeries>(opt.out_dir + "/vtk", "grains");
        if (spec_.vtk && rigid_)
            vtk_bodies = std::make_unique<io::VtkSeries>(opt.out_dir + "/vtk", "bodies");
        if (spec_.vtk && fem_)
            vtk_fem = std::make_unique<io::VtkSeries>(opt.out_dir + "/vtk", "fem");
        if (resume_.active) {
            const std::array<io::VtkSeries*, 4> series{vtk.get(), vtk_grains.get(),
                                                       vtk_bodies.get(), vtk_fem.get()};
            for (std::size_t k = 0; k < series.size(); ++k)
                if (series[k]) series[k]->resume(resume_.frames[k]);
        }
    }
    if (resume_.active) {
        log_.line(fmt::format("restarted from {} at t = {:.9g} s, step {}", resume_.file, t_,
                              resume_.step));
        if (resume_.threads != exec::max_threads())
            log_.line(fmt::format("note: the checkpoint was written with {} threads, this run "
                                  "has {}: results match the uninterrupted run only to "
                                  "round-off (bit for bit at the same thread count)",
                                  resume_.threads, exec::max_threads()));
    }
}

void Simulation::log_case(const RunReport& report) {
    if (fem_) {
        for (const auto& s : fem_->solids())
            log_.line(fmt::format("solid '{}': {} {} elements, {} nodes", s.name, s.volume.size(),
                                  fem::name_of(s.type), s.nodes));
        log_.line(
            fmt::format("fem: critical step {:.4g} s (element eigenvalue bound, cfl {}){}",
                        fem_->critical_dt(), spec_.fem.params.cfl,
                        solver_ || dem_ || rigid_ ? ", sub-cycled inside the global step" : ""));
    }
    log_.line(fmt::format("debrisflow: case '{}' ({}), {}D, end time {} s", spec_.name, spec_.file,
                          spec_.dim, spec_.t_end));
    log_.line(fmt::format("particles: {} fluid, {} boundary, {} grains; threads: {}", report.fluid,
                          report.boundary, report.grains, report.threads));
    if (const auto note = probes::wall_pressure_note(spec_); !note.empty()) log_.line(note);
    if (solver_)
        log_.line(
            fmt::format("sph: dp = {} m, kernel {}, h = {:.4g} m, c0 = {:.4g} m/s, viscosity "
                        "{}, diffusion {}, walls {}, pairs {}; initial dt = {:.3g} s (limited "
                        "by {})",
                        spec_.dp, spec_.sph.kernel, spec_.sph.h, spec_.sph.c0, spec_.sph.viscosity,
                        spec_.sph.diffusion, sph::wall_words(spec_.sph),
                        resident_ ? "gathered over cells" : sph::pair_loop_words(spec_.sph),
                        report.initial_dt.dt, report.initial_dt.limiter));
    if (solver_)
        log_.line("backend: " +
                  sph::backend_words(spec_.backend, spec_.has_bodies(), spec_.has_fem()));
    if (dem_ && (!solver_ || spec_.backend != "host")) // each resident phase says where it runs
        log_.line("backend: " + dem::backend_words(spec_.backend));
    if (resident_sph_dem_)
        log_.line("backend: the SPH-DEM drag coupling evaluated where the particles and grains "
                  "are (coupling/resident_sph_dem.hpp)");
    if (dem_)
        log_.line(fmt::format("dem: {} grains{}, {:.4g} kg, {} walls; dt = {:.3g} s ({}; automatic "
                              "{:.3g} s){}",
                              grains_.size(),
                              grains_.clumps.empty() ? ""
                                                     : fmt::format(" ({} of them in {} clumps)",
                                                                   grains_.clumps.member_id.size(),
                                                                   grains_.clumps.size()),
                              grains_.total_mass(), dem_walls_.walls().size(), dem_->dt(),
                              report.dem_dt.limiter, dem_->automatic_dt().dt,
                              spec_.dem.params.subcycle ? ", sub-cycled inside the SPH step" : ""));
    if (sph_dem_)
        log_.line(fmt::format("sph-dem: grains feel the fluid's pressure gradient and {} drag "
                              "(unresolved coupling, kernel support {:.4g} m)",
                              sph_dem_->drag_law(), solver_->support()));
    else if (dem_ && solver_)
        log_.line("sph-dem: grains and fluid do not exchange forces (set [dem] fluid_drag to "
                  "couple them)");
    if (rigid_)
        for (std::size_t b = 0; b < rigid_->bodies().size(); ++b) {
            const auto& s = rigid_->bodies()[b];
            log_.line(
                fmt::format("body '{}': {} motion, mass {:.6g} kg, centre of mass ({:.5g}, "
                            "{:.5g}, {:.5g}) m, principal moments ({:.5g}, {:.5g}, {:.5g}) "
                            "kg m^2",
                            rigid_->models()[b].name,
                            b < spec_.rigid.bodies.size() ? spec_.rigid.bodies[b].motion : "free",
                            s.mass, s.pos.x, s.pos.y, s.pos.z, 1 / s.inv_inertia.x,
                            1 / s.inv_inertia.y, 1 / s.inv_inertia.z));
        }
    for (const coupling::Coupling* c : couplings())
        for (const auto& e : c->exchanges())
            log_.line(fmt::format("coupling {}: {}", c->coupling_name(), coupling::describe(e)));
}

void Simulation::log_design(const std::vector<probes::DesignCheck>& design) {
    for (const auto& d : design) {
        if (d.hydro)
            log_.line(fmt::format("design '{}': peak normal load {:.4g} at t = {:.4g} s; "
                                  "F = alpha rho v^2 h w with rho {:.4g}, v {:.4g} m/s, h {:.4g} "
                                  "m, w {:.4g} m gives alpha = {:.3g}",
                                  d.probe, d.f_peak, d.f_peak_time, d.rho, d.v, d.h, d.w, d.alpha));
        if (d.hertz)
            log_.line(fmt::format("design '{}': Hertz boulder load {:.4g} N (m {:.4g} kg, r "
                                  "{:.4g} m, v {:.4g} m/s, E* {:.4g} Pa), K_c = {} -> {:.4g} N; "
                                  "measured bodies' peak {:.4g} N",
                                  d.probe, d.f_hertz, d.mass, d.radius, d.v_impact, d.e_star, d.k_c,
                                  d.k_c * d.f_hertz, d.f_bodies_peak));
        if (!d.note.empty()) log_.line("design '" + d.probe + "': " + d.note);
    }
}

} // namespace debrisflow::app
