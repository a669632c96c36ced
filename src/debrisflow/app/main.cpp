// debrisflow command line: run and check case files.
#include "debrisflow/app/simulation.hpp"
#include "debrisflow/core/error.hpp"
#include "debrisflow/io/case_spec.hpp"
#include <CLI/CLI.hpp>
#include <filesystem>
#include <fmt/format.h>
#include <iostream>

using namespace debrisflow;

namespace {

int check(const std::string& file, const std::vector<std::string>& sets) {
    const io::CaseSpec spec = io::read_case(file, sets);
    app::Simulation sim(spec);
    const auto& set = sim.particles();
    const auto dt = sim.solver().initial_dt();
    const long fluid = set.count(particles::Kind::fluid);
    const long boundary = set.count(particles::Kind::boundary);
    std::cout << fmt::format("case '{}' is valid ({}D, dp = {} m, end time {} s)\n", spec.name,
                             spec.dim, spec.dp, spec.t_end);
    std::cout << fmt::format("particles: {} fluid, {} boundary, {} total\n", fluid, boundary,
                             fluid + boundary);
    std::cout << fmt::format("memory estimate: {:.1f} MiB\n", sim.memory_bytes() / 1048576.0);
    std::cout << fmt::format("sph: kernel {}, h = {:.4g} m, c0 = {:.4g} m/s\n", spec.sph.kernel,
                             spec.sph.h, spec.sph.c0);
    std::cout << fmt::format("initial dt: {:.4g} s, limited by {}; about {:.0f} steps to the "
                             "end time\n",
                             dt.dt, dt.limiter, spec.t_end / dt.dt);
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
        sim.run({out, quiet, threads});
        return 0;
    } catch (const InputError& e) {
        std::cerr << "error: " << e.what() << "\n";
        return 2;
    } catch (const InstabilityError& e) {
        std::cerr << "error: the run went unstable: " << e.what() << "\n";
        return 3;
    } catch (const std::exception& e) {
        std::cerr << "error: " << e.what() << "\n";
        return 1;
    }
}
