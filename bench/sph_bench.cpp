// Micro-benchmarks: neighbour-grid build and the WCSPH interaction loop on the 3D dam-break
// benchmark case, at the thread count given by OMP_NUM_THREADS.
#include "debrisflow/app/simulation.hpp"
#include "debrisflow/io/case_spec.hpp"
#include <benchmark/benchmark.h>

using namespace debrisflow;

static app::Simulation& sim() {
    static app::Simulation s(io::read_case(DEBRISFLOW_SOURCE_DIR "/cases/bench/dambreak3d.toml", {}));
    return s;
}

static void BM_NeighborBuild(benchmark::State& state) {
    auto& s = sim();
    for (auto _ : state) s.solver().update_neighbors(true);
    state.counters["particles/s"] = benchmark::Counter(double(s.particles().size()),
                                                       benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_NeighborBuild)->Unit(benchmark::kMillisecond)->UseRealTime();

static void BM_Interaction(benchmark::State& state) {
    auto& s = sim();
    s.solver().update_neighbors(true);
    for (auto _ : state) s.solver().compute_forces();
    state.counters["particles/s"] = benchmark::Counter(double(s.particles().size()),
                                                       benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_Interaction)->Unit(benchmark::kMillisecond)->UseRealTime();

BENCHMARK_MAIN();
