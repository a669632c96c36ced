#pragma once
#include "debrisflow/probes/flow_instruments.hpp"
#include "debrisflow/probes/probe.hpp"

namespace debrisflow::probes {

// Flow section over a window [min, max] of a channel whose flow runs along +x with gravity
// in the x-z plane (slope theta = atan(|g_x| / |g_z|)): flow depth h (95th percentile of the
// grain tops above the bed), depth-averaged velocity v (mass-weighted mean v_x), bulk density
// (grain mass / (window length x width x h)), Froude number v / sqrt(|g| h cos theta) and
// Savage number (v/h)^2 d^2 / (|g| h tan theta) with d the mass-weighted mean diameter; also
// the solid-equivalent depth m / (rho_s x window length x width), which divided by a solid
// fraction gives a depth independent of the dilute surface layer.
class SectionProbe : public Probe {
public:
    static constexpr std::string_view type_name = "section";
    static std::unique_ptr<Probe> from_config(const ProbeSetup& s); // keys: min, max, bed
    // width: the window's extent across the flow (2D: the grains' thickness).
    SectionProbe(std::string name, Real every, Vec3 lo, Vec3 hi, Real bed, Real width)
        : Probe(std::move(name), every), lo_(lo), hi_(hi), bed_(bed), width_(width) {}
    std::vector<std::string> columns() const override {
        return {"h [m]",        "v [m/s]",    "rho_bulk [kg/m3]", "Fr [-]",
                "N_savage [-]", "grains [-]", "h_solid [m]"};
    }
    std::vector<Real> sample(Real t, const ProbeContext& ctx) override;
    bool reads_particles() const override { return false; } // ctx.grains

private:
    Vec3 lo_, hi_;
    Real bed_, width_;
};

// Kinetic energy of the grains whose centres lie in a box: translational sum 1/2 m v^2 and
// rotational sum 1/2 I w^2; a clump counts once, by its centre of mass (1/2 M V^2, 1/2 w . L).
class KineticEnergyProbe : public Probe {
public:
    static constexpr std::string_view type_name = "kinetic_energy";
    static std::unique_ptr<Probe> from_config(const ProbeSetup& s); // keys: min, max
    KineticEnergyProbe(std::string name, Real every, Vec3 lo, Vec3 hi)
        : Probe(std::move(name), every), lo_(lo), hi_(hi) {}
    std::vector<std::string> columns() const override {
        return {"E_kin [J]", "E_rot [J]", "grains [-]"};
    }
    std::vector<Real> sample(Real t, const ProbeContext& ctx) override;
    bool reads_particles() const override { return false; } // ctx.grains

private:
    Vec3 lo_, hi_;
};

// Run-up on a wall: the highest grain top (z + r) above `bed` among grains touching the
// wall (within 5 % of their radius of it); the summary's peak is the maximum run-up.
class RunupProbe : public Probe {
public:
    static constexpr std::string_view type_name = "runup";
    static std::unique_ptr<Probe> from_config(const ProbeSetup& s); // keys: wall, bed
    RunupProbe(std::string name, Real every, int wall, Real bed)
        : Probe(std::move(name), every), wall_(wall), bed_(bed) {}
    std::vector<std::string> columns() const override { return {"runup [m]"}; }
    std::vector<Real> sample(Real t, const ProbeContext& ctx) override;
    bool reads_particles() const override { return false; } // ctx.grains

private:
    int wall_;
    Real bed_;
};

// Mass of grains (and rigid bodies) crossing a plane (point, normal), counted one by one from
// the side each was on at the previous sample (periodic wraps are not crossings): cumulative
// net mass in the +normal direction and its rate over the sampling interval.
class MassFluxProbe : public Probe {
public:
    static constexpr std::string_view type_name = "mass_flux";
    static std::unique_ptr<Probe> from_config(const ProbeSetup& s); // keys: point, normal
    // wrap: a jump larger than this across the plane is a periodic wrap.
    MassFluxProbe(std::string name, Real every, Vec3 point, Vec3 normal, Real wrap)
        : Probe(std::move(name), every), crossing_(point, normal, wrap) {}
    std::vector<std::string> columns() const override { return {"flux [kg/s]", "cumulative [kg]"}; }
    std::vector<Real> sample(Real t, const ProbeContext& ctx) override;
    bool reads_particles() const override { return false; } // ctx.grains (and bodies)
    void extra_state(checkpoint::Archive& ar) override;

private:
    SolidCrossing crossing_;
    Real last_cumulative_ = 0, last_t_ = 0;
    bool started_ = false;
};

} // namespace debrisflow::probes
