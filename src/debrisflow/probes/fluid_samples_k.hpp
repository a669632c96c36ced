#pragma once
// What the SPH probes read of the particles, written once for the host (probes/sph_probes.cpp)
// and a device, where a probe evaluated beside the particle arrays brings back its few numbers
// instead of the arrays (exec/cuda_instantiations.cu compiles these with nvcc).
#include "debrisflow/neighbors/grid_view_k.hpp"
#include "debrisflow/particles/particle_set.hpp"
#include <cmath>
#include <type_traits>

namespace debrisflow::probes {

// Shepard-normalised kernel interpolation of fluid fields at a point:
// f(x) = sum_j f_j W(x - x_j) m_j/rho_j / sum_j W(x - x_j) m_j/rho_j (fluid particles only).
struct PointSample {
    Real weight = 0; // sum_j W m_j / rho_j (1 inside the fluid, ~0.5 at the free surface)
    Real p = 0, rho = 0;
    Vec3 v;
};

template <class Kernel> struct ShepardSample {
    particles::ParticleView pv;
    neighbors::GridView grid;
    Kernel kernel;
    DF_HD PointSample operator()(Vec3 x) const {
        PointSample out;
        grid.for_each_neighbor(-1, x, pv.x, pv.y, pv.z, [&](Index j, Vec3, Real r2) {
            if (!pv.is_fluid(j)) return;
            const Real w = kernel.w(std::sqrt(r2)) * pv.mass[j] / pv.rho[j];
            out.weight += w;
            out.p += w * pv.p[j];
            out.rho += w * pv.rho[j];
            out.v += w * pv.vel(j);
        });
        if (out.weight > 0) {
            out.p /= out.weight;
            out.rho /= out.weight;
            out.v = (1 / out.weight) * out.v;
        }
        return out;
    }
};

// Kernel sum of the volume of fluid and boundary particles at x, sum_j W(x - x_j) m_j / rho_j:
// 1 inside water or a solid, 1/2 on their surface (the gauge's filled fraction).
template <class Kernel> struct FilledFraction {
    particles::ParticleView pv;
    neighbors::GridView grid;
    Kernel kernel;
    DF_HD Real operator()(Vec3 x) const {
        Real sum = 0;
        grid.for_each_neighbor(-1, x, pv.x, pv.y, pv.z, [&](Index j, Vec3, Real r2) {
            sum += kernel.w(std::sqrt(r2)) * pv.mass[j] / pv.rho[j];
        });
        return sum;
    }
};

// Coordinate `axis` of particle i times `sign` for a fluid particle, -max otherwise: the
// front probe's maximum over the particles.
struct FrontCoordinate {
    particles::ParticleView pv;
    int axis;
    Real sign;
    Real lowest; // what a particle that is not fluid gives
    DF_HD Real operator()(Index i) const {
        if (!pv.is_fluid(i)) return lowest;
        const Real* c = axis == 0 ? pv.x : (axis == 1 ? pv.y : pv.z);
        return sign * c[i];
    }
};

// The force of the fluid on boundary particle i of wall `group`, m_i a_i (zero for others):
// a wall's fluid load is the sum over its particles.
struct WallParticleLoad {
    particles::ParticleView pv;
    int group;
    DF_HD bool on_wall(Index i) const { return !pv.is_fluid(i) && pv.group[i] == group; }
    DF_HD Vec3 operator()(Index i) const {
        if (!on_wall(i)) return {};
        return pv.mass[i] * Vec3{pv.ax[i], pv.ay[i], pv.az[i]};
    }
};

// out[k] = f(x[k]) for a point sampler f (ShepardSample, FilledFraction), one item per point.
template <class F, class Out> struct AtPoints {
    F f;
    const Vec3* x;
    Out* out;
    DF_HD void operator()(Index k) const { out[k] = f(x[k]); }
};

// Component `axis` of WallParticleLoad (a sum over the particles per component).
struct WallLoadComponent {
    WallParticleLoad load;
    int axis;
    DF_HD Real operator()(Index i) const { return load(i)[axis]; }
};

// A particle that a probe reads on the host (FluidReader::rows): the few it selects, not the
// arrays.
struct ParticleRow {
    ParticleId id = 0;
    Vec3 x, v, a;
    Real mass = 0, rho = 0;
};

// Which particles FluidReader::rows brings back: fluid (or, not fluid_only, every particle) in
// a closed box (y ignored unless use_y: a 2D case's particles lie at y = 0), the boundary
// particles of one wall, or fluid within `width` of a plane. A probe applies its own exact
// test to what comes back.
struct RowSelection {
    enum class What : std::uint8_t { fluid_in_box, wall, fluid_near_plane };
    What what = What::fluid_in_box;
    Vec3 lo, hi;
    bool use_y = true;
    bool fluid_only = true;
    int group = -1;
    Vec3 point, normal;
    Real width = 0;

    static RowSelection fluid_in(Vec3 lo, Vec3 hi, bool use_y) {
        RowSelection s;
        s.lo = lo, s.hi = hi, s.use_y = use_y;
        return s;
    }
    static RowSelection particles_in(Vec3 lo, Vec3 hi) {
        RowSelection s = fluid_in(lo, hi, true);
        s.fluid_only = false;
        return s;
    }
    static RowSelection wall_particles(int group) {
        RowSelection s;
        s.what = What::wall, s.group = group;
        return s;
    }
    static RowSelection fluid_near(Vec3 point, Vec3 normal, Real width) {
        RowSelection s;
        s.what = What::fluid_near_plane, s.point = point, s.normal = normal, s.width = width;
        return s;
    }
    DF_HD bool operator()(const particles::ParticleView& pv, Index i) const {
        if (what == What::wall) return !pv.is_fluid(i) && pv.group[i] == group;
        if (fluid_only && !pv.is_fluid(i)) return false;
        if (what == What::fluid_near_plane) {
            const Real d = (pv.x[i] - point.x) * normal.x + (pv.y[i] - point.y) * normal.y +
                           (pv.z[i] - point.z) * normal.z;
            return d < width && d > -width;
        }
        return pv.x[i] >= lo.x && pv.x[i] <= hi.x && pv.z[i] >= lo.z && pv.z[i] <= hi.z &&
               (!use_y || (pv.y[i] >= lo.y && pv.y[i] <= hi.y));
    }
};

// flag[i] = 1 for a selected particle, 0 otherwise (the rows' stream compaction).
struct FlagSelected {
    particles::ParticleView pv;
    RowSelection selection;
    Index* flag;
    DF_HD void operator()(Index i) const { flag[i] = selection(pv, i) ? 1 : 0; }
};

DF_HD inline ParticleRow row_of(const particles::ParticleView& pv, ParticleId id, Index i) {
    ParticleRow r;
    r.id = id;
    r.x = pv.pos(i);
    r.v = pv.vel(i);
    r.a = {pv.ax[i], pv.ay[i], pv.az[i]};
    r.mass = pv.mass[i];
    r.rho = pv.rho[i];
    return r;
}

// out[at[i]] = particle i's row for each flagged i (at: the exclusive scan of the flags).
struct GatherRows {
    particles::ParticleView pv;
    const ParticleId* id;
    const Index* flag;
    const Index* at;
    ParticleRow* out;
    DF_HD void operator()(Index i) const {
        if (flag[i]) out[at[i]] = row_of(pv, id[i], i);
    }
};

static_assert(std::is_trivially_copyable_v<FrontCoordinate>);
static_assert(std::is_trivially_copyable_v<RowSelection>);
static_assert(std::is_trivially_copyable_v<ParticleRow>);
static_assert(std::is_trivially_copyable_v<WallParticleLoad>);

} // namespace debrisflow::probes
