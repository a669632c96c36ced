#pragma once
// The SPH phase's stable step and health-check wording, shared by the host solver
// (sph_stability.cpp) and the resident loop (resident_sph.hpp): the loops reduce their
// particles to a few extremes on their own memory, the rules below turn them into a step.
#include "debrisflow/core/domain.hpp"
#include "debrisflow/sph/sph_params.hpp"
#include "debrisflow/time/phase.hpp"
#include <string>

namespace debrisflow::sph {

// What a step's criteria read of the particles: the fastest signal c + |v| and the largest
// |a| of a fluid particle, and the largest kinematic viscosity.
struct StepExtremes {
    Real cmax = 0, amax = 0, nu = 0;
};

// DualSPHysics's criteria: dt = cfl h / max(c + |v|), cfl sqrt(h / |a|max) (Monaghan 1992),
// and 0.125 h^2 / nu (Morris et al. 1997, eq. 19), whichever is smallest.
time::DtLimit step_limit(const SphParams& p, const StepExtremes& e);

// Which particle to name when one holds the step far below its nominal value: the fastest
// signal (limit "cfl", above 1.5 c0), the largest acceleration (limit "force", above 100 g),
// or none.
enum class LowStep { none, signal, force };
LowStep low_step(const SphParams& p, const time::DtLimit& lim, const StepExtremes& e);

// One particle as the messages name it.
struct ParticleState {
    ParticleId id;
    Vec3 x, v, a;
    Real rho;
    bool fluid;
};

// " (fluid id .. at (..) m: rho/rho0 .., |v| .., |a| ..)", appended to the step's limiter.
std::string low_step_words(const ParticleState& s, Real rho0);

// The health check's message for the first particle that left the domain, is not finite, or
// (fluid) was compressed or expanded beyond max_density_change.
std::string unhealthy_message(const ParticleState& s, Real t, const Domain& d, const SphParams& p);

} // namespace debrisflow::sph
