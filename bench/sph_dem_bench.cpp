// Unresolved SPH-DEM coupling throughput (cases/bench/sph_dem_tank.toml: 64,000 fluid
// particles, 5,000 grains of 3 mm in a 0.4 m tank): one coupling evaluation (fluid and grain
// grids, interpolation at every grain with the renormalised pressure gradient, the reaction
// scattered to the fluid) beside one SPH force evaluation of the same state.
// Counters: grains/s (coupling), particles/s (SPH). Threads: OMP_NUM_THREADS.
//   OMP_NUM_THREADS=1 build/bench/sph_dem_bench ; OMP_NUM_THREADS=2 build/bench/sph_dem_bench
#include "debrisflow/app/simulation.hpp"
#include "debrisflow/io/case_spec.hpp"
#include <benchmark/benchmark.h>

using namespace debrisflow;

namespace {

app::Simulation& tank() {
    static app::Simulation* s = [] {
        auto* sim = new app::Simulation(
            io::read_case(DEBRISFLOW_SOURCE_DIR "/cases/bench/sph_dem_tank.toml", {}));
        sim->run({"", true, 0, 0}); // a few steps: pressures, and an impulse to hand over
        return sim;
    }();
    return *s;
}

void BM_SphDemCoupling(benchmark::State& state) {
    app::Simulation& s = tank();
    auto* c = s.fluid_grain_coupling();
    for (auto _ : state) c->compute_forces();
    state.counters["grains/s"] = benchmark::Counter(double(s.grains().grains().size()),
                                                    benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_SphDemCoupling)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_SphForcesSameState(benchmark::State& state) {
    app::Simulation& s = tank();
    for (auto _ : state) s.solver().compute_forces();
    state.counters["particles/s"] = benchmark::Counter(
        double(s.particles().size()), benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_SphForcesSameState)->Unit(benchmark::kMillisecond)->UseRealTime();

} // namespace

BENCHMARK_MAIN();
