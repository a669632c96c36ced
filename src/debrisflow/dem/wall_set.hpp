#pragma once
#include "debrisflow/dem/wall_geometry_k.hpp"
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace debrisflow::checkpoint {
class Archive;
}

namespace debrisflow::dem {

// A named geometric wall: planes and/or triangles moving with a prescribed velocity, removable
// at a time (a gate). Its contact force and moment (about `origin`) are summed every step.
// One contact's load on a wall: where it acts and the force on the wall [N].
struct ContactLoad {
    Vec3 point, force;
};

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
    // Pressure maps need each contact's point: with record_contacts the last force evaluation's
    // grain contacts on this wall are kept in `contacts` (ordered by grain).
    bool record_contacts = false;
    std::vector<ContactLoad> contacts;
};

// The moving nodes under nodal triangles: positions and velocities set by the owner (the
// DEM-FEM coupling) and drifted with the walls; the grains' reaction impulse on each node
// (split by the barycentric weights of the contact point) accumulates until collected.
struct MovingNodes {
    std::vector<Vec3> x, v;
    std::vector<Vec3> impulse; // [N s] since the last collection
};

// A convex solid (a structure's box): faces first .. first + count - 1 of the primitive list,
// normals pointing into it.
struct Solid {
    std::size_t first = 0, count = 0;
    int wall = -1;
};

class WallSet {
public:
    // Adds a wall; the `solid` numbers of its primitives count from 0 within `prims` (each
    // solid's faces listed together) and become indices of solids().
    int add(Wall w, std::vector<WallPrimitive> prims);
    // Adds a wall of triangles whose corners follow the moving nodes; returns its index.
    int add_nodal(Wall w, const std::vector<NodalCorners>& triangles);
    // Replaces the triangles of nodal wall `wall` (eroded elements left the surface). The
    // primitive list changes: the DEM must rebuild its wall contact lists.
    void replace_nodal(int wall, const std::vector<NodalCorners>& triangles);
    // Recomputes every nodal triangle from the moving nodes' positions.
    void place_nodal();
    // Moves every moving wall by velocity * dt (nodal triangles: their nodes by v * dt).
    void advance(Real dt);
    // Largest wall or node speed (for the neighbour skin).
    Real max_speed() const;
    MovingNodes& nodes() { return nodes_; }
    const MovingNodes& nodes() const { return nodes_; }
    const std::vector<NodalCorners>& corners() const { return corners_; }
    // Bumped when primitives are added or replaced.
    std::uint64_t layout() const { return layout_; }

    std::vector<Wall>& walls() { return walls_; }
    const std::vector<Wall>& walls() const { return walls_; }
    const std::vector<WallPrimitive>& primitives() const { return prims_; }
    const std::vector<Solid>& solids() const { return solids_; }
    // Whether p lies inside solid s: behind (on the normal side of) every face plane.
    bool inside(std::int32_t s, Vec3 p) const;
    int find(const std::string& name) const; // -1 if absent
    bool empty() const { return prims_.empty(); }

    // Saves or restores the walls' motion, activity and loads and the faces' positions
    // (dem/dem_checkpoint.cpp), FEM surfaces (nodal walls) included.
    void state(checkpoint::Archive& ar);

private:
    void index_solids();
    void cover_faces();

    std::vector<Wall> walls_;
    std::vector<Solid> solids_;
    std::vector<WallPrimitive> prims_;
    std::vector<NodalCorners> corners_;
    MovingNodes nodes_;
    std::uint64_t layout_ = 0;
};

} // namespace debrisflow::dem
