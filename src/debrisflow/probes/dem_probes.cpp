#include "debrisflow/probes/dem_probes.hpp"
#include "debrisflow/dem/dem_solver.hpp"
#include <algorithm>
#include <cmath>
#include <limits>

namespace debrisflow::probes {

namespace {
bool inside(Vec3 p, Vec3 lo, Vec3 hi) {
    return p.x >= lo.x && p.x <= hi.x && p.y >= lo.y && p.y <= hi.y && p.z >= lo.z && p.z <= hi.z;
}
} // namespace

std::unique_ptr<Probe> SectionProbe::from_config(const ProbeSetup& s) {
    s.require(s.c.has_dem, "[[grains]]");
    const auto [lo, hi] = s.box(-1e30, 1e30);
    const Real bed = s.t.real("bed", lo.z);
    return std::make_unique<SectionProbe>(s.name(), s.every(), lo, hi, bed,
                                          s.c.dim == 2 ? s.c.dem.thickness : hi.y - lo.y);
}

std::unique_ptr<Probe> KineticEnergyProbe::from_config(const ProbeSetup& s) {
    s.require(s.c.has_dem, "[[grains]]");
    const auto [lo, hi] = s.box(-1e30, 1e30);
    return std::make_unique<KineticEnergyProbe>(s.name(), s.every(), lo, hi);
}

std::unique_ptr<Probe> RunupProbe::from_config(const ProbeSetup& s) {
    s.require(s.c.has_dem, "[[grains]]");
    const int wall = s.wall();
    return std::make_unique<RunupProbe>(s.name(), s.every(), wall,
                                        s.t.real("bed", s.c.domain.lo.z));
}

std::unique_ptr<Probe> MassFluxProbe::from_config(const ProbeSetup& s) {
    s.require(s.c.has_dem, "[[grains]]");
    const Vec3 point = s.t.vec3("point", s.c.dim);
    const Vec3 n = s.direction("normal");
    return std::make_unique<MassFluxProbe>(s.name(), s.every(), point, n,
                                           SolidCrossing::wrap_distance(s.c, n));
}

std::vector<Real> SectionProbe::sample(Real, const ProbeContext& ctx) {
    const auto& g = ctx.dem->grains();
    std::vector<Real> tops;
    Real m = 0, mv = 0, md = 0, vs = 0;
    for (Index i = 0; i < g.size(); ++i) {
        const std::size_t k = std::size_t(i);
        if (!inside({g.pos[k].x, g.pos[k].y, g.pos[k].z}, lo_, hi_)) continue;
        tops.push_back(g.pos[k].z + g.radius[k] - bed_);
        m += g.mass[k];
        mv += g.mass[k] * g.vel[k].x;
        md += g.mass[k] * 2 * g.radius[k];
        vs += g.mass[k] / ctx.dem->materials()[g.material[k]].density;
    }
    if (tops.empty()) return {0, 0, 0, 0, 0, 0, 0};
    std::sort(tops.begin(), tops.end());
    const Real h = tops[std::min(tops.size() - 1, std::size_t(0.95 * Real(tops.size())))];
    const Real v = mv / m, d = md / m;
    const Vec3 grav = ctx.dem->params().gravity;
    const Real gmag = norm(grav), cos_t = std::fabs(grav.z) / gmag;
    const Real tan_t = std::fabs(grav.x) / std::max(std::fabs(grav.z), Real(1e-300));
    const Real fr = h > 0 ? v / std::sqrt(gmag * h * cos_t) : 0;
    const Real rate = h > 0 ? v / h : 0;
    const Real savage = h > 0 && tan_t > 0 ? rate * rate * d * d / (gmag * h * tan_t) : 0;
    const Real rho = h > 0 ? m / ((hi_.x - lo_.x) * width_ * h) : 0;
    const Real h_solid = vs / ((hi_.x - lo_.x) * width_);
    return {h, v, rho, fr, savage, Real(tops.size()), h_solid};
}

std::vector<Real> KineticEnergyProbe::sample(Real, const ProbeContext& ctx) {
    const auto& g = ctx.dem->grains();
    Real ek = 0, er = 0;
    long n = 0;
    // a clump counts once, by its centre of mass: (1/2) M V^2 and (1/2) w . L
    const auto& cl = g.clumps;
    for (Index c = 0; c < cl.size(); ++c) {
        const std::size_t k = std::size_t(c);
        if (!inside({cl.pos[k].x, cl.pos[k].y, cl.pos[k].z}, lo_, hi_)) continue;
        ek += 0.5 * cl.mass[k] * dot(cl.vel[k], cl.vel[k]);
        er += 0.5 * dot(cl.spin(c), cl.ang_mom[k]);
        ++n;
    }
    for (Index i = 0; i < g.size(); ++i) {
        const std::size_t k = std::size_t(i);
        if (ctx.dem->clump_of(i) >= 0) continue;
        if (!inside({g.pos[k].x, g.pos[k].y, g.pos[k].z}, lo_, hi_)) continue;
        ek += 0.5 * g.mass[k] *
              (g.vel[k].x * g.vel[k].x + g.vel[k].y * g.vel[k].y + g.vel[k].z * g.vel[k].z);
        er += 0.5 / g.inv_inertia[k] *
              (g.spin[k].x * g.spin[k].x + g.spin[k].y * g.spin[k].y + g.spin[k].z * g.spin[k].z);
        ++n;
    }
    return {ek, er, Real(n)};
}

std::vector<Real> RunupProbe::sample(Real, const ProbeContext& ctx) {
    const auto& g = ctx.dem->grains();
    const auto& prims = ctx.dem->walls().primitives();
    Real top = 0;
    for (Index i = 0; i < g.size(); ++i) {
        const std::size_t k = std::size_t(i);
        const Vec3 p{g.pos[k].x, g.pos[k].y, g.pos[k].z};
        const Real reach = 1.05 * g.radius[k];
        for (const auto& w : prims) {
            if (w.wall != wall_) continue;
            if (dem::wall_distance(w, p, dem::closest_point(w, p)) < reach) {
                top = std::max(top, p.z + g.radius[k] - bed_);
                break;
            }
        }
    }
    return {top};
}

std::vector<Real> MassFluxProbe::sample(Real t, const ProbeContext& ctx) {
    crossing_.update(ctx);
    const Real cumulative = crossing_.mass();
    const Real dt = t - last_t_;
    const Real flux = started_ && dt > 0 ? (cumulative - last_cumulative_) / dt : 0;
    started_ = true;
    last_t_ = t;
    last_cumulative_ = cumulative;
    return {flux, cumulative};
}

} // namespace debrisflow::probes
