#include "debrisflow/probes/wall_force_probe.hpp"
#include "debrisflow/dem/dem_solver.hpp"
#include "debrisflow/probes/fluid_reader.hpp"
#include "debrisflow/probes/sph_probes.hpp"
#include "debrisflow/rigid/body_solver.hpp"

namespace debrisflow::probes {

std::unique_ptr<Probe> WallForceProbe::from_config(const ProbeSetup& s) {
    const auto& c = s.c;
    const int wall = s.wall();
    Vec3 normal = s.t.vec3("normal", c.dim, {});
    if (norm(normal) > 0) normal = (1 / norm(normal)) * normal;
    Companions d;
    d.approach = s.t.string("approach", "");
    d.boulder = s.t.string("boulder", "");
    if ((!d.approach.empty() || !d.boulder.empty()) && norm(normal) == 0)
        s.t.fail("normal", "design companions need the wall's normal (the load direction)");
    if (!d.approach.empty()) {
        d.width = c.dim == 2 ? s.t.positive("width", 1) : s.t.positive("width");
        d.rho = s.t.real("rho", 0);
        if (d.rho < 0) s.t.fail("rho", "must be >= 0 (0: the approach probe's density)");
        s.require_probe_above("approach", d.approach, {"flow_section", "section"});
    }
    if (!d.boulder.empty()) {
        d.k_c = s.t.positive("k_c", Real(0.1));
        s.require_probe_above("boulder", d.boulder, {"body"});
    }
    return std::make_unique<WallForceProbe>(s.name(), s.every(), wall, normal, d, c);
}

WallForceProbe::WallForceProbe(std::string name, Real every, int wall, Vec3 normal,
                               Companions companions, const io::CaseSpec& c)
    : Probe(std::move(name), every), wall_(wall), normal_(normal),
      companions_(std::move(companions)), unit_(c.dim == 2 && !c.fluids.empty() ? "N/m" : "N"),
      grains_(c.has_dem), bodies_(c.has_bodies()), fluid_(!c.fluids.empty()) {}

std::vector<std::string> WallForceProbe::columns() const {
    std::vector<std::string> c{"Fx [" + unit_ + "]", "Fy [" + unit_ + "]", "Fz [" + unit_ + "]",
                               "|F| [" + unit_ + "]"};
    if (norm(normal_) > 0) {
        c.push_back("Fn [" + unit_ + "]");
        c.push_back("Fn_avg [" + unit_ + "]");
    }
    if (grains_) {
        c.push_back("Mx_grains [N m]");
        c.push_back("My_grains [N m]");
        c.push_back("Mz_grains [N m]");
    }
    if (bodies_)
        for (const char* a : {"x", "y", "z"})
            c.push_back(std::string("F") + a + "_bodies [" + unit_ + "]");
    if (fluid_ && (grains_ || bodies_)) { // the split by source
        for (const char* a : {"x", "y", "z"})
            c.push_back(std::string("F") + a + "_fluid [" + unit_ + "]");
        if (grains_)
            for (const char* a : {"x", "y", "z"})
                c.push_back(std::string("F") + a + "_grains [" + unit_ + "]");
    }
    return c;
}

std::vector<Real> WallForceProbe::sample(Real, const ProbeContext& ctx) {
    Vec3 f, avg, ff, fg;
    if (ctx.fluid) {
        f = ff = ctx.fluid->wall_load(wall_);
        avg = f;
    }
    if (ctx.dem) {
        auto& w = ctx.dem->walls().walls()[std::size_t(wall_)];
        fg = w.force;
        f += w.force;
        avg += w.impulse_time > 0 ? (1 / w.impulse_time) * w.impulse : w.force;
        w.impulse = {};
        w.impulse_time = 0;
    }
    Vec3 fb;
    if (ctx.rigid) {
        fb = ctx.rigid->wall_force(wall_);
        f += fb;
        avg += fb;
    }
    std::vector<Real> out{f.x, f.y, f.z, norm(f)};
    if (norm(normal_) > 0) {
        out.push_back(dot(f, normal_));
        out.push_back(dot(avg, normal_));
    }
    if (ctx.dem) {
        const Vec3 m = ctx.dem->walls().walls()[std::size_t(wall_)].moment;
        out.insert(out.end(), {m.x, m.y, m.z});
    }
    if (bodies_) out.insert(out.end(), {fb.x, fb.y, fb.z});
    if (fluid_ && (grains_ || bodies_)) {
        out.insert(out.end(), {ff.x, ff.y, ff.z});
        if (grains_) out.insert(out.end(), {fg.x, fg.y, fg.z});
    }
    return out;
}

} // namespace debrisflow::probes
