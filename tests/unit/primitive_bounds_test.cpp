#include "debrisflow/dem/wall_geometry_k.hpp"
#include <gtest/gtest.h>
#include <random>

using namespace debrisflow;
using namespace debrisflow::dem;

// The box filter of the wall-candidate search must never reject a triangle that lies within
// reach of a grain centre: random triangles and points, checked against the exact distance.
TEST(PrimitiveBounds, NeverRejectsATriangleWithinReach) {
    std::mt19937 rng(3);
    std::uniform_real_distribution<Real> u(-1, 1), r(0.01, 0.5);
    int within = 0, rejected = 0;
    for (int t = 0; t < 20000; ++t) {
        WallPrimitive w{};
        w.type = PrimitiveType::triangle;
        w.a = {u(rng), u(rng), u(rng)}, w.b = {u(rng), u(rng), u(rng)};
        w.c = {u(rng), u(rng), u(rng)};
        const Vec3 p{2 * u(rng), 2 * u(rng), 2 * u(rng)};
        const Real reach = r(rng);
        const bool near = wall_distance(w, p, closest_point(w, p)) < reach;
        const bool kept = PrimitiveBounds::of(w).may_reach(p, reach);
        if (near) {
            ++within;
            EXPECT_TRUE(kept) << "triangle " << t << " within reach was rejected";
        }
        if (!kept) ++rejected;
    }
    EXPECT_GT(within, 100);    // the test exercises triangles within reach
    EXPECT_GT(rejected, 1000); // and the filter does reject far ones
}

TEST(PrimitiveBounds, PlanesAreNeverRejected) {
    WallPrimitive w{};
    w.type = PrimitiveType::plane;
    w.n = {0, 0, 1};
    EXPECT_TRUE(PrimitiveBounds::of(w).may_reach({100, 100, 100}, 0.01));
}
