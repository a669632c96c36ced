// The half pair list holds what its pairs need, not its longest row times the number of rows:
// one fluid particle beside a dense knot of boundary particles (overlapping walls, a gate
// column on a floor) has a long row, and before the storage was sized per block of rows every
// fluid row paid for it (a full-size 3D case ran out of memory with its estimate well inside
// the machine's). Also checks that the list holds exactly the pairs within the radius
// (boundary-boundary pairs left out, a fluid-fluid pair once), before and after the knot moves
// into another block of rows and a block outgrows its region.
#include "debrisflow/core/error.hpp"
#include "debrisflow/core/memory_budget.hpp"
#include "debrisflow/neighbors/cell_grid.hpp"
#include "debrisflow/neighbors/pair_list.hpp"
#include "debrisflow/particles/particle_set.hpp"
#include "run_case.hpp"
#include <algorithm>
#include <gtest/gtest.h>
#include <set>
#include <utility>

using namespace debrisflow;

namespace {

constexpr Real dp = 0.01, radius = 0.03;

// A 2D block of fluid, 120 x 60 particles at dp, and a knot of 400 boundary particles at
// dp/10 spacing around `knot`.
particles::ParticleSet fluid_with_knot(Vec3 knot) {
    particles::ParticleSet s;
    for (int i = 0; i < 120; ++i)
        for (int k = 0; k < 60; ++k)
            s.add({(i + Real(0.5)) * dp, 0, (k + Real(0.5)) * dp}, {}, 1000, 0.1,
                  particles::Kind::fluid, 0);
    for (int i = 0; i < 20; ++i)
        for (int k = 0; k < 20; ++k)
            s.add({knot.x + (i - 10) * dp / 10, 0, knot.z + (k - 10) * dp / 10}, {}, 1000, 0.1,
                  particles::Kind::boundary, 1);
    return s;
}

using Pairs = std::set<std::pair<Index, Index>>;

Pairs listed(const neighbors::PairList& list) {
    Pairs out;
    for (Index i = 0; i < list.particles(); ++i)
        for (Index k = 0; k < list.count(i); ++k) {
            const Index j = list.neighbors()[list.begin(i) + std::size_t(k)];
            out.insert({std::min(i, j), std::max(i, j)});
        }
    return out;
}

// Every pair within the radius with at least one fluid particle, by brute force.
Pairs brute_force(particles::ParticleSet& s) {
    Pairs out;
    const particles::ParticleView v = s.view();
    for (Index i = 0; i < s.size(); ++i)
        for (Index j = i + 1; j < s.size(); ++j) {
            if (!v.is_fluid(i) && !v.is_fluid(j)) continue;
            const Vec3 d = v.pos(i) - v.pos(j);
            if (dot(d, d) < radius * radius) out.insert({i, j});
        }
    return out;
}

void build(neighbors::PairList& list, particles::ParticleSet& s) {
    neighbors::CellGrid grid;
    grid.configure({-0.05, -0.05, -0.05}, {1.25, 0.05, 0.65}, radius, 2, {false, false, false});
    grid.build(s.x.data(), s.y.data(), s.z.data(), s.size());
    list.build(grid.view(), s.view());
}

} // namespace

TEST(PairListMemory, FollowsThePairsNotTheLongestRow) {
    auto s = fluid_with_knot({0.3, 0, 0.3});
    neighbors::PairList list;
    build(list, s);
    const Pairs expected = brute_force(s);
    ASSERT_EQ(listed(list), expected);
    Index longest = 0;
    for (Index i = 0; i < s.size(); ++i) longest = std::max(longest, list.count(i));
    const double rows = 120 * 60, pairs = double(list.pairs());
    ASSERT_GT(longest, 4 * pairs / rows) << "the knot must make one row much longer than most";
    // Storage: the regions (pairs + a quarter + 8 per row) and the per-particle indexes
    // (count, row, owner, start, rows, touched, mask: 29 B, up to 37 B where the lists of rows
    // and touched particles were grown by doubling; 40 B here), with 4 KiB to spare.
    // A list sized by its longest row needs longest * rows * 4 B for the storage alone.
    const double bound = 4 * (1.25 * pairs + 8 * rows) + 40 * double(s.size()) + 4096;
    EXPECT_LT(double(list.bytes()), bound);
    EXPECT_LT(bound, 4 * double(longest) * rows);

    // The knot moves to the other end of the block of fluid (other rows, another block):
    // a block outgrows its region and the list is rebuilt, still exact.
    for (Index i = 120 * 60; i < s.size(); ++i) s.x[std::size_t(i)] += 0.6;
    build(list, s);
    EXPECT_EQ(listed(list), brute_force(s));
    const double most = std::max(pairs, double(list.pairs())); // the storage may be kept
    EXPECT_LT(double(list.bytes()), 4 * (1.25 * most + 8 * rows) + 40 * double(s.size()) + 4096);
}

// What `check` estimates and `run` refuses beyond the budget covers what the SPH phase holds
// after its first steps: the 3D dam break against a column (walls on five sides and around
// the column, DBC) and the 2D demo. Measured: 20.8 MB held against 28.9 MB estimated (3D),
// 1.99 MB against 2.29 MB (2D).
TEST(PairListMemory, EstimateCoversWhatTheSphPhaseHolds) {
    for (const char* file : {"/cases/bench/dambreak3d.toml", "/cases/dambreak2d.toml"}) {
        app::Simulation sim(io::read_case(std::string(DEBRISFLOW_SOURCE_DIR) + file,
                                          {"time.end=0.002", "output.vtk=false"}));
        sim.run({"", true, 0});
        const double held = double(sim.solver().memory_bytes());
        const double estimated = double(sim.memory_bytes());
        std::printf("%s: SPH phase holds %.3g B, estimated %.3g B\n", file, held, estimated);
        EXPECT_GT(held, 0);
        EXPECT_LE(held, estimated) << file;
    }
}

// A list that would take the process beyond the memory budget stops the run before it is
// allocated (an overcommitting kernel would otherwise kill the process when its pages are
// touched, without a message): here a budget of 64 KiB above what the process holds, against
// a list of about 1 MB.
TEST(PairListMemory, AListBeyondTheBudgetStopsBeforeItIsAllocated) {
    auto s = fluid_with_knot({0.3, 0, 0.3});
    struct Restore {
        double budget = memory_budget_bytes();
        ~Restore() { set_memory_budget_bytes(budget); }
    } restore;
    ASSERT_GT(resident_bytes(), 0) << "/proc/self/statm unreadable";
    set_memory_budget_bytes(resident_bytes() + 64 * 1024);
    neighbors::PairList list;
    try {
        build(list, s);
        FAIL() << "a list beyond the budget was built";
    } catch (const OutOfMemoryError& e) {
        EXPECT_NE(std::string(e.what()).find("the SPH pair list"), std::string::npos) << e.what();
    }
    set_memory_budget_bytes(restore.budget);
    build(list, s);
    EXPECT_EQ(listed(list), brute_force(s));
}
