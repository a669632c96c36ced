#pragma once
#include "debrisflow/probes/fluid_reader.hpp"
#include "debrisflow/probes/probe.hpp"

namespace debrisflow::probes {

// A probe that samples the fluid through a FluidReader (where the particles are: a resident
// backend is not copied to the host for it).
class FluidProbe : public Probe {
public:
    std::vector<Real> sample(Real, const ProbeContext& ctx) override {
        return sample_fluid(*ctx.fluid);
    }
    virtual std::vector<Real> sample_fluid(const FluidReader& fluid) const = 0;
    bool reads_particles() const override { return false; }

protected:
    using Probe::Probe;
};

// Pressure at a point, as a wall-mounted sensor measures it.
class PressureProbe : public FluidProbe {
public:
    static constexpr std::string_view type_name = "pressure";
    static std::unique_ptr<Probe> from_config(const ProbeSetup& s); // keys: position
    PressureProbe(std::string name, Real every, Vec3 x)
        : FluidProbe(std::move(name), every), x_(x) {}
    std::vector<std::string> columns() const override { return {"p [Pa]"}; }
    std::vector<Real> sample_fluid(const FluidReader& fluid) const override;

private:
    Vec3 x_;
};

// Fluid velocity at a point.
class VelocityProbe : public FluidProbe {
public:
    static constexpr std::string_view type_name = "velocity";
    static std::unique_ptr<Probe> from_config(const ProbeSetup& s); // keys: position
    VelocityProbe(std::string name, Real every, Vec3 x)
        : FluidProbe(std::move(name), every), x_(x) {}
    std::vector<std::string> columns() const override {
        return {"vx [m/s]", "vy [m/s]", "vz [m/s]", "speed [m/s]"};
    }
    std::vector<Real> sample_fluid(const FluidReader& fluid) const override;

private:
    Vec3 x_;
};

// Free-surface elevation at (x, y): the highest level where fluid and solid (boundary)
// volume fill half the kernel, as a wave gauge sees the water column: a dry gauge reads the
// bed's elevation, a film the bed plus the film's thickness; spray smaller than a kernel is
// not seen, a jet overturning above the gauge is.
class GaugeProbe : public FluidProbe {
public:
    static constexpr std::string_view type_name = "gauge";
    static std::unique_ptr<Probe> from_config(const ProbeSetup& s); // keys: position (plan)
    // x: the plan position (z unused); dz: the vertical scan step from `top` down to `bottom`
    // (the domain's).
    GaugeProbe(std::string name, Real every, Vec3 x, Real dz, Real bottom, Real top)
        : FluidProbe(std::move(name), every), x_(x), dz_(dz), bottom_(bottom), top_(top) {}
    std::vector<std::string> columns() const override { return {"elevation [m]"}; }
    std::vector<Real> sample_fluid(const FluidReader& fluid) const override;

private:
    Vec3 x_;
    Real dz_, bottom_, top_;
};

// Surge-front position along an axis: the largest coordinate of any fluid particle, or with a
// negative direction ("-x") the smallest (a surge running towards -x). The position of the
// particle centre, without the dp/2 a particle stands for.
class FrontProbe : public FluidProbe {
public:
    static constexpr std::string_view type_name = "front";
    static std::unique_ptr<Probe> from_config(const ProbeSetup& s); // keys: axis ("+x", "-z" ...)
    // sign: +1 the largest coordinate along axis, -1 the smallest.
    FrontProbe(std::string name, Real every, int axis, Real sign)
        : FluidProbe(std::move(name), every), axis_(axis), sign_(sign) {}
    std::vector<std::string> columns() const override {
        return {std::string(1, "xyz"[axis_]) + "_front [m]"};
    }
    std::vector<Real> sample_fluid(const FluidReader& fluid) const override;

private:
    int axis_;
    Real sign_;
};

} // namespace debrisflow::probes
