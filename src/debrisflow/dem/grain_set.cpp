#include "debrisflow/dem/grain_set.hpp"
#include <numeric>

namespace debrisflow::dem {

Index GrainSet::add(Vec3 p, Vec3 v, Real r, Real m, Real inertia, std::uint8_t mat) {
    pos.push_back(p);
    vel.push_back(v);
    spin.push_back({});
    force.push_back({});
    torque.push_back({});
    radius.push_back(r);
    mass.push_back(m);
    inv_mass.push_back(1 / m);
    inv_inertia.push_back(1 / inertia);
    material.push_back(mat);
    id.push_back(next_id_++);
    return size() - 1;
}

void GrainSet::set_spin(Index i, Vec3 w) {
    spin[std::size_t(i)] = w;
}

namespace {
template <class T>
void apply(std::vector<T>& v, const std::vector<Index>& perm, std::vector<T>& tmp) {
    tmp.resize(perm.size());
    for (std::size_t i = 0; i < perm.size(); ++i) tmp[i] = v[std::size_t(perm[i])];
    v.swap(tmp);
}
} // namespace

void GrainSet::permute(const std::vector<Index>& perm) {
    std::vector<Vec3> tmp3;
    for (auto* f : {&pos, &vel, &spin, &force, &torque}) apply(*f, perm, tmp3);
    std::vector<Real> tmp;
    for (auto* f : {&radius, &mass, &inv_mass, &inv_inertia}) apply(*f, perm, tmp);
    std::vector<std::uint8_t> t8;
    apply(material, perm, t8);
    std::vector<std::uint32_t> t32;
    apply(id, perm, t32);
}

void GrainSet::select(const std::vector<Index>& kept) {
    permute(kept); // a permutation onto a subset
}

GrainView GrainSet::view() {
    return {pos.data(),         vel.data(),      spin.data(), force.data(),
            torque.data(),      radius.data(),   mass.data(), inv_mass.data(),
            inv_inertia.data(), material.data(), id.data(),   size()};
}

Real GrainSet::total_mass() const {
    return std::accumulate(mass.begin(), mass.end(), Real(0));
}

} // namespace debrisflow::dem
