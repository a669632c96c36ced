// Rigid-body vertices against the solid boxes of a structure (a slit post beside the flume's
// side wall): inside only when behind every face, out by the nearest exposed face.
#include "debrisflow/dem/box_faces.hpp"
#include "rigid_rig.hpp"
#include <gtest/gtest.h>
#include <stdexcept>

using namespace debrisflow;

namespace {

// A slit post (x 0-0.05, y 0-0.041, z 0-0.3; wall 0) against the flume's side wall (y <= 0;
// wall 1), both solid boxes; a cube rock of half-size a centred at `centre` (linear springs,
// k_n = 1e5 N/m per vertex, no friction).
test::RigidRig post_beside_side_wall(Vec3 centre, Real a) {
    test::RigidRig rig;
    rig.materials[0].kn = 1e5;
    rig.materials[0].restitution = 1.0;
    rig.materials[0].friction = 0;
    rig.add(test::RigidRig::box("rock", centre - Vec3{a, a, a}, centre + Vec3{a, a, a}), 2650);
    std::vector<dem::WallPrimitive> post, side;
    dem::box_faces(post, {0, 0, 0}, {0.05, 0.041, 0.3}, {}, 0);
    dem::box_faces(side, {-0.5, -0.02, 0}, {0.5, 0, 0.4}, {}, 0);
    dem::Wall w;
    w.name = "dam";
    rig.walls.add(w, post);
    w.name = "flume";
    rig.walls.add(w, side);
    rig.start({0, 0, 0});
    return rig;
}

} // namespace

TEST(RigidSolidWalls, BoxFacesFaceIntoTheirSolidAndFacesOnANeighbourAreCovered) {
    auto rig = post_beside_side_wall({-1, 0.5, 0.15}, 0.01); // rock far away
    const auto& walls = rig.walls;
    ASSERT_EQ(walls.solids().size(), 2u);
    EXPECT_EQ(walls.solids()[1].first, 12u);
    EXPECT_EQ(walls.solids()[1].wall, 1);
    EXPECT_TRUE(walls.inside(0, {0.01, 0.02, 0.1}));
    EXPECT_FALSE(walls.inside(0, {0.01, 0.045, 0.1})); // out in the slit
    EXPECT_FALSE(walls.inside(0, {-0.001, 0.02, 0.1}));
    // The post's y = 0 face lies on the side wall; the side wall's face is longer than the
    // post and stays exposed.
    int covered = 0;
    for (const auto& p : walls.primitives())
        if (p.covered_by >= 0) {
            ++covered;
            EXPECT_EQ(p.solid, 0);
            EXPECT_EQ(p.covered_by, 1);
            EXPECT_NEAR(p.a.y, 0, 1e-15);
            EXPECT_NEAR(p.b.y, 0, 1e-15);
            EXPECT_NEAR(p.c.y, 0, 1e-15);
        }
    EXPECT_EQ(covered, 2);
    // A solid whose face points out of it is refused.
    std::vector<dem::WallPrimitive> bad;
    dem::box_faces(bad, {0, 0, 0}, {1, 1, 1}, {}, 0);
    bad[3].n = -1 * bad[3].n;
    dem::WallSet set;
    EXPECT_THROW(set.add(dem::Wall{}, bad), std::logic_error);
}

TEST(RigidSolidWalls, VertexOutInTheSlitIsNotInsideThePost) {
    // Cube rock (a = 20 mm) in front of the post, its centre within the post's y range: two
    // corners are 1 mm past the upstream face's plane and inside the post (pushed back along
    // -x: 2 k_n x 1 mm on the post), two are past that plane but 3 mm out in the slit
    // (y = 0.044 > 0.041), outside the post: no contact. Judged by the side of the centre,
    // the slit face took them as 3 mm inside and pushed the rock at the side wall, which
    // threw rocks out of the s/d95 = 1.49 check dam.
    auto rig = post_beside_side_wall({-0.019, 0.024, 0.15}, 0.02);
    EXPECT_EQ(rig.solver->contacts(), 2);
    const Vec3 f = rig.solver->wall_force(0);
    EXPECT_NEAR(f.x, 2 * 1e5 * 0.001, 1e-9);
    EXPECT_NEAR(f.y, 0, 1e-9);
    EXPECT_NEAR(f.z, 0, 1e-9);
    EXPECT_NEAR(norm(rig.solver->wall_force(1)), 0, 1e-12);
}

TEST(RigidSolidWalls, VertexAtTheSeamWithTheSideWallLeavesUpstream) {
    // Cube rock (a = 10 mm, vertex reach 2 mm) pressed into the post's upstream face next to
    // the side wall: four corners 1.5 mm deep, two of them 0.5 mm from the post's y = 0 face.
    // That face lies on the side wall (covered), so every corner leaves upstream: 4 k_n x
    // 1.5 mm on the post along +x. With the side wall gone (a removed gate) the face is
    // exposed and the two corners by it leave through it: 2 k_n x 0.5 mm on the post along +y.
    auto rig = post_beside_side_wall({-0.0085, 0.0105, 0.15}, 0.01);
    EXPECT_EQ(rig.solver->contacts(), 4);
    Vec3 f = rig.solver->wall_force(0);
    EXPECT_NEAR(f.x, 4 * 1e5 * 0.0015, 1e-9);
    EXPECT_NEAR(f.y, 0, 1e-9);
    rig.walls.walls()[1].active = false;
    rig.solver->compute_forces();
    EXPECT_EQ(rig.solver->contacts(), 4);
    f = rig.solver->wall_force(0);
    EXPECT_NEAR(f.x, 2 * 1e5 * 0.0015, 1e-9);
    EXPECT_NEAR(f.y, 2 * 1e5 * 0.0005, 1e-9);
}
