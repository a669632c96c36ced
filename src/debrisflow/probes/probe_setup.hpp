#pragma once
#include "debrisflow/io/case_spec.hpp"
#include "debrisflow/io/config_table.hpp"
#include <span>
#include <string>
#include <utility>

namespace debrisflow::probes {

// What a probe type reads its settings from: its [[probe]] block (errors name the file, line
// and key), the case, and the probes above it in the case file (that it may refer to).
struct ProbeSetup {
    const io::ConfigTable& t;
    const io::CaseSpec& c;
    const io::ProbeSpec& spec;
    std::span<const io::ProbeSpec> above;

    const std::string& name() const { return spec.name; }
    Real every() const { return spec.every; }
    // Rejects the probe (at its `type`) unless `ok`: "a <type> probe needs <what>".
    void require(bool ok, const std::string& what) const;
    // A point [x, y, z] (2D: [x, z]) inside the domain (a probe outside it would read nothing).
    Vec3 point_in_domain(const std::string& key) const;
    // Rejects `key` unless the point p lies inside the domain (2D: y ignored).
    void require_in_domain(const std::string& key, Vec3 p) const;
    // The box [min, max] with max > min along every axis; in 2D its y extent is [y_lo, y_hi].
    std::pair<Vec3, Vec3> box(Real y_lo, Real y_hi) const;
    // A non-zero vector, made unit.
    Vec3 direction(const std::string& key) const;
    Vec3 direction(const std::string& key, Vec3 fallback) const;
    // `bed`, the floor's height that a deposit's or run-up's heights are measured from;
    // required, since the domain's lower bound usually lies below the floor.
    Real bed() const;
    // The wall named by `wall`: its index in c.walls.
    int wall() const;
    // Rejects `key` unless a probe above this one is called `name` and is of one of `types`.
    void require_probe_above(const std::string& key, const std::string& name,
                             const std::vector<std::string>& types) const;
};

} // namespace debrisflow::probes
