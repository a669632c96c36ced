#pragma once
#include "debrisflow/dem/grain_set.hpp"
#include "debrisflow/flow/hydrograph.hpp"
#include "debrisflow/flow/solid_feed.hpp"
#include "debrisflow/io/case_spec.hpp"
#include "debrisflow/particles/particle_set.hpp"
#include "debrisflow/scenario/size_sampler.hpp"
#include "debrisflow/scenario/stl_mesh.hpp"

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

    // Releases what is owed after a step of dt ending at t.
    void apply(rigid::BodySolver& bodies, const dem::GrainSet* grains,
               const particles::ParticleSet* fluid, Real t, Real dt);

    const std::string& name() const override { return spec_.name; }
    Real discharge(Real t) const override { return q_.at(t); }
    Real volume_in() const override { return volume_in_; }
    Real mass_in() const override { return mass_in_; }
    Real owed() const override { return owed_; }
    long pieces_in() const override { return count_; }
    // Sphericity of library shape k, and the extremes of the rocks released (ratio to their
    // shape's sphericity).
    Real shape_sphericity(std::size_t k) const { return shapes_[k].sphericity; }
    Real ratio_min() const { return ratio_min_; }
    Real ratio_max() const { return ratio_max_; }

    // A rock of equivalent diameter d centred at the origin: a library shape, stretched
    // within the sphericity bound and turned at random. Returns the mesh; `ratio` receives its
    // sphericity over the shape's.
    scenario::TriangleMesh make_rock(Real d, Real& ratio);

private:
    struct Shape {
        scenario::TriangleMesh mesh; // centroid at the origin, equivalent diameter 1
        Real sphericity;
    };

    io::FeedSpec spec_;
    const io::CaseSpec& case_;
    Hydrograph q_;
    scenario::SizeSampler sizes_;
    std::vector<Shape> shapes_;
    Real density_;
    Real next_d_;
    Real owed_ = 0, volume_in_ = 0, mass_in_ = 0;
    Real ratio_min_ = 1, ratio_max_ = 1;
    long count_ = 0;
};

} // namespace debrisflow::flow
