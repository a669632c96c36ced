// Rigid-body phase throughput: 1,000 boxes (0.1 m, contact sample spacing 0.05 m: 26 samples
// each) resting side by side on a floor plane, gravity on; a step evaluates 4,000
// smooth corner-floor contacts and the distributed body-body sample contacts.
// Counters: body-steps/s and contacts/s.
#include "debrisflow/dem/materials.hpp"
#include "debrisflow/rigid/body_solver.hpp"
#include "debrisflow/scenario/body_geometry.hpp"
#include <benchmark/benchmark.h>
#include <memory>

using namespace debrisflow;

namespace {

std::unique_ptr<rigid::BodySolver> make_boxes(int per_side, dem::WallSet& walls) {
    io::CaseSpec c;
    c.dim = 3;
    c.rigid.contact_spacing = 0.05;
    std::vector<dem::Material> mats(1);
    mats[0].name = "rock";
    mats[0].law = "hertz_mindlin";
    mats[0].youngs_modulus = 1e9;
    mats[0].poisson = 0.25;
    mats[0].density = 2650;
    std::vector<rigid::BodyState> bodies;
    std::vector<rigid::BodyModel> models;
    for (int i = 0; i < per_side; ++i)
        for (int j = 0; j < per_side; ++j) {
            io::BodySpec b;
            b.name = "b";
            b.shape.type = "box";
            b.shape.min = {0.11 * i, 0.11 * j, -1e-5};
            b.shape.max = {0.11 * i + 0.1, 0.11 * j + 0.1, 0.1 - 1e-5};
            auto built = scenario::build_body(b, c, 2650, 0, 0);
            bodies.push_back(built.state);
            models.push_back(built.model);
        }
    dem::Wall floor;
    floor.name = "floor";
    walls.add(floor,
              {dem::WallPrimitive{{0, 0, 0}, {}, {}, {0, 0, 1}, dem::PrimitiveType::plane, 0}});
    rigid::RigidParams p;
    p.domain.lo = {-10, -10, -10};
    p.domain.hi = {10, 10, 10};
    return std::make_unique<rigid::BodySolver>(
        p, bodies, models, rigid::JointSet{},
        rigid::BodyContacts(dem::build_pair_table(mats, {}, "none"), 1), &walls);
}

void BM_RigidBoxesOnFloor(benchmark::State& state) {
    dem::WallSet walls;
    auto solver = make_boxes(int(state.range(0)), walls);
    solver->compute_forces();
    const Real dt = 1e-5;
    long contacts = 0;
    for (auto _ : state) {
        solver->step(dt);
        contacts += solver->contacts();
    }
    const double n = double(solver->bodies().size());
    state.counters["body_steps_per_s"] =
        benchmark::Counter(n * double(state.iterations()), benchmark::Counter::kIsRate);
    state.counters["contacts_per_s"] =
        benchmark::Counter(double(contacts), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_RigidBoxesOnFloor)->Arg(10)->Arg(32)->Unit(benchmark::kMillisecond)->UseRealTime();

} // namespace

BENCHMARK_MAIN();
