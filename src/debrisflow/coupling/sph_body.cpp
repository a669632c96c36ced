#include "debrisflow/coupling/sph_body.hpp"
#include "debrisflow/coupling/sph_body_k.hpp"
#include "debrisflow/exec/parallel.hpp"
#include "debrisflow/rigid/body_solver.hpp"

namespace debrisflow::coupling {

SphBodyCoupling::SphBodyCoupling(rigid::BodySolver& bodies, particles::ParticleSet& set,
                                 BodyParticles rows)
    : set_(set), rows_(std::move(rows)), initial_rows_(rows_.owner.size()) {
    bodies.attach_fluid(this);
}

std::vector<Exchange> SphBodyCoupling::exchanges() const {
    return {{"sph", "rigid",
             "fluid force and moment on each body, summed over its boundary particles "
             "(F = sum m_k a_k, body loads)",
             When::force_evaluation},
            {"rigid", "sph",
             "positions, velocities and wall normals of the bodies' boundary particles "
             "(particle set)",
             When::body_motion}};
}

void SphBodyCoupling::refresh() {
    if (set_.layout_version() == layout_seen_) return;
    layout_seen_ = set_.layout_version();
    members_.clear();
    member_rows_.clear();
    for (Index i = 0; i < set_.size(); ++i) {
        const long r = rows_.row(set_.id[i], initial_rows_);
        if (r < 0) continue;
        members_.push_back(i);
        member_rows_.push_back(std::uint32_t(r));
    }
}

// F_b = sum_k m_k a_k, T_b = sum_k (x_k - X_b) x m_k a_k over body b's boundary particles
// (Dominguez et al. 2022 eqs. 31-32), in particle order.
void SphBodyCoupling::add_loads(const std::vector<rigid::BodyState>& bodies,
                                std::vector<rigid::BodyLoads>& loads) {
    refresh();
    const auto pv = set_.view();
    for (std::size_t k = 0; k < members_.size(); ++k) {
        const Index i = members_[k];
        const int b = rows_.owner[member_rows_[k]];
        const Wrench w = particle_load(pv, i, bodies[std::size_t(b)].pos);
        loads[std::size_t(b)].fluid_force += w.force;
        loads[std::size_t(b)].fluid_torque += w.torque;
    }
}

// x_k = X + R o_k, n_k = R n0_k, v_k = V + w x R o_k
void SphBodyCoupling::follow(const std::vector<rigid::BodyState>& bodies, bool positions) {
    refresh();
    auto pv = set_.view();
    const Index* mem = members_.data();
    const std::uint32_t* rows = member_rows_.data();
    const std::int32_t* owner = rows_.owner.data();
    const Vec3 *off = rows_.offset.data(), *nrm = rows_.normal.data();
    const rigid::BodyState* bs = bodies.data();
    exec::for_each(Index(members_.size()), [=](Index k) {
        const std::size_t r = rows[k];
        place_on_body(pv, mem[k], bs[owner[r]], off[r], nrm[r], positions);
    });
}

void SphBodyCoupling::add_shell(int b, const rigid::BodyState& state,
                                const std::vector<rigid::ShellPoint>& shell, Real rho,
                                Real m_particle) {
    if (shell.empty()) return;
    for (const auto& sp : shell) {
        set_.add(sp.p, state.vel + cross(state.omega(), sp.p - state.pos), rho, m_particle,
                 particles::Kind::boundary, std::int16_t(-1));
        set_.set_wall(set_.size() - 1, sp.n, sp.depth);
    }
    add_rows(b, state, shell, set_.id[set_.id.size() - shell.size()]);
}

void SphBodyCoupling::add_rows(int b, const rigid::BodyState& state,
                               const std::vector<rigid::ShellPoint>& shell, ParticleId first_id) {
    for (std::size_t k = 0; k < shell.size(); ++k) {
        rows_.extra_rows.emplace(first_id + ParticleId(k), std::uint32_t(rows_.owner.size()));
        rows_.append(b, state, shell[k].p, shell[k].n);
    }
}

void SphBodyCoupling::release(int b, std::vector<std::uint8_t>& keep) {
    refresh();
    keep.resize(std::size_t(set_.size()), 1);
    for (std::size_t k = 0; k < members_.size(); ++k)
        if (rows_.owner[member_rows_[k]] == b) keep[std::size_t(members_[k])] = 0;
}

std::size_t SphBodyCoupling::particles_of(int b) const {
    std::size_t n = 0;
    for (Index i = 0; i < set_.size(); ++i) {
        const long r = rows_.row(set_.id[i], initial_rows_);
        n += r >= 0 && rows_.owner[std::size_t(r)] == b;
    }
    return n;
}

} // namespace debrisflow::coupling
