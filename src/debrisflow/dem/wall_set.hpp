#pragma once
#include "debrisflow/dem/wall_geometry_k.hpp"
#include <optional>
#include <string>
#include <vector>

namespace debrisflow::dem {

// A named geometric wall: planes and/or triangles moving with a prescribed velocity, removable
// at a time (a gate). Its contact force and moment (about `origin`) are summed every step.
struct Wall {
    std::string name;
    int material = -1; // -1: contacts use the grain's own material
    Vec3 velocity;
    Vec3 origin;
    std::optional<Real> remove_at;
    bool active = true;
    Vec3 force, moment; // on the wall from the grains, last step [N], [N m]
    Vec3 impulse;       // time integral of force since the last reset_impulse() [N s]
    Real impulse_time = 0;
};

class WallSet {
public:
    int add(Wall w, std::vector<WallPrimitive> prims);
    // Moves every moving wall by velocity * dt.
    void advance(Real dt);
    // Largest wall speed (for the neighbour skin).
    Real max_speed() const;

    std::vector<Wall>& walls() { return walls_; }
    const std::vector<Wall>& walls() const { return walls_; }
    const std::vector<WallPrimitive>& primitives() const { return prims_; }
    int find(const std::string& name) const; // -1 if absent
    bool empty() const { return prims_.empty(); }

private:
    std::vector<Wall> walls_;
    std::vector<WallPrimitive> prims_;
};

} // namespace debrisflow::dem
