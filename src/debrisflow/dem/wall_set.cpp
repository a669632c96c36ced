#include "debrisflow/dem/wall_set.hpp"

namespace debrisflow::dem {

int WallSet::add(Wall w, std::vector<WallPrimitive> prims) {
    const int index = int(walls_.size());
    walls_.push_back(std::move(w));
    for (auto& p : prims) {
        p.wall = std::int16_t(index);
        prims_.push_back(p);
    }
    return index;
}

void WallSet::advance(Real dt) {
    for (auto& p : prims_) {
        const Vec3 d = dt * walls_[std::size_t(p.wall)].velocity;
        if (d.x == 0 && d.y == 0 && d.z == 0) continue;
        p.a += d;
        p.b += p.type == PrimitiveType::triangle ? d : Vec3{};
        p.c += p.type == PrimitiveType::triangle ? d : Vec3{};
    }
    for (auto& w : walls_) w.origin += dt * w.velocity;
}

Real WallSet::max_speed() const {
    Real m = 0;
    for (const auto& w : walls_) m = std::max(m, norm(w.velocity));
    return m;
}

int WallSet::find(const std::string& name) const {
    for (std::size_t i = 0; i < walls_.size(); ++i)
        if (walls_[i].name == name) return int(i);
    return -1;
}

} // namespace debrisflow::dem
