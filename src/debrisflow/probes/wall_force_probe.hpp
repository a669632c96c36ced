#pragma once
#include "debrisflow/probes/probe.hpp"

namespace debrisflow::probes {

// Force on a named wall from the fluid (sum of m_i a_i over its boundary particles) and the
// grains (sum of contact forces), in N (N/m in a 2D fluid case). With a `normal`, also the
// normal component, instantaneous (the last step) and averaged over the sampling interval
// (grain impulse / interval; the instantaneous value of a stiff contact network fluctuates
// at the contact frequency, the averaged one is what a load cell of that bandwidth reads).
// With grains, also the grains' moment on the wall about its origin (plane point, box or mesh
// centre). With rigid bodies, their contact force on the wall is included and also
// reported alone (F*_bodies). With a fluid and solids, the fluid part (F*_fluid) and the grain
// part (F*_grains) are also given alone: the split by source.
class WallForceProbe : public Probe {
public:
    WallForceProbe(const io::ProbeSpec& s, int wall, const io::CaseSpec& c);
    std::vector<std::string> columns() const override;
    std::vector<Real> sample(Real t, const ProbeContext& ctx) override;

private:
    int wall_;
    Vec3 normal_;
    std::string unit_;
    bool grains_, bodies_, fluid_;
};

} // namespace debrisflow::probes
