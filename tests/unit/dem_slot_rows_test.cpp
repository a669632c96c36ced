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
