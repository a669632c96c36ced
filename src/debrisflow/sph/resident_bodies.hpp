#pragma once
// Rigid bodies in a resident backend's fluid (issue #33): the fluid side of the body solver
// (rigid::FluidSide) where the particles are. Each body's fluid force and moment are reduced
// there (the body particles sorted by body, then a segmented sum) and only the bodies' few
// loads come back to the host; the 6-DOF update stays on the host (rigid::BodySolver), and the
// new body states go to the backend, where the body particles take their motion. The rules
// are coupling/sph_body_k.hpp's, shared with the host coupling (coupling/sph_body.cpp).
#include "debrisflow/coupling/sph_body.hpp"
#include "debrisflow/coupling/sph_body_k.hpp"
#include "debrisflow/rigid/fluid_side.hpp"
#include "debrisflow/sph/resident_steps_k.hpp"
#include <vector>

namespace debrisflow::sph {

template <class Space> class ResidentSph;

template <class Space> class ResidentBodies final : public rigid::FluidSide {
    template <class T> using Buffer = typename Space::template Buffer<T>;

public:
    // The rows stay the host coupling's (the id -> row map, which its checkpoint saves); the
    // backend holds a copy of the row tables and each particle's row.
    ResidentBodies(ResidentSph<Space>& sph, coupling::SphBodyCoupling& coupling)
        : sph_(sph), coupling_(coupling) {
        upload_rows();
    }

    // The row of each particle of the host's set (by persistent id), or -1.
    std::vector<std::int32_t> rows_of(const std::vector<ParticleId>& ids) const {
        const auto& table = coupling_.rows();
        std::vector<std::int32_t> r(ids.size());
        for (std::size_t k = 0; k < ids.size(); ++k)
            r[k] = std::int32_t(table.row(ids[k], coupling_.initial_rows()));
        return r;
    }

    // F_b, T_b summed over body b's particles in index order (coupling/sph_body_k.hpp).
    void add_loads(const std::vector<rigid::BodyState>& bodies,
                   std::vector<rigid::BodyLoads>& loads) override {
        sph_.upload_once();
        const Index nb = Index(bodies.size());
        states_.upload(bodies.data(), nb);
        sort_by_body(nb);
        wrench_.resize(members_);
        sums_.resize(nb);
        Space::for_each(members_, coupling::MemberLoads{sph_.view(), rows(), order_.data(),
                                                        states_.data(), wrench_.data()});
        Space::segmented_sum(nb, start_.data(), wrench_.data(), sums_.data());
        std::vector<coupling::Wrench> sums(bodies.size());
        sums_.download(sums.data());
        for (std::size_t b = 0; b < bodies.size(); ++b) {
            loads[b].fluid_force += sums[b].force;
            loads[b].fluid_torque += sums[b].torque;
        }
    }

    void follow(const std::vector<rigid::BodyState>& bodies, bool positions) override {
        sph_.upload_once();
        states_.upload(bodies.data(), Index(bodies.size()));
        Space::for_each(sph_.n_,
                        coupling::FollowBodies{sph_.view(), rows(), states_.data(), positions});
        Space::synchronize();
    }

    // A body added during the run (a rock feed's): its shell's particles appended where the
    // particles are, as the host coupling's add_shell adds them, with their new rows.
    void add_shell(int b, const rigid::BodyState& state,
                   const std::vector<rigid::ShellPoint>& shell, Real rho,
                   Real m_particle) override {
        if (shell.empty()) return;
        std::vector<particles::NewParticle> fresh;
        std::vector<std::int32_t> rows;
        const auto row0 = std::int32_t(coupling_.rows().owner.size());
        for (const auto& sp : shell) {
            fresh.push_back({sp.p, state.vel + cross(state.omega(), sp.p - state.pos), rho,
                             m_particle, particles::Kind::boundary, std::int16_t(-1)});
            rows.push_back(row0 + std::int32_t(rows.size()));
        }
        coupling_.add_rows(b, state, shell, sph_.append_particles(fresh, shell, rows));
        upload_rows();
    }
    // Removes body b's particles where they are, at once (`keep`, the host's list of
    // particles to remove, is left as it is).
    void release(int b, std::vector<std::uint8_t>&) override {
        sph_.remove_where(coupling::KeepOffBody{{rows(), std::int32_t(b)}, nullptr});
    }
    std::size_t particles_of(int b) const override {
        return std::size_t(Space::sum_of(sph_.n_, coupling::OfBody{rows(), std::int32_t(b)}));
    }

    std::size_t bytes() const {
        return owner_.bytes() + offset_.bytes() + normal_.bytes() + states_.bytes() +
               keys_.bytes() + order_.bytes() + start_.bytes() + wrench_.bytes() + sums_.bytes() +
               sorter_.bytes();
    }

private:
    template <class T> static void upload(Buffer<T>& b, const std::vector<T>& v) {
        b.upload(v.data(), Index(v.size()));
    }
    void upload_rows() {
        const auto& table = coupling_.rows();
        upload(owner_, table.owner);
        upload(offset_, table.offset);
        upload(normal_, table.normal);
    }

    coupling::BodyRows rows() const {
        return {sph_.row_.data(), owner_.data(), offset_.data(), normal_.data()};
    }

    // The body particles grouped by body in index order (a stable sort by body, the others
    // last), body b's at order_[start_[b]] .. order_[start_[b+1]-1]; redone when the
    // particles were reordered, removed or added.
    void sort_by_body(Index nb) {
        if (layout_seen_ == sph_.layout_ && bodies_seen_ == nb) return;
        layout_seen_ = sph_.layout_;
        bodies_seen_ = nb;
        const Index n = sph_.n_;
        keys_.resize(n);
        order_.resize(n);
        start_.resize(nb + 1);
        Space::for_each(n, coupling::BodyKeys{rows(), nb, keys_.data()});
        sorter_.sort(keys_.data(), n, nb + 1, order_.data());
        Space::for_each(nb + 1, CellStarts{keys_.data(), order_.data(), n, start_.data()});
        members_ = start_.at(nb);
    }

    ResidentSph<Space>& sph_;
    coupling::SphBodyCoupling& coupling_; // on the host: the rows and the id -> row map
    Buffer<std::int32_t> owner_;
    Buffer<Vec3> offset_, normal_;
    Buffer<rigid::BodyState> states_;
    Buffer<Index> keys_, order_, start_;
    Buffer<coupling::Wrench> wrench_, sums_;
    typename Space::Sorter sorter_;
    Index members_ = 0, bodies_seen_ = -1;
    std::uint64_t layout_seen_ = ~std::uint64_t(0);
};

} // namespace debrisflow::sph
