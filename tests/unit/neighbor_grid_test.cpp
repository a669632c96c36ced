// Cell-list neighbour search finds exactly the pairs a brute-force search finds (2D, 3D,
// periodic directions with minimum-image separations), and a grid sorted in two classes
// (fluid and walls) finds the same pairs, or only the class-0 partners when asked.
#include "debrisflow/neighbors/cell_grid.hpp"
#include <gtest/gtest.h>
#include <random>
#include <set>

using namespace debrisflow;

namespace {

void compare_with_brute_force(int dim, std::array<bool, 3> periodic, bool two_classes = false) {
    std::mt19937 rng(42);
    std::uniform_real_distribution<double> u(0, 1);
    const int n = 1500;
    const Vec3 lo{0, 0, 0}, hi{1, dim == 3 ? 0.7 : 0, 0.8};
    std::vector<Real> x(n), y(n), z(n);
    std::vector<std::uint8_t> cls(n);
    for (int i = 0; i < n; ++i) {
        x[i] = hi.x * u(rng);
        y[i] = dim == 3 ? hi.y * u(rng) : 0;
        z[i] = hi.z * u(rng);
        cls[i] = u(rng) < 0.35 ? 1 : 0;
    }
    const Real radius = dim == 3 ? 0.12 : 0.06;
    neighbors::CellGrid grid;
    grid.configure(lo, hi, radius, dim, periodic);
    grid.build(x.data(), y.data(), z.data(), n, 1, two_classes ? cls.data() : nullptr);
    const auto g = grid.view();
    EXPECT_EQ(g.classes, two_classes ? 2 : 1);
    std::set<std::pair<int, int>> found, expected, found0, expected0;
    for (int i = 0; i < n; ++i) {
        g.for_each_neighbor(i, {x[i], y[i], z[i]}, x.data(), y.data(), z.data(),
                            [&](Index j, Vec3 r, Real r2) {
                                EXPECT_NEAR(dot(r, r), r2, 1e-15);
                                EXPECT_TRUE(found.insert({i, j}).second) << "duplicate pair";
                            });
        g.for_each_class0_neighbor(i, {x[i], y[i], z[i]}, x.data(), y.data(), z.data(),
                                   [&](Index j, Vec3, Real) {
                                       EXPECT_TRUE(found0.insert({i, j}).second);
                                   });
        for (int j = 0; j < n; ++j) {
            if (j == i) continue;
            Vec3 r{x[i] - x[j], y[i] - y[j], z[i] - z[j]};
            for (int d = 0; d < 3; ++d)
                if (periodic[d]) {
                    const Real len = hi[d] - lo[d];
                    r[d] -= len * std::round(r[d] / len);
                }
            if (dot(r, r) < radius * radius) {
                expected.insert({i, j});
                if (!two_classes || cls[j] == 0) expected0.insert({i, j});
            }
        }
    }
    EXPECT_EQ(found, expected);
    // one class: every partner; two: the class-0 partners only
    EXPECT_EQ(found0, expected0);
    if (two_classes) {
        EXPECT_LT(expected0.size(), expected.size());
    }
    EXPECT_GT(expected.size(), std::size_t(n));
}

} // namespace

TEST(CellGrid, MatchesBruteForce2D) {
    compare_with_brute_force(2, {false, false, false});
}
TEST(CellGrid, MatchesBruteForce3D) {
    compare_with_brute_force(3, {false, false, false});
}
TEST(CellGrid, MatchesBruteForcePeriodic) {
    compare_with_brute_force(2, {true, false, false});
    compare_with_brute_force(3, {true, true, false});
}
TEST(CellGrid, TwoClassesMatchBruteForce) {
    compare_with_brute_force(2, {false, false, false}, true);
    compare_with_brute_force(3, {false, false, false}, true);
    compare_with_brute_force(2, {true, false, false}, true);
    compare_with_brute_force(3, {true, true, false}, true);
}
