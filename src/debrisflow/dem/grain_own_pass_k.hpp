#pragma once
// The per-grain part of a DEM force evaluation, written once for the host's pass
// (DemSolver::forces, each thread over its range of grains) and the device's layout
// (`dem.contact_pass = "slots"`, dem_own_pass.cpp): grain i's sum of grain-grain contacts plus
// gravity, its walls (the overlapping primitives sorted by distance, a contact seen again
// through a neighbouring facet counted once), the spheres of rigid bodies, the fluid's load,
// and the closing half kick. Where the reactions go is the Sink's business: the host adds them
// to its thread's sums at once; the device's layout writes them to the contact slots and sums
// them per wall and per body afterwards (GrainOwnSlotSink, WallSlotLoad, BodySlotLoad).
#include "debrisflow/dem/grain_contact_k.hpp"
#include "debrisflow/dem/grain_slot_pass_k.hpp"
#include "debrisflow/dem/obstacles.hpp"
#include "debrisflow/dem/wall_geometry_k.hpp"
#include <cstdint>
#include <type_traits>

namespace debrisflow::dem {

// A named wall as the per-grain pass reads it (WallSet's Wall without its strings and lists).
struct WallState {
    Vec3 velocity, origin;
    int material; // -1: contacts use the grain's own material
    bool active;
    bool record; // keeps its contacts' loads (a pressure map reads them)
};
static_assert(std::is_trivially_copyable_v<WallState>);

// What the per-grain pass reads and writes besides the sink.
struct GrainOwnInputs {
    GrainView g;
    const GrainState* hot;        // the contact loop's copy of the grain state
    const Real* acc;              // grain-grain contact sums, 6 reals per grain
    const std::int32_t* clump_of; // clump of each grain id (< 0: none), or null
    PairTable table;
    Vec3 gravity;
    Real h_contact; // spring increment (0: a re-evaluation that must not advance the springs)
    Real h_step;    // the step the evaluation ends (the fluid's impulse)
    Real half;      // closing half kick (0: none)
    bool plane;     // 2D: forces in the x-z plane, torque about y
    // walls: primitives, named walls, nodal triangles' corners and their nodes' velocities
    const WallPrimitive* prims;
    const WallState* walls;
    const NodalCorners* corners;
    const Vec3* node_v;
    const Index *wall_partner, *wall_count;
    Vec3 *wall_xi, *wall_roll; // slot histories (wall_roll null: no rolling memory)
    Index wall_capacity;
    // rigid bodies' contact spheres (obstacle_count null: none)
    const ObstacleSphere* spheres;
    const Index *obstacle_partner, *obstacle_count;
    Vec3 *obstacle_xi, *obstacle_roll;
    Index obstacle_capacity;
    // fluid loads (fluid_force null: none): held force, drag beta (u - v), impulse and last force
    const Vec3 *fluid_force, *fluid_u;
    const Real* fluid_beta;
    Vec3 *fluid_impulse, *fluid_felt; // fluid_impulse null: the evaluation does not end a step
};
static_assert(std::is_trivially_copyable_v<GrainOwnInputs>);

struct GrainOwnPass {
    GrainOwnInputs in;

    DF_HD const PairParams& wall_pair(int material, const WallPrimitive& pr) const {
        const int mw = in.walls[pr.wall].material;
        return in.table(material, mw < 0 ? material : mw);
    }

    // Sink: wall(i, slot, primitive, q, barycentric weights, force), obstacle(i, slot, sphere,
    // force), contact(force on the grain), begin(i, wall slots, obstacle slots).
    template <class Sink>
    DF_HD DF_HOT_INLINE void operator()(Index i, WallCandidates& cand, Sink& sink) const {
        run(i, &cand, sink);
    }

    // The same with the candidates' scratch space only where the grain has wall slots (null
    // otherwise): the device's layout makes it per grain, and only where it is needed.
    template <class Sink>
    DF_HD DF_HOT_INLINE void run(Index i, WallCandidates* scratch, Sink& sink) const {
        const GrainView& g = in.g;
        const PairTable& tab = in.table;
        // a clump member's force is its contacts'; gravity acts on the clump
        const bool member = in.clump_of && in.clump_of[g.id[i]] >= 0;
        const Real* ai = in.acc + 6 * std::size_t(i);
        Vec3 f = (member ? Real(0) : g.mass[i]) * in.gravity + Vec3{ai[0], ai[1], ai[2]};
        Vec3 t{ai[3], ai[4], ai[5]};
        const Index cw = in.wall_count[i];
        const Index co = in.obstacle_count ? in.obstacle_count[i] : 0;
        if (cw == 0 && co == 0 && !in.fluid_force) {
            // most grains: nothing but grain contacts and gravity
            finish(i, f, t, member);
            return;
        }
        sink.begin(i, cw, co);
        const std::size_t base = std::size_t(i) * std::size_t(in.wall_capacity);
        const auto wall_history = [&](std::size_t slot) {
            return HistoryRef{in.wall_xi + slot, in.wall_roll ? in.wall_roll + slot : nullptr};
        };
        if (cw > 0) {
            WallCandidates& cand = *scratch;
            const GrainState si = in.hot[i];
            // a local, not the member: covered() takes the list by reference, and the member's
            // address passed to it would make the compiler reload every member after a store
            const WallPrimitive* const prims = in.prims;
            cand.size = 0;
            for (Index k = 0; k < cw; ++k) {
                const WallPrimitive& pr = in.prims[in.wall_partner[base + std::size_t(k)]];
                if (!in.walls[pr.wall].active) {
                    wall_history(base + std::size_t(k)).clear();
                    continue;
                }
                const Vec3 q = closest_point(pr, si.x);
                const Real d = wall_distance(pr, si.x, q);
                if (d >= si.r &&
                    !(tab.adhesive && within_reach(wall_pair(si.material, pr), d - si.r, si.r))) {
                    wall_history(base + std::size_t(k)).clear();
                    continue;
                }
                cand.add(k, q, d);
            }
            cand.sort();
            for (int c = 0; c < cand.size; ++c) {
                const Index k = cand.slot[c];
                const std::size_t slot = base + std::size_t(k);
                const WallPrimitive& pr = in.prims[in.wall_partner[slot]];
                if (cand.covered(c, prims, in.wall_partner + base, si.r, si.x)) {
                    wall_history(slot).clear();
                    continue;
                }
                // A triangle on moving nodes moves with the barycentric blend of its corners'
                // velocities and takes the reaction back with the same weights (the sink).
                Vec3 vw = in.walls[pr.wall].velocity, bw{};
                if (pr.corners >= 0) {
                    bw = barycentric(cand.q[c], pr.a, pr.b, pr.c);
                    vw = blend(in.corners[pr.corners], in.node_v, bw);
                }
                const WallContactForce c2 =
                    wall_contact_force(wall_pair(si.material, pr), si, pr, cand.q[c], cand.d[c], vw,
                                       in.h_contact, wall_history(slot));
                f += c2.force;
                t += c2.torque;
                sink.wall(i, slot, pr, cand.q[c], bw, c2);
                sink.contact(c2.force);
            }
        }
        if (co > 0) {
            const GrainState si = in.hot[i];
            const std::size_t obase = std::size_t(i) * std::size_t(in.obstacle_capacity);
            for (Index k = 0; k < co; ++k) {
                const std::size_t sk = obase + std::size_t(k);
                const ObstacleSphere& o = in.spheres[in.obstacle_partner[sk]];
                const HistoryRef hk{in.obstacle_xi + sk,
                                    in.obstacle_roll ? in.obstacle_roll + sk : nullptr};
                const Vec3 r = si.x - o.x;
                const Real rs = si.r + o.r, d2 = dot(r, r);
                if (d2 == 0 ||
                    (d2 >= rs * rs &&
                     !(tab.adhesive && within_reach(tab(si.material, o.material),
                                                    std::sqrt(d2) - rs, si.r * o.r / rs)))) {
                    hk.clear();
                    continue;
                }
                const GrainState so{o.x, o.v, o.w, o.r, o.m, o.material};
                const GrainPairForce c =
                    grain_pair_force(tab(si.material, o.material), si, so, r, d2, in.h_contact, hk);
                f += c.force_i;
                t += c.torque_i;
                sink.obstacle(i, sk, o, c);
                sink.contact(c.force_i);
            }
        }
        if (in.fluid_force) {
            const Vec3 ff = in.fluid_force[i] + in.fluid_beta[i] * (in.fluid_u[i] - in.hot[i].v);
            f += ff;
            // the kicks of this step gave the grain h/2 (f_n + f_n+1)
            if (in.fluid_impulse)
                in.fluid_impulse[i] += (Real(0.5) * in.h_step) * (in.fluid_felt[i] + ff);
            in.fluid_felt[i] = ff;
        }
        finish(i, f, t, member);
    }

    // 2D: forces in the x-z plane, torque about y; the closing half kick; the new force kept.
    DF_HD DF_HOT_INLINE void finish(Index i, Vec3 f, Vec3 t, bool member) const {
        const GrainView& g = in.g;
        if (in.plane) f = Vec3{f.x, 0, f.z}, t = Vec3{0, t.y, 0};
        if (in.half > 0 && !member) {
            const Real im = g.inv_mass[i], ii = g.inv_inertia[i];
            g.vel[i] += (in.half * im) * (f - g.force[i]);
            g.spin[i] += (in.half * ii) * (t - g.torque[i]);
        }
        g.force[i] = f;
        g.torque[i] = t;
    }
};
static_assert(std::is_trivially_copyable_v<GrainOwnPass>);

// The device's sink: each wall slot keeps the force on the grain, the contact point and the
// rolling moment (9 reals) and whether it touched; each obstacle slot the force on the grain
// and the torque on the sphere (6 reals) and whether it touched. Sums go to a SlotReport.
struct GrainOwnSlotSink {
    Real* wall_out;
    std::uint8_t* wall_touching;
    Real* obstacle_out;
    std::uint8_t* obstacle_touching;
    Index wall_capacity, obstacle_capacity;
    bool measure;
    SlotReport& report;

    DF_HD void begin(Index i, Index walls, Index obstacles) {
        const std::size_t wb = std::size_t(i) * std::size_t(wall_capacity);
        for (Index k = 0; k < walls; ++k) wall_touching[wb + std::size_t(k)] = 0;
        const std::size_t ob = std::size_t(i) * std::size_t(obstacle_capacity);
        for (Index k = 0; k < obstacles; ++k) obstacle_touching[ob + std::size_t(k)] = 0;
    }
    DF_HD void wall(Index, std::size_t slot, const WallPrimitive&, Vec3 q, Vec3,
                    const WallContactForce& c) {
        Real* o = wall_out + 9 * slot;
        const Vec3 v[3] = {c.force, q, c.mroll};
        for (int k = 0; k < 3; ++k) o[3 * k] = v[k].x, o[3 * k + 1] = v[k].y, o[3 * k + 2] = v[k].z;
        wall_touching[slot] = 1;
    }
    DF_HD void obstacle(Index, std::size_t slot, const ObstacleSphere&, const GrainPairForce& c) {
        Real* o = obstacle_out + 6 * slot;
        o[0] = c.force_i.x, o[1] = c.force_i.y, o[2] = c.force_i.z;
        o[3] = c.torque_j.x, o[4] = c.torque_j.y, o[5] = c.torque_j.z;
        obstacle_touching[slot] = 1;
    }
    DF_HD void contact(Vec3 force) {
        ++report.touching;
        if (measure) report.force_sum += norm(force);
    }
};

// The per-grain pass in the device's layout, one grain per item (exec::reduce).
struct GrainOwnSlots {
    GrainOwnPass pass;
    Real* wall_out;
    std::uint8_t* wall_touching;
    Real* obstacle_out;
    std::uint8_t* obstacle_touching;
    bool measure;
    DF_HD void operator()(Index i, SlotReport& report) const {
        GrainOwnSlotSink sink{wall_out,
                              wall_touching,
                              obstacle_out,
                              obstacle_touching,
                              pass.in.wall_capacity,
                              pass.in.obstacle_capacity,
                              measure,
                              report};
        if (pass.in.wall_count[i] > 0) {
            WallCandidates cand; // zeroes its points: made only for a grain with wall slots
            pass.run(i, &cand, sink);
        } else {
            pass.run(i, nullptr, sink);
        }
    }
};
static_assert(std::is_trivially_copyable_v<GrainOwnSlots>);

// Force and moment on one body (a wall about its origin, a rigid body about its centre of mass).
struct LoadSum {
    Vec3 force, moment;
    DF_HD static void combine(LoadSum& a, const LoadSum& b) {
        a.force += b.force;
        a.moment += b.moment;
    }
};

// The load of the grains on wall `wall`: over grain i's touching wall slots on its primitives,
// -F and (q - origin) x (-F) - M_roll.
struct WallSlotLoad {
    int wall;
    Vec3 origin;
    const WallPrimitive* prims;
    const Index *partner, *count;
    Index capacity;
    const Real* out;
    const std::uint8_t* touching;
    DF_HD void operator()(Index i, LoadSum& sum) const {
        const std::size_t base = std::size_t(i) * std::size_t(capacity);
        for (Index k = 0; k < count[i]; ++k) {
            const std::size_t s = base + std::size_t(k);
            if (!touching[s] || prims[partner[s]].wall != wall) continue;
            const Real* o = out + 9 * s;
            const Vec3 f{o[0], o[1], o[2]}, q{o[3], o[4], o[5]}, mroll{o[6], o[7], o[8]};
            sum.force -= f;
            sum.moment += cross(q - origin, -f) - mroll;
        }
    }
};

// The load of the grains on rigid body `body` through its contact spheres: -F and the torque on
// the sphere plus (x_sphere - com) x (-F).
struct BodySlotLoad {
    int body;
    Vec3 com;
    const ObstacleSphere* spheres;
    const Index *partner, *count;
    Index capacity;
    const Real* out;
    const std::uint8_t* touching;
    DF_HD void operator()(Index i, LoadSum& sum) const {
        const std::size_t base = std::size_t(i) * std::size_t(capacity);
        for (Index k = 0; k < count[i]; ++k) {
            const std::size_t s = base + std::size_t(k);
            const ObstacleSphere& o = spheres[partner[s]];
            if (!touching[s] || o.body != body) continue;
            const Real* v = out + 6 * s;
            const Vec3 f{v[0], v[1], v[2]}, tj{v[3], v[4], v[5]};
            sum.force -= f;
            sum.moment += tj + cross(o.x - com, -f);
        }
    }
};

static_assert(std::is_trivially_copyable_v<WallSlotLoad>);
static_assert(std::is_trivially_copyable_v<BodySlotLoad>);

} // namespace debrisflow::dem
