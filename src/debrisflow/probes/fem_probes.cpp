#include "debrisflow/probes/fem_probes.hpp"
#include "debrisflow/fem/fem_solver.hpp"
#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <limits>

namespace debrisflow::probes {

namespace {
bool has_solid(const io::CaseSpec& c, const std::string& name) {
    return std::any_of(c.fem.solids.begin(), c.fem.solids.end(),
                       [&](const auto& s) { return s.name == name; });
}
} // namespace

std::unique_ptr<Probe> FemDisplacementProbe::from_config(const ProbeSetup& s) {
    s.require(s.c.has_fem(), "a [[solid]]");
    if (!s.t.has("set"))
        return std::make_unique<FemDisplacementProbe>(s.name(), s.every(), "",
                                                      s.t.vec3("position", s.c.dim), s.c.dim);
    const std::string set = s.t.string("set");
    const std::string solid = set.substr(0, set.find('.'));
    if (!has_solid(s.c, solid))
        s.t.fail("set", "no [[solid]] named \"" + solid +
                            "\" (a set is \"<solid>.<set>\" or \"<solid>\")");
    return std::make_unique<FemDisplacementProbe>(s.name(), s.every(), set, Vec3{}, s.c.dim);
}

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

std::unique_ptr<Probe> FemForceProbe::from_config(const ProbeSetup& s) {
    s.require(s.c.has_fem(), "a [[solid]]");
    return std::make_unique<FemForceProbe>(s.name(), s.every(), s.c.dim);
}

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

std::unique_ptr<Probe> FemFaceLoadProbe::from_config(const ProbeSetup& s) {
    s.require(s.c.has_fem(), "a [[solid]]");
    const std::string set = s.t.string("set");
    const auto dot = set.find('.');
    if (dot == std::string::npos || !has_solid(s.c, set.substr(0, dot)))
        s.t.fail("set", "needs \"<solid>.<set>\" naming a [[solid]] (e.g. \"dam.upstream\")");
    const Vec3 normal = s.direction("normal");
    const std::string axis = s.t.choice("axis", {"x", "y", "z"}, "z");
    const int bins = int(s.t.integer("bins", 5, 1, 100));
    return std::make_unique<FemFaceLoadProbe>(s.name(), s.every(), set, normal,
                                              axis == "x"   ? 0
                                              : axis == "y" ? 1
                                                            : 2,
                                              bins, s.c.dim);
}

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
