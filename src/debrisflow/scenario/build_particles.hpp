#pragma once
#include "debrisflow/io/case_spec.hpp"
#include "debrisflow/particles/particle_set.hpp"

namespace debrisflow::scenario {

// Creates the fluid and boundary particles of a case: fluid group = index in spec.fluids,
// boundary group = index in spec.walls. Fluid that overlaps a wall is removed; fluid bodies
// with `hydrostatic = true` start with the hydrostatic density of their own column.
void build_particles(const io::CaseSpec& spec, particles::ParticleSet& set);

} // namespace debrisflow::scenario
