#include "debrisflow/rigid/body_contacts.hpp"
#include "debrisflow/dem/contact_time.hpp"
#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>

namespace debrisflow::rigid {

namespace {

// Signed gap (< 0: overlap) and contact normal (from the wall to the body) of a sphere of
// radius r > 0 at p against a wall primitive.
bool sphere_gap(const dem::WallPrimitive& w, Vec3 p, Real r, Vec3& n, Real& gap) {
    if (w.type == dem::PrimitiveType::plane) {
        n = w.n;
        gap = dot(p - w.a, w.n) - r;
        return true;
    }
    const Vec3 q = dem::closest_on_triangle(p, w.a, w.b, w.c);
    const Vec3 d = p - q;
    const Real dist = norm(d);
    if (dist == 0) return false;
    n = (1 / dist) * d;
    gap = dist - r;
    return true;
}

// Distance of a vertex at p from the plane of triangle w along its normal, when the vertex's
// foot lies on the triangle (otherwise the triangle does not see the vertex).
bool vertex_over_triangle(const dem::WallPrimitive& w, Vec3 p, Real reach, Real& along_n) {
    along_n = dot(p - w.a, w.n);
    const Vec3 foot = p - along_n * w.n;
    const Vec3 q = dem::closest_on_triangle(foot, w.a, w.b, w.c);
    return dot(q - foot, q - foot) <= Real(1e-18) + Real(1e-12) * reach * reach;
}

// A face of a solid lying on another (active) solid of the structure is no way in or out.
bool covered(const dem::WallSet& walls, const dem::WallPrimitive& w) {
    if (w.covered_by < 0) return false;
    const auto& holder = walls.solids()[std::size_t(w.covered_by)];
    return walls.walls()[std::size_t(holder.wall)].active;
}

// The active primitives that any feature of body b can touch, or reach within the horizon:
// a feature at p lies within R (the body's bound radius, sphere radii included) of the
// centre, so its gap to a triangle is at least dist(centre, triangle) - R and to a plane at
// least the centre's height - R. A primitive beyond R + the vertex reach + the closing
// distance over the horizon gives no contact, no imminent contact and no side memory for
// any feature, so dropping it changes nothing but the cost (features x primitives). Covered
// faces of solids are dropped too.
std::vector<std::size_t> primitives_near(const dem::WallSet& walls, const BodyState& b,
                                         const BodyModel& model, Real horizon) {
    const auto& prims = walls.primitives();
    const auto& wl = walls.walls();
    const Real bound = model.bound_radius.x;
    const Real spin = norm(b.omega()) * bound;
    std::vector<std::size_t> near;
    for (std::size_t pi = 0; pi < prims.size(); ++pi) {
        const auto& w = prims[pi];
        if (!wl[w.wall].active || covered(walls, w)) continue;
        const Real closing = (norm(b.vel - wl[w.wall].velocity) + spin) * horizon;
        if (w.type == dem::PrimitiveType::plane) {
            if (dot(b.pos - w.a, w.n) - bound > closing) continue;
        } else {
            const Vec3 d = b.pos - dem::closest_on_triangle(b.pos, w.a, w.b, w.c);
            if (norm(d) - bound > b.contact_radius + closing) continue;
        }
        near.push_back(pi);
    }
    return near;
}

std::uint64_t key(std::uint64_t a, std::uint64_t b, std::uint64_t c) {
    return (a << 40) ^ (b << 16) ^ c;
}

} // namespace

void BodyContacts::add(const dem::PairParams& p, const Hit& h, const BodyState& a,
                       const BodyState* b, int wall, Vec3 wall_velocity, Real r_eff, Real m_eff,
                       BodyLoads& la, BodyLoads* lb, dem::ContactHistory& hist, Real elapsed) {
    const Vec3 vb = b ? b->point_velocity(h.point) : wall_velocity;
    const Vec3 vrel = a.point_velocity(h.point) - vb;
    const Vec3 wrel = a.omega() - (b ? b->omega() : Vec3{});
    const auto res = dem::resolve_contact(p, h.delta, h.n, vrel, wrel, r_eff, m_eff, elapsed, hist);
    la.contact_force += res.force;
    la.contact_torque += cross(h.point - a.pos, res.force);
    if (lb) {
        lb->contact_force -= res.force;
        lb->contact_torque -= cross(h.point - b->pos, res.force);
    }
    // Stiffness x compliance for the time step: k = 1.5 F_n / delta (Hertz), and the normal
    // compliance of each body at the contact point, 1/m + (r x n) . I^-1 (r x n) (rotation
    // makes a vertex contact of an elongated rock much softer in mass, stiffer in rate). Each
    // body sums its contacts (a rock wedged in a pile or a slit oscillates at the sum); the
    // step uses the largest sum (Gershgorin bound of the contact stiffness matrix).
    if (h.delta > 0) {
        auto compliance = [&](const BodyState& s) {
            if (s.inv_mass == 0) return Real(0);
            const Vec3 rn = cross(h.point - s.pos, h.n);
            return s.inv_mass + dot(rn, s.inv_inertia_world(rn));
        };
        const Real pair_rate =
            Real(1.5) * res.fn / h.delta * (compliance(a) + (b ? compliance(*b) : Real(0)));
        const auto bump = [&](const BodyState& s) {
            Real& r = rate_[std::size_t(&s - first_)];
            r += pair_rate;
            max_rate_ = std::max(max_rate_, r);
        };
        bump(a);
        if (b) bump(*b);
    }
    const int ia = int(&a - first_), ib = b ? int(b - first_) : -1;
    const auto note = [&](int self, int other) {
        StrongestContact& sc = strongest_[std::size_t(self)];
        if (res.fn > sc.fn) sc = {other < 0 ? wall : -1, other, res.fn, h.delta, h.point};
    };
    note(ia, ib);
    if (b) note(ib, ia);
    ++contacts_;
}

Real BodyContacts::compute(const std::vector<BodyState>& s, const std::vector<BodyModel>& m,
                           const dem::WallSet* walls, std::vector<BodyLoads>& loads, Real elapsed,
                           bool commit, Real horizon) {
    contacts_ = 0;
    max_rate_ = 0;
    first_ = s.data();
    rate_.assign(s.size(), 0);
    strongest_.assign(s.size(), StrongestContact{});
    imminent_dt_ = std::numeric_limits<Real>::max();
    std::unordered_map<std::uint64_t, dem::ContactHistory> wall_next, body_next;
    std::unordered_map<SideKey, std::int8_t, SideKeyHash> side_next;
    // Body-wall: vertices and exact spheres against every active primitive.
    wall_force_.assign(walls ? walls->walls().size() : 0, Vec3{});
    wall_contacts_.assign(wall_force_.size(), {});
    node_force_.assign(walls ? walls->nodes().x.size() : 0, Vec3{});
    if (walls && !walls->empty()) {
        const auto& prims = walls->primitives();
        const auto& wl = walls->walls();
        for (std::size_t bi = 0; bi < s.size(); ++bi) {
            const BodyState& b = s[bi];
            if (b.motion != Motion::free) continue;
            const BodyModel& model = m[bi];
            const std::size_t nf = model.vertices.size() + model.spheres.size();
            const std::vector<std::size_t> near = primitives_near(*walls, b, model, horizon);
            for (std::size_t f = 0; f < nf; ++f) {
                const bool vertex = f < model.vertices.size();
                const BodySphere sp = vertex ? BodySphere{model.vertices[f], 0}
                                             : model.spheres[f - model.vertices.size()];
                const Vec3 p = b.to_world(sp.center);
                const Real reach = std::max(b.contact_radius, sp.radius);
                // One hit per wall (and the primitive it is on). A sphere takes the deepest
                // (its nearest face). A vertex takes the shallowest: inside a convex edge of a
                // wall (the corner of a slit post) it is behind both faces, and only the nearer
                // face is the way out; the deeper one would throw it across the edge.
                std::vector<std::tuple<int, Hit, std::size_t>> best;
                for (const std::size_t pi : near) {
                    const auto& w = prims[pi];
                    Vec3 n;
                    Real gap;
                    if (!vertex || w.type == dem::PrimitiveType::plane) {
                        if (!sphere_gap(w, p, sp.radius, n, gap)) continue;
                    } else if (w.solid >= 0) {
                        // A vertex at a face of a convex solid (a post): outside is against
                        // the face's normal. Behind the face's plane the vertex is inside only
                        // if it is behind every face (one out in the slit can be past the plane
                        // of the post's upstream face); inside, it leaves by the nearest
                        // exposed face (the wall's shallowest hit, below).
                        Real along_n;
                        if (!vertex_over_triangle(w, p, reach, along_n)) continue;
                        if (along_n > 0 && !walls->inside(w.solid, p)) continue;
                        n = -w.n;
                        gap = -along_n;
                        if (gap < -reach) continue;
                    } else {
                        // A vertex over a triangle: which side is outside? The side it was on
                        // when it came within reach of the triangle, remembered while it stays
                        // within reach (the body's centre tells only at first sight: a rock
                        // over a post's edge has its centre past the upstream face while a
                        // vertex still hangs in front of it). Deeper than reach: not seen.
                        Real along_n;
                        if (!vertex_over_triangle(w, p, reach, along_n)) continue;
                        int side = dot(b.pos - w.a, w.n) >= 0 ? 1 : -1;
                        if (std::fabs(along_n) <= reach) {
                            const SideKey k{std::uint32_t(bi), std::uint32_t(f), pi};
                            if (const auto it = side_.find(k); it != side_.end()) side = it->second;
                            side_next[k] = std::int8_t(side);
                        }
                        n = Real(side) * w.n;
                        gap = Real(side) * along_n;
                        if (gap < -reach) continue;
                    }
                    if (gap >= 0) { // not touching: does it touch within the horizon?
                        const Real vn = -dot(b.point_velocity(p) - wl[w.wall].velocity, n);
                        if (vn > 0 && gap < vn * horizon) {
                            const int wm =
                                wl[w.wall].material >= 0 ? wl[w.wall].material : b.material;
                            const Real r_eff = vertex ? b.contact_radius : sp.radius;
                            imminent_dt_ =
                                std::min(imminent_dt_,
                                         Real(0.1) * dem::undamped_contact_time(
                                                         pair(b.material, wm), b.mass, r_eff, vn));
                        }
                        continue;
                    }
                    const Real delta = -gap;
                    const Hit h{delta, n, p - (sp.radius - Real(0.5) * delta) * n};
                    auto it = std::find_if(best.begin(), best.end(),
                                           [&](const auto& e) { return std::get<0>(e) == w.wall; });
                    if (it == best.end())
                        best.emplace_back(w.wall, h, pi);
                    else if (vertex ? delta < std::get<1>(*it).delta
                                    : delta > std::get<1>(*it).delta)
                        *it = {w.wall, h, pi};
                }
                for (const auto& [wall, h, pi] : best) {
                    const int wm = wl[wall].material >= 0 ? wl[wall].material : b.material;
                    const auto k = key(bi, f, std::uint64_t(wall));
                    auto it = wall_hist_.find(k);
                    dem::ContactHistory hist =
                        it != wall_hist_.end() ? it->second : dem::ContactHistory{};
                    const Vec3 before = loads[bi].contact_force;
                    // A triangle on moving nodes (FEM surface): blended corner velocity, and
                    // the reaction split onto the corners with the same weights.
                    const auto& pr = prims[pi];
                    Vec3 vw = wl[wall].velocity, bw{};
                    if (pr.corners >= 0) {
                        const auto& nc = walls->corners()[std::size_t(pr.corners)];
                        bw = dem::barycentric(dem::closest_point(pr, h.point), pr.a, pr.b, pr.c);
                        vw = dem::blend(nc, walls->nodes().v.data(), bw);
                    }
                    add(pair(b.material, wm), h, b, nullptr, wall, vw,
                        vertex ? b.contact_radius : sp.radius, b.mass, loads[bi], nullptr, hist,
                        elapsed);
                    const Vec3 reaction = before - loads[bi].contact_force;
                    wall_force_[std::size_t(wall)] += reaction;
                    if (wl[wall].record_contacts)
                        wall_contacts_[std::size_t(wall)].push_back({h.point, reaction});
                    if (pr.corners >= 0) {
                        const auto& nc = walls->corners()[std::size_t(pr.corners)];
                        for (int a = 0; a < 3; ++a)
                            node_force_[std::size_t(nc.node[a])] += bw[a] * reaction;
                    }
                    wall_next[k] = hist;
                }
            }
        }
    }
    // Body-body: sample spheres of different bodies, hashed on a grid.
    Real rmax = 0;
    std::size_t total = 0;
    for (const auto& model : m) {
        total += model.samples.size();
        for (const auto& sp : model.samples) rmax = std::max(rmax, sp.radius);
    }
    if (s.size() > 1 && total > 0) {
        const Real cell = 2 * rmax;
        struct Sample {
            Vec3 x;
            Real r;
            int body;
            std::uint32_t id;
        };
        std::vector<Sample> pts;
        pts.reserve(total);
        std::uint32_t id = 0;
        for (std::size_t bi = 0; bi < s.size(); ++bi) {
            if (s[bi].motion == Motion::removed) { // gone; ids stay those of the samples
                id += std::uint32_t(m[bi].samples.size());
                continue;
            }
            for (const auto& sp : m[bi].samples)
                pts.push_back({s[bi].to_world(sp.center), sp.radius, int(bi), id++});
        }
        auto cell_of = [&](Vec3 x) {
            return std::tuple<long, long, long>{long(std::floor(x.x / cell)),
                                                long(std::floor(x.y / cell)),
                                                long(std::floor(x.z / cell))};
        };
        auto hash = [](const std::tuple<long, long, long>& c) {
            return std::uint64_t(std::get<0>(c)) * 73856093u ^
                   std::uint64_t(std::get<1>(c)) * 19349663u ^
                   std::uint64_t(std::get<2>(c)) * 83492791u;
        };
        std::unordered_multimap<std::uint64_t, std::uint32_t> grid;
        grid.reserve(pts.size());
        for (std::uint32_t k = 0; k < pts.size(); ++k) grid.emplace(hash(cell_of(pts[k].x)), k);
        for (const auto& a : pts) {
            const auto [cx, cy, cz] = cell_of(a.x);
            for (long dz = -1; dz <= 1; ++dz)
                for (long dy = -1; dy <= 1; ++dy)
                    for (long dx = -1; dx <= 1; ++dx) {
                        const std::tuple<long, long, long> c{cx + dx, cy + dy, cz + dz};
                        auto [lo, hi] = grid.equal_range(hash(c));
                        for (auto it = lo; it != hi; ++it) {
                            const Sample& b = pts[it->second];
                            if (b.body <= a.body) continue;
                            if (cell_of(b.x) != c) continue; // hash collision
                            const BodyState &A = s[a.body], &B = s[b.body];
                            if (A.motion != Motion::free && B.motion != Motion::free) continue;
                            const Vec3 d = a.x - b.x;
                            const Real dist = norm(d);
                            const Real delta = a.r + b.r - dist;
                            if (dist == 0) continue;
                            const Vec3 n = (1 / dist) * d;
                            if (delta <= 0) {
                                const Real vn =
                                    -dot(A.point_velocity(a.x) - B.point_velocity(b.x), n);
                                if (vn > 0 && -delta < vn * horizon) {
                                    const Real m_eff = A.inv_mass + B.inv_mass > 0
                                                           ? 1 / (A.inv_mass + B.inv_mass)
                                                           : A.mass;
                                    imminent_dt_ = std::min(
                                        imminent_dt_,
                                        Real(0.1) * dem::undamped_contact_time(
                                                        pair(A.material, B.material), m_eff,
                                                        a.r * b.r / (a.r + b.r), vn));
                                }
                                continue;
                            }
                            const Hit h{delta, n, b.x + (b.r - Real(0.5) * delta) * n};
                            const Real m_eff = A.inv_mass + B.inv_mass > 0
                                                   ? 1 / (A.inv_mass + B.inv_mass)
                                                   : A.mass;
                            const auto k = (std::uint64_t(a.id) << 32) | b.id;
                            auto hit = body_hist_.find(k);
                            dem::ContactHistory hist =
                                hit != body_hist_.end() ? hit->second : dem::ContactHistory{};
                            add(pair(A.material, B.material), h, A, &B, -1, {},
                                a.r * b.r / (a.r + b.r), m_eff, loads[a.body], &loads[b.body], hist,
                                elapsed);
                            body_next[k] = hist;
                        }
                    }
        }
    }
    if (commit) {
        wall_hist_.swap(wall_next);
        body_hist_.swap(body_next);
        side_.swap(side_next);
    }
    return max_rate_;
}

} // namespace debrisflow::rigid
