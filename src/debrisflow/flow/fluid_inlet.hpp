#pragma once
#include "debrisflow/flow/hydrograph.hpp"
#include "debrisflow/flow/inlet_buffer_k.hpp"
#include "debrisflow/io/case_spec.hpp"
#include "debrisflow/models/eos_tait_k.hpp"
#include "debrisflow/particles/particle_set.hpp"

namespace debrisflow::checkpoint {
class Archive;
}

namespace debrisflow::flow {

// Velocity inlet with a buffer zone (after the DualSPHysics inlet of Tafuni et al. 2018, with
// prescribed state): fluid particles inside the buffer box move at U(t) = Q(t) / A along the
// inflow direction and carry the hydrostatic density of the buffer's depth; they become free
// fluid when they leave through the downstream face. Each time the upstream layer has advanced
// by dp a new lattice layer is added behind it, so the volume entering is Q dt on average.
class FluidInlet {
public:
    FluidInlet(const io::InletSpec& spec, const io::CaseSpec& c);

    // After each step: prescribes the buffer state at time t and adds layers for the advance
    // of the last dt (buffer(t), then new_layers(t, dt)).
    void apply(particles::ParticleSet& set, Real t, Real dt);
    // The buffer's prescribed state at time t (flow/inlet_buffer_k.hpp).
    InletBuffer buffer(Real t) const;
    // The lattice layers that enter behind the upstream one for the advance of the last dt,
    // counted in mass_in and volume_in.
    std::vector<particles::NewParticle> new_layers(Real t, Real dt);

    const std::string& name() const { return spec_.name; }
    Real discharge(Real t) const { return q_.at(t); } // [m^3/s] (2D: m^2/s)
    Real velocity(Real t) const { return q_.at(t) / area_; }
    Real area() const { return area_; }
    // Mass and volume (at the reference density) of the particles created since t = 0, the
    // initial buffer excluded [kg], [m^3] (2D: per metre).
    Real mass_in() const { return mass_in_; }
    Real volume_in() const { return volume_in_; }
    void state(checkpoint::Archive& ar); // totals and the layer advance (flow/flow_state.cpp)

private:
    void add_layer(std::vector<particles::NewParticle>& out, Real along, Real t);

    io::InletSpec spec_;
    Hydrograph q_;
    models::TaitEos eos_;
    Real dp_, rho0_, area_, g_down_; // g_down_: |g_z| when the fluid carries gravity
    int dim_;
    std::int16_t group_;
    Real advance_ = 0; // distance the upstream layer moved since the last layer was added
    Real mass_in_ = 0, volume_in_ = 0;
};

} // namespace debrisflow::flow
