// Grain-grain contact slots keep each pair once, in the row of the smaller grain: a boulder
// among fines holds only the grains at least as large as itself. The slots have one capacity
// for every grain (the longest row's), so a boulder whose row held the fines around it would
// size every grain's row (before: a boulder block listed before the fines, the order the
// random insertion asks for, made a two-level slit-dam case take 4.5 times the memory).
#include "debrisflow/dem/contact_slots.hpp"
#include "debrisflow/dem/slot_candidates_k.hpp"
#include "debrisflow/neighbors/cell_grid.hpp"
#include <gtest/gtest.h>
#include <set>
#include <utility>
#include <vector>

using namespace debrisflow;

TEST(DemSlotRows, APairLivesInTheSmallerGrainsRow) {
    // A boulder of radius 20 mm (id 0, the lowest) at the centre of a cubic lattice of 5 mm
    // fines at 5.5 mm spacing; the fines that overlap the boulder are left out. Ties between
    // equal fines go by id. Search margin 2 mm.
    const Real rb = 0.02, rf = 0.0025, spacing = 0.0055, skin = 0.002;
    std::vector<Vec3> pos{{0, 0, 0}};
    std::vector<Real> radius{rb};
    for (int i = -8; i <= 8; ++i)
        for (int j = -8; j <= 8; ++j)
            for (int k = -8; k <= 8; ++k) {
                const Vec3 p{i * spacing, j * spacing, k * spacing};
                if (norm(p) < rb + rf) continue;
                pos.push_back(p), radius.push_back(rf);
            }
    const Index n = Index(pos.size());
    std::vector<std::uint32_t> id(pos.size());
    for (std::size_t i = 0; i < id.size(); ++i) id[i] = std::uint32_t(i);
    neighbors::CellGrid grid;
    grid.configure({-0.06, -0.06, -0.06}, {0.06, 0.06, 0.06}, 2 * rb + skin, 3,
                   {false, false, false});
    grid.build(&pos[0].x, &pos[0].x + 1, &pos[0].x + 2, n, 3);
    dem::ContactSlots slots;
    slots.build(
        n, dem::GrainCandidates{grid.view(), pos.data(), radius.data(), id.data(), nullptr, skin});

    // Every pair within reach once, in the smaller grain's row (equal radii: the lower id).
    std::set<std::pair<Index, Index>> expected, found;
    for (Index a = 0; a < n; ++a)
        for (Index b = a + 1; b < n; ++b) {
            const Real reach = radius[a] + radius[b] + skin;
            const Vec3 d = pos[std::size_t(a)] - pos[std::size_t(b)];
            if (dot(d, d) >= reach * reach) continue;
            const bool a_owns = radius[a] < radius[b] || (radius[a] == radius[b] && a < b);
            expected.insert(a_owns ? std::pair{a, b} : std::pair{b, a});
        }
    for (Index i = 0; i < n; ++i)
        for (Index k = 0; k < slots.count(i); ++k)
            found.insert({i, slots.partners()[std::size_t(i) * std::size_t(slots.capacity()) +
                                              std::size_t(k)]});
    EXPECT_EQ(found, expected);
    Index around = 0; // fines within the boulder's reach
    for (const auto& [i, j] : expected) around += j == 0 ? 1 : 0;
    ASSERT_GT(around, 100) << "the boulder must have many fines within reach";
    EXPECT_EQ(slots.count(0), 0) << "the boulder's row holds only grains at least as large";
    // A fine's row: its larger or equal neighbours of higher id (at most the 26 of its 3x3x3
    // lattice cube within reach: 6 at 5.5 mm; the diagonals are beyond 5 + 2 mm) and the boulder.
    EXPECT_LE(slots.capacity(), 16);
}

namespace {

// Slots of n grains of radius 1 mm (ids in order) at the given positions, search margin 1 mm.
void build_slots(dem::ContactSlots& slots, const std::vector<Vec3>& pos) {
    const Index n = Index(pos.size());
    const Real skin = 0.001;
    const std::vector<Real> radius(pos.size(), 0.001);
    std::vector<std::uint32_t> id(pos.size());
    for (std::size_t i = 0; i < id.size(); ++i) id[i] = std::uint32_t(i);
    neighbors::CellGrid grid;
    grid.configure({-0.01, -0.01, -0.01}, {0.1, 0.01, 0.01}, 0.003, 3, {false, false, false});
    grid.build(&pos[0].x, &pos[0].x + 1, &pos[0].x + 2, n, 3);
    slots.build(
        n, dem::GrainCandidates{grid.view(), pos.data(), radius.data(), id.data(), nullptr, skin});
}

} // namespace

// The capacity of every row follows the longest row of the last rebuild, down as well as up,
// and the springs of the pairs that stay are carried into the narrower rows. Before, the
// capacity only grew: one dense moment (a packing at the start, a jam) left every grain's row
// that wide for the rest of the run, and the contact loop read the empty slots' stride.
TEST(DemSlotRows, CapacityFollowsTheLongestRowDownAsWellAsUp) {
    const int n = 30;
    std::vector<Vec3> cluster, line;
    for (int i = 0; i < n; ++i) {
        cluster.push_back({0.00002 * i, 0, 0}); // every grain within reach of every other
        line.push_back({0.0025 * i, 0, 0});     // each within reach of its next only (2.5 < 3 mm)
    }
    dem::ContactSlots slots;
    build_slots(slots, cluster);
    EXPECT_EQ(slots.count(0), n - 1);
    ASSERT_GE(slots.capacity(), n - 1);
    EXPECT_EQ(slots.capacity(), dem::slot_capacity_for(n - 1));

    // Spread out: this build still has the cluster's stride, the next one the line's.
    build_slots(slots, line);
    for (Index i = 0; i + 1 < n; ++i) {
        ASSERT_EQ(slots.count(i), 1);
        const std::size_t s = std::size_t(i) * std::size_t(slots.capacity());
        EXPECT_EQ(slots.partners()[s], i + 1);
        slots.tangential()[s] = Vec3{Real(i), 1, 2}; // a spring that the next build must keep
    }
    build_slots(slots, line);
    EXPECT_EQ(slots.capacity(), dem::slot_capacity_for(1)) << "the rows' stride shrinks";
    for (Index i = 0; i + 1 < n; ++i) {
        ASSERT_EQ(slots.count(i), 1);
        const std::size_t s = std::size_t(i) * std::size_t(slots.capacity());
        EXPECT_EQ(slots.partners()[s], i + 1);
        EXPECT_EQ(slots.tangential()[s].x, Real(i)) << "grain " << i << "'s spring carried over";
        EXPECT_EQ(slots.tangential()[s].z, Real(2));
    }
    EXPECT_EQ(slots.count(n - 1), 0);

    // Back into the cluster: the narrow rows overflow and the build goes round again with room,
    // keeping the springs of the pairs that remain.
    build_slots(slots, cluster);
    EXPECT_EQ(slots.count(0), n - 1);
    EXPECT_EQ(slots.capacity(), dem::slot_capacity_for(n - 1));
    const std::size_t row = std::size_t(3) * std::size_t(slots.capacity());
    Index with4 = -1;
    for (Index k = 0; k < slots.count(3); ++k)
        if (slots.partners()[row + std::size_t(k)] == 4) with4 = k;
    ASSERT_GE(with4, 0);
    EXPECT_EQ(slots.tangential()[row + std::size_t(with4)].x, Real(3))
        << "grain 3's spring with grain 4 kept through the regrowth";
}
