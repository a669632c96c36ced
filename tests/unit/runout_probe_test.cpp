// The run-out of a granular deposit (probes/runout_probe.hpp): the front of the group of
// touching grains of largest mass, against hand-built arrangements whose answer is known.
#include "debrisflow/probes/runout_probe.hpp"
#include <cmath>
#include <gtest/gtest.h>
#include <vector>

using namespace debrisflow;

namespace {
struct Grains {
    std::vector<Vec3> pos;
    std::vector<Real> radius, mass;
    std::vector<std::int32_t> clump;
    void add(Real x, Real z, Real r, std::int32_t c = -1) {
        pos.push_back({x, 0, z});
        radius.push_back(r);
        mass.push_back(r * r); // discs of one thickness and density
        clump.push_back(c);
    }
    probes::Runout measure(int axis, int sign, Real gap = 0.05, bool clumps = false) const {
        return probes::measure_runout(pos, radius, mass,
                                      clumps ? std::span<const std::int32_t>(clump)
                                             : std::span<const std::int32_t>(),
                                      axis, sign, 0, gap);
    }
};

// A row of 10 touching discs of radius 1 on the bed (z = 1), centres at x = 0, 2, ..., 18.
Grains row() {
    Grains g;
    for (int i = 0; i < 10; ++i) g.add(2 * i, 1, 1);
    return g;
}
} // namespace

TEST(Runout, TouchingRowIsOneDeposit) {
    const auto r = row().measure(0, +1);
    EXPECT_DOUBLE_EQ(r.front, 19); // last centre 18 + r
    EXPECT_DOUBLE_EQ(r.front_max, 19);
    EXPECT_DOUBLE_EQ(r.height, 2);
    EXPECT_EQ(r.detached, 0);
    EXPECT_DOUBLE_EQ(r.detached_mass, 0);
    // 95 % of 10 equal masses lies behind the tenth grain's edge
    EXPECT_DOUBLE_EQ(r.front_95, 19);
}

TEST(Runout, StragglersAheadOfTheDepositAreDetached) {
    Grains g = row();
    g.add(30, 1, 1);     // a disc rolled away: a gap of 10 radii
    g.add(18, 4.1, 0.5); // a bouncing disc above the last one (surfaces 1.6 apart): detached
    const auto r = g.measure(0, +1);
    EXPECT_DOUBLE_EQ(r.front, 19);
    EXPECT_DOUBLE_EQ(r.front_max, 31);
    EXPECT_EQ(r.detached, 2);
    EXPECT_DOUBLE_EQ(r.detached_mass, 1 + 0.25);
    EXPECT_DOUBLE_EQ(r.height, 2);
}

TEST(Runout, GapIsAFractionOfTheSmallerDiameter) {
    Grains g = row();
    g.add(20.09, 1, 1); // surfaces 0.09 apart: 0.045 x the diameter 2
    EXPECT_DOUBLE_EQ(g.measure(0, +1, 0.05).front, 21.09);
    EXPECT_DOUBLE_EQ(g.measure(0, +1, 0.04).front, 19);
    EXPECT_EQ(g.measure(0, +1, 0.04).detached, 1);
}

TEST(Runout, TowardsMinusXIsTheMirrorImage) {
    Grains g = row();
    g.add(-12, 1, 1); // detached, on the -x side
    const auto r = g.measure(0, -1);
    EXPECT_DOUBLE_EQ(r.front, -1);      // first centre 0 - r
    EXPECT_DOUBLE_EQ(r.front_max, -13); // the straggler's far edge
    EXPECT_EQ(r.detached, 1);
}

TEST(Runout, LargestGroupByMassIsTheDeposit) {
    // three small discs touching each other far ahead of one big disc: the big disc (mass 16)
    // outweighs them (3 x 1) and is the deposit
    Grains g;
    g.add(0, 4, 4);
    for (int i = 0; i < 3; ++i) g.add(20 + 2 * i, 1, 1);
    const auto r = g.measure(0, +1);
    EXPECT_DOUBLE_EQ(r.front, 4);
    EXPECT_EQ(r.detached, 3);
    // 95 % of the mass (19) lies behind the last small disc's edge, 90 % behind the second's
    EXPECT_DOUBLE_EQ(r.front_95, 25);
}

TEST(Runout, MembersOfAClumpAreOneGrain) {
    Grains g = row();
    g.add(24, 1, 1, 7); // a clump whose two members do not touch (a long clump's ends)
    g.add(20, 1, 1, 7); // touches the row
    EXPECT_EQ(g.measure(0, +1, 0.05, false).detached, 1);
    const auto r = g.measure(0, +1, 0.05, true);
    EXPECT_EQ(r.detached, 0);
    EXPECT_DOUBLE_EQ(r.front, 25);
}

TEST(Runout, GrainsSpreadOverManyCellsAreLinkedAcrossCellFaces) {
    // a diagonal staircase of touching discs of two sizes in 3D crosses cell faces on every axis
    Grains g;
    Vec3 p{-3.3, -2.2, 0.7};
    Real r = 0.5;
    for (int i = 0; i < 50; ++i) {
        g.pos.push_back(p);
        g.radius.push_back(r);
        g.mass.push_back(r * r * r);
        const Real next = i % 2 ? 0.5 : 0.3;
        const Real d = (r + next) / std::sqrt(Real(3));
        p = p + Vec3{d, d, d};
        r = next;
    }
    // (touching to round-off: a gap of 1e-9 diameters)
    const auto res = probes::measure_runout(g.pos, g.radius, g.mass, {}, 2, +1, 0, 1e-9);
    EXPECT_EQ(res.detached, 0);
    // the last disc (radius 0.3) sits (0.3 + 0.5) / sqrt(3) below p along each axis
    EXPECT_NEAR(res.front, p.z - (0.3 + 0.5) / std::sqrt(Real(3)) + 0.3, 1e-12);
}
