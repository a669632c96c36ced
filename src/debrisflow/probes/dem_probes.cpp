#include "debrisflow/probes/dem_probes.hpp"
#include "debrisflow/dem/dem_solver.hpp"
#include "debrisflow/probes/grain_reader.hpp"
#include <algorithm>
#include <cmath>
#include <limits>

namespace debrisflow::probes {

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
    return std::make_unique<RunupProbe>(s.name(), s.every(), wall, s.bed());
}

std::unique_ptr<Probe> MassFluxProbe::from_config(const ProbeSetup& s) {
    s.require(s.c.has_dem, "[[grains]]");
    const Vec3 point = s.t.vec3("point", s.c.dim);
    const Vec3 n = s.direction("normal");
    return std::make_unique<MassFluxProbe>(s.name(), s.every(), point, n,
                                           SolidCrossing::wrap_distance(s.c, n));
}

std::vector<Real> SectionProbe::sample(Real, const ProbeContext& ctx) {
    std::vector<Real> tops;
    Real m = 0, mv = 0, md = 0, vs = 0;
    for (const GrainRow& r : ctx.grains->rows({lo_, hi_})) { // in id order
        tops.push_back(r.pos.z + r.radius - bed_);
        m += r.mass;
        mv += r.mass * r.vel.x;
        md += r.mass * 2 * r.radius;
        vs += r.volume;
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

// Free grains by their own energy, clumps once by their centre of mass (GrainReader::sums).
std::vector<Real> KineticEnergyProbe::sample(Real, const ProbeContext& ctx) {
    const GrainSums s = ctx.grains->sums({lo_, hi_});
    return {s.translational, s.rotational, s.count};
}

std::vector<Real> RunupProbe::sample(Real, const ProbeContext& ctx) {
    return {ctx.grains->runup(wall_, bed_)};
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
