// debrisflow command line: run and check case files.
#include "debrisflow/app/build_info.hpp"
#include "debrisflow/app/simulation.hpp"
#include "debrisflow/app/step_estimate.hpp"
#include "debrisflow/app/stop_request.hpp"
#include "debrisflow/checkpoint/checkpoint_file.hpp"
#include "debrisflow/core/error.hpp"
#include "debrisflow/core/memory_budget.hpp"
#include "debrisflow/exec/parallel.hpp"
#include "debrisflow/probes/pressure_notes.hpp"
#if defined(DEBRISFLOW_CUDA_BACKEND)
#include "debrisflow/exec/cuda_backend.hpp"
#endif
#include "debrisflow/io/case_spec.hpp"
#include "debrisflow/io/output_dir.hpp"
#include "debrisflow/scenario/resource_estimate.hpp"
#include <CLI/CLI.hpp>
#include <cmath>
#include <filesystem>
#include <fmt/format.h>
#include <iostream>
#include <limits>

using namespace debrisflow;

namespace {

int check(const std::string& file, const std::vector<std::string>& sets) {
    const io::CaseSpec spec = io::read_case(file, sets);
    const auto estimate = scenario::estimate_resources(spec);
    app::Simulation sim(spec);
    app::require_feasible_steps(sim);
    const auto& set = sim.particles();
    const long fluid = set.count(particles::Kind::fluid);
    const long boundary = set.count(particles::Kind::boundary);
    const long grains = sim.has_grains() ? sim.grains().grains().size() : 0;
    std::cout << fmt::format("case '{}' is valid ({}D, end time {} s)\n", spec.name, spec.dim,
                             spec.t_end);
    std::cout << fmt::format("particles: {} fluid, {} boundary, {} grains, {} total\n", fluid,
                             boundary, grains, fluid + boundary + grains);
    std::cout << fmt::format("memory estimate: {:.1f} MiB (before building: {:.1f} MiB; budget "
                             "{}); threads: {}\n",
                             sim.memory_bytes() / 1048576.0, estimate.total_bytes() / 1048576.0,
                             format_bytes(memory_budget_bytes()), exec::max_threads());
    if (sim.has_fluid()) {
        const auto d = sim.solver().initial_dt();
        std::cout << fmt::format(
            "sph: dp = {} m, kernel {}, h = {:.4g} m, c0 = {:.4g} m/s, diffusion {}, "
            "walls {}, pairs {}; initial dt {:.4g} s ({})\n",
            spec.dp, spec.sph.kernel, spec.sph.h, spec.sph.c0, spec.sph.diffusion,
            sph::wall_words(spec.sph),
            spec.backend == "host" ? sph::pair_loop_words(spec.sph) : "gathered over cells", d.dt,
            d.limiter);
        std::cout << fmt::format(
            "backend: {}\n", sph::backend_words(spec.backend, spec.has_bodies(), spec.has_fem()));
        if (const auto note = probes::wall_pressure_note(spec); !note.empty())
            std::cout << note << "\n";
    }
    if (sim.has_grains()) {
        const auto& d = sim.grains();
        const auto clumps = d.grains().clumps.size();
        std::cout << fmt::format("dem: {} grains{}, {:.4g} kg, {} materials, {} walls; dt {:.4g} s "
                                 "({}), automatic {:.4g} s ({}), largest accepted {:.4g} s{}\n",
                                 grains,
                                 clumps ? fmt::format(" ({} of them in {} clumps)",
                                                      d.grains().clumps.member_id.size(), clumps)
                                        : "",
                                 d.grains().total_mass(), spec.dem.materials.size(),
                                 d.walls().walls().size(), d.dt(),
                                 spec.dem.params.dt > 0 ? "user" : "automatic", d.automatic_dt().dt,
                                 d.automatic_dt().limiter, d.stability_dt().dt,
                                 spec.dem.params.subcycle ? ", sub-cycled" : "");
        if (const auto& bed = sim.bed_overlap(); bed.fraction > 0)
            std::cout << fmt::format("dem: the beds' own weight presses {:.3g} N into a contact "
                                     "at their base, {:.2g} % of the mean radius deep ({}; "
                                     "refused above {:.0f} %)\n",
                                     bed.force, 100 * bed.fraction, bed.where,
                                     100 * scenario::max_bed_overlap);
        if (!sim.has_fluid() || spec.backend != "host")
            std::cout << fmt::format("backend: {}\n", dem::backend_words(spec.backend));
        if (sim.has_fluid() && spec.backend != "host" && spec.dem.fluid_drag != "none")
            std::cout << "backend: the SPH-DEM drag coupling evaluated where the particles and "
                         "grains are (coupling/resident_sph_dem.hpp)\n";
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
    const app::StepEstimate step = app::estimate_step(sim);
    std::cout << fmt::format("time step: {:.4g} s ({}); about {:.0f} steps to the end time\n",
                             step.dt, step.limiter, spec.t_end / step.dt);
    return 0;
}

// The checkpoint file --restart names: a file, or the newest in OUT/checkpoint or in the
// folder given.
std::string newest_checkpoint(const std::string& where) {
    namespace fs = std::filesystem;
    if (fs::is_regular_file(where)) return where;
    if (!fs::is_directory(where))
        throw InputError("--restart " + where + ": no such checkpoint file or output folder");
    for (const auto& dir : {fs::path(where) / "checkpoint", fs::path(where)}) {
        const auto files = checkpoint::list(dir.string());
        if (!files.empty()) return files.front();
    }
    throw InputError("--restart " + where +
                     ": no checkpoint (checkpoint/step_*.dfc) in this folder; set "
                     "output.checkpoint_every or checkpoint_wall, or stop a run with Ctrl-C, to "
                     "write one");
}

} // namespace

int main(int argc, char** argv) {
    CLI::App cli{"debrisflow: particle simulation of debris flows and floods against structures\n"
                 "exit codes: 0 done, 2 bad input or usage, 3 the run went unstable (output "
                 "kept),\n130 stopped by a signal (output kept), 1 internal error"};
    cli.require_subcommand(0, 1);
    std::string file, out, max_memory, restart, backend;
    std::vector<std::string> sets;
    int threads = 0;
    bool quiet = false, overwrite = false, version = false;
    cli.add_flag("--version", version, "print the version, git revision and build options");
    const auto threads_range = CLI::Range(1, 4096);
    const auto backends = CLI::IsMember({"host", "host_resident", "cuda"});
    const char* backend_help = "where the SPH phase's time loop runs: host (default), "
                               "host_resident (the device's loop on the host) or cuda; "
                               "the same as --set exec.backend=...";
    auto* run = cli.add_subcommand("run", "run a case");
    run->add_option("case", file, "case file (TOML)")->required();
    run->add_option("--out", out, "output folder (default: out/<case name>)");
    run->add_option("--set", sets, "override a key: --set time.end=0.05")->take_all();
    run->add_option("--threads", threads, "OpenMP threads (default: all cores)")
        ->check(threads_range);
    run->add_option("--backend", backend, backend_help)->check(backends);
    run->add_flag("--quiet", quiet, "only errors on the terminal");
    run->add_option("--restart", restart,
                    "continue from the newest checkpoint of an output folder (OUT or "
                    "OUT/checkpoint), or from one checkpoint file; the output continues there");
    run->add_flag("--overwrite", overwrite,
                  "replace the results of an earlier run in the output folder");
    run->add_option("--max-memory", max_memory,
                    "refuse cases estimated to need more memory (e.g. 4G; default: the "
                    "machine's memory)");
    auto* chk = cli.add_subcommand("check", "validate a case and print what it would run");
    chk->add_option("case", file, "case file (TOML)")->required();
    chk->add_option("--set", sets, "override a key")->take_all();
    chk->add_option("--threads", threads, "OpenMP threads used to build the case")
        ->check(threads_range);
    chk->add_option("--max-memory", max_memory, "as for run");
    chk->add_option("--backend", backend, backend_help)->check(backends);
    try {
        cli.parse(argc, argv);
        if (!version && !run->parsed() && !chk->parsed()) {
            std::cerr << cli.help();
            return 2; // no subcommand: a usage error
        }
    } catch (const CLI::ParseError& e) {
        const int rc = cli.exit(e); // prints the message or the help
        return rc == 0 ? 0 : 2;     // usage errors are bad input, like a bad case file
    }
    if (version) {
        std::cout << fmt::format("debrisflow {} (git {})\nbuild: {}\n", DEBRISFLOW_VERSION,
                                 app::build_revision(), app::build_options());
        return 0;
    }
#if defined(DEBRISFLOW_CUDA_BACKEND)
    cuda::register_backend();
#endif
    if (!backend.empty()) sets.push_back("exec.backend=\"" + backend + "\"");
    try {
        if (!max_memory.empty()) set_memory_budget_bytes(parse_bytes(max_memory));
        if (threads > 0) exec::set_threads(threads);
        if (chk->parsed()) return check(file, sets);
        const io::CaseSpec spec = io::read_case(file, sets);
        std::string checkpoint_file;
        if (!restart.empty()) {
            checkpoint_file = newest_checkpoint(restart);
            const auto folder =
                std::filesystem::path(checkpoint_file).parent_path().parent_path().string();
            if (!out.empty() && !std::filesystem::equivalent(out, folder))
                throw InputError(fmt::format("--out {} differs from the folder of the "
                                             "checkpoint ({}): a restart continues there",
                                             out, folder));
            out = folder;
        }
        if (out.empty()) out = "out/" + spec.name;
        app::Simulation sim(spec);
        app::require_feasible_steps(sim);
        if (checkpoint_file.empty())
            io::prepare_output_dir(out, overwrite);
        else
            sim.restore(checkpoint_file);
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
    } catch (const OutOfMemoryError& e) {
        std::cerr << "error: out of memory: " << e.what() << "\n";
        return 2;
    } catch (const std::bad_alloc&) {
        std::cerr << "error: out of memory: the case needs more than this machine can give "
                     "(its estimate is printed by `debrisflow check`); coarsen it or set "
                     "--max-memory\n";
        return 2;
    } catch (const std::exception& e) {
        std::cerr << "error: internal error: " << e.what() << "\n";
        return 1;
    }
}
