#pragma once
#include "debrisflow/dem/wall_bins.hpp"
#include "debrisflow/dem/wall_set.hpp"
#include <vector>

namespace debrisflow::dem {

// How deep a sphere would sit in the walls: overlap r - d with each primitive within reach (d
// signed for a plane, negative behind it; the distance to a triangle), and whether its centre
// lies inside a solid (a structure's box), where no face may be within reach. Used to keep
// grains from starting inside walls (scenario/build_grains.cpp, flow/grain_feed.cpp).
struct WallOverlap {
    Real overlap = 0; // [m], the deepest; > r: the centre is behind a plane or in a solid
    int wall = -1;    // named wall holding the deepest primitive or solid (-1: none)
    bool in_solid = false;
};

class WallProximity {
public:
    // The primitives and solids of the walls present at the start (those removed at t <= 0
    // left out) or, with `fixed_only`, of the active walls that do not move (a feed's region
    // is tested against the walls where they are now); reach: the largest sphere radius.
    WallProximity(const WallSet& walls, Real reach, int dim, bool fixed_only = false);
    // A solid block of wall `wall` given by its box (a "box" wall, whose faces are an open
    // surface to the contacts): a centre inside it is inside the wall.
    void add_solid_box(Vec3 lo, Vec3 hi, int wall);
    WallOverlap deepest(Vec3 p, Real r) const;
    bool empty() const { return active_.empty() && solids_.empty() && boxes_.empty(); }

private:
    const WallSet& walls_;
    std::vector<Index> active_; // primitives tested
    std::vector<PrimitiveBounds> bounds_;
    std::vector<int> solids_; // solids tested
    struct Box {
        Vec3 lo, hi;
        int wall;
    };
    std::vector<Box> boxes_;
    bool fixed_only_;
    WallBins bins_;
};

} // namespace debrisflow::dem
