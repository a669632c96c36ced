#include "debrisflow/dem/dem_solver.hpp"
#include "debrisflow/dem/grain_kick_drift_k.hpp"
#include "debrisflow/exec/parallel.hpp"
#include "debrisflow/rigid/free_rotation_k.hpp"
#include <algorithm>

// The DemSolver's clump stepping (grains_.clumps): members found by id, the rigid-body kick
// and drift of each clump with its members placed and moved with it, and the members' forces
// summed on the clump (multi-sphere method, Favier et al. 1999).
namespace debrisflow::dem {

namespace {
// Below this many clumps the loops run on one thread (the grains' threshold / 4: a clump
// visits several members).
constexpr Index clump_parallel_min = 1024;
} // namespace

void DemSolver::expand_to_clumps(std::vector<std::uint8_t>& keep) const {
    const ClumpSet& cl = grains_.clumps;
    for (Index c = 0; c < cl.size(); ++c) {
        const std::size_t b = cl.first[std::size_t(c)], e = cl.first[std::size_t(c) + 1];
        bool whole = true;
        for (std::size_t k = b; k < e; ++k)
            whole = whole && keep[std::size_t(index_of_id_[cl.member_id[k]])];
        if (whole) continue;
        for (std::size_t k = b; k < e; ++k) keep[std::size_t(index_of_id_[cl.member_id[k]])] = 0;
    }
}

void DemSolver::map_clumps() {
    const ClumpSet& cl = grains_.clumps;
    if (cl.empty()) {
        clump_of_id_.clear();
        index_of_id_.clear();
        return;
    }
    clump_of_id_.assign(grains_.next_id(), -1);
    for (Index c = 0; c < cl.size(); ++c)
        for (std::size_t k = cl.first[std::size_t(c)]; k < cl.first[std::size_t(c) + 1]; ++k)
            clump_of_id_[cl.member_id[k]] = std::int32_t(c);
    index_of_id_.assign(grains_.next_id(), -1);
    for (Index i = 0; i < grains_.size(); ++i) index_of_id_[grains_.id[std::size_t(i)]] = i;
}

Real DemSolver::clump_kick_drift(Real h) {
    ClumpSet& cl = grains_.clumps;
    GrainView g = grains_.view();
    GrainState* hot = hot_.data();
    const Real half = Real(0.5) * h;
    const bool plane = params_.dim == 2;
    const Domain dom = domain_;
    const Index* where = index_of_id_.data();
    const auto move_clump = [&](Index c, DriftReport& out) {
        const std::size_t k = std::size_t(c);
        // as the grains: v_n+1/2 = v_n + (h/2) F/M drives the drift, the stored velocity is the
        // prediction v_n+1/2 + (h/2) F/M; likewise the angular momentum, whose half-step value
        // turns the clump (rigid::free_rotation)
        const Vec3 dv = (half / cl.mass[k]) * cl.force[k], dl = half * cl.torque[k];
        Vec3 v = cl.vel[k] + dv, l = cl.ang_mom[k] + dl;
        if (plane) v.y = 0, l.x = 0, l.z = 0;
        Vec3 x = cl.pos[k] + h * v;
        rigid::free_rotation(cl.orient[k], l, cl.inv_inertia[k], h);
        v += dv, l += dl;
        if (plane) v.y = 0, l.x = 0, l.z = 0;
        for (int d = 0; d < 3; ++d)
            if (dom.periodic[d]) {
                const Real len = dom.hi[d] - dom.lo[d];
                if (x[d] >= dom.hi[d]) x[d] -= len;
                if (x[d] < dom.lo[d]) x[d] += len;
            }
        cl.pos[k] = x, cl.vel[k] = v, cl.ang_mom[k] = l;
        const Vec3 w = rigid::angular_velocity(cl.orient[k], l, cl.inv_inertia[k]);
        for (std::size_t m = cl.first[k]; m < cl.first[k + 1]; ++m) {
            const Index i = where[cl.member_id[m]];
            const Vec3 lever = rigid::rotate(cl.orient[k], cl.offset[m]);
            Vec3 p = x + lever;
            const Vec3 vi = v + cross(w, lever);
            for (int d = 0; d < 3; ++d) {
                if (dom.periodic[d]) {
                    const Real len = dom.hi[d] - dom.lo[d];
                    if (p[d] >= dom.hi[d]) p[d] -= len;
                    if (p[d] < dom.lo[d]) p[d] += len;
                } else if (!(plane && d == 1) && !(p[d] >= dom.lo[d] && p[d] <= dom.hi[d])) {
                    ++out.outside;
                }
            }
            g.pos[i] = p, g.vel[i] = vi, g.spin[i] = w;
            hot[i].x = p, hot[i].v = vi, hot[i].w = w;
            out.vmax2 = std::max(out.vmax2, dot(vi, vi));
        }
    };
    const DriftReport m = exec::reduce(cl.size(), DriftReport{}, move_clump, DriftReport::combine,
                                       exec::serial_below(clump_parallel_min + 1));
    if (m.outside > 0) bad_ = true;
    return m.vmax2;
}

void DemSolver::clump_forces(Real half) {
    ClumpSet& cl = grains_.clumps;
    GrainView g = grains_.view();
    const Vec3 grav = params_.gravity;
    const bool plane = params_.dim == 2;
    const Index* where = index_of_id_.data();
    const auto sum_clump = [&](Index c) {
        const std::size_t k = std::size_t(c);
        Vec3 f = cl.mass[k] * grav, t{};
        for (std::size_t m = cl.first[k]; m < cl.first[k + 1]; ++m) {
            const Index i = where[cl.member_id[m]];
            const Vec3 lever = rigid::rotate(cl.orient[k], cl.offset[m]);
            f += g.force[i];
            t += cross(lever, g.force[i]) + g.torque[i];
        }
        if (plane) f.y = 0, t.x = 0, t.z = 0;
        if (half > 0) {
            cl.vel[k] += (half / cl.mass[k]) * (f - cl.force[k]);
            cl.ang_mom[k] += half * (t - cl.torque[k]);
        }
        cl.force[k] = f, cl.torque[k] = t;
        const Vec3 w = rigid::angular_velocity(cl.orient[k], cl.ang_mom[k], cl.inv_inertia[k]);
        for (std::size_t m = cl.first[k]; m < cl.first[k + 1]; ++m) {
            const Index i = where[cl.member_id[m]];
            const Vec3 lever = rigid::rotate(cl.orient[k], cl.offset[m]);
            g.vel[i] = cl.vel[k] + cross(w, lever);
            g.spin[i] = w;
        }
    };
    exec::for_each(cl.size(), sum_clump, exec::serial_below(clump_parallel_min + 1));
}

} // namespace debrisflow::dem
