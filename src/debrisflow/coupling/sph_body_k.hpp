#pragma once
// The per-particle rules of the fluid <-> rigid-body coupling through the bodies' SPH boundary
// particles (coupling/sph_body.hpp), written once for the host's particle set and a resident
// backend's (sph/resident_bodies.hpp).
#include "debrisflow/particles/particle_set.hpp"
#include "debrisflow/rigid/body_state.hpp"
#include <type_traits>

namespace debrisflow::coupling {

// A force and its moment about a body's centre of mass.
struct Wrench {
    Vec3 force, torque;
};
DF_HD constexpr Wrench operator+(Wrench a, Wrench b) {
    return {a.force + b.force, a.torque + b.torque};
}

// The fluid's load carried by boundary particle i of a body centred at X: f = m_i a_i,
// T = (x_i - X) x f (Dominguez et al. 2022 eqs. 31-32).
DF_HD inline Wrench particle_load(const particles::ParticleView& pv, Index i, Vec3 centre) {
    const Vec3 f = pv.mass[i] * Vec3{pv.ax[i], pv.ay[i], pv.az[i]};
    return {f, cross(pv.pos(i) - centre, f)};
}

// Boundary particle i takes its body's rigid motion: x = X + R o, n = R n0 (when `positions`),
// v = V + w x R o.
DF_HD inline void place_on_body(const particles::ParticleView& pv, Index i,
                                const rigid::BodyState& b, Vec3 offset, Vec3 normal,
                                bool positions) {
    const Vec3 arm = rigid::rotate(b.q, offset);
    if (positions) {
        pv.x[i] = b.pos.x + arm.x;
        pv.y[i] = b.pos.y + arm.y;
        pv.z[i] = b.pos.z + arm.z;
        const Vec3 n = rigid::rotate(b.q, normal);
        pv.wnx[i] = n.x, pv.wny[i] = n.y, pv.wnz[i] = n.z; // into the fluid
    }
    const Vec3 v = b.vel + cross(b.omega(), arm);
    pv.vx[i] = v.x, pv.vy[i] = v.y, pv.vz[i] = v.z;
}

// The rows of the body particles (coupling::BodyParticles) as arrays: particle i is body
// particle row[i] (or -1), of body owner[row], at body-frame offset and normal.
struct BodyRows {
    const std::int32_t* row; // per particle
    const std::int32_t* owner;
    const Vec3* offset;
    const Vec3* normal;
};

// Every body particle takes its body's motion (one item per particle).
struct FollowBodies {
    particles::ParticleView pv;
    BodyRows rows;
    const rigid::BodyState* bodies;
    bool positions;
    DF_HD void operator()(Index i) const {
        const std::int32_t r = rows.row[i];
        if (r < 0) return;
        place_on_body(pv, i, bodies[rows.owner[r]], rows.offset[r], rows.normal[r], positions);
    }
};

// key[i] = the body of particle i, or `none` (the number of bodies) when it is not a body's.
struct BodyKeys {
    BodyRows rows;
    Index none;
    Index* key;
    DF_HD void operator()(Index i) const {
        const std::int32_t r = rows.row[i];
        key[i] = r < 0 ? none : Index(rows.owner[r]);
    }
};

// out[k] = the load of the k-th body particle in the order `member` (grouped by body).
struct MemberLoads {
    particles::ParticleView pv;
    BodyRows rows;
    const Index* member;
    const rigid::BodyState* bodies;
    Wrench* out;
    DF_HD void operator()(Index k) const {
        const Index i = member[k];
        out[k] = particle_load(pv, i, bodies[rows.owner[rows.row[i]]].pos);
    }
};

// 1 for the particles of body b, else 0 (a count by a sum).
struct OfBody {
    BodyRows rows;
    std::int32_t body;
    DF_HD Real operator()(Index i) const {
        const std::int32_t r = rows.row[i];
        return r >= 0 && rows.owner[r] == body ? Real(1) : Real(0);
    }
};

// keep[i] = 0 for body `body`'s particles, 1 for the others (a body that left through an
// outlet takes its particles with it).
struct KeepOffBody {
    OfBody of;
    Index* keep;
    DF_HD void operator()(Index i) const { keep[i] = of(i) > 0 ? 0 : 1; }
};

static_assert(std::is_trivially_copyable_v<FollowBodies>);
static_assert(std::is_trivially_copyable_v<MemberLoads>);

} // namespace debrisflow::coupling
