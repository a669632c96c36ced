#include "debrisflow/probes/fem_probes.hpp"
#include "debrisflow/fem/fem_solver.hpp"
#include <algorithm>
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

FemFaceLoadProbe::FemFaceLoadProbe(const io::ProbeSpec& s, const io::CaseSpec& c)
    : Probe(s.name, s.every), set_(s.set), unit_(c.dim == 2 ? "N/m" : "N"),
      normal_((1 / norm(s.normal)) * s.normal), axis_(s.axis), bins_(s.panels_u) {}

std::vector<std::string> FemFaceLoadProbe::columns() const {
    // Band 1 is the lowest along the axis (equal bands between the set's extreme nodes).
    std::vector<std::string> c;
    for (int b = 0; b < bins_; ++b) c.push_back(fmt::format("F_band{} [{}]", b + 1, unit_));
    c.push_back(fmt::format("F_face [{}]", unit_));
    return c;
}

std::vector<Real> FemFaceLoadProbe::sample(Real, const ProbeContext& ctx) {
    const fem::FemSolver& fem = *ctx.fem;
    if (nodes_.empty()) {
        nodes_ = fem.node_set(set_);
        Real lo = std::numeric_limits<Real>::max(), hi = -lo;
        for (auto n : nodes_) {
            const Real v = fem.reference()[std::size_t(n)][axis_];
            lo = std::min(lo, v), hi = std::max(hi, v);
        }
        for (auto n : nodes_) {
            const Real v = fem.reference()[std::size_t(n)][axis_];
            const int b = hi > lo ? int((v - lo) / (hi - lo) * bins_) : 0;
            bin_.push_back(std::min(b, bins_ - 1));
        }
    }
    std::vector<Real> out(std::size_t(bins_) + 1, 0);
    for (std::size_t k = 0; k < nodes_.size(); ++k) {
        const Real f = dot(fem.coupling_force(std::size_t(nodes_[k])), normal_);
        out[std::size_t(bin_[k])] += f;
        out.back() += f;
    }
    return out;
}

} // namespace debrisflow::probes
