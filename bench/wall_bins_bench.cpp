// The grain-wall candidate search at a neighbour rebuild against a large wall mesh: 20,000
// grains (radii 3-12 mm) over a rough bed of 100,000 triangles (2 m x 1 m), searched over every
// face (Arg 0) and through the bins (Arg 1, dem/wall_bins_k.hpp). One thread: the search runs
// per grain inside ContactSlots::build, which the host splits over its threads.
// Counters: grains searched per second, faces per second (of the mesh: the work a brute-force
// search would do).
#include "debrisflow/dem/slot_candidates_k.hpp"
#include "debrisflow/dem/wall_bins.hpp"
#include <benchmark/benchmark.h>
#include <random>
#include <vector>

using namespace debrisflow;
using namespace debrisflow::dem;

namespace {

struct Bed {
    std::vector<WallPrimitive> faces;
    std::vector<Index> active;
    std::vector<PrimitiveBounds> bounds;
    std::vector<Vec3> pos;
    std::vector<Real> radius;
};

Bed rough_bed() {
    constexpr int nx = 250, ny = 200, grains = 20000;
    std::mt19937 rng(11);
    std::uniform_real_distribution<Real> bump(-0.01, 0.01);
    std::vector<Real> height((nx + 1) * (ny + 1));
    for (Real& h : height) h = bump(rng);
    const Real dx = Real(2) / nx, dy = Real(1) / ny;
    const auto node = [&](int i, int j) {
        return Vec3{i * dx, j * dy, height[std::size_t(j * (nx + 1) + i)]};
    };
    Bed b;
    const auto add = [&](Vec3 p, Vec3 q, Vec3 r) {
        WallPrimitive w{};
        w.type = PrimitiveType::triangle;
        w.a = p, w.b = q, w.c = r;
        const Vec3 n = cross(q - p, r - p);
        w.n = (1 / norm(n)) * n;
        b.active.push_back(Index(b.faces.size()));
        b.bounds.push_back(PrimitiveBounds::of(w));
        b.faces.push_back(w);
    };
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) {
            add(node(i, j), node(i + 1, j), node(i + 1, j + 1));
            add(node(i, j), node(i + 1, j + 1), node(i, j + 1));
        }
    std::uniform_real_distribution<Real> ux(0, 2), uy(0, 1), uz(0, 0.05), ur(0.003, 0.012);
    for (int k = 0; k < grains; ++k) {
        b.pos.push_back({ux(rng), uy(rng), uz(rng)});
        b.radius.push_back(ur(rng));
    }
    return b;
}

void BM_WallCandidates(benchmark::State& state) {
    static const Bed bed = rough_bed();
    const Real skin = 0.002;
    WallBins bins;
    if (state.range(0) == 1) bins.build(bed.bounds, 0.012 + skin, 3);
    const WallCandidatesOf find{bed.faces.data(),
                                bed.active.data(),
                                bed.bounds.data(),
                                Index(bed.active.size()),
                                bed.pos.data(),
                                bed.radius.data(),
                                skin,
                                bins.view()};
    long found = 0;
    for (auto _ : state) {
        for (Index i = 0; i < Index(bed.pos.size()); ++i)
            find(i, [&](Index, std::uint32_t) { ++found; });
        benchmark::DoNotOptimize(found);
    }
    const double n = double(state.iterations()) * double(bed.pos.size());
    state.counters["grains/s"] = benchmark::Counter(n, benchmark::Counter::kIsRate);
    state.counters["faces/s"] =
        benchmark::Counter(n * double(bed.faces.size()), benchmark::Counter::kIsRate);
    state.counters["candidates/grain"] = double(found) / n;
}
BENCHMARK(BM_WallCandidates)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

} // namespace

BENCHMARK_MAIN();
