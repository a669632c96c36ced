#include "debrisflow/probes/probe_setup.hpp"
#include <algorithm>
#include <fmt/format.h>

namespace debrisflow::probes {

void ProbeSetup::require(bool ok, const std::string& what) const {
    if (!ok) t.fail("type", "a " + spec.type + " probe needs " + what);
}

Real ProbeSetup::bed() const {
    if (!t.has("bed"))
        t.fail("bed", fmt::format("a {} probe measures heights from the floor: give bed = the "
                                  "floor's height z (domain.min.z = {:g} usually lies below it)",
                                  spec.type, c.domain.lo.z));
    return t.real("bed");
}

Vec3 ProbeSetup::point_in_domain(const std::string& key) const {
    const Vec3 p = t.vec3(key, c.dim);
    require_in_domain(key, p);
    return p;
}

void ProbeSetup::require_in_domain(const std::string& key, Vec3 p) const {
    for (int d = 0; d < 3; ++d)
        if (!(c.dim == 2 && d == 1) && (p[d] < c.domain.lo[d] || p[d] > c.domain.hi[d]))
            t.fail(key, fmt::format("({:.4g}, {:.4g}, {:.4g}) m lies outside the domain ({:.4g}, "
                                    "{:.4g}, {:.4g}) to ({:.4g}, {:.4g}, {:.4g}) m",
                                    p.x, p.y, p.z, c.domain.lo.x, c.domain.lo.y, c.domain.lo.z,
                                    c.domain.hi.x, c.domain.hi.y, c.domain.hi.z));
}

std::pair<Vec3, Vec3> ProbeSetup::box(Real y_lo, Real y_hi) const {
    Vec3 lo = t.vec3("min", c.dim), hi = t.vec3("max", c.dim);
    if (c.dim == 2) lo.y = y_lo, hi.y = y_hi;
    for (int d = 0; d < 3; ++d)
        if (!(hi[d] > lo[d])) t.fail("max", "must exceed min");
    return {lo, hi};
}

Vec3 ProbeSetup::direction(const std::string& key) const {
    const Vec3 n = t.vec3(key, c.dim);
    if (!(norm(n) > 0)) t.fail(key, "must be a non-zero vector");
    return (1 / norm(n)) * n;
}

Vec3 ProbeSetup::direction(const std::string& key, Vec3 fallback) const {
    return t.has(key) ? direction(key) : fallback;
}

int ProbeSetup::wall() const {
    const std::string name = t.string("wall");
    for (std::size_t w = 0; w < c.walls.size(); ++w)
        if (c.walls[w].name == name) return int(w);
    t.fail("wall", "no wall named \"" + name + "\"");
}

void ProbeSetup::require_probe_above(const std::string& key, const std::string& name,
                                     const std::vector<std::string>& types) const {
    for (const auto& q : above)
        if (q.name == name && std::find(types.begin(), types.end(), q.type) != types.end()) return;
    std::string kinds;
    for (std::size_t k = 0; k < types.size(); ++k)
        kinds += (k == 0 ? "" : (k + 1 == types.size() ? " or " : ", ")) + types[k];
    t.fail(key, "no " + kinds + " probe named \"" + name + "\" above this one");
}

} // namespace debrisflow::probes
