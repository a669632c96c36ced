#pragma once
// The clumps' half of a DEM step, written once for the host (DemSolver's clump stepping,
// dem_clumps.cpp) and the resident loop (dem/resident_dem.hpp): each clump's kick and drift
// with its members placed and moved with it, and the members' forces summed on the clump
// (multi-sphere method, Favier et al. 1999). Members are found by id (where[id]: their index).
#include "debrisflow/core/domain.hpp"
#include "debrisflow/dem/grain_contact_k.hpp"
#include "debrisflow/dem/grain_kick_drift_k.hpp"
#include "debrisflow/rigid/free_rotation_k.hpp"
#include "debrisflow/rigid/quaternion_k.hpp"
#include <cstdint>
#include <type_traits>

namespace debrisflow::dem {

// A ClumpSet's arrays (dem/clump_set.hpp) in some memory space.
struct ClumpView {
    Vec3 *pos, *vel, *ang_mom, *force, *torque;
    rigid::Quat* orient;
    const Real* mass;
    const Vec3* inv_inertia;
    const std::uint32_t* first; // members of clump c: first[c] .. first[c + 1] - 1
    const std::uint32_t* member_id;
    const Vec3* offset; // body frame
};
static_assert(std::is_trivially_copyable_v<ClumpView>);

// Clump c's opening kick and drift, as the grains' (GrainKickDrift): v_n+1/2 = v_n + (h/2) F/M
// drives the drift and the stored velocity is the prediction v_n+1/2 + (h/2) F/M; likewise the
// angular momentum, whose half-step value turns the clump (rigid::free_rotation). Its members
// are placed and moved with it; the report gathers their largest squared speed and how many
// left a closed side of the domain.
struct ClumpKickDrift {
    ClumpView cl;
    GrainView g;
    GrainState* hot;
    const Index* where;
    Real h;
    bool plane;
    Domain dom;
    DF_HD void operator()(Index c, DriftReport& out) const {
        const Real half = Real(0.5) * h;
        const Vec3 dv = (half / cl.mass[c]) * cl.force[c], dl = half * cl.torque[c];
        Vec3 v = cl.vel[c] + dv, l = cl.ang_mom[c] + dl;
        if (plane) v.y = 0, l.x = 0, l.z = 0;
        Vec3 x = cl.pos[c] + h * v;
        rigid::free_rotation(cl.orient[c], l, cl.inv_inertia[c], h);
        v += dv, l += dl;
        if (plane) v.y = 0, l.x = 0, l.z = 0;
        for (int d = 0; d < 3; ++d)
            if (dom.periodic[d]) {
                const Real len = dom.hi[d] - dom.lo[d];
                if (x[d] >= dom.hi[d]) x[d] -= len;
                if (x[d] < dom.lo[d]) x[d] += len;
            }
        cl.pos[c] = x, cl.vel[c] = v, cl.ang_mom[c] = l;
        const Vec3 w = rigid::angular_velocity(cl.orient[c], l, cl.inv_inertia[c]);
        for (std::uint32_t m = cl.first[c]; m < cl.first[c + 1]; ++m) {
            const Index i = where[cl.member_id[m]];
            const Vec3 lever = rigid::rotate(cl.orient[c], cl.offset[m]);
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
            const Real v2 = dot(vi, vi);
            out.vmax2 = out.vmax2 < v2 ? v2 : out.vmax2;
        }
    }
};
static_assert(std::is_trivially_copyable_v<ClumpKickDrift>);

// The members' forces and torques (and gravity) summed on clump c: F = M g + sum f_i,
// T = sum (r_i x f_i + t_i); the closing half kick with the change of force (half > 0), and the
// members' velocities and spins moved with the clump.
struct ClumpSum {
    ClumpView cl;
    GrainView g;
    const Index* where;
    Vec3 gravity;
    bool plane;
    Real half;
    DF_HD void operator()(Index c) const {
        Vec3 f = cl.mass[c] * gravity, t{};
        for (std::uint32_t m = cl.first[c]; m < cl.first[c + 1]; ++m) {
            const Index i = where[cl.member_id[m]];
            const Vec3 lever = rigid::rotate(cl.orient[c], cl.offset[m]);
            f += g.force[i];
            t += cross(lever, g.force[i]) + g.torque[i];
        }
        if (plane) f.y = 0, t.x = 0, t.z = 0;
        if (half > 0) {
            cl.vel[c] += (half / cl.mass[c]) * (f - cl.force[c]);
            cl.ang_mom[c] += half * (t - cl.torque[c]);
        }
        cl.force[c] = f, cl.torque[c] = t;
        const Vec3 w = rigid::angular_velocity(cl.orient[c], cl.ang_mom[c], cl.inv_inertia[c]);
        for (std::uint32_t m = cl.first[c]; m < cl.first[c + 1]; ++m) {
            const Index i = where[cl.member_id[m]];
            const Vec3 lever = rigid::rotate(cl.orient[c], cl.offset[m]);
            g.vel[i] = cl.vel[c] + cross(w, lever);
            g.spin[i] = w;
        }
    }
};
static_assert(std::is_trivially_copyable_v<ClumpSum>);

// where[id[i]] = i: each member's index after the grains were reordered.
struct IndexOfId {
    const std::uint32_t* id;
    Index* where;
    DF_HD void operator()(Index i) const { where[id[i]] = i; }
};
static_assert(std::is_trivially_copyable_v<IndexOfId>);

} // namespace debrisflow::dem
