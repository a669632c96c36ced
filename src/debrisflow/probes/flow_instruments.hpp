#pragma once
#include "debrisflow/probes/grain_reader.hpp"
#include "debrisflow/probes/probe.hpp"
#include <unordered_map>

namespace debrisflow::probes {

// Solid mass crossing a plane (point, normal), grain by grain and body by body, from the
// signed distance each had at the previous sample; a jump by more than half the domain is a
// periodic wrap, not a crossing. Cumulative net mass and volume in the +normal direction. The
// grains are counted where they are (GrainReader::cross), the few bodies here.
class SolidCrossing {
public:
    SolidCrossing(Vec3 point, Vec3 normal, Real wrap) : point_(point), n_(normal), wrap_(wrap) {}
    // The wrap distance of a plane with normal n in the case's domain: half the domain's
    // extent along n's dominant axis.
    static Real wrap_distance(const io::CaseSpec& c, Vec3 n);
    void update(const ProbeContext& ctx);
    Real mass() const { return mass_; }
    Real volume() const { return volume_; }
    void state(checkpoint::Archive& ar);

private:
    static constexpr std::uint64_t body_key = std::uint64_t(1) << 40; // body k's key: + k
    void cross(std::uint64_t key, Vec3 x, Real m, Real v);
    Vec3 point_, n_;
    Real wrap_;
    Real mass_ = 0, volume_ = 0;
    std::unordered_map<std::uint64_t, Real> last_; // signed distance by body
    GrainReader* grains_ = nullptr;                // where the grains' distances are kept
    int plane_ = -1;                               // their plane there
    std::vector<Real> restored_;                   // the grains' distances from a checkpoint
    bool pending_ = false;                         // restored_ not yet handed to grains_
};

// Discharge through a plane by phase: fluid as the slab estimate sum w_i m_i (v_i . n) / dp
// with the hat weight w = max(0, 1 - |d_i| / dp) of the distance d_i to the plane (the hats
// of a lattice's layers sum to one wherever the plane lies) (kg/s; volume at rho0), in time for the
// cumulative mass; solids (grains and bodies) counted as they cross, with their mean rate over
// the sampling interval.
class DischargeProbe : public Probe {
public:
    static constexpr std::string_view type_name = "discharge";
    static std::unique_ptr<Probe> from_config(const ProbeSetup& s); // keys: point, normal
    DischargeProbe(std::string name, Real every, Vec3 point, Vec3 normal, const io::CaseSpec& c);
    std::vector<std::string> columns() const override;
    std::vector<Real> sample(Real t, const ProbeContext& ctx) override;
    void extra_state(checkpoint::Archive& ar) override;
    bool reads_particles() const override { return false; } // ctx.fluid, ctx.grains

private:
    Vec3 point_, n_;
    Real dp_, rho0_;
    bool fluid_, solids_;
    std::string unit_;
    SolidCrossing solid_;
    Real t_last_ = 0, fluid_rate_last_ = 0, fluid_cum_ = 0, solid_last_ = 0, solid_vol_last_ = 0;
    bool started_ = false;
};

// Trapping efficiency (Canelas et al. 2017): E = 1 - M_down / M_up, with M the solid mass
// crossing the upstream and the downstream plane within the window [t0, t1].
class TrappingProbe : public Probe {
public:
    static constexpr std::string_view type_name = "trapping";
    // keys: upstream, downstream (points), normal, window [t0, t1]
    static std::unique_ptr<Probe> from_config(const ProbeSetup& s);
    TrappingProbe(std::string name, Real every, Vec3 upstream, Vec3 downstream, Vec3 normal,
                  Real t0, Real t1, const io::CaseSpec& c);
    std::vector<std::string> columns() const override {
        return {"M_up [kg]", "M_down [kg]", "E [-]"};
    }
    std::vector<Real> sample(Real t, const ProbeContext& ctx) override;
    void extra_state(checkpoint::Archive& ar) override;
    bool reads_particles() const override { return false; } // ctx.grains and bodies

private:
    SolidCrossing up_, down_;
    Real t0_, t1_;
    Real up0_ = 0, down0_ = 0, up_w_ = 0, down_w_ = 0;
    bool opened_ = false;
};

// Material inside a box (a deposit behind a structure): solid volume and mass (grains and
// bodies whose centre is inside; volume = mass / solid density) and fluid volume (m / rho0).
class DepositProbe : public Probe {
public:
    static constexpr std::string_view type_name = "deposit";
    static std::unique_ptr<Probe> from_config(const ProbeSetup& s); // keys: min, max
    DepositProbe(std::string name, Real every, Vec3 lo, Vec3 hi, Real rho0)
        : Probe(std::move(name), every), lo_(lo), hi_(hi), rho0_(rho0) {}
    std::vector<std::string> columns() const override {
        return {"solid_volume [m3]", "solid_mass [kg]", "fluid_volume [m3]"};
    }
    std::vector<Real> sample(Real t, const ProbeContext& ctx) override;
    bool reads_particles() const override { return false; } // rows, ctx.fluid, ctx.grains

private:
    Vec3 lo_, hi_;
    Real rho0_;
};

// Fluid flow section over a window (flow along +x, bed = min.z): depth h (95th percentile of
// the fluid particles' tops above the bed), depth-averaged velocity v (mean v_x), unit
// discharge q = v h and Froude number v / sqrt(|g| h cos theta).
class FlowSectionProbe : public Probe {
public:
    static constexpr std::string_view type_name = "flow_section";
    static std::unique_ptr<Probe> from_config(const ProbeSetup& s); // keys: min, max, bed
    FlowSectionProbe(std::string name, Real every, Vec3 lo, Vec3 hi, Real bed,
                     const io::CaseSpec& c)
        : Probe(std::move(name), every), lo_(lo), hi_(hi), bed_(bed), dp_(c.dp),
          gravity_(c.sph.gravity) {}
    std::vector<std::string> columns() const override {
        return {"h [m]", "v [m/s]", "q [m2/s]", "Fr [-]"};
    }
    std::vector<Real> sample(Real t, const ProbeContext& ctx) override;
    bool reads_particles() const override { return false; } // rows, ctx.fluid

private:
    Vec3 lo_, hi_;
    Real bed_, dp_;
    Vec3 gravity_;
};

// Fluid run-up on a structure: the highest fluid particle top above `bed` within 2 dp of the
// wall's bounding box (for grains use `runup`).
class FluidRunupProbe : public Probe {
public:
    static constexpr std::string_view type_name = "fluid_runup";
    static std::unique_ptr<Probe> from_config(const ProbeSetup& s); // keys: wall, bed
    FluidRunupProbe(std::string name, Real every, const io::WallSpec& w, Real bed,
                    const io::CaseSpec& c)
        : Probe(std::move(name), every), lo_(w.shape.min), hi_(w.shape.max), bed_(bed), dp_(c.dp),
          dim_(c.dim) {}
    std::vector<std::string> columns() const override { return {"runup [m]"}; }
    std::vector<Real> sample(Real t, const ProbeContext& ctx) override;
    bool reads_particles() const override { return false; } // rows, ctx.fluid

private:
    Vec3 lo_, hi_;
    Real bed_, dp_;
    int dim_;
};

} // namespace debrisflow::probes
