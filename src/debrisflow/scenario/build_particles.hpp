#pragma once
#include "debrisflow/io/case_spec.hpp"
#include "debrisflow/particles/particle_set.hpp"
#include "debrisflow/scenario/body_geometry.hpp"

namespace debrisflow::scenario {

// Creates the fluid and boundary particles of a case: fluid group = index in spec.fluids,
// boundary group = index in spec.walls. Fluid that overlaps a wall, or lies inside a solid
// wall (a box, a structure, behind a plane, inside a closed STL mesh), is left out; fluid bodies
// with `hydrostatic = true` start with the hydrostatic density of their own column.
// Rigid bodies carve the fluid (none inside a body or within 0.75 dp of its boundary
// particles) and their boundary particles are appended last, group -1, in body order: the
// returned id is the first of them (ids are contiguous).
ParticleId build_particles(const io::CaseSpec& spec, particles::ParticleSet& set,
                           const std::vector<BuiltBody>& bodies = {});

} // namespace debrisflow::scenario
