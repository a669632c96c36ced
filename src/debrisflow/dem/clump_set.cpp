#include "debrisflow/dem/clump_set.hpp"
#include "debrisflow/rigid/free_rotation_k.hpp"
#include <algorithm>
#include <numeric>

namespace debrisflow::dem {

Index ClumpSet::add(Vec3 com, Vec3 v, Vec3 w, rigid::Quat q, Real m, Vec3 inv_i,
                    const std::vector<std::uint32_t>& ids, const std::vector<Vec3>& offsets) {
    pos.push_back(com);
    vel.push_back(v);
    ang_mom.push_back(rigid::angular_momentum(q, w, inv_i));
    force.push_back({});
    torque.push_back({});
    orient.push_back(q);
    mass.push_back(m);
    inv_inertia.push_back(inv_i);
    member_id.insert(member_id.end(), ids.begin(), ids.end());
    offset.insert(offset.end(), offsets.begin(), offsets.end());
    first.push_back(std::uint32_t(member_id.size()));
    return size() - 1;
}

Vec3 ClumpSet::spin(Index c) const {
    const std::size_t k = std::size_t(c);
    return rigid::angular_velocity(orient[k], ang_mom[k], inv_inertia[k]);
}

void ClumpSet::select(const std::vector<std::uint8_t>& keep) {
    ClumpSet out;
    for (Index c = 0; c < size(); ++c) {
        const std::size_t k = std::size_t(c);
        if (!keep[k]) continue;
        const std::vector<std::uint32_t> ids(member_id.begin() + first[k],
                                             member_id.begin() + first[k + 1]);
        const std::vector<Vec3> offs(offset.begin() + first[k], offset.begin() + first[k + 1]);
        out.add(pos[k], vel[k], {}, orient[k], mass[k], inv_inertia[k], ids, offs);
        out.ang_mom.back() = ang_mom[k];
        out.force.back() = force[k];
        out.torque.back() = torque[k];
    }
    *this = std::move(out);
}

Real ClumpSet::max_inv_inertia(Index c) const {
    const Vec3 v = inv_inertia[std::size_t(c)];
    return std::max({v.x, v.y, v.z});
}

Real ClumpSet::total_mass() const {
    return std::accumulate(mass.begin(), mass.end(), Real(0));
}

} // namespace debrisflow::dem
