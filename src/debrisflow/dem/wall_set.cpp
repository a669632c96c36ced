#include "debrisflow/dem/wall_set.hpp"
#include <algorithm>

namespace debrisflow::dem {

namespace {

WallPrimitive nodal_triangle(const NodalCorners& c, const std::vector<Vec3>& x, int wall,
                             std::int32_t row) {
    WallPrimitive p{};
    p.a = x[std::size_t(c.node[0])] + c.offset[0];
    p.b = x[std::size_t(c.node[1])] + c.offset[1];
    p.c = x[std::size_t(c.node[2])] + c.offset[2];
    const Vec3 n = cross(p.b - p.a, p.c - p.a);
    const Real len = norm(n);
    p.n = len > 0 ? (1 / len) * n : Vec3{0, 0, 1};
    p.type = PrimitiveType::triangle;
    p.wall = std::int16_t(wall);
    p.corners = row;
    return p;
}

} // namespace

int WallSet::add(Wall w, std::vector<WallPrimitive> prims) {
    const int index = int(walls_.size());
    walls_.push_back(std::move(w));
    for (auto& p : prims) {
        p.wall = std::int16_t(index);
        p.corners = -1;
        prims_.push_back(p);
    }
    ++layout_;
    return index;
}

int WallSet::add_nodal(Wall w, const std::vector<NodalCorners>& triangles) {
    const int index = int(walls_.size());
    walls_.push_back(std::move(w));
    replace_nodal(index, triangles);
    return index;
}

void WallSet::replace_nodal(int wall, const std::vector<NodalCorners>& triangles) {
    // Drop the wall's old triangles (and their corner rows), then append the new ones.
    std::vector<WallPrimitive> kept;
    std::vector<NodalCorners> kept_corners;
    for (const auto& p : prims_) {
        if (p.wall == wall) continue;
        WallPrimitive q = p;
        if (q.corners >= 0) {
            kept_corners.push_back(corners_[std::size_t(q.corners)]);
            q.corners = std::int32_t(kept_corners.size() - 1);
        }
        kept.push_back(q);
    }
    for (const auto& t : triangles) {
        kept_corners.push_back(t);
        kept.push_back(nodal_triangle(t, nodes_.x, wall, std::int32_t(kept_corners.size() - 1)));
    }
    prims_ = std::move(kept);
    corners_ = std::move(kept_corners);
    ++layout_;
}

void WallSet::place_nodal() {
    for (auto& p : prims_)
        if (p.corners >= 0)
            p = nodal_triangle(corners_[std::size_t(p.corners)], nodes_.x, p.wall, p.corners);
}

void WallSet::advance(Real dt) {
    for (auto& p : prims_) {
        if (p.corners >= 0) continue;
        const Vec3 d = dt * walls_[std::size_t(p.wall)].velocity;
        if (d.x == 0 && d.y == 0 && d.z == 0) continue;
        p.a += d;
        p.b += p.type == PrimitiveType::triangle ? d : Vec3{};
        p.c += p.type == PrimitiveType::triangle ? d : Vec3{};
    }
    for (auto& w : walls_) w.origin += dt * w.velocity;
    if (!corners_.empty()) {
        for (std::size_t i = 0; i < nodes_.x.size(); ++i) nodes_.x[i] += dt * nodes_.v[i];
        place_nodal();
    }
}

Real WallSet::max_speed() const {
    Real m = 0;
    for (const auto& w : walls_) m = std::max(m, norm(w.velocity));
    if (!corners_.empty())
        for (const auto& v : nodes_.v) m = std::max(m, norm(v));
    return m;
}

int WallSet::find(const std::string& name) const {
    for (std::size_t i = 0; i < walls_.size(); ++i)
        if (walls_[i].name == name) return int(i);
    return -1;
}

} // namespace debrisflow::dem
