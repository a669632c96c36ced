#include "debrisflow/probes/design_formulas.hpp"
#include "debrisflow/dem/materials.hpp"
#include "debrisflow/io/named.hpp"
#include "debrisflow/probes/body_probe.hpp"
#include "debrisflow/probes/wall_force_probe.hpp"
#include <algorithm>
#include <cmath>

namespace debrisflow::probes {

namespace {
constexpr Real pi = 3.14159265358979323846;

const Probe* find(const std::vector<std::unique_ptr<Probe>>& probes, const std::string& name) {
    for (const auto& p : probes)
        if (p->name() == name) return p.get();
    return nullptr;
}
int column(const Probe& p, const std::string& prefix) {
    const auto cols = p.columns();
    for (std::size_t k = 0; k < cols.size(); ++k)
        if (cols[k].rfind(prefix + " ", 0) == 0) return int(k);
    return -1;
}
} // namespace

Real hertz_impact_force(Real m, Real r, Real v, Real e_star) {
    const Real sr = std::sqrt(r);
    const Real delta = std::pow(15 * m * v * v / (16 * e_star * sr), Real(0.4));
    return Real(4) / 3 * e_star * sr * std::pow(delta, Real(1.5));
}

std::vector<DesignCheck> design_checks(const io::CaseSpec& c,
                                       const std::vector<std::unique_ptr<Probe>>& probes,
                                       const std::vector<BodyInfo>& bodies) {
    std::vector<DesignCheck> out;
    for (const auto& probe : probes) {
        const auto* wf = dynamic_cast<const WallForceProbe*>(probe.get());
        if (!wf || !wf->has_samples()) continue;
        const auto& spec = wf->companions();
        if (spec.approach.empty() && spec.boulder.empty()) continue;
        DesignCheck d;
        d.probe = wf->name();
        const int fn = column(*wf, "Fn");
        d.f_peak = wf->peaks()[std::size_t(fn)];
        d.f_peak_time = wf->peak_time(std::size_t(fn));
        if (!spec.approach.empty()) {
            const Probe* ap = find(probes, spec.approach);
            const int ih = column(*ap, "h"), iv = column(*ap, "v"), ir = column(*ap, "rho_bulk");
            Real best = 0;
            for (const auto& row : ap->history()) {
                const Real h = row[std::size_t(ih) + 1], v = row[std::size_t(iv) + 1];
                const Real rho = spec.rho > 0 ? spec.rho
                                 : ir >= 0    ? row[std::size_t(ir) + 1]
                                              : c.sph.rho0;
                if (rho * v * v * h > best) best = rho * v * v * h, d.rho = rho, d.v = v, d.h = h;
            }
            d.w = spec.width;
            d.hydro = best > 0;
            if (d.hydro)
                d.alpha = d.f_peak / (best * d.w);
            else
                d.note += "the approach probe saw no flow; ";
        }
        if (!spec.boulder.empty()) {
            const auto* bprobe = dynamic_cast<const BodyProbe*>(find(probes, spec.boulder));
            const auto b = std::find_if(bodies.begin(), bodies.end(),
                                        [&](const auto& x) { return x.name == bprobe->body(); });
            const int vx = column(*bprobe, "vx");
            for (const auto& row : bprobe->history()) {
                const Real* v = &row[std::size_t(vx) + 1];
                d.v_impact =
                    std::max(d.v_impact, std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]));
            }
            // Wall material: the wall's own, or the body's (as the contact laws default).
            const io::WallSpec& wall = c.walls[std::size_t(wf->wall())];
            const int wm =
                wall.material.empty() ? -1 : io::index_named(c.dem.materials, wall.material);
            const auto& mb = c.dem.materials[std::size_t(b->material)];
            const auto& mw = c.dem.materials[std::size_t(wm >= 0 ? wm : b->material)];
            if (c.dim == 2) {
                d.note += "Hertz boulder load: 3D only (a 2D disc makes a line contact); ";
            } else if (!(mb.youngs_modulus > 0)) {
                d.note += "the boulder's material has no Young's modulus; ";
            } else {
                d.e_star = 1 / (dem::hertz_compliance(mb) + dem::hertz_compliance(mw));
                d.mass = b->mass;
                d.radius =
                    c.dim == 3 ? std::cbrt(3 * b->volume / (4 * pi)) : std::sqrt(b->volume / pi);
                d.k_c = spec.k_c;
                d.f_hertz = hertz_impact_force(d.mass, d.radius, d.v_impact, d.e_star);
                d.hertz = true;
                const int fbx = column(*wf, "Fx_bodies");
                if (fbx >= 0)
                    for (const auto& row : wf->history()) {
                        const Vec3 f{row[std::size_t(fbx) + 1], row[std::size_t(fbx) + 2],
                                     row[std::size_t(fbx) + 3]};
                        d.f_bodies_peak = std::max(d.f_bodies_peak, dot(f, wf->normal()));
                    }
            }
        }
        out.push_back(d);
    }
    return out;
}

} // namespace debrisflow::probes
