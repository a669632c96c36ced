#pragma once
#include "debrisflow/core/vec3_k.hpp"
#include <unordered_map>
#include <vector>

namespace debrisflow::scenario {

// Spheres placed so far by random insertion, for the question "does a sphere at p of radius r
// overlap any of them?". A hierarchy of hash grids, one per size class (cell 2 r_min 2^L holds
// the spheres of radius up to r_min 2^L), so that a query costs the same few cells per level
// whatever the spread of sizes: a wide gradation no longer puts thousands of fine grains in a
// cell sized for the largest one (Ericson 2005, Real-Time Collision Detection, 7.2.3).
class OverlapGrid {
public:
    OverlapGrid(Real r_min, Real r_max, int dim);
    bool overlaps(Vec3 p, Real r) const;
    void add(Vec3 p, Real r);

private:
    struct Level {
        Real cell = 0, r_max = 0, r_held = 0; // cell, class bound, largest radius held
        std::unordered_map<long, std::vector<int>> cells;
        std::vector<int> members;
    };
    static long key(long i, long j, long k);
    bool overlaps_any(Vec3 p, Real r, const std::vector<int>& ids) const;
    int dim_;
    std::vector<Level> levels_;
    std::vector<Vec3> centre_;
    std::vector<Real> radius_;
};

} // namespace debrisflow::scenario
