#include "debrisflow/particles/particle_set.hpp"
#include "debrisflow/checkpoint/archive.hpp"
#include "debrisflow/core/bytes_of.hpp"
#include "debrisflow/exec/parallel.hpp"

namespace debrisflow::particles {

namespace {
template <class Fn> void for_each_field(ParticleSet& s, Fn&& fn) {
    for (auto* f : {&s.x,  &s.y,   &s.z,      &s.vx,     &s.vy,     &s.vz,     &s.ax,  &s.ay,
                    &s.az, &s.rho, &s.drho,   &s.p,      &s.mass,   &s.wnx,    &s.wny, &s.wnz,
                    &s.wd, &s.mu,  &s.vx_old, &s.vy_old, &s.vz_old, &s.rho_old})
        fn(*f);
    fn(s.kind);
    fn(s.group);
    fn(s.id);
}

constexpr std::size_t sps_width = 6; // components of ParticleSet::sps_tau per particle
} // namespace

Index ParticleSet::count(Kind k) const {
    Index c = 0;
    for (auto v : kind) c += (v == std::uint8_t(k));
    return c;
}

void ParticleSet::add(Vec3 pos, Vec3 vel, Real density, Real m, Kind k, std::int16_t grp) {
    x.push_back(pos.x);
    y.push_back(pos.y);
    z.push_back(pos.z);
    vx.push_back(vel.x);
    vy.push_back(vel.y);
    vz.push_back(vel.z);
    ax.push_back(0);
    ay.push_back(0);
    az.push_back(0);
    rho.push_back(density);
    drho.push_back(0);
    p.push_back(0);
    mass.push_back(m);
    wnx.push_back(0);
    wny.push_back(0);
    wnz.push_back(0);
    wd.push_back(0);
    mu.push_back(0);
    if (previous_state_) {
        vx_old.push_back(vel.x);
        vy_old.push_back(vel.y);
        vz_old.push_back(vel.z);
        rho_old.push_back(density);
    }
    if (!sps_tau.empty()) sps_tau.resize(sps_tau.size() + sps_width, Real(0));
    kind.push_back(std::uint8_t(k));
    group.push_back(grp);
    id.push_back(next_id_++);
    ++layout_version_;
}

void ParticleSet::permute(const std::vector<Index>& perm) {
    ++layout_version_;
    const Index n = Index(perm.size());
    const Index* from = perm.data();
    const auto gather = [&](auto& field, std::size_t width) {
        using V = std::decay_t<decltype(field)>;
        if (field.empty()) return; // the Verlet state of a symplectic run
        V out(field.size());
        auto* o = out.data();
        const auto* f = field.data();
        exec::for_each(n, [=](Index i) {
            for (std::size_t c = 0; c < width; ++c)
                o[width * std::size_t(i) + c] = f[width * std::size_t(from[i]) + c];
        });
        field.swap(out);
    };
    for_each_field(*this, [&](auto& field) { gather(field, 1); });
    gather(sps_tau, sps_width);
}

void ParticleSet::compact(const std::vector<std::uint8_t>& keep) {
    ++layout_version_;
    // Stream compaction: each kept particle's new index is the number kept before it (an
    // exclusive scan), then every array is gathered into its new place in parallel.
    const Index n = Index(keep.size());
    const std::uint8_t* k = keep.data();
    std::vector<Index> to(keep.size());
    Index* dest = to.data();
    const Index kept = exec::exclusive_scan(
        n, [=](Index i) { return Index(k[i] != 0); }, dest);
    const auto scatter = [&](auto& field, std::size_t width) {
        using V = std::decay_t<decltype(field)>;
        if (field.empty()) return; // the Verlet state of a symplectic run
        V out(std::size_t(kept) * width);
        auto* o = out.data();
        const auto* f = field.data();
        exec::for_each(n, [=](Index i) {
            if (!k[i]) return;
            for (std::size_t c = 0; c < width; ++c)
                o[width * std::size_t(dest[i]) + c] = f[width * std::size_t(i) + c];
        });
        field.swap(out);
    };
    for_each_field(*this, [&](auto& field) { scatter(field, 1); });
    scatter(sps_tau, sps_width);
}

void ParticleSet::set_wall(Index i, Vec3 normal, Real depth) {
    wnx[i] = normal.x;
    wny[i] = normal.y;
    wnz[i] = normal.z;
    wd[i] = depth;
}

std::size_t ParticleSet::bytes() const {
    return bytes_of(x, y, z, vx, vy, vz, ax, ay, az, rho, drho, p, mass, wnx, wny, wnz, wd, mu,
                    vx_old, vy_old, vz_old, rho_old, sps_tau, kind, group, id);
}

ParticleView ParticleSet::view() {
    return {x.data(),   y.data(),   z.data(),   vx.data(),   vy.data(),   vz.data(),    ax.data(),
            ay.data(),  az.data(),  rho.data(), drho.data(), p.data(),    mass.data(),  wnx.data(),
            wny.data(), wnz.data(), wd.data(),  mu.data(),   kind.data(), group.data(), size()};
}

void ParticleSet::state(checkpoint::Archive& ar) {
    ar.section("particles");
    ar(x, y, z, vx, vy, vz, ax, ay, az, rho, drho, p, mass, wnx, wny, wnz, wd, mu);
    ar(vx_old, vy_old, vz_old, rho_old, sps_tau, kind, group, id, next_id_);
    const std::size_t n = x.size();
    for (const auto* a :
         {&y, &z, &vx, &vy, &vz, &ax, &ay, &az, &rho, &drho, &p, &mass, &wnx, &wny, &wnz, &wd, &mu})
        if (a->size() != n) ar.fail("particle arrays of different lengths");
    if (kind.size() != n || group.size() != n || id.size() != n)
        ar.fail("particle arrays of different lengths");
    if (!ar.is_loading()) return;
    ++layout_version_;
    previous_state_ = !(vx_old.empty() && n > 0);
    for (const auto* a : {&vx_old, &vy_old, &vz_old, &rho_old})
        if (a->size() != (previous_state_ ? n : 0)) ar.fail("particle arrays of different lengths");
}

void ParticleSet::drop_previous_state() {
    previous_state_ = false;
    for (auto* a : {&vx_old, &vy_old, &vz_old, &rho_old}) std::vector<Real>().swap(*a);
}

} // namespace debrisflow::particles
