#include "debrisflow/probes/fem_probes.hpp"
#include "debrisflow/fem/fem_solver.hpp"
#include <cmath>
#include <fmt/format.h>
#include <limits>

namespace debrisflow::probes {

FemDisplacementProbe::FemDisplacementProbe(const io::ProbeSpec& s, const io::CaseSpec& c)
    : Probe(s.name, s.every), set_(s.set), position_(s.position), dim_(c.dim) {}

std::vector<std::string> FemDisplacementProbe::columns() const {
    if (dim_ == 2) return {"ux [m]", "uz [m]", "u [m]"};
    return {"ux [m]", "uy [m]", "uz [m]", "u [m]"};
}

std::vector<Real> FemDisplacementProbe::sample(Real, const ProbeContext& ctx) {
    const fem::FemSolver& fem = *ctx.fem;
    if (nodes_.empty()) {
        if (!set_.empty()) {
            nodes_ = fem.node_set(set_);
        } else {
            Real best = std::numeric_limits<Real>::max();
            for (std::size_t n = 0; n < fem.nodes(); ++n) {
                const Vec3 d = fem.reference()[n] - position_;
                if (dot(d, d) < best) best = dot(d, d), nodes_ = {std::int32_t(n)};
            }
        }
    }
    Vec3 u{};
    for (auto n : nodes_) u = u + fem.displacement(std::size_t(n));
    u = (Real(1) / Real(nodes_.size())) * u;
    if (dim_ == 2) return {u.x, u.z, norm(u)};
    return {u.x, u.y, u.z, norm(u)};
}

FemForceProbe::FemForceProbe(const io::ProbeSpec& s, const io::CaseSpec& c)
    : Probe(s.name, s.every), unit_(c.dim == 2 ? "N/m" : "N") {}

std::vector<std::string> FemForceProbe::columns() const {
    std::vector<std::string> c;
    for (const char* src : {"fluid", "grains", "bodies", "total"})
        for (const char* comp : {"Fx", "Fy", "Fz", "F"})
            c.push_back(fmt::format("{}_{} [{}]", comp, src, unit_));
    return c;
}

std::vector<Real> FemForceProbe::sample(Real, const ProbeContext& ctx) {
    std::vector<Real> out;
    Vec3 total{};
    for (const char* src : {"fluid", "grains", "bodies"}) {
        const Vec3 f = ctx.fem->interface_force(src);
        total += f;
        out.insert(out.end(), {f.x, f.y, f.z, norm(f)});
    }
    out.insert(out.end(), {total.x, total.y, total.z, norm(total)});
    return out;
}

} // namespace debrisflow::probes
