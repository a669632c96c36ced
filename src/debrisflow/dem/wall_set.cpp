#include "debrisflow/dem/wall_set.hpp"
#include <algorithm>
#include <cmath>
#include <stdexcept>

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
    const auto base = std::int32_t(solids_.size());
    for (auto& p : prims) {
        p.wall = std::int16_t(index);
        p.corners = -1;
        p.covered_by = -1;
        if (p.solid >= 0) p.solid += base;
        prims_.push_back(p);
    }
    index_solids();
    cover_faces();
    ++layout_;
    return index;
}

// Rebuilds solids_ from the primitives' solid numbers; each solid's faces must be listed
// together and face into it (the centroid of its corners behind every face).
void WallSet::index_solids() {
    std::int32_t count = 0;
    for (const auto& p : prims_) count = std::max(count, p.solid + 1);
    solids_.assign(std::size_t(count), Solid{});
    for (std::size_t i = 0; i < prims_.size(); ++i) {
        const auto& p = prims_[i];
        if (p.solid < 0) continue;
        Solid& s = solids_[std::size_t(p.solid)];
        if (s.count == 0) s.first = i, s.wall = p.wall;
        if (p.type != PrimitiveType::triangle || i != s.first + s.count)
            throw std::logic_error("WallSet: a solid's faces must be triangles listed together");
        ++s.count;
    }
    for (std::size_t k = 0; k < solids_.size(); ++k) {
        const Solid& s = solids_[k];
        Vec3 centre{};
        for (std::size_t i = s.first; i < s.first + s.count; ++i)
            centre += prims_[i].a + prims_[i].b + prims_[i].c;
        centre = (Real(1) / Real(3 * s.count)) * centre;
        for (std::size_t i = s.first; i < s.first + s.count; ++i)
            if (!(dot(centre - prims_[i].a, prims_[i].n) > 0))
                throw std::logic_error("WallSet: a solid's face normal points out of it");
    }
}

// A face of one solid lying on or in another solid that moves with it (a post's foot on the
// bed, its side against the flume wall) is covered: a point behind it is inside the structure,
// and leaving through it would lead into the neighbour.
void WallSet::cover_faces() {
    for (auto& p : prims_) {
        if (p.solid < 0) continue;
        p.covered_by = -1;
        const Real tol =
            Real(1e-9) * (1 + std::max({std::fabs(p.a.x), std::fabs(p.a.y), std::fabs(p.a.z)}));
        for (std::size_t k = 0; k < solids_.size() && p.covered_by < 0; ++k) {
            const Solid& s = solids_[k];
            if (std::int32_t(k) == p.solid) continue;
            const Vec3 dv =
                walls_[std::size_t(s.wall)].velocity - walls_[std::size_t(p.wall)].velocity;
            if (dv.x != 0 || dv.y != 0 || dv.z != 0) continue;
            bool on = true;
            for (std::size_t i = s.first; i < s.first + s.count && on; ++i) {
                const auto& f = prims_[i];
                on = dot(p.a - f.a, f.n) >= -tol && dot(p.b - f.a, f.n) >= -tol &&
                     dot(p.c - f.a, f.n) >= -tol;
            }
            if (on) p.covered_by = std::int32_t(k);
        }
    }
}

bool WallSet::inside(std::int32_t s, Vec3 p) const {
    const Solid& solid = solids_[std::size_t(s)];
    for (std::size_t i = solid.first; i < solid.first + solid.count; ++i)
        if (dot(p - prims_[i].a, prims_[i].n) < 0) return false;
    return true;
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
    index_solids();
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
