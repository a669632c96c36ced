#pragma once
#include "debrisflow/coupling/sph_body.hpp"
#include "debrisflow/dem/wall_set.hpp"
#include "debrisflow/io/case_spec.hpp"
#include "debrisflow/rigid/body_solver.hpp"
#include "debrisflow/scenario/body_geometry.hpp"
#include <memory>

namespace debrisflow::scenario {

// Geometry, mass properties and SPH samples of every [[body]] (before the fluid is built).
std::vector<BuiltBody> build_body_geometry(const io::CaseSpec& c);

// The rigid-body phase: bodies, joints (anchors and axes turned into body frames) and the
// contact pair table over the case's materials.
std::unique_ptr<rigid::BodySolver> make_body_solver(const io::CaseSpec& c,
                                                    const std::vector<BuiltBody>& built,
                                                    const dem::WallSet* walls);

// The bodies' SPH boundary particles in body frames, their ids starting at first_id (as
// build_particles numbered them).
coupling::BodyParticles body_particles(const std::vector<BuiltBody>& built, ParticleId first_id);

} // namespace debrisflow::scenario
