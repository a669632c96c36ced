#include "debrisflow/dem/dem_solver.hpp"
#include "debrisflow/dem/grain_contact_k.hpp"
#include "debrisflow/exec/parallel.hpp"

// The DemSolver's force evaluation: grain-grain contacts over the half list on contiguous
// thread ranges, then per grain gravity, walls, bodies and fluid loads and the closing kick.
namespace debrisflow::dem {

void DemSolver::forces(Real half_kick, bool collect_obstacles) {
    const Index n = grains_.size();
    GrainView g = grains_.view();
    const PairTable table = pair_table();
    const neighbors::GridView grid = grid_.view();
    const int nt = n > parallel_min ? exec::max_threads() : 1;
    balance_threads(nt);
    const bool measure = measure_contact_force_; // |F| summed only for the settling ratio
    // Only the evaluation that ends a step advances the tangential springs and hands impulses
    // to bodies and FEM nodes; a re-evaluation of the same state (compute_forces) must not.
    const bool ends_step = half_kick > 0;
    const Real h_contact = ends_step ? current_h_ : 0;
    // The device's layout fills acc_ before the per-grain pass; the host's pass in it, below.
    const bool by_slot = params_.slot_contacts;
    const SlotReport slot_report = by_slot ? slot_contacts(h_contact, measure) : SlotReport{};
    acc_.resize(6 * std::size_t(n));
    spills_.resize(std::size_t(nt));
    Real* acc = acc_.data();
    const Index* range = ranges_.data();
    const Index gcap = grain_slots_.capacity();
    const Index* gp = grain_slots_.partners();
    const Index* gcount = grain_slots_.counts();
    Vec3* gxi = grain_slots_.tangential();
    Vec3* groll = grain_slots_.rolling();
    const GrainState* hot = hot_.data();
    // What the per-grain pass needs: walls, bodies, fluid loads.
    const auto& prims = walls_.primitives();
    auto& wl = walls_.walls();
    // a wall's own material, or the grain's where the wall has none
    const auto wall_pair = [&](int mi, const WallPrimitive& pr) -> const PairParams& {
        const int mw = wl[std::size_t(pr.wall)].material;
        return table(mi, mw < 0 ? mi : mw);
    };
    const std::size_t nw = wl.size();
    wall_sum_.assign(6 * nw, 0);
    bool record = false; // some wall keeps its contacts' loads (a pressure map reads them)
    for (auto& w : wl) {
        w.contacts.clear();
        record = record || w.record_contacts;
    }
    thread_sums_.resize(std::size_t(nt));
    const Index wcap = wall_slots_.capacity();
    const Index* wp = wall_slots_.partners();
    const Index* wcount = wall_slots_.counts();
    Vec3* wxi = wall_slots_.tangential();
    Vec3* wroll = wall_slots_.rolling();
    const auto wall_history = [=](std::size_t slot) {
        return HistoryRef{wxi + slot, wroll ? wroll + slot : nullptr};
    };
    const Vec3 grav = params_.gravity;
    const bool plane = params_.dim == 2;
    // nodal (deforming) triangles: corner nodes, their velocities and reaction impulses
    const auto& corners = walls_.corners();
    auto& moving = walls_.nodes();
    if (moving.impulse.size() != moving.x.size()) moving.impulse.assign(moving.x.size(), Vec3{});
    const Vec3* node_v = moving.v.data();
    Vec3* node_j = ends_step ? moving.impulse.data() : nullptr;
    const Real current_h = current_h_;
    const Real half = half_kick;
    // grain-obstacle (rigid body) contacts
    const std::size_t nb = obstacles_ ? obstacles_->body_com.size() : 0;
    body_sum_.assign(6 * nb, 0);
    const Index ocap = obstacle_slots_.capacity();
    const Index* op = obstacles_ ? obstacle_slots_.partners() : nullptr;
    const Index* ocount =
        obstacles_ && obstacle_slots_.slots() > 0 ? obstacle_slots_.counts() : nullptr;
    Vec3* oxi = obstacle_slots_.tangential();
    Vec3* oroll = obstacle_slots_.rolling();
    const ObstacleSphere* osph = obstacles_ ? obstacles_->spheres.data() : nullptr;
    const Vec3* ocom = obstacles_ ? obstacles_->body_com.data() : nullptr;
    // fluid loads (unresolved SPH-DEM coupling): held force plus drag with the grain's velocity
    if (fluid_) fluid_->resize(std::size_t(n));
    const Vec3* ffix = fluid_ ? fluid_->force.data() : nullptr;
    const Vec3* fu = fluid_ ? fluid_->u.data() : nullptr;
    const Real* fbeta = fluid_ ? fluid_->beta.data() : nullptr;
    Vec3* fimp = fluid_ && ends_step ? fluid_->impulse.data() : nullptr;
    Vec3* ffelt = fluid_ ? fluid_->felt.data() : nullptr;
    const std::int32_t* clump_of = clump_of_id_.empty() ? nullptr : clump_of_id_.data();
    // One parallel region, each thread on its own contiguous range of grains (balanced on
    // contact slots): (1) grain-grain contacts of its rows (half list: each pair once, Newton's
    // third law), the reaction on partners in its range added at once, on others set aside;
    // (2) after all rows, the reactions set aside for its range by the other threads, in
    // thread order; (3) per grain: gravity, walls, bodies, fluid, the closing half kick.
    // Scalars and pointers by value: a by-reference capture would be reloaded after every
    // store through acc (the compiler cannot rule out aliasing), about 6 % of the loop.
    exec::team(nt, [=, this, &wl, &prims, &corners](const exec::Team& team) {
        // Locals, not the closure's members: the closure is reached through a pointer in the
        // parallel region, so its Real members would be reloaded after every store of a Real.
        const PairTable tab = table;
        const neighbors::GridView grd = grid;
        const Real h_c = h_contact, h_now = current_h, h_half = half;
        const Vec3 g_acc = grav;
        const int th = team.thread;
        ThreadSums& mine = thread_sums_[std::size_t(th)];
        long touching = 0;
        Real fsum = 0;
        const Index lo = range[th], hi = range[th + 1];
        std::vector<Spill>& spill = spills_[std::size_t(th)];
        spill.clear();
        // (1) and (2) are the host's pass; the device's layout (by_slot) filled acc_ already.
        if (!by_slot) {
            std::fill(acc + 6 * std::size_t(lo), acc + 6 * std::size_t(hi), Real(0));
            for (Index i = lo; i < hi; ++i) {
                const std::size_t base = std::size_t(i) * std::size_t(gcap);
                const GrainState si = hot[i];
                Vec3 fi{}, ti{};
                const Index ci = gcount[i];
                for (Index k = 0; k < ci; ++k) {
                    const Index j = gp[base + std::size_t(k)];
                    const std::size_t sk = base + std::size_t(k);
                    const HistoryRef h{gxi + sk, groll ? groll + sk : nullptr};
                    GrainPairForce c;
                    if (!grain_slot_force(tab, grd, si, hot[j], h_c, h, c)) continue;
                    fi += c.force_i;
                    ti += c.torque_i;
                    if (j >= lo && j < hi) {
                        Real* aj = acc + 6 * std::size_t(j);
                        aj[0] -= c.force_i.x, aj[1] -= c.force_i.y, aj[2] -= c.force_i.z;
                        aj[3] += c.torque_j.x, aj[4] += c.torque_j.y, aj[5] += c.torque_j.z;
                    } else {
                        spill.push_back({j, -1 * c.force_i, c.torque_j});
                    }
                    if (measure) fsum += norm(c.force_i);
                    ++touching;
                }
                Real* ai = acc + 6 * std::size_t(i);
                ai[0] += fi.x, ai[1] += fi.y, ai[2] += fi.z;
                ai[3] += ti.x, ai[4] += ti.y, ai[5] += ti.z;
            }
            if (nt > 1) {
                team.barrier();
                for (int u = 0; u < nt; ++u) {
                    if (u == th) continue;
                    for (const Spill& sp : spills_[std::size_t(u)]) {
                        if (sp.j < lo || sp.j >= hi) continue;
                        Real* aj = acc + 6 * std::size_t(sp.j);
                        aj[0] += sp.force.x, aj[1] += sp.force.y, aj[2] += sp.force.z;
                        aj[3] += sp.torque.x, aj[4] += sp.torque.y, aj[5] += sp.torque.z;
                    }
                }
            }
        }
        mine.wall.assign(6 * nw, 0);
        mine.body.assign(6 * nb, 0);
        mine.loads.clear();
        WallCandidates cand; // one per thread: its arrays are not cleared for every grain
        for (Index i = lo; i < hi; ++i) {
            // a clump member's force is its contacts'; gravity acts on the clump
            const bool member = clump_of && clump_of[g.id[i]] >= 0;
            const Real* ai = acc + 6 * std::size_t(i);
            Vec3 f = (member ? Real(0) : g.mass[i]) * g_acc + Vec3{ai[0], ai[1], ai[2]};
            Vec3 t{ai[3], ai[4], ai[5]};
            const std::size_t base = std::size_t(i) * std::size_t(wcap);
            const Index cw = wcount[i];
            if (cw > 0) {
                const GrainState si = hot[i];
                cand.size = 0;
                for (Index k = 0; k < cw; ++k) {
                    const Index pidx = wp[base + std::size_t(k)];
                    const WallPrimitive& pr = prims[std::size_t(pidx)];
                    if (!wl[std::size_t(pr.wall)].active) {
                        wall_history(base + std::size_t(k)).clear();
                        continue;
                    }
                    const Vec3 q = closest_point(pr, si.x);
                    const Real d = wall_distance(pr, si.x, q);
                    if (d >= si.r && !(tab.adhesive &&
                                       within_reach(wall_pair(si.material, pr), d - si.r, si.r))) {
                        wall_history(base + std::size_t(k)).clear();
                        continue;
                    }
                    cand.add(k, q, d);
                }
                cand.sort();
                for (int c = 0; c < cand.size; ++c) {
                    const Index k = cand.slot[c];
                    const WallPrimitive& pr = prims[std::size_t(wp[base + std::size_t(k)])];
                    if (cand.covered(c, prims, wp + base, si.r, si.x)) {
                        wall_history(base + std::size_t(k)).clear();
                        continue;
                    }
                    const std::size_t w = std::size_t(pr.wall);
                    // A triangle on moving nodes moves with the barycentric blend of its
                    // corners' velocities and hands the reaction back with the same weights.
                    Vec3 vw = wl[w].velocity, bw{};
                    const NodalCorners* nc = nullptr;
                    if (pr.corners >= 0) {
                        nc = &corners[std::size_t(pr.corners)];
                        bw = barycentric(cand.q[c], pr.a, pr.b, pr.c);
                        vw = blend(*nc, node_v, bw);
                    }
                    const WallContactForce c2 =
                        wall_contact_force(wall_pair(si.material, pr), si, pr, cand.q[c], cand.d[c],
                                           vw, h_c, wall_history(base + std::size_t(k)));
                    if (nc && node_j) {
                        for (int a = 0; a < 3; ++a) {
                            Vec3& J = node_j[nc->node[std::size_t(a)]];
                            const Vec3 dj = (-h_now * bw[a]) * c2.force;
                            exec::atomic_add(J.x, dj.x);
                            exec::atomic_add(J.y, dj.y);
                            exec::atomic_add(J.z, dj.z);
                        }
                    }
                    f += c2.force;
                    t += c2.torque;
                    const Vec3 m = cross(cand.q[c] - wl[w].origin, -c2.force) - c2.mroll;
                    Real* ws = mine.wall.data() + 6 * w;
                    ws[0] -= c2.force.x, ws[1] -= c2.force.y, ws[2] -= c2.force.z;
                    ws[3] += m.x, ws[4] += m.y, ws[5] += m.z;
                    if (record && wl[w].record_contacts)
                        mine.loads.push_back({i, w, {cand.q[c], -1 * c2.force}});
                    if (measure) fsum += norm(c2.force);
                    ++touching;
                }
            }
            const Index co = ocount ? ocount[i] : 0;
            if (co > 0) {
                const GrainState si = hot[i];
                const std::size_t obase = std::size_t(i) * std::size_t(ocap);
                for (Index k = 0; k < co; ++k) {
                    const ObstacleSphere& o = osph[op[obase + std::size_t(k)]];
                    const std::size_t sk = obase + std::size_t(k);
                    const HistoryRef hk{oxi + sk, oroll ? oroll + sk : nullptr};
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
                        grain_pair_force(tab(si.material, o.material), si, so, r, d2, h_c, hk);
                    f += c.force_i;
                    t += c.torque_i;
                    const Vec3 tb = c.torque_j + cross(o.x - ocom[o.body], -c.force_i);
                    Real* bs = mine.body.data() + 6 * std::size_t(o.body);
                    bs[0] -= c.force_i.x, bs[1] -= c.force_i.y, bs[2] -= c.force_i.z;
                    bs[3] += tb.x, bs[4] += tb.y, bs[5] += tb.z;
                    if (measure) fsum += norm(c.force_i);
                    ++touching;
                }
            }
            if (ffix) {
                const Vec3 ff = ffix[i] + fbeta[i] * (fu[i] - hot[i].v);
                f += ff;
                // the kicks of this step gave the grain h/2 (f_n + f_n+1)
                if (fimp) fimp[i] += (Real(0.5) * h_now) * (ffelt[i] + ff);
                ffelt[i] = ff;
            }
            if (plane) f.y = 0, t.x = 0, t.z = 0;
            if (h_half > 0 && !member) {
                const Real im = g.inv_mass[i], ii = g.inv_inertia[i];
                g.vel[i] += (h_half * im) * (f - g.force[i]);
                g.spin[i] += (h_half * ii) * (t - g.torque[i]);
            }
            g.force[i] = f;
            g.torque[i] = t;
        }
        mine.touching = touching;
        mine.force_sum = fsum;
    });
    // Walls' and bodies' sums in thread order (ranges ascend), so that a run repeats bitwise.
    long touching = slot_report.touching;
    Real fsum = slot_report.force_sum;
    for (std::size_t th = 0; th < std::size_t(nt); ++th) {
        const ThreadSums& ps = thread_sums_[th];
        for (std::size_t k = 0; k < ps.wall.size(); ++k) wall_sum_[k] += ps.wall[k];
        for (std::size_t k = 0; k < ps.body.size(); ++k) body_sum_[k] += ps.body[k];
        for (const auto& r : ps.loads) wl[r.wall].contacts.push_back(r.load); // in grain order
        touching += ps.touching;
        fsum += ps.force_sum;
    }
    if (clump_of) clump_forces(half_kick);
    if (obstacles_ && (ends_step || collect_obstacles) && current_h_ > 0) {
        auto& o = *obstacles_;
        o.impulse.resize(nb);
        o.angular_impulse.resize(nb);
        for (std::size_t b = 0; b < nb; ++b) {
            o.impulse[b] +=
                current_h_ * Vec3{body_sum_[6 * b], body_sum_[6 * b + 1], body_sum_[6 * b + 2]};
            o.angular_impulse[b] +=
                current_h_ * Vec3{body_sum_[6 * b + 3], body_sum_[6 * b + 4], body_sum_[6 * b + 5]};
        }
        o.time += current_h_;
    }
    if (fimp) fluid_->time += current_h_;
    contacts_ = touching;
    sum_contact_force_ = measure ? fsum : 0;
    for (std::size_t w = 0; w < nw; ++w) {
        wl[w].force = {wall_sum_[6 * w], wall_sum_[6 * w + 1], wall_sum_[6 * w + 2]};
        wl[w].moment = {wall_sum_[6 * w + 3], wall_sum_[6 * w + 4], wall_sum_[6 * w + 5]};
    }
}

void DemSolver::balance_threads(int nt) {
    const Index n = grains_.size();
    if (ranges_.size() == std::size_t(nt) + 1 && ranges_balanced_ == builds_ && ranges_.back() == n)
        return;
    // Contiguous ranges of about equal work: a grain's contact slots with grains and walls plus
    // one for its own pass.
    const Index* count = grain_slots_.counts();
    const Index* walls = wall_slots_.slots() > 0 ? wall_slots_.counts() : nullptr;
    const auto work = [&](Index i) { return 1 + count[i] + (walls ? walls[i] : 0); };
    long total = 0;
    for (Index i = 0; i < n; ++i) total += work(i);
    ranges_.assign(std::size_t(nt) + 1, n);
    ranges_[0] = 0;
    long sum = 0;
    int t = 1;
    for (Index i = 0; i < n && t < nt; ++i) {
        sum += work(i);
        while (t < nt && sum * nt >= total * t) ranges_[std::size_t(t++)] = i + 1;
    }
    ranges_balanced_ = builds_;
}

} // namespace debrisflow::dem
