#pragma once
#include "debrisflow/dem/contact_force_k.hpp"
#include "debrisflow/dem/grain_set.hpp"
#include "debrisflow/dem/wall_geometry_k.hpp"

namespace debrisflow::dem {

// A grain's state as the contact functors need it, loaded once per grain.
struct GrainState {
    Vec3 x, v, w;
    Real r, m;
    int material;
    DF_HD static GrainState load(const GrainView& g, Index i) {
        return {g.pos[i], g.vel[i], g.spin[i], g.radius[i], g.mass[i], int(g.material[i])};
    }
};

struct GrainPairForce {
    Vec3 force_i;            // on i; j receives -force_i
    Vec3 torque_i, torque_j; // about each centre
};

// Contact of grains i and j with separation r = x_i - x_j, |r|^2 = d2 < (r_i + r_j)^2.
// Contact point velocity of i relative to j: v_i - v_j - (r_i w_i + r_j w_j) x n; torques
// -r_i n x F_t + M_r on i and -r_j n x F_t - M_r on j.
DF_HD DF_HOT_INLINE GrainPairForce grain_pair_force(const PairParams& p, const GrainState& i,
                                                    const GrainState& j, Vec3 r, Real d2, Real dt,
                                                    HistoryRef h) {
    // 1/d as sqrt(d2) / d2: the division runs beside the square root, not after it
    const Real d = std::sqrt(d2), inv_d2 = Real(1) / d2;
    const Vec3 n = (d * inv_d2) * r;
    const Vec3 vrel = i.v - j.v - cross(i.r * i.w + j.r * j.w, n);
    // R* = r_i r_j / (r_i + r_j) and m* = m_i m_j / (m_i + m_j) with one division
    const Real rs = i.r + j.r, ms = i.m + j.m, inv = Real(1) / (rs * ms);
    const Real reff = i.r * j.r * ms * inv, meff = i.m * j.m * rs * inv;
    const ContactResult c = resolve_contact(p, rs - d, n, vrel, i.w - j.w, reff, meff, dt, h);
    const Vec3 nxft = cross(n, c.ft);
    return {c.force, -i.r * nxft + c.mroll, -j.r * nxft - c.mroll};
}

DF_HD DF_HOT_INLINE GrainPairForce grain_pair_force(const PairParams& p, const GrainState& i,
                                                    const GrainState& j, Vec3 r, Real d2, Real dt,
                                                    ContactHistory& h) {
    return grain_pair_force(p, i, j, r, d2, dt, HistoryRef::of(h));
}

struct WallContactForce {
    Vec3 force, torque, mroll; // on the grain
};

// Contact of a grain with a wall primitive at closest point q and distance d < r (a wall has
// infinite mass: R* = r, m* = m). The wall moves with velocity vw.
DF_HD DF_HOT_INLINE WallContactForce wall_contact_force(const PairParams& p, const GrainState& g,
                                                        const WallPrimitive& w, Vec3 q, Real d,
                                                        Vec3 vw, Real dt, HistoryRef h) {
    Vec3 n = w.n;
    if (w.type == PrimitiveType::triangle) {
        const Vec3 gap = g.x - q;
        if (d > Real(1e-12) * g.r)
            n = (Real(1) / d) * gap;
        else if (dot(n, gap) < 0)
            n = -n;
    }
    const Vec3 vrel = g.v - vw - g.r * cross(g.w, n);
    const ContactResult c = resolve_contact(p, g.r - d, n, vrel, g.w, g.r, g.m, dt, h);
    return {c.force, -g.r * cross(n, c.ft) + c.mroll, c.mroll};
}

DF_HD DF_HOT_INLINE WallContactForce wall_contact_force(const PairParams& p, const GrainState& g,
                                                        const WallPrimitive& w, Vec3 q, Real d,
                                                        Vec3 vw, Real dt, ContactHistory& h) {
    return wall_contact_force(p, g, w, q, d, vw, dt, HistoryRef::of(h));
}

// The overlapping wall primitives of one grain, sorted by distance, so that a contact seen
// again through a neighbouring triangle of the same surface is counted once.
struct WallCandidates {
    static constexpr int capacity = 16;
    int size = 0;
    Index slot[capacity];
    Vec3 q[capacity];
    Real d[capacity];
    bool accepted[capacity];

    DF_HD void add(Index k, Vec3 point, Real dist) {
        if (size == capacity) return;
        slot[size] = k, q[size] = point, d[size] = dist, accepted[size] = false;
        ++size;
    }
    DF_HD void sort() {
        for (int a = 1; a < size; ++a)
            for (int b = a; b > 0 && d[b] < d[b - 1]; --b) {
                const Index s = slot[b];
                slot[b] = slot[b - 1], slot[b - 1] = s;
                const Vec3 t = q[b];
                q[b] = q[b - 1], q[b - 1] = t;
                const Real e = d[b];
                d[b] = d[b - 1], d[b - 1] = e;
            }
    }
    // Whether candidate c's contact point lies on a closer, accepted triangle of the same wall;
    // marks c accepted otherwise. On a deforming (nodal) surface the facets around a contact
    // are no longer coplanar: a candidate of the same nodal wall whose normal is within ~25
    // degrees of an accepted one (grain centre x) is the same contact of one smooth surface.
    template <class Prims>
    DF_HD bool covered(int c, const Prims& prims, const Index* partners, Real r, Vec3 x) {
        const WallPrimitive& pc = prims[std::size_t(partners[slot[c]])];
        for (int a = 0; a < c; ++a) {
            if (!accepted[a]) continue;
            const WallPrimitive& pa = prims[std::size_t(partners[slot[a]])];
            if (pa.wall != pc.wall) continue;
            if (lies_on_triangle(pa, q[c], Real(1e-6) * r)) return true;
            if (pa.corners >= 0 && pc.corners >= 0 &&
                dot(x - q[a], x - q[c]) > Real(0.9) * d[a] * d[c])
                return true;
        }
        accepted[c] = true;
        return false;
    }
};

} // namespace debrisflow::dem
