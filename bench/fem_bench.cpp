// Explicit FEM throughput: a concrete block (E 32.5 GPa) meshed with n x n x n hex8 or
// 6 n^3 tet4, clamped at its base and swaying after an initial velocity; each step evaluates
// every element's corotational force (polar decomposition of F, K_e u, rotation back) and
// gathers the nodal forces. Counter: element-steps/s (and node-steps/s).
#include "debrisflow/fem/fem_solver.hpp"
#include <benchmark/benchmark.h>

using namespace debrisflow;

namespace {

void run(benchmark::State& state, fem::ElementType type) {
    const int n = int(state.range(0));
    fem::FemMaterial m;
    m.name = "concrete";
    m.density = 2320;
    m.youngs_modulus = 32.5e9;
    m.poisson = 0.2;
    fem::FemParams p;
    fem::FemSolver solver(p, {m});
    solver.add_solid("block", fem::box_mesh(type, {0, 0, 0}, {1, 1, 1}, {n, n, n}), 0);
    solver.fix(solver.node_set("block.zmin"), {true, true, true});
    solver.initialize();
    for (std::size_t i = 0; i < solver.nodes(); ++i)
        solver.velocities()[i] = {0.01 * solver.reference()[i].z, 0, 0};
    const Real dt = solver.critical_dt();
    for (auto _ : state) solver.advance(dt);
    const double elements = double(solver.solids()[0].volume.size());
    state.counters["element_steps_per_s"] =
        benchmark::Counter(elements * double(state.iterations()), benchmark::Counter::kIsRate);
    state.counters["node_steps_per_s"] = benchmark::Counter(
        double(solver.nodes()) * double(state.iterations()), benchmark::Counter::kIsRate);
}

void BM_FemHex8(benchmark::State& state) {
    run(state, fem::ElementType::hex8);
}
void BM_FemTet4(benchmark::State& state) {
    run(state, fem::ElementType::tet4);
}
BENCHMARK(BM_FemHex8)->Arg(10)->Arg(30)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_FemTet4)->Arg(10)->Arg(20)->Unit(benchmark::kMillisecond)->UseRealTime();

} // namespace

BENCHMARK_MAIN();
