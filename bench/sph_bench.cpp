// Micro-benchmarks on the 3D dam-break benchmark case (cases/bench/dambreak3d.toml) at its
// initial state: cell-grid build, pair-list build, one force evaluation (scatter over the half
// pair list) and the gather loop (the GPU layout); and one force evaluation in a
// boundary-dominated flume (cases/bench/channel_sph.toml). Threads: OMP_NUM_THREADS.
//   OMP_NUM_THREADS=1 build/bench/sph_bench ; OMP_NUM_THREADS=2 build/bench/sph_bench
#include "debrisflow/app/simulation.hpp"
#include "debrisflow/io/case_spec.hpp"
#include <benchmark/benchmark.h>

using namespace debrisflow;

// A case at its initial state with its pair list built, loaded once per process.
static app::Simulation& load(const char* path) {
    auto* s = new app::Simulation(io::read_case(path, {}));
    s->solver().update_neighbors(true);
    return *s;
}

static app::Simulation& sim() {
    static app::Simulation& s = load(DEBRISFLOW_SOURCE_DIR "/cases/bench/dambreak3d.toml");
    return s;
}

// A boundary-dominated flume (cases/bench/channel_sph.toml): 3,750 fluid among 52,470
// boundary particles, laminar + SPS viscosity.
static app::Simulation& channel() {
    static app::Simulation& s = load(DEBRISFLOW_SOURCE_DIR "/cases/bench/channel_sph.toml");
    return s;
}

static void set_counters(benchmark::State& state, double pairs, app::Simulation& s = sim()) {
    const double n = double(s.particles().size());
    state.counters["particles/s"] =
        benchmark::Counter(n, benchmark::Counter::kIsIterationInvariantRate);
    if (pairs > 0)
        state.counters["pairs/s"] =
            benchmark::Counter(pairs, benchmark::Counter::kIsIterationInvariantRate);
}

static void BM_CellGridBuild(benchmark::State& state) {
    auto& s = sim();
    const auto& p = s.particles();
    neighbors::CellGrid grid;
    const auto& d = s.spec().domain;
    grid.configure(d.lo, d.hi, s.solver().support() * 1.1, 3, d.periodic);
    for (auto _ : state) grid.build(p.x.data(), p.y.data(), p.z.data(), p.size());
    set_counters(state, 0);
}
BENCHMARK(BM_CellGridBuild)->Unit(benchmark::kMillisecond)->UseRealTime();

static void BM_PairListBuild(benchmark::State& state) {
    auto& s = sim();
    neighbors::PairList list;
    for (auto _ : state) list.build(s.solver().grid().view(), s.particles().view());
    set_counters(state, double(list.pairs()));
}
BENCHMARK(BM_PairListBuild)->Unit(benchmark::kMillisecond)->UseRealTime();

static void BM_ForcesScatter(benchmark::State& state) {
    auto& s = sim();
    for (auto _ : state) s.solver().compute_forces();
    set_counters(state, double(s.solver().pair_list().pairs()));
}
BENCHMARK(BM_ForcesScatter)->Unit(benchmark::kMillisecond)->UseRealTime();

static void BM_ForcesScatterChannel(benchmark::State& state) {
    auto& s = channel();
    for (auto _ : state) s.solver().compute_forces();
    set_counters(state, double(s.solver().pair_list().pairs()), s);
}
BENCHMARK(BM_ForcesScatterChannel)->Unit(benchmark::kMillisecond)->UseRealTime();

static void BM_ForcesGather(benchmark::State& state) {
    auto& s = sim();
    for (auto _ : state) s.solver().compute_forces_gather();
    set_counters(state, 2.0 * double(s.solver().pair_list().pairs()));
}
BENCHMARK(BM_ForcesGather)->Unit(benchmark::kMillisecond)->UseRealTime();

BENCHMARK_MAIN();
