#pragma once
#include "debrisflow/probes/probe.hpp"
#include <cstdint>
#include <span>

namespace debrisflow::probes {

// Where a granular deposit ends along an axis. Grains closer than `gap` x the smaller diameter
// (surface to surface) are linked, and the members of a clump always are; the deposit is the
// linked group of largest mass (Staron & Hinch 2005: the run-out is the furthest grain still in
// contact with the rest of the deposit; a disc rolling away on its own is not the deposit).
struct Runout {
    Real front = 0;     // furthest grain edge of the deposit along the axis
    Real front_95 = 0;  // the edge behind which 95 % of all grain mass lies
    Real front_max = 0; // furthest grain edge of any grain
    Real height = 0;    // highest grain top of the deposit above the bed (z)
    long detached = 0;  // grains outside the deposit
    Real detached_mass = 0;
};

// pos, radius, mass: the grains; clump[i] >= 0 links grain i to the other members of that
// clump (empty: no clumps). axis 0-2 and sign +1 / -1 give the direction of spreading.
Runout measure_runout(std::span<const Vec3> pos, std::span<const Real> radius,
                      std::span<const Real> mass, std::span<const std::int32_t> clump, int axis,
                      int sign, Real bed, Real gap);

// Run-out of the grains along `axis` (+x default, -x for a deposit spreading towards -x) with
// the deposit's height above `bed`: every sample → front, front_95, front_max [m], height [m],
// detached [-], detached_mass [kg] (2D: the grains' mass, thickness included).
class RunoutProbe : public Probe {
public:
    static constexpr std::string_view type_name = "runout";
    static std::unique_ptr<Probe> from_config(const ProbeSetup& s); // keys: axis, bed, gap
    RunoutProbe(std::string name, Real every, int axis, int sign, Real bed, Real gap)
        : Probe(std::move(name), every), axis_(axis), sign_(sign), bed_(bed), gap_(gap) {}
    std::vector<std::string> columns() const override {
        return {"front [m]",  "front_95 [m]", "front_max [m]",
                "height [m]", "detached [-]", "detached_mass [kg]"};
    }
    std::vector<Real> sample(Real t, const ProbeContext& ctx) override;
    bool reads_particles() const override { return false; } // ctx.grains' rows

private:
    int axis_, sign_;
    Real bed_, gap_;
};

} // namespace debrisflow::probes
