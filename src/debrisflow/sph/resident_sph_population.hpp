#pragma once
// The resident SPH phase's population (sph/resident_sph.hpp, included at its end): particles
// removed where they are by stream compaction (a gate's group, fluid leaving the domain or
// entering an outlet, with the leavers' masses and faces brought to the host), an inlet
// buffer's particles prescribed, and new particles appended after the ones held.
#include <array>
#include <cstdint>
#include <vector>

namespace debrisflow::sph {

template <class Space> template <class Flags> void ResidentSph<Space>::remove_where(Flags flags) {
    upload_once();
    keep_.resize(n_);
    flags.keep = keep_.data();
    Space::for_each(n_, flags);
    compact();
}

template <class Space>
auto ResidentSph<Space>::remove_fluid_outside(const flow::ExitFaces& faces) -> Leaving {
    upload_once();
    keep_.resize(n_);
    Space::for_each(n_, KeepInsideDomain{view(), faces, keep_.data()});
    return remove_leavers(&faces);
}

template <class Space>
auto ResidentSph<Space>::remove_fluid_inside(const flow::OutletBox& box) -> Leaving {
    upload_once();
    keep_.resize(n_);
    Space::for_each(n_, KeepOutsideBox{view(), box, keep_.data()});
    return remove_leavers(nullptr);
}

template <class Space> void ResidentSph<Space>::prescribe(const flow::InletBuffer& buffer) {
    upload_once();
    const bool old = set_.keeps_previous_state();
    Space::for_each(n_, flow::PrescribeBuffer{buffer, view(), old ? old_[0].data() : nullptr,
                                              old ? old_[1].data() : nullptr,
                                              old ? old_[2].data() : nullptr,
                                              old ? old_[3].data() : nullptr});
    Space::synchronize();
}

template <class Space>
ParticleId ResidentSph<Space>::append_particles(const std::vector<particles::NewParticle>& fresh,
                                                const std::vector<rigid::ShellPoint>& walls,
                                                const std::vector<std::int32_t>& rows,
                                                const std::vector<std::int32_t>& fem_rows) {
    upload_once();
    const Index k = Index(fresh.size());
    if (k == 0) return set_.claim_ids(0);
    std::array<std::vector<Real>, kReal> real;
    for (auto& column : real) column.assign(std::size_t(k), Real(0));
    std::vector<std::uint8_t> kind(fresh.size());
    std::vector<std::int16_t> group(fresh.size());
    std::vector<ParticleId> id(fresh.size());
    const ParticleId first = set_.claim_ids(k);
    for (std::size_t j = 0; j < fresh.size(); ++j) {
        const auto& q = fresh[j];
        real[0][j] = q.pos.x, real[1][j] = q.pos.y, real[2][j] = q.pos.z;
        real[3][j] = q.vel.x, real[4][j] = q.vel.y, real[5][j] = q.vel.z;
        real[9][j] = q.rho, real[12][j] = q.mass;
        kind[j] = std::uint8_t(q.kind);
        group[j] = q.group;
        id[j] = first + ParticleId(j);
        if (!walls.empty()) {
            const auto& w = walls[j];
            real[13][j] = w.n.x, real[14][j] = w.n.y, real[15][j] = w.n.z, real[16][j] = w.depth;
        }
    }
    for (std::size_t f = 0; f < kReal; ++f)
        if (held(f)) append_tail(real_[f], real[f], 1);
    if (set_.keeps_previous_state())
        for (std::size_t f = 0; f < old_.size(); ++f) // vx, vy, vz, rho at t_n-1
            append_tail(old_[f], real[f < 3 ? 3 + f : 9], 1);
    if (sps_) append_tail(tau_, std::vector<Real>(6 * std::size_t(k), Real(0)), 6);
    append_tail(kind_, kind, 1);
    append_tail(group_, group, 1);
    append_tail(id_, id, 1);
    if (bodies_)
        append_tail(row_, rows.empty() ? std::vector<std::int32_t>(fresh.size(), -1) : rows, 1);
    if (fem_)
        append_tail(fem_row_,
                    fem_rows.empty() ? std::vector<std::int32_t>(fresh.size(), -1) : fem_rows, 1);
    ++layout_;
    n_ += k;
    return first;
}

template <class Space>
auto ResidentSph<Space>::remove_leavers(const flow::ExitFaces* faces) -> Leaving {
    Leaving out;
    const auto pv = view();
    if (Space::first_where(n_, Dropped{keep_.data()}) == n_) return out; // none left
    if (faces) out.mass_in_set = Space::sum_of(n_, FluidMass{pv});
    leave_.resize(n_);
    pos_.resize(n_);
    Space::for_each(n_, Complement{keep_.data(), leave_.data()});
    const Index m = Space::exclusive_scan(n_, leave_.data(), pos_.data());
    out.mass = gather_leavers(pv.mass, m);
    if (faces) {
        Buffer<int> picked;
        picked.resize(m);
        Space::for_each(n_, LeaverFaces{pv, *faces, leave_.data(), pos_.data(), picked.data()});
        out.face.resize(std::size_t(m));
        picked.download(out.face.data());
    }
    compact();
    return out;
}

template <class Space>
template <class T>
std::vector<T> ResidentSph<Space>::gather_leavers(const T* values, Index m) {
    Buffer<T> picked;
    picked.resize(m);
    Space::for_each(n_, ScatterKept<T>{values, leave_.data(), pos_.data(), picked.data(), 1});
    std::vector<T> out(static_cast<std::size_t>(m));
    picked.download(out.data());
    return out;
}

template <class Space>
template <class T>
void ResidentSph<Space>::append_tail(Buffer<T>& b, const std::vector<T>& tail, int width) {
    b.resize(width * n_ + Index(tail.size()));
    b.upload_at(width * n_, tail.data(), Index(tail.size()));
}

template <class Space> void ResidentSph<Space>::compact() {
    pos_.resize(n_);
    const Index m = Space::exclusive_scan(n_, keep_.data(), pos_.data());
    if (m == n_) return;
    for (std::size_t f = 0; f < kReal; ++f)
        if (held(f)) scatter(real_[f], real_scratch(), 1, m);
    if (set_.keeps_previous_state())
        for (auto& a : old_) scatter(a, real_scratch(), 1, m);
    if (sps_) {
        scatter(tau_, tau_next_, 6, m);
        tau_next_.resize(6 * m);
    }
    scatter_through(kind_, m);
    scatter_through(group_, m);
    scatter_through(id_, m);
    if (bodies_) scatter_through(row_, m);
    if (fem_) scatter_through(fem_row_, m);
    ++layout_;
    n_ = m;
    Space::synchronize();
}

template <class Space>
template <class T>
void ResidentSph<Space>::scatter_through(Buffer<T>& a, Index m) {
    Buffer<Real>& carrier = real_scratch();
    carrier.resize(n_);
    Space::for_each(
        n_, ScatterIntoCarrier<T, Real>{a.data(), keep_.data(), pos_.data(), carrier.data()});
    a.resize(m);
    Space::for_each(m, FromCarrier<T, Real>{carrier.data(), a.data()});
}

template <class Space>
template <class T>
void ResidentSph<Space>::scatter(Buffer<T>& a, Buffer<T>& scratch, int width, Index m) {
    scratch.resize(width * m);
    Space::for_each(n_, ScatterKept<T>{a.data(), keep_.data(), pos_.data(), scratch.data(), width});
    a.swap(scratch);
}

} // namespace debrisflow::sph
