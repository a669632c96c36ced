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
    // Design-formula companions (design_formulas.hpp): the approach-flow probe (flow_section or
    // section), impact width [m] and bulk density [kg/m^3] (0: from the probe) for
    // F = alpha rho v^2 h w; a body probe for the Hertz boulder load with the load-reduction
    // factor K_c (Kwan 2012).
    struct Companions {
        std::string approach, boulder;
        Real width = 0, rho = 0, k_c = Real(0.1);
    };
    static constexpr std::string_view type_name = "wall_force";
    // keys: wall, normal; approach, width, rho; boulder, k_c
    static std::unique_ptr<Probe> from_config(const ProbeSetup& s);
    // normal: the direction of the normal component (zero: none).
    WallForceProbe(std::string name, Real every, int wall, Vec3 normal, Companions companions,
                   const io::CaseSpec& c);
    int wall() const { return wall_; }
    Vec3 normal() const { return normal_; }
    const Companions& companions() const { return companions_; }
    std::vector<std::string> columns() const override;
    std::vector<Real> sample(Real t, const ProbeContext& ctx) override;
    bool reads_particles() const override { return false; } // the fluid through ctx.fluid

private:
    int wall_;
    Vec3 normal_;
    Companions companions_;
    std::string unit_;
    bool grains_, bodies_, fluid_;
};

} // namespace debrisflow::probes
