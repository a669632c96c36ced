#pragma once
#include "debrisflow/dem/wall_set.hpp"
#include "debrisflow/io/case_spec.hpp"
#include "debrisflow/rigid/body_solver.hpp"
#include "debrisflow/scenario/body_geometry.hpp"
#include <memory>

namespace debrisflow::scenario {

// Geometry, mass properties and SPH samples of every [[body]] (before the fluid is built).
std::vector<BuiltBody> build_body_geometry(const io::CaseSpec& c);

// The rigid-body phase: bodies, joints (anchors and axes turned into body frames), the contact
// pair table over the case's materials, and, with a fluid, the boundary particles whose ids
// start at first_id in `set`.
std::unique_ptr<rigid::BodySolver>
make_body_solver(const io::CaseSpec& c, const std::vector<BuiltBody>& built,
                 const dem::WallSet* walls, particles::ParticleSet* set, ParticleId first_id);

} // namespace debrisflow::scenario
