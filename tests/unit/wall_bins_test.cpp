// The binned grain-wall candidate search (dem/wall_bins_k.hpp, issue #34: a wall mesh of many
// triangles is not searched by brute force) against the search over every active primitive:
// the same candidates in the same order for every grain, while testing a small share of the
// faces.
#include "debrisflow/dem/slot_candidates_k.hpp"
#include "debrisflow/dem/wall_bins.hpp"
#include <cmath>
#include <cstdio>
#include <gtest/gtest.h>
#include <random>
#include <vector>

using namespace debrisflow;
using namespace debrisflow::dem;

namespace {

WallPrimitive triangle(Vec3 a, Vec3 b, Vec3 c) {
    WallPrimitive w{};
    w.type = PrimitiveType::triangle;
    w.a = a, w.b = b, w.c = c;
    const Vec3 n = cross(b - a, c - a);
    w.n = (1 / norm(n)) * n;
    return w;
}

WallPrimitive plane(Vec3 a, Vec3 n) {
    WallPrimitive w{};
    w.type = PrimitiveType::plane;
    w.a = a, w.n = n;
    return w;
}

// A bumpy bed z = 0.05 sin(6x) cos(5y) over 2 m x 1 m in 2 x nx x ny triangles, two side planes,
// a few faces much larger than the mesh's (they stay out of the bins), and some primitives
// inactive (left out of the active list, as a removed gate's).
struct Scene {
    std::vector<WallPrimitive> prims;
    std::vector<Index> active;
    std::vector<PrimitiveBounds> bounds;
};

Scene bumpy_bed(int nx, int ny) {
    Scene s;
    const auto z = [](Real x, Real y) { return Real(0.05) * std::sin(6 * x) * std::cos(5 * y); };
    const Real dx = Real(2) / nx, dy = Real(1) / ny;
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) {
            const Real x0 = i * dx, y0 = j * dy, x1 = x0 + dx, y1 = y0 + dy;
            const Vec3 a{x0, y0, z(x0, y0)}, b{x1, y0, z(x1, y0)}, c{x1, y1, z(x1, y1)},
                d{x0, y1, z(x0, y1)};
            s.prims.push_back(triangle(a, b, c));
            s.prims.push_back(triangle(a, c, d));
        }
    s.prims.push_back(plane({0, 0, 0}, {0, 1, 0}));
    s.prims.push_back(plane({0, 1, 0}, {0, -1, 0}));
    s.prims.push_back(triangle({-1, -1, -0.2}, {3, -1, -0.2}, {3, 2, -0.2})); // under the bed
    s.prims.push_back(triangle({-1, 0.5, -1}, {3, 0.5, -1}, {1, 0.5, 1}));    // across it
    for (std::size_t k = 0; k < s.prims.size(); ++k) {
        if (k % 97 == 5) continue; // inactive
        s.active.push_back(Index(k));
        s.bounds.push_back(PrimitiveBounds::of(s.prims[k]));
    }
    return s;
}

struct Grains {
    std::vector<Vec3> pos;
    std::vector<Real> radius;
};

Grains grains_over_the_bed(int n, unsigned seed, bool plane2d) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<Real> ux(-0.1, 2.1), uy(-0.05, 1.05), uz(-0.1, 0.1),
        ur(0.003, 0.012);
    Grains g;
    for (int i = 0; i < n; ++i) {
        g.pos.push_back({ux(rng), plane2d ? Real(0.5) : uy(rng), uz(rng)});
        g.radius.push_back(ur(rng));
    }
    return g;
}

// Each grain's candidates (primitive index, in emission order) and the faces tested.
struct Found {
    std::vector<std::vector<Index>> rows;
    long tested = 0;
};

Found search(const Scene& s, const Grains& g, Real skin, WallBinsView bins) {
    const WallCandidatesOf find{s.prims.data(),
                                s.active.data(),
                                s.bounds.data(),
                                Index(s.active.size()),
                                g.pos.data(),
                                g.radius.data(),
                                skin,
                                bins};
    Found f;
    for (Index i = 0; i < Index(g.pos.size()); ++i) {
        std::vector<Index> row;
        find(i, [&](Index prim, std::uint32_t key) {
            EXPECT_EQ(key, std::uint32_t(prim));
            row.push_back(prim);
        });
        bins.for_each_candidate(g.pos[std::size_t(i)], Index(s.active.size()),
                                [&](Index) { ++f.tested; });
        f.rows.push_back(row);
    }
    return f;
}

void expect_same_candidates(int dim) {
    // 10,000 triangles; in a plane case one strip of them across the thickness
    const Scene s = dim == 3 ? bumpy_bed(100, 50) : bumpy_bed(5000, 1);
    const Grains g = grains_over_the_bed(4000, 7, dim == 2);
    const Real skin = 0.002, largest = 0.012;
    WallBins bins;
    bins.build(s.bounds, largest + skin, dim);
    ASSERT_TRUE(bins.view().binned);
    const Found all = search(s, g, skin, WallBinsView{});
    const Found binned = search(s, g, skin, bins.view());
    long candidates = 0;
    for (std::size_t i = 0; i < all.rows.size(); ++i) {
        EXPECT_EQ(all.rows[i], binned.rows[i]) << "grain " << i;
        candidates += long(all.rows[i].size());
    }
    EXPECT_GT(candidates, 2000); // grains near the bed have candidates
    // The large faces and the planes are tested by every grain, the mesh's faces only in a
    // grain's cell (cells about a widened face wide: those within reach and their neighbours):
    // 42 per grain in 3D, 193 along the strip of faces 0.4 mm wide in the plane case (a reach
    // of 14 mm spans dozens of them), instead of all 10,000; the bound asks for twenty times
    // fewer.
    const double per_grain = double(binned.tested) / double(g.pos.size());
    std::printf("dim %d: %.1f faces tested per grain (of %zu), %zu kept out of the bins\n", dim,
                per_grain, s.active.size(), bins.always().size());
    EXPECT_LT(per_grain, 0.05 * double(s.active.size()));
    EXPECT_EQ(bins.always().size(), 4u); // the two planes and the two large faces
}

} // namespace

TEST(WallBins, SameCandidatesInTheSameOrderAsTheSearchOverEveryFace) {
    expect_same_candidates(3);
}

TEST(WallBins, SameCandidatesInAPlaneCase) {
    expect_same_candidates(2);
}

// Few faces (a flume's planes and boxes) are searched one by one.
TEST(WallBins, FewFacesAreNotBinned) {
    const Scene s = bumpy_bed(4, 4); // 32 triangles and 4 large primitives
    WallBins bins;
    bins.build(s.bounds, 0.01, 3);
    EXPECT_FALSE(bins.view().binned);
    int visited = 0;
    bins.view().for_each_candidate({0, 0, 0}, 7, [&](Index a) { EXPECT_EQ(a, visited++); });
    EXPECT_EQ(visited, 7);
}
