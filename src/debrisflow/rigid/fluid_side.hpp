#pragma once
#include "debrisflow/rigid/body_state.hpp"
#include <cstdint>
#include <vector>

namespace debrisflow::rigid {

// A surface point of a body added during the run: world position and outward unit normal.
struct ShellPoint {
    Vec3 p, n;
    Real depth;
};

// The fluid a body solver is coupled to, as the bodies see it: what the fluid hands them and
// what they hand back. The implementation (coupling::SphBodyCoupling) owns the bodies' SPH
// boundary particles; the body solver calls it at the points of its step named below.
class FluidSide {
public:
    virtual ~FluidSide() = default;
    // Adds the fluid's force and moment on every body to loads[b].fluid_force/fluid_torque
    // (after the fluid's force evaluation).
    virtual void add_loads(const std::vector<BodyState>& bodies, std::vector<BodyLoads>& loads) = 0;
    // The boundary particles follow the bodies: velocities, and positions and wall normals
    // when `positions` (after every update of the bodies).
    virtual void follow(const std::vector<BodyState>& bodies, bool positions) = 0;
    // Boundary particles for body b added during the run: its shell points, of density rho
    // and mass m_particle, moving with `state`.
    virtual void add_shell(int b, const BodyState& state, const std::vector<ShellPoint>& shell,
                           Real rho, Real m_particle) = 0;
    // Marks body b's boundary particles 0 in `keep` (sized to the particle set), for the
    // caller to remove.
    virtual void release(int b, std::vector<std::uint8_t>& keep) = 0;
    // Number of boundary particles of body b in the particle set.
    virtual std::size_t particles_of(int b) const = 0;
};

} // namespace debrisflow::rigid
