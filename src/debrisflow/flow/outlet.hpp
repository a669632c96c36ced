#pragma once
#include "debrisflow/flow/outlet_box_k.hpp"
#include "debrisflow/io/case_spec.hpp"
#include <cstdint>
#include <vector>

namespace debrisflow::sph {
class SphSolver;
}
namespace debrisflow::dem {
class DemSolver;
struct Material;
} // namespace debrisflow::dem
namespace debrisflow::rigid {
class BodySolver;
}

namespace debrisflow::checkpoint {
class Archive;
}

namespace debrisflow::flow {

// A sink: fluid particles and grains found inside the box are removed and counted by phase
// (mass, and volume at the reference density / the grain's solid density); a free rigid body
// whose centre of mass is inside leaves the model too (BodySolver::remove_body: parked, inert,
// its SPH boundary particles removed), counted by mass and number. Bodies held by a joint stay.
class Outlet {
public:
    Outlet(const io::OutletSpec& spec, Real rho0) : spec_(spec), rho0_(rho0) {}

    // Removes what is inside now (any solver may be null).
    void apply(sph::SphSolver* fluid, dem::DemSolver* grains, rigid::BodySolver* bodies);

    // Counts fluid removed elsewhere (a resident phase's, in its index order): the masses of
    // the particles that were inside.
    void tally_fluid(const std::vector<Real>& masses);
    // Counts grains removed (here or by a resident phase, in index order): their masses and
    // materials, the volume at each material's density.
    void tally_grains(const std::vector<Real>& masses, const std::vector<std::uint8_t>& materials,
                      const std::vector<dem::Material>& mats);
    OutletBox box() const { return {spec_.min, spec_.max}; }

    const std::string& name() const { return spec_.name; }
    Real fluid_mass() const { return fluid_mass_; }     // [kg] (2D: kg/m)
    Real fluid_volume() const { return fluid_volume_; } // [m^3] (2D: m^2)
    Real grain_mass() const { return grain_mass_; }
    Real grain_volume() const { return grain_volume_; }
    long grains_removed() const { return grains_removed_; }
    Real body_mass() const { return body_mass_; } // [kg] (2D: kg/m)
    long bodies_removed() const { return bodies_removed_; }
    void state(checkpoint::Archive& ar); // totals removed (flow/flow_state.cpp)

private:
    bool inside(Real x, Real y, Real z) const { return box().contains({x, y, z}); }
    io::OutletSpec spec_;
    Real rho0_;
    Real fluid_mass_ = 0, fluid_volume_ = 0, grain_mass_ = 0, grain_volume_ = 0, body_mass_ = 0;
    long grains_removed_ = 0, bodies_removed_ = 0;
};

} // namespace debrisflow::flow
