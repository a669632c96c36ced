#include "debrisflow/probes/flow_instruments.hpp"
#include "debrisflow/dem/dem_solver.hpp"
#include "debrisflow/probes/fluid_reader.hpp"
#include "debrisflow/probes/grain_reader.hpp"
#include "debrisflow/rigid/body_solver.hpp"
#include <algorithm>
#include <cmath>
#include <limits>

namespace debrisflow::probes {

namespace {
bool in_box(Vec3 p, Vec3 lo, Vec3 hi) {
    return p.x >= lo.x && p.x <= hi.x && p.y >= lo.y && p.y <= hi.y && p.z >= lo.z && p.z <= hi.z;
}
} // namespace

Real SolidCrossing::wrap_distance(const io::CaseSpec& c, Vec3 n) {
    int a = 0;
    for (int k = 1; k < 3; ++k)
        if (std::abs(n[k]) > std::abs(n[a])) a = k;
    return Real(0.5) * (c.domain.hi[a] - c.domain.lo[a]);
}

void SolidCrossing::cross(std::uint64_t key, Vec3 x, Real m, Real v) {
    const Real s = dot(x - point_, n_);
    auto it = last_.find(key);
    if (it != last_.end()) {
        const Real prev = it->second;
        const bool wrapped = std::abs(s - prev) > wrap_;
        if (!wrapped && (prev < 0) != (s < 0)) {
            const Real sign = s >= 0 ? 1 : -1;
            mass_ += sign * m;
            volume_ += sign * v;
        }
        it->second = s;
    } else {
        last_.emplace(key, s);
    }
}

void SolidCrossing::update(const ProbeContext& ctx) {
    if (ctx.grains) {
        if (plane_ < 0) {
            grains_ = ctx.grains;
            plane_ = grains_->add_plane({point_, n_, wrap_});
        }
        if (pending_) grains_->restore(plane_, restored_);
        pending_ = false;
        const GrainSums crossed = grains_->cross(plane_);
        mass_ += crossed.mass;
        volume_ += crossed.volume;
    }
    if (ctx.rigid) {
        const auto& b = ctx.rigid->bodies();
        const auto& m = ctx.rigid->models();
        for (std::size_t k = 0; k < b.size(); ++k)
            cross(body_key + k, b[k].pos, b[k].mass, m[k].volume);
    }
}

std::unique_ptr<Probe> DischargeProbe::from_config(const ProbeSetup& s) {
    const Vec3 point = s.t.vec3("point", s.c.dim);
    return std::make_unique<DischargeProbe>(s.name(), s.every(), point, s.direction("normal"), s.c);
}

DischargeProbe::DischargeProbe(std::string name, Real every, Vec3 point, Vec3 normal,
                               const io::CaseSpec& c)
    : Probe(std::move(name), every), point_(point), n_(normal), dp_(c.dp), rho0_(c.sph.rho0),
      fluid_(!c.fluids.empty()), solids_(c.has_dem || c.has_bodies()),
      unit_(c.dim == 2 ? "/m" : ""),
      solid_(point, normal, SolidCrossing::wrap_distance(c, normal)) {}

std::vector<std::string> DischargeProbe::columns() const {
    std::vector<std::string> c;
    if (fluid_)
        c.insert(c.end(), {"fluid [kg/s" + unit_ + "]", "fluid_Q [m3/s" + unit_ + "]",
                           "fluid_cumulative [kg" + unit_ + "]"});
    if (solids_)
        // 2D grains are discs of the case's thickness (kg); 2D bodies are per metre.
        c.insert(c.end(), {"solid [kg/s]", "solid_Q [m3/s]", "solid_cumulative [kg]"});
    return c;
}

std::vector<Real> DischargeProbe::sample(Real t, const ProbeContext& ctx) {
    std::vector<Real> out;
    const Real dt = started_ ? t - t_last_ : 0;
    if (fluid_) {
        const Real inv_dp = 1 / dp_;
        Real rate = 0;
        for (const ParticleRow& r : ctx.fluid->rows(RowSelection::fluid_near(point_, n_, dp_))) {
            const Real d = dot(r.x - point_, n_);
            const Real w = 1 - std::abs(d) * inv_dp; // hat of width 2 dp: sums to 1 on a lattice
            if (w > 0) rate += w * r.mass * dot(r.v, n_);
        }
        rate *= inv_dp;
        if (!started_) fluid_rate_last_ = rate;
        fluid_cum_ += Real(0.5) * (rate + fluid_rate_last_) * dt; // trapezoid in time
        fluid_rate_last_ = rate;
        out.insert(out.end(), {rate, rate / rho0_, fluid_cum_});
    }
    if (solids_) {
        solid_.update(ctx);
        const Real rate = dt > 0 ? (solid_.mass() - solid_last_) / dt : 0;
        const Real q = dt > 0 ? (solid_.volume() - solid_vol_last_) / dt : 0;
        solid_last_ = solid_.mass(), solid_vol_last_ = solid_.volume();
        out.insert(out.end(), {rate, q, solid_.mass()});
    }
    t_last_ = t;
    started_ = true;
    return out;
}

std::unique_ptr<Probe> TrappingProbe::from_config(const ProbeSetup& s) {
    s.require(s.c.has_dem || s.c.has_bodies(), "grains or bodies");
    const Vec3 up = s.t.vec3("upstream", s.c.dim);
    const Vec3 down = s.t.vec3("downstream", s.c.dim);
    const Vec3 n = s.direction("normal", {1, 0, 0});
    if (!(dot(down - up, n) > 0))
        s.t.fail("downstream", "must lie downstream (along normal) of the upstream plane");
    const auto w = s.t.reals("window");
    if (w.size() != 2 || !(w[1] > w[0]) || w[0] < 0)
        s.t.fail("window", "expected [t_start, t_end] with t_end > t_start >= 0 [s]");
    return std::make_unique<TrappingProbe>(s.name(), s.every(), up, down, n, w[0], w[1], s.c);
}

TrappingProbe::TrappingProbe(std::string name, Real every, Vec3 upstream, Vec3 downstream,
                             Vec3 normal, Real t0, Real t1, const io::CaseSpec& c)
    : Probe(std::move(name), every), up_(upstream, normal, SolidCrossing::wrap_distance(c, normal)),
      down_(downstream, normal, SolidCrossing::wrap_distance(c, normal)), t0_(t0), t1_(t1) {}

std::unique_ptr<Probe> DepositProbe::from_config(const ProbeSetup& s) {
    const auto [lo, hi] = s.box(-1e30, 1e30);
    return std::make_unique<DepositProbe>(s.name(), s.every(), lo, hi, s.c.sph.rho0);
}

std::unique_ptr<Probe> FlowSectionProbe::from_config(const ProbeSetup& s) {
    s.require(!s.c.fluids.empty(), "a fluid");
    const auto [lo, hi] = s.box(-1e30, 1e30);
    const Real bed = s.t.real("bed", lo.z);
    return std::make_unique<FlowSectionProbe>(s.name(), s.every(), lo, hi, bed, s.c);
}

std::unique_ptr<Probe> FluidRunupProbe::from_config(const ProbeSetup& s) {
    s.require(!s.c.fluids.empty(), "a fluid");
    const int wall = s.wall();
    return std::make_unique<FluidRunupProbe>(s.name(), s.every(), s.c.walls[std::size_t(wall)],
                                             s.bed(), s.c);
}

std::vector<Real> TrappingProbe::sample(Real t, const ProbeContext& ctx) {
    up_.update(ctx);
    down_.update(ctx);
    if (t >= t0_ && !opened_) {
        up0_ = up_.mass(), down0_ = down_.mass();
        opened_ = true;
    }
    if (opened_ && t <= t1_ + 1e-12) {
        up_w_ = up_.mass() - up0_;
        down_w_ = down_.mass() - down0_;
    }
    const Real e = up_w_ > 0 ? 1 - down_w_ / up_w_ : 0;
    return {up_w_, down_w_, e};
}

std::vector<Real> DepositProbe::sample(Real, const ProbeContext& ctx) {
    Real vs = 0, ms = 0, vf = 0;
    if (ctx.grains) { // summed where the grains are
        const GrainSums grains = ctx.grains->sums({lo_, hi_});
        ms += grains.mass;
        vs += grains.volume;
    }
    if (ctx.rigid)
        for (std::size_t k = 0; k < ctx.rigid->bodies().size(); ++k)
            if (!ctx.rigid->removed(int(k)) && in_box(ctx.rigid->bodies()[k].pos, lo_, hi_)) {
                ms += ctx.rigid->bodies()[k].mass;
                vs += ctx.rigid->models()[k].volume;
            }
    if (ctx.fluid)
        for (const ParticleRow& r : ctx.fluid->rows(RowSelection::fluid_in(lo_, hi_, true)))
            if (in_box(r.x, lo_, hi_)) vf += r.mass / rho0_;
    return {vs, ms, vf};
}

std::vector<Real> FlowSectionProbe::sample(Real, const ProbeContext& ctx) {
    std::vector<Real> tops;
    Real u = 0;
    for (const ParticleRow& r : ctx.fluid->rows(RowSelection::fluid_in(lo_, hi_, true))) {
        if (!in_box(r.x, lo_, hi_)) continue;
        tops.push_back(r.x.z + Real(0.5) * dp_ - bed_);
        u += r.v.x;
    }
    if (tops.empty()) return {0, 0, 0, 0};
    std::sort(tops.begin(), tops.end());
    const Real h = tops[std::min(tops.size() - 1, std::size_t(0.95 * Real(tops.size())))];
    const Real v = u / Real(tops.size());
    const Real g = norm(gravity_), cos_t = g > 0 ? std::abs(gravity_.z) / g : 1;
    const Real fr = h > 0 && g > 0 ? v / std::sqrt(g * h * cos_t) : 0;
    return {h, v, v * h, fr};
}

std::vector<Real> FluidRunupProbe::sample(Real, const ProbeContext& ctx) {
    const Real m = 2 * dp_, far = std::numeric_limits<Real>::max();
    // the fluid above and beside the wall's box, within 2 dp of it in plan
    const RowSelection near_wall = RowSelection::fluid_in({lo_.x - m, lo_.y - m, -far},
                                                          {hi_.x + m, hi_.y + m, far}, dim_ == 3);
    Real top = 0;
    for (const ParticleRow& r : ctx.fluid->rows(near_wall))
        top = std::max(top, r.x.z + Real(0.5) * dp_ - bed_);
    return {top};
}

} // namespace debrisflow::probes
