// debrisflow command line: run and check case files.
#include "debrisflow/app/simulation.hpp"
#include "debrisflow/app/stop_request.hpp"
#include "debrisflow/core/error.hpp"
#include "debrisflow/io/case_spec.hpp"
#include <CLI/CLI.hpp>
#include <filesystem>
#include <fmt/format.h>
#include <iostream>
#include <limits>

using namespace debrisflow;

namespace {

int check(const std::string& file, const std::vector<std::string>& sets) {
    const io::CaseSpec spec = io::read_case(file, sets);
    app::Simulation sim(spec);
    const auto& set = sim.particles();
    const long fluid = set.count(particles::Kind::fluid);
    const long boundary = set.count(particles::Kind::boundary);
    const long grains = sim.has_grains() ? sim.grains().grains().size() : 0;
    std::cout << fmt::format("case '{}' is valid ({}D, end time {} s)\n", spec.name, spec.dim,
                             spec.t_end);
    std::cout << fmt::format("particles: {} fluid, {} boundary, {} grains, {} total\n", fluid,
                             boundary, grains, fluid + boundary + grains);
    std::cout << fmt::format("memory estimate: {:.1f} MiB\n", sim.memory_bytes() / 1048576.0);
    Real dt = std::numeric_limits<Real>::max();
    std::string limiter;
    if (sim.has_fluid()) {
        const auto d = sim.solver().initial_dt();
        std::cout << fmt::format("sph: dp = {} m, kernel {}, h = {:.4g} m, c0 = {:.4g} m/s; "
                                 "initial dt {:.4g} s ({})\n",
                                 spec.dp, spec.sph.kernel, spec.sph.h, spec.sph.c0, d.dt,
                                 d.limiter);
        dt = d.dt, limiter = "sph/" + d.limiter;
    }
    if (sim.has_grains()) {
        const auto& d = sim.grains();
        std::cout << fmt::format("dem: {} grains, {:.4g} kg, {} materials, {} walls; dt {:.4g} s "
                                 "({}), automatic {:.4g} s ({}), largest accepted {:.4g} s{}\n",
                                 grains, d.grains().total_mass(), spec.dem.materials.size(),
                                 d.walls().walls().size(), d.dt(),
                                 spec.dem.params.dt > 0 ? "user" : "automatic", d.automatic_dt().dt,
                                 d.automatic_dt().limiter, d.stability_dt().dt,
                                 spec.dem.params.subcycle ? ", sub-cycled" : "");
        if (!spec.dem.params.subcycle && d.dt() < dt) dt = d.dt(), limiter = "dem";
    }
    if (sim.has_bodies()) {
        const auto& r = sim.bodies();
        for (std::size_t b = 0; b < r.bodies().size(); ++b) {
            const auto& s = r.bodies()[b];
            std::cout << fmt::format("body '{}': {} motion, mass {:.6g} kg, centre of mass "
                                     "({:.5g}, {:.5g}, {:.5g}) m, {} contact features, {} "
                                     "contact samples\n",
                                     r.models()[b].name, spec.rigid.bodies[b].motion, s.mass,
                                     s.pos.x, s.pos.y, s.pos.z,
                                     r.models()[b].vertices.size() + r.models()[b].spheres.size(),
                                     r.models()[b].samples.size());
        }
        if (spec.rigid.dt > 0 && spec.rigid.dt < dt) dt = spec.rigid.dt, limiter = "rigid dt";
    }
    if (sim.has_fem()) {
        const auto& f = sim.fem();
        for (const auto& s : f.solids()) {
            Real mass = 0;
            for (std::int32_t n = 0; n < s.nodes; ++n)
                mass += f.masses()[std::size_t(s.first_node + n)];
            std::cout << fmt::format("solid '{}': {} {} elements, {} nodes, mass {:.6g} kg\n",
                                     s.name, s.volume.size(), fem::name_of(s.type), s.nodes, mass);
        }
        const bool alone = !sim.has_fluid() && !sim.has_grains() && !sim.has_bodies();
        std::cout << fmt::format("fem: critical step {:.4g} s{}\n", f.critical_dt(),
                                 alone ? "" : " (sub-cycled inside the global step)");
        if (alone && f.critical_dt() < dt) dt = f.critical_dt(), limiter = "fem element CFL";
    }
    for (const auto& w : spec.walls)
        if (!w.structure.empty())
            std::cout << fmt::format(
                "structure '{}': {} of {} boxes, ({:.4g}, {:.4g}, {:.4g}) to "
                "({:.4g}, {:.4g}, {:.4g}) m{}\n",
                w.name, w.structure, w.boxes.size(), w.shape.min.x, w.shape.min.y, w.shape.min.z,
                w.shape.max.x, w.shape.max.y, w.shape.max.z,
                w.structure == "slit_dam" ? fmt::format(", slit density {:.4g}", w.slit_density)
                                          : std::string());
    for (const auto& in : spec.inlets)
        std::cout << fmt::format("inlet '{}': Q(0) = {:.4g} m^3/s{}\n", in.name,
                                 in.discharge.front(), in.times.size() > 1 ? " (hydrograph)" : "");
    for (const auto& f : spec.dem.feeds)
        std::cout << fmt::format("feed '{}': Q_s(0) = {:.4g} m^3/s of {} grains\n", f.name,
                                 f.discharge.front(), f.material);
    for (const auto& f : spec.rigid.feeds)
        std::cout << fmt::format(
            "feed '{}': Q_s(0) = {:.4g} m^3/s of rocks of material '{}' ({} shapes, "
            "sphericity within +-{:.0f} %)\n",
            f.name, f.discharge.front(), f.material, f.rocks.size(), 100 * f.sphericity_tolerance);
    std::cout << fmt::format("time step: {:.4g} s ({}); about {:.0f} steps to the end time\n", dt,
                             limiter, spec.t_end / dt);
    return 0;
}

} // namespace

int main(int argc, char** argv) {
    CLI::App cli{"debrisflow: particle simulation of debris flows and floods against structures"};
    cli.require_subcommand(1);
    std::string file, out;
    std::vector<std::string> sets;
    int threads = 0;
    bool quiet = false;
    auto* run = cli.add_subcommand("run", "run a case");
    run->add_option("case", file, "case file (TOML)")->required();
    run->add_option("--out", out, "output folder (default: out/<case name>)");
    run->add_option("--set", sets, "override a key: --set time.end=0.05")->take_all();
    run->add_option("--threads", threads, "OpenMP threads (default: all cores)")
        ->check(CLI::PositiveNumber);
    run->add_flag("--quiet", quiet, "only errors on the terminal");
    auto* chk = cli.add_subcommand("check", "validate a case and print what it would run");
    chk->add_option("case", file, "case file (TOML)")->required();
    chk->add_option("--set", sets, "override a key")->take_all();
    CLI11_PARSE(cli, argc, argv);
    try {
        if (chk->parsed()) return check(file, sets);
        const io::CaseSpec spec = io::read_case(file, sets);
        if (out.empty()) out = "out/" + spec.name;
        app::Simulation sim(spec);
        app::install_stop_handlers();
        sim.run({out, quiet, threads});
        return 0;
    } catch (const InputError& e) {
        std::cerr << "error: " << e.what() << "\n";
        return 2;
    } catch (const InterruptedError& e) {
        std::cerr << "debrisflow: " << e.what() << "; output so far kept in " << out << "\n";
        return 130;
    } catch (const InstabilityError& e) {
        std::cerr << "error: the run went unstable: " << e.what() << "\n";
        return 3;
    } catch (const std::exception& e) {
        std::cerr << "error: " << e.what() << "\n";
        return 1;
    }
}
