#pragma once
// What the probes read of the fluid, wherever its particles are (issue #33): the host
// solver's set (probes/host_fluid_reader.cpp) or a resident backend's memory
// (sph/resident_fluid_reader.hpp). Point samples and reductions (pressure, velocity, gauge,
// front, a wall's fluid load) are evaluated beside the particle arrays and only their few
// numbers come back; the probes that need particles (pressure and hazard maps, flow sections,
// discharge, deposit, run-up) get the rows they select, never the arrays. The per-particle
// and per-point rules are fluid_samples_k.hpp's, shared by both.
#include "debrisflow/probes/fluid_samples_k.hpp"
#include <algorithm>
#include <vector>

namespace debrisflow::sph {
class SphSolver;
}

namespace debrisflow::probes {

class FluidReader {
public:
    virtual ~FluidReader() = default;
    // Shepard-normalised fluid fields at each point (ShepardSample).
    virtual std::vector<PointSample> samples(const std::vector<Vec3>& points) const = 0;
    // Kernel sum of fluid and boundary volume at each point (FilledFraction).
    virtual std::vector<Real> filled(const std::vector<Vec3>& points) const = 0;
    // The largest sign x coordinate `axis` over the fluid particles (-max without fluid).
    virtual Real front(int axis, Real sign) const = 0;
    // The fluid's force on wall `group`: the sum of m_i a_i over its boundary particles.
    virtual Vec3 wall_load(int group) const = 0;
    // The selected particles, in the order of their ids: a probe's sums over them come out the
    // same on every backend, whatever order the particles are stored in.
    std::vector<ParticleRow> rows(const RowSelection& selection) const {
        std::vector<ParticleRow> r = select(selection);
        std::sort(r.begin(), r.end(),
                  [](const ParticleRow& a, const ParticleRow& b) { return a.id < b.id; });
        return r;
    }

protected:
    // The selected particles in storage order.
    virtual std::vector<ParticleRow> select(const RowSelection& selection) const = 0;
};

// The host solver's particles and grid, read in place (loops in index order).
class HostFluidReader final : public FluidReader {
public:
    explicit HostFluidReader(const sph::SphSolver& solver) : solver_(solver) {}
    std::vector<PointSample> samples(const std::vector<Vec3>& points) const override;
    std::vector<Real> filled(const std::vector<Vec3>& points) const override;
    Real front(int axis, Real sign) const override;
    Vec3 wall_load(int group) const override;

protected:
    std::vector<ParticleRow> select(const RowSelection& selection) const override;

private:
    const sph::SphSolver& solver_;
};

} // namespace debrisflow::probes
