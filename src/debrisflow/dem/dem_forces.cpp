#include "debrisflow/dem/dem_solver.hpp"
#include "debrisflow/dem/grain_contact_k.hpp"
#include "debrisflow/exec/parallel.hpp"

// The DemSolver's force evaluation: grain-grain contacts over the half list on contiguous
// thread ranges, then per grain gravity, walls, bodies and fluid loads and the closing kick.
namespace debrisflow::dem {

namespace {

// The host's sink of the per-grain pass: each thread adds the reactions on walls and bodies to
// its own sums at once (in grain order: a run repeats bitwise), records the contact loads a
// pressure map reads, and hands nodal triangles their share of the impulse.
struct ThreadSink {
    Real* wall_sums;
    Real* body_sums;
    std::vector<DemSolver::RecordedLoad>* loads;
    const WallState* walls;
    bool record;
    const NodalCorners* corners;
    Vec3* node_j; // null: the evaluation does not end a step
    Real h;
    const Vec3* com;
    bool measure;
    long touching;
    Real force_sum;

    void begin(Index, Index, Index) {}
    void wall(Index i, std::size_t, const WallPrimitive& pr, Vec3 q, Vec3 bw,
              const WallContactForce& c) {
        if (pr.corners >= 0 && node_j) {
            const NodalCorners& nc = corners[pr.corners];
            for (int a = 0; a < 3; ++a) {
                Vec3& J = node_j[nc.node[std::size_t(a)]];
                const Vec3 dj = (-h * bw[a]) * c.force;
                exec::atomic_add(J.x, dj.x);
                exec::atomic_add(J.y, dj.y);
                exec::atomic_add(J.z, dj.z);
            }
        }
        const std::size_t w = std::size_t(pr.wall);
        const Vec3 m = cross(q - walls[w].origin, -c.force) - c.mroll;
        Real* ws = wall_sums + 6 * w;
        ws[0] -= c.force.x, ws[1] -= c.force.y, ws[2] -= c.force.z;
        ws[3] += m.x, ws[4] += m.y, ws[5] += m.z;
        if (record && walls[w].record) loads->push_back({i, w, {q, -1 * c.force}});
    }
    void obstacle(Index, std::size_t, const ObstacleSphere& o, const GrainPairForce& c) {
        const Vec3 tb = c.torque_j + cross(o.x - com[o.body], -c.force_i);
        Real* bs = body_sums + 6 * std::size_t(o.body);
        bs[0] -= c.force_i.x, bs[1] -= c.force_i.y, bs[2] -= c.force_i.z;
        bs[3] += tb.x, bs[4] += tb.y, bs[5] += tb.z;
    }
    void contact(Vec3 force) {
        if (measure) force_sum += norm(force);
        ++touching;
    }
};

} // namespace

const std::vector<WallState>& DemSolver::refresh_wall_states() {
    const auto& wl = walls_.walls();
    wall_states_.resize(wl.size());
    for (std::size_t w = 0; w < wl.size(); ++w)
        wall_states_[w] = {wl[w].velocity, wl[w].origin, wl[w].material, wl[w].active,
                           wl[w].record_contacts};
    return wall_states_;
}

GrainOwnInputs DemSolver::own_inputs(Real half_kick) {
    const bool ends_step = half_kick > 0;
    refresh_wall_states();
    auto& moving = walls_.nodes();
    if (moving.impulse.size() != moving.x.size()) moving.impulse.assign(moving.x.size(), Vec3{});
    const bool bodies = obstacles_ && obstacle_slots_.slots() > 0;
    if (fluid_) fluid_->resize(std::size_t(grains_.size()));
    GrainOwnInputs in{};
    in.g = grains_.view();
    in.hot = hot_.data();
    in.acc = acc_.data();
    in.clump_of = clump_of_id_.empty() ? nullptr : clump_of_id_.data();
    in.table = pair_table();
    in.gravity = params_.gravity;
    // Only the evaluation that ends a step advances the tangential springs and hands impulses
    // to bodies, FEM nodes and the fluid; a re-evaluation of the same state must not.
    in.h_contact = ends_step ? current_h_ : 0;
    in.h_step = current_h_;
    in.half = half_kick;
    in.plane = params_.dim == 2;
    in.prims = walls_.primitives().data();
    in.walls = wall_states_.data();
    in.corners = walls_.corners().data();
    in.node_v = moving.v.data();
    in.wall_partner = wall_slots_.partners();
    in.wall_count = wall_slots_.counts();
    in.wall_xi = wall_slots_.tangential();
    in.wall_roll = wall_slots_.rolling();
    in.wall_capacity = wall_slots_.capacity();
    in.spheres = obstacles_ ? obstacles_->spheres.data() : nullptr;
    in.obstacle_partner = bodies ? obstacle_slots_.partners() : nullptr;
    in.obstacle_count = bodies ? obstacle_slots_.counts() : nullptr;
    in.obstacle_xi = obstacle_slots_.tangential();
    in.obstacle_roll = obstacle_slots_.rolling();
    in.obstacle_capacity = obstacle_slots_.capacity();
    if (fluid_) {
        in.fluid_force = fluid_->force.data();
        in.fluid_u = fluid_->u.data();
        in.fluid_beta = fluid_->beta.data();
        in.fluid_impulse = ends_step ? fluid_->impulse.data() : nullptr;
        in.fluid_felt = fluid_->felt.data();
    }
    return in;
}

void DemSolver::forces(Real half_kick, bool collect_obstacles) {
    const Index n = grains_.size();
    const bool ends_step = half_kick > 0;
    const bool measure = measure_contact_force_; // |F| summed only for the settling ratio
    acc_.resize(6 * std::size_t(n));
    auto& wl = walls_.walls();
    const std::size_t nw = wl.size();
    const std::size_t nb = obstacles_ ? obstacles_->body_com.size() : 0;
    wall_sum_.assign(6 * nw, 0);
    body_sum_.assign(6 * nb, 0);
    for (auto& w : wl) w.contacts.clear();
    long touching = 0;
    Real fsum = 0;
    if (params_.slot_contacts) {
        // The device's layout: contacts per slot into buffers, then sums per grain, wall, body.
        const SlotReport gg = slot_contacts(ends_step ? current_h_ : 0, measure);
        const SlotReport own = own_slots(half_kick, measure);
        touching = gg.touching + own.touching;
        fsum = gg.force_sum + own.force_sum;
    } else {
        const ThreadReport r = own_ranges(half_kick, measure);
        touching = r.touching;
        fsum = r.force_sum;
    }
    if (!clump_of_id_.empty()) clump_forces(half_kick);
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
    if (fluid_ && ends_step) fluid_->time += current_h_;
    contacts_ = touching;
    sum_contact_force_ = measure ? fsum : 0;
    for (std::size_t w = 0; w < nw; ++w) {
        wl[w].force = {wall_sum_[6 * w], wall_sum_[6 * w + 1], wall_sum_[6 * w + 2]};
        wl[w].moment = {wall_sum_[6 * w + 3], wall_sum_[6 * w + 4], wall_sum_[6 * w + 5]};
    }
}

DemSolver::ThreadReport DemSolver::own_ranges(Real half_kick, bool measure) {
    const Index n = grains_.size();
    const PairTable table = pair_table();
    const neighbors::GridView grid = grid_.view();
    const int nt = n > parallel_min ? exec::max_threads() : 1;
    balance_threads(nt);
    const Real h_contact = half_kick > 0 ? current_h_ : 0;
    spills_.resize(std::size_t(nt));
    Real* acc = acc_.data();
    const Index* range = ranges_.data();
    const Index gcap = grain_slots_.capacity();
    const Index* gp = grain_slots_.partners();
    const Index* gcount = grain_slots_.counts();
    Vec3* gxi = grain_slots_.tangential();
    Vec3* groll = grain_slots_.rolling();
    const GrainState* hot = hot_.data();
    const GrainOwnPass own{own_inputs(half_kick)};
    const GrainOwnPass* shared_pass = &own; // by pointer: the closure stays small
    const std::size_t nw = walls_.walls().size();
    const std::size_t nb = obstacles_ ? obstacles_->body_com.size() : 0;
    bool record = false; // some wall keeps its contacts' loads (a pressure map reads them)
    for (const auto& w : walls_.walls()) record = record || w.record_contacts;
    thread_sums_.resize(std::size_t(nt));
    Vec3* node_j = half_kick > 0 ? walls_.nodes().impulse.data() : nullptr;
    const Real current_h = current_h_;
    const Vec3* com = obstacles_ ? obstacles_->body_com.data() : nullptr;
    // One parallel region, each thread on its own contiguous range of grains (balanced on
    // contact slots): (1) grain-grain contacts of its rows (half list: each pair once, Newton's
    // third law), the reaction on partners in its range added at once, on others set aside;
    // (2) after all rows, the reactions set aside for its range by the other threads, in
    // thread order; (3) per grain (GrainOwnPass): gravity, walls, bodies, fluid, the closing
    // half kick. Scalars and pointers by value: a by-reference capture would be reloaded after
    // every store through acc (the compiler cannot rule out aliasing), about 6 % of the loop.
    exec::team(nt, [=, this](const exec::Team& team) {
        // Locals, not the closure's members: the closure is reached through a pointer in the
        // parallel region, so its Real members would be reloaded after every store of a Real.
        const PairTable tab = table;
        const neighbors::GridView grd = grid;
        const Real h_c = h_contact;
        const int th = team.thread;
        ThreadSums& mine = thread_sums_[std::size_t(th)];
        long touching = 0;
        Real fsum = 0;
        const Index lo = range[th], hi = range[th + 1];
        std::vector<Spill>& spill = spills_[std::size_t(th)];
        spill.clear();
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
        mine.wall.assign(6 * nw, 0);
        mine.body.assign(6 * nb, 0);
        mine.loads.clear();
        const GrainOwnPass& pass = *shared_pass;
        ThreadSink sink{mine.wall.data(), mine.body.data(), &mine.loads,
                        pass.in.walls,    record,           pass.in.corners,
                        node_j,           current_h,        com,
                        measure,          touching,         fsum};
        WallCandidates cand; // one per thread: its arrays are not cleared for every grain
        for (Index i = lo; i < hi; ++i) pass(i, cand, sink);
        mine.touching = sink.touching;
        mine.force_sum = sink.force_sum;
    });
    // Walls' and bodies' sums in thread order (ranges ascend), so that a run repeats bitwise.
    ThreadReport out;
    auto& wl = walls_.walls();
    for (std::size_t th = 0; th < std::size_t(nt); ++th) {
        const ThreadSums& ps = thread_sums_[th];
        for (std::size_t k = 0; k < ps.wall.size(); ++k) wall_sum_[k] += ps.wall[k];
        for (std::size_t k = 0; k < ps.body.size(); ++k) body_sum_[k] += ps.body[k];
        for (const auto& r : ps.loads) wl[r.wall].contacts.push_back(r.load); // in grain order
        out.touching += ps.touching;
        out.force_sum += ps.force_sum;
    }
    return out;
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
