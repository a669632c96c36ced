#pragma once
// Rigid bodies assembled directly (no case file) for dynamics tests.
#include "debrisflow/dem/materials.hpp"
#include "debrisflow/rigid/body_solver.hpp"
#include "debrisflow/scenario/body_geometry.hpp"
#include <memory>

namespace debrisflow::test {

struct RigidRig {
    io::CaseSpec spec;
    std::vector<rigid::BodyState> bodies;
    std::vector<rigid::BodyModel> models;
    rigid::JointSet joints;
    std::vector<dem::Material> materials{dem::Material{}};
    dem::WallSet walls;
    std::unique_ptr<rigid::BodySolver> solver;

    explicit RigidRig(int dim = 3) {
        spec.dim = dim;
        spec.domain.lo = {-100, -100, -100};
        spec.domain.hi = {100, 100, 100};
        materials[0].name = "solid";
        materials[0].density = 1000;
        materials[0].kn = 1e6;
    }
    static io::BodySpec box(const std::string& name, Vec3 lo, Vec3 hi) {
        io::BodySpec b;
        b.name = name;
        b.shape.type = "box";
        b.shape.min = lo;
        b.shape.max = hi;
        return b;
    }
    static io::BodySpec sphere(const std::string& name, Vec3 c, Real r) {
        io::BodySpec b;
        b.name = name;
        b.shape.type = "sphere";
        b.shape.center = c;
        b.shape.radius = r;
        return b;
    }
    int add(const io::BodySpec& b, Real density) {
        auto built = scenario::build_body(b, spec, density, 0, 0);
        bodies.push_back(built.state);
        models.push_back(built.model);
        return int(bodies.size()) - 1;
    }
    void start(Vec3 gravity, Real dt = 0) {
        rigid::RigidParams p;
        p.gravity = gravity;
        p.dt = dt;
        p.dim = spec.dim;
        p.domain = spec.domain;
        auto table = dem::build_pair_table(materials, {}, "none");
        solver = std::make_unique<rigid::BodySolver>(
            p, bodies, models, joints, rigid::BodyContacts(std::move(table), int(materials.size())),
            walls.empty() ? nullptr : &walls);
        solver->compute_forces();
    }
    rigid::BodyState& body(int b) { return solver->bodies()[b]; }
};

} // namespace debrisflow::test
