#pragma once
#include "debrisflow/dem/grain_set.hpp"
#include "debrisflow/flow/feed_reach_k.hpp"
#include "debrisflow/flow/solid_feed.hpp"
#include "debrisflow/particles/particle_set.hpp"
#include "debrisflow/probes/fluid_reader.hpp"
#include "debrisflow/scenario/stl_mesh.hpp"
#include <functional>
#include <utility>
#include <vector>

namespace debrisflow::rigid {
class BodySolver;
}

namespace debrisflow::flow {

// Wadell sphericity of a closed mesh, psi = pi^(1/3) (6 V)^(2/3) / A (1 for a sphere).
Real sphericity(const scenario::TriangleMesh& mesh);

// Rigid-rock feed (the slit-check-dam hopper, section A): rocks are released in the region at
// the target solid discharge Q_s(t) as rigid bodies. Each rock is a shape drawn from the
// library, stretched along its own axes by factors (a, b, 1/(ab)) (volume kept) whose sphericity
// stays within +-tolerance of the shape's (rejection sampling), turned to a uniformly random
// orientation and scaled to an equivalent-sphere diameter drawn from the size distribution.
// A rock goes where its bounding sphere lies inside the region and clear of bodies, grains and
// SPH particles; when no place is found the debt waits for the next step.
class RockFeed : public SolidFeed {
public:
    RockFeed(const io::FeedSpec& spec, const io::CaseSpec& c);

    // The grains (centre, radius) that `reach` may count near a region, in index order:
    // wherever the grains are (the host's GrainSet, or a resident DEM loop's grains_near).
    using GrainsNear = std::function<std::vector<std::pair<Vec3, Real>>(const FeedReach&)>;
    // Releases what is owed after a step of dt ending at t; the grains near the region come
    // from `grains` (none when empty), the SPH particles from `fluid` (the rows it selects,
    // wherever the particles are).
    void apply(rigid::BodySolver& bodies, const GrainsNear& grains,
               const probes::FluidReader* fluid, Real t, Real dt);
    // The host's grains as a GrainsNear.
    static GrainsNear near_in(const dem::GrainSet& grains);

    // Sphericity of library shape k.
    Real shape_sphericity(std::size_t k) const { return shapes_[k].sphericity; }

    // A rock of equivalent diameter d centred at the origin: a library shape, stretched
    // within the sphericity bound and turned at random. Returns the mesh; `ratio` receives its
    // sphericity over the shape's.
    scenario::TriangleMesh make_rock(Real d, Real& ratio);

private:
    struct Shape {
        scenario::TriangleMesh mesh; // centroid at the origin, equivalent diameter 1
        Real sphericity;
    };

    std::vector<Shape> shapes_;
    int material_;
    Real density_;
    int layers_;  // SPH boundary layers of each rock
    Real sph_dp_; // 0 without a fluid (no SPH shell)
};

} // namespace debrisflow::flow
