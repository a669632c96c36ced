#include "debrisflow/dem/grain_set.hpp"
#include <numeric>

namespace debrisflow::dem {

Index GrainSet::add(Vec3 p, Vec3 v, Real r, Real m, Real inertia, std::uint8_t mat) {
    x.push_back(p.x), y.push_back(p.y), z.push_back(p.z);
    vx.push_back(v.x), vy.push_back(v.y), vz.push_back(v.z);
    for (auto* f : {&wx, &wy, &wz, &fx, &fy, &fz, &tx, &ty, &tz}) f->push_back(0);
    radius.push_back(r);
    mass.push_back(m);
    inv_mass.push_back(1 / m);
    inv_inertia.push_back(1 / inertia);
    material.push_back(mat);
    id.push_back(next_id_++);
    return size() - 1;
}

void GrainSet::set_spin(Index i, Vec3 w) {
    wx[std::size_t(i)] = w.x, wy[std::size_t(i)] = w.y, wz[std::size_t(i)] = w.z;
}

namespace {
template <class T>
void apply(std::vector<T>& v, const std::vector<Index>& perm, std::vector<T>& tmp) {
    tmp.resize(v.size());
    for (std::size_t i = 0; i < perm.size(); ++i) tmp[i] = v[std::size_t(perm[i])];
    v.swap(tmp);
}
} // namespace

void GrainSet::permute(const std::vector<Index>& perm) {
    std::vector<Real> tmp;
    for (auto* f : {&x, &y, &z, &vx, &vy, &vz, &wx, &wy, &wz, &fx, &fy, &fz, &tx, &ty, &tz, &radius,
                    &mass, &inv_mass, &inv_inertia})
        apply(*f, perm, tmp);
    std::vector<std::uint8_t> t8;
    apply(material, perm, t8);
    std::vector<std::uint32_t> t32;
    apply(id, perm, t32);
}

GrainView GrainSet::view() {
    return {x.data(),      y.data(),    z.data(),        vx.data(),          vy.data(),
            vz.data(),     wx.data(),   wy.data(),       wz.data(),          fx.data(),
            fy.data(),     fz.data(),   tx.data(),       ty.data(),          tz.data(),
            radius.data(), mass.data(), inv_mass.data(), inv_inertia.data(), material.data(),
            id.data(),     size()};
}

Real GrainSet::total_mass() const {
    return std::accumulate(mass.begin(), mass.end(), Real(0));
}

} // namespace debrisflow::dem
