// The DEM time loop with the device's contact layout (`dem.contact_pass = "slots"`: one
// evaluation per candidate slot into a buffer, then each grain gathers its own slots and, by a
// reverse index, the reactions of the slots naming it as partner) run on the host against the
// host's pass (`"ranges"`: contiguous thread ranges, Newton's third law applied at once), on
// whole cases: issue #34 asks that the device code path be exercised in CI, history included.
// The two passes add the same contact forces in another order, so they differ by round-off
// from the first step; the bound on each comparison is that round-off after the steps run,
// measured below (the largest differences seen, times about thirty).
#include "probe_difference.hpp"
#include "run_case.hpp"
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <map>
#include <utility>

using namespace debrisflow;

namespace {

struct GrainRecord {
    Vec3 x, v, w, f;
};

struct State {
    std::map<std::uint32_t, GrainRecord> grains;
    // tangential spring of each contact slot, by the pair's persistent ids
    std::map<std::pair<std::uint32_t, std::uint32_t>, Vec3> springs;
    test::ProbeHistories probes;
    long steps = 0, contacts = 0;
    double particle_steps = 0;
    flow::ExitTally left; // grains removed at the domain's faces
    long copies_to_host = -1;
    std::size_t bodies = 0; // rigid bodies still moving at the end (not removed)
};

State run(const std::string& file, std::vector<std::string> sets, const std::string& pass,
          Real until, const std::string& backend = "host") {
    sets.push_back(fmt::format("dem.contact_pass=\"{}\"", pass));
    sets.push_back(fmt::format("exec.backend=\"{}\"", backend));
    // a case of the repository, or one a test wrote (an absolute path)
    const std::string path =
        file.front() == '/' ? file : std::string(DEBRISFLOW_SOURCE_DIR) + "/" + file;
    app::Simulation sim(io::read_case(path, sets));
    const auto report = sim.run({"", true, 0, until});
    State s;
    s.steps = report.result.steps;
    s.particle_steps = report.particle_steps;
    s.left = report.grain_exit;
    s.copies_to_host = report.dem_copies_to_host;
    if (sim.has_bodies())
        for (const auto& b : sim.bodies().bodies()) s.bodies += b.motion != rigid::Motion::removed;
    auto& dem = sim.grains();
    s.contacts = dem.contacts();
    const auto& g = dem.grains();
    for (Index i = 0; i < g.size(); ++i) {
        const auto k = std::size_t(i);
        s.grains[g.id[k]] = {g.pos[k], g.vel[k], g.spin[k], g.force[k]};
    }
    const dem::GrainContactInputs in = dem.grain_contact_inputs();
    for (Index i = 0; i < in.n; ++i)
        for (Index k = 0; k < in.count[i]; ++k) {
            const std::size_t slot = std::size_t(i) * std::size_t(in.capacity) + std::size_t(k);
            s.springs[{g.id[std::size_t(i)], g.id[std::size_t(in.partner[slot])]}] = in.xi[slot];
        }
    for (const auto& pr : sim.probes()) s.probes.push_back(pr->history());
    return s;
}

// Largest differences: positions in grain diameters, velocities, spins, forces and springs
// against the largest of each in the run, probe samples against each column's largest value.
struct Diff {
    double x = 0, v = 0, w = 0, f = 0, spring = 0, probe = 0;
};

double largest(const State& s, Vec3 GrainRecord::*m) {
    double out = 0;
    for (const auto& [id, r] : s.grains) out = std::max(out, double(norm(r.*m)));
    return out;
}

Diff compare(const State& a, const State& b, double d) {
    Diff out;
    const double vmax = largest(a, &GrainRecord::v), wmax = largest(a, &GrainRecord::w),
                 fmax = largest(a, &GrainRecord::f);
    for (const auto& [id, r] : a.grains) {
        const GrainRecord& t = b.grains.at(id);
        out.x = std::max(out.x, double(norm(r.x - t.x)) / d);
        out.v = std::max(out.v, double(norm(r.v - t.v)) / vmax);
        out.w = std::max(out.w, double(norm(r.w - t.w)) / wmax);
        out.f = std::max(out.f, double(norm(r.f - t.f)) / fmax);
    }
    double smax = 0;
    for (const auto& [key, xi] : a.springs) smax = std::max(smax, double(norm(xi)));
    // A pair that is a candidate in one run only (the lists were built from positions that
    // differ by round-off, and it lies at the edge of the skin) has no spring in the other.
    const auto spring_of = [](const State& s, const auto& key) {
        const auto it = s.springs.find(key);
        return it == s.springs.end() ? Vec3{} : it->second;
    };
    for (const auto& [key, xi] : a.springs)
        out.spring = std::max(out.spring, double(norm(xi - spring_of(b, key))) / smax);
    for (const auto& [key, xi] : b.springs)
        out.spring = std::max(out.spring, double(norm(xi - spring_of(a, key))) / smax);
    out.probe = test::probe_difference(a.probes, b.probes);
    return out;
}

void check(const std::string& file, const std::vector<std::string>& sets, Real until, double d,
           Diff bound, bool touching_at_end = true) {
    const State ranges = run(file, sets, "ranges", until);
    const State slots = run(file, sets, "slots", until);
    ASSERT_EQ(ranges.steps, slots.steps);
    ASSERT_EQ(ranges.grains.size(), slots.grains.size());
    if (touching_at_end) {
        ASSERT_GT(ranges.contacts, 0);
    }
    ASSERT_EQ(ranges.probes.size(), slots.probes.size());
    for (std::size_t k = 0; k < ranges.probes.size(); ++k)
        ASSERT_EQ(ranges.probes[k].size(), slots.probes[k].size());
    const Diff x = compare(ranges, slots, d);
    std::cout << fmt::format("{}: {} steps, {} grains, {} contacts; largest differences: position "
                             "{:.2e} d, velocity {:.2e}, spin {:.2e}, force {:.2e}, spring {:.2e} "
                             "of their largest values, probes {:.2e}\n",
                             file, ranges.steps, ranges.grains.size(), ranges.contacts, x.x, x.v,
                             x.w, x.f, x.spring, x.probe);
    EXPECT_LE(x.x, bound.x);
    EXPECT_LE(x.v, bound.v);
    EXPECT_LE(x.w, bound.w);
    EXPECT_LE(x.f, bound.f);
    EXPECT_LE(x.spring, bound.spring);
    EXPECT_LE(x.probe, bound.probe);
}

// The resident DEM loop (exec.backend = "host_resident": grains and slots in the backend's
// memory, every step through exec/'s primitives, dem/resident_dem.hpp) against the host's loop
// in the same contact layout ("slots"): the same functors in the same order per grain, and the
// walls' and bodies' loads split over the threads alike, so grains, springs, contacts, bodies
// and probes agree bitwise.
void check_same(const State& host, const State& resident, const std::string& file, double d) {
    ASSERT_EQ(host.steps, resident.steps);
    ASSERT_EQ(host.grains.size(), resident.grains.size());
    EXPECT_EQ(host.particle_steps, resident.particle_steps);
    EXPECT_EQ(host.left.count, resident.left.count);
    EXPECT_EQ(host.left.mass, resident.left.mass);
    EXPECT_EQ(host.bodies, resident.bodies);
    ASSERT_GT(host.contacts, 0);
    EXPECT_EQ(host.contacts, resident.contacts);
    ASSERT_EQ(host.probes.size(), resident.probes.size());
    for (std::size_t k = 0; k < host.probes.size(); ++k)
        ASSERT_EQ(host.probes[k].size(), resident.probes[k].size());
    ASSERT_EQ(host.springs.size(), resident.springs.size());
    const Diff x = compare(host, resident, d);
    std::cout << fmt::format("{} (resident): {} steps, {} grains, {} contacts; largest "
                             "differences: position {:.2e} d, velocity {:.2e}, spin {:.2e}, force "
                             "{:.2e}, spring {:.2e}, probes {:.2e}\n",
                             file, host.steps, host.grains.size(), host.contacts, x.x, x.v, x.w,
                             x.f, x.spring, x.probe);
    EXPECT_EQ(x.x, 0);
    EXPECT_EQ(x.v, 0);
    EXPECT_EQ(x.w, 0);
    EXPECT_EQ(x.f, 0);
    EXPECT_EQ(x.spring, 0);
    EXPECT_EQ(x.probe, 0);
}

State check_resident(const std::string& file, const std::vector<std::string>& sets, Real until,
                     double d, std::size_t* grains_at_end = nullptr) {
    const State host = run(file, sets, "slots", until);
    State resident = run(file, sets, "slots", until, "host_resident");
    if (grains_at_end) *grains_at_end = resident.grains.size();
    check_same(host, resident, file, d);
    return resident;
}

} // namespace

// Bounds: round-off, measured when the test was written (2026-12-04, 2 threads): positions,
// velocities and forces at most 1e-12 of their scales (the slit dam at 0.07 s), spins 2e-10
// and springs 9e-10 of the largest in the box of 100,000 grains at rest (where both are
// themselves round-off). A contact term that differed between the passes (a reaction missed,
// a torque on the wrong grain, a spring not carried) would show at 1e-3 or more. The runs stop
// before collisions amplify the round-off chaotically, as between any two summation orders of
// a granular flow: the reduced flume differs by 1e-16 at 0.06 s, 2e-7 at 0.07 s and 1e-2 d at
// 0.08 s; the slit dam by 1e-13 d at 0.07 s and 6e-11 d at 0.1 s.
const Diff round_off{1e-10, 1e-10, 1e-8, 1e-10, 3e-8, 1e-10};

// 100,000 touching spheres in an open box (linear law, k = 1e8 N/m): every grain in contact.
TEST(DemDevicePath, Box100k) {
    check("cases/bench/box100k.toml", {"time.end=2e-5"}, 2e-5, 0.01, round_off);
}
// The reduced section-E flume, 115,000 steps: the release, the run along the bed and side
// walls (walls in the per-grain pass, springs that slide).
TEST(DemDevicePath, ReducedFlume) {
    check("cases/flume/flume30_reduced.toml", {"time.end=0.05"}, 0.05, 0.01, round_off);
}
// The two-level slit dam, type A (Hertz-Mindlin, 12,393 grains on two threads), released from
// its packing without settling: the first grains land.
TEST(DemDevicePath, SlitDamTypeA) {
    check("cases/papers/slit_dam_dem/typeA.toml", {"dem.settle=false", "time.end=0.07"}, 0.07, 0.01,
          round_off);
}

// Every part of the per-grain pass (dem/grain_own_pass_k.hpp) in the device's layout, whose
// reactions are kept per slot and summed per wall and per body afterwards: 300 spheres and 60
// two-sphere clumps fall onto a free steel block and a floor box between four plane walls; the
// floor keeps its contact loads for a pressure map. The two passes agree bitwise to 0.21 s; at
// 0.23 s (12,956 steps, 170 contacts) by 3e-12 d in position and 6e-12 in force (2026-12-05),
// at 0.25 s already by 2e-9 in force as the pack's collisions amplify the round-off.
TEST(DemDevicePath, GrainsAndClumpsOnABodyAndAMappedFloor) {
    check("cases/validation/grains_on_body_floor.toml", {"output.vtk=false"}, 0.23, 0.01,
          round_off);
}
// The fluid's load on a grain (unresolved SPH-DEM: held force, drag, impulse for the fluid's
// reaction): one nylon sphere settling in oil.
TEST(DemDevicePath, GrainSettlingInAFluid) {
    check("cases/coupling/settling_grain.toml", {"output.vtk=false"}, 0.1, 0.01, round_off, false);
}
// Nodal triangles (DEM-FEM): 27 rock spheres dropped on an elastic plate fixed at its base; the
// contacts move with the corners' blended velocities and hand the plate their impulse by the
// barycentric weights (summed per slot in the device's layout).
std::string plate_case() {
    return test::write_temp_case("grains_on_plate", R"(
name = "grains_on_plate"
dimensions = 3
[time]
end = 0.02
[domain]
min = [-0.1, -0.1, -0.1]
max = [0.5, 0.5, 0.6]
[[material]]
name = "rock"
law = "hertz_mindlin"
density = 2650
youngs_modulus = 1e8
poisson = 0.3
restitution = 0.5
friction = 0.4
[[grains]]
name = "rocks"
material = "rock"
packing = "lattice"
diameter = 0.04
gap = 0.2
region = { shape = "box", min = [0.12, 0.12, 0.21], max = [0.28, 0.28, 0.37] }
velocity = [0.2, 0.1, -1]
[fem]
cfl = 0.9
[[fem_material]]
name = "soft"
model = "linear_elastic"
density = 1000
youngs_modulus = 5e6
poisson = 0.3
[[solid]]
name = "plate"
material = "soft"
dem_material = "rock"
mesh = "box"
element = "hex8"
min = [0, 0, 0]
max = [0.4, 0.4, 0.2]
divisions = [4, 4, 2]
fixed = ["zmin"]
[[probe]]
name = "load"
type = "fem_force"
every = 2e-4
)");
}
TEST(DemDevicePath, GrainsOnAnElasticPlate) {
    check(plate_case(), {}, 0.02, 0.01, round_off);
}

// The resident loop on the cases issue #34 names: box100k (short), the reduced flume (walls,
// reordering, neighbour rebuilds with carried springs) and the type-A slit dam (Hertz-Mindlin).
TEST(DemResident, Box100k) {
    check_resident("cases/bench/box100k.toml", {"time.end=2e-5"}, 2e-5, 0.01);
}
// Its probes (flow section, kinetic energy, run-up, mass flux, wall forces) are evaluated where
// the grains are and bring back their few numbers, or the section's rows (GrainReader): the
// grains are copied to the host once, at the end.
TEST(DemResident, ReducedFlume) {
    const State resident =
        check_resident("cases/flume/flume30_reduced.toml", {"time.end=0.05"}, 0.05, 0.01);
    EXPECT_EQ(resident.copies_to_host, 1);
}
TEST(DemResident, SlitDamTypeA) {
    check_resident("cases/papers/slit_dam_dem/typeA.toml", {"dem.settle=false", "time.end=0.07"},
                   0.07, 0.01);
}
// Discs with the elastic-plastic rolling model (a rolling moment carried in each slot), settled
// on the host before the loop takes them over, then released by a gate removed at t = 0.
TEST(DemResident, ColumnCollapseWithRollingMemory) {
    check_resident("cases/deposits/column_collapse2d.toml", {"time.end=0.3", "output.vtk=false"},
                   0.3, 0.005);
}
// A moving wall (its faces uploaded after every move) pushes discs along a floor, with the
// constant-torque rolling model, out of the domain or into an outlet. Both remove grains where
// they are (stream compaction of the grains and their slot rows, then a rebuild): only the
// leavers' masses, materials and faces come to the host.
std::string pushed_off_case(const std::string& name, const std::string& extra) {
    return test::write_temp_case(name,
                                 fmt::format(R"(
name = "{name}"
dimensions = 2
[time]
end = 0.25
[output]
vtk = false
[domain]
min = [-0.02, 0, -0.02]
max = [0.2, 0, 0.2]
[dem]
thickness = 0.005
safety = 0.1
rolling = "constant_torque"
[[material]]
name = "glass"
density = 2500
kn = 1e5
restitution = 0.5
friction = 0.5
rolling_friction = 0.1
[[wall]]
name = "floor"
shape = "plane"
material = "glass"
point = [0, 0, 0]
normal = [0, 0, 1]
[[wall]]
name = "pusher"
shape = "plane"
material = "glass"
point = [0, 0, 0]
normal = [1, 0, 0]
velocity = [0.6, 0, 0]
[[grains]]
name = "heap"
material = "glass"
packing = "lattice"
diameter = 0.01
gap = 0.05
region = {{ shape = "box", min = [0.005, 0, 0], max = [0.15, 0, 0.04] }}
[[probe]]
name = "push"
type = "wall_force"
wall = "pusher"
every = 0.005
{extra})",
                                             fmt::arg("name", name), fmt::arg("extra", extra)));
}

TEST(DemResident, PushedOffTheDomainByAMovingWall) {
    const std::string file = pushed_off_case("pushed_off", R"(
[[probe]]
name = "energy"
type = "kinetic_energy"
min = [-0.02, 0, -0.02]
max = [0.2, 0, 0.2]
every = 0.005
[[probe]]
name = "left"
type = "domain_exit"
every = 0.005
[[probe]]
name = "across"
type = "mass_flux"
point = [0.1, 0, 0]
normal = [1, 0, 0]
every = 0.005
[[probe]]
name = "ahead"
type = "deposit"
min = [0.1, -0.01, -0.02]
max = [0.2, 0.01, 0.2]
every = 0.005
[[probe]]
name = "flow"
type = "section"
min = [0.05, -0.01, 0]
max = [0.15, 0.01, 0.1]
every = 0.005
[[probe]]
name = "on_pusher"
type = "runup"
wall = "pusher"
bed = -0.02
every = 0.005
)");
    std::size_t at_start = 0, at_end = 0;
    const State start = check_resident(file, {"time.end=1e-6"}, 1e-6, 0.01, &at_start);
    const State s = check_resident(file, {}, 0.25, 0.01, &at_end);
    EXPECT_LT(at_end, at_start);                         // some left, and were removed
    EXPECT_EQ(s.left.count[1], long(at_start - at_end)); // through x+
    // The grain probes sample where the grains are (GrainReader): the grains come to the host
    // once, at the end.
    EXPECT_EQ(s.copies_to_host, 1);
    // The mass flux at x = 0.1 m, counted where the grains are from each grain id's side at the
    // sample before, against the grains' own record: those that started behind the plane and
    // ended ahead of it or left through x+, less those that went the other way. Each disc is
    // rho pi r^2 thickness.
    const double disc = 2500 * 3.14159265358979 * 0.005 * 0.005 * 0.005;
    long net = 0;
    for (const auto& [id, g] : start.grains) {
        const auto it = s.grains.find(id);
        const bool ahead = it == s.grains.end() || it->second.x.x >= 0.1;
        net += g.x.x < 0.1 && ahead ? 1 : 0;
        net -= g.x.x >= 0.1 && !ahead ? 1 : 0;
    }
    ASSERT_GT(net, 0);
    const auto& across = s.probes[3].back(); // time, flux, cumulative
    EXPECT_NEAR(across[2], double(net) * disc, 1e-9 * disc);
    // The deposit ahead of the plane and the run-up on the pusher (at 0.6 m/s from x = 0; the
    // grains' tops above bed = -0.02 m, the domain's floor, within 1.05 r of it), against the same
    // record.
    long ahead_now = 0;
    double top = 0;
    const double pusher = 0.6 * s.probes[6].back()[0];
    for (const auto& [id, g] : s.grains) {
        ahead_now += g.x.x >= 0.1 && g.x.x <= 0.2 ? 1 : 0;
        if (g.x.x - pusher < 1.05 * 0.005) top = std::max(top, double(g.x.z) + 0.005 + 0.02);
    }
    EXPECT_NEAR(s.probes[4].back()[2], double(ahead_now) * disc, 1e-9 * disc); // solid_mass
    EXPECT_GT(top, 0);
    EXPECT_DOUBLE_EQ(s.probes[6].back()[1], top);
}

TEST(DemResident, PushedIntoAnOutlet) {
    const std::string file = pushed_off_case("pushed_into_outlet", R"(
[[outlet]]
name = "sink"
min = [0.185, -0.05, -0.05]
max = [0.3, 0.05, 0.3]
every = 0.005
)");
    std::size_t at_start = 0, at_end = 0;
    check_resident(file, {"time.end=1e-6"}, 1e-6, 0.01, &at_start);
    const State s = check_resident(file, {}, 0.25, 0.01, &at_end);
    EXPECT_LT(at_end, at_start);
    EXPECT_EQ(s.left.total_count(), 0); // the outlet took them first
    // no probe reads the grains in the run: the one copy to the host is the end's
    EXPECT_EQ(s.copies_to_host, 1);
}
// Spheres falling into a box onto a floor mapped by pressure panels: before each sample of the
// map the floor's contact loads of the last evaluation come back (the touching slots on the
// floor, compacted where the grains are), recorded in the host slot pass's order; the grains
// themselves are not copied for it.
// Glass spheres' material and a 0.2 m square glass box: a floor (a box wall, which a pressure
// map can read) and four side planes.
constexpr const char* glass_box = R"(
[[material]]
name = "glass"
density = 2500
kn = 2e4
restitution = 0.3
friction = 0.5
[[wall]]
name = "floor"
shape = "box"
material = "glass"
min = [0, 0, -0.05]
max = [0.2, 0.2, 0]
[[wall]]
name = "left"
shape = "plane"
material = "glass"
point = [0, 0, 0]
normal = [1, 0, 0]
[[wall]]
name = "right"
shape = "plane"
material = "glass"
point = [0.2, 0, 0]
normal = [-1, 0, 0]
[[wall]]
name = "front"
shape = "plane"
material = "glass"
point = [0, 0, 0]
normal = [0, 1, 0]
[[wall]]
name = "back"
shape = "plane"
material = "glass"
point = [0, 0.2, 0]
normal = [0, -1, 0]
)";

TEST(DemResident, PressureMapUnderFallingSpheres) {
    const std::string file = test::write_temp_case("resident_pressure_map", R"(
name = "resident_pressure_map"
dimensions = 3
[time]
end = 0.15
[output]
vtk = false
[domain]
min = [-0.01, -0.01, -0.06]
max = [0.21, 0.21, 0.3]
[dem]
safety = 0.1
)" + std::string(glass_box) + R"([[grains]]
name = "spheres"
material = "glass"
count = 300
seed = 3
diameter = 0.01
region = { shape = "box", min = [0.01, 0.01, 0.02], max = [0.19, 0.19, 0.1] }
[[probe]]
name = "map"
type = "pressure_map"
wall = "floor"
axis = "z"
normal = [0, 0, 1]
panels = [2, 2]
every = 0.005
)");
    const State s = check_resident(file, {}, 0.15, 0.01);
    // the map read loads: its panels' mean pressure is positive once the spheres land
    Real largest = 0;
    for (const auto& row : s.probes[0]) // time, then the panels' columns
        for (std::size_t k = 1; k < row.size(); ++k) largest = std::max(largest, row[k]);
    EXPECT_GT(largest, 0);
    EXPECT_EQ(s.copies_to_host, 1); // the end's
}

// Rigid bodies as obstacles (issue #34: "their obstacle spheres live on the device, the
// reaction on each body is reduced there, and the few bodies are updated on the host"): 300
// spheres fall onto a free steel block in a box. The block's contact spheres are uploaded when
// it moves, each grain's candidate spheres come from a cell grid of the spheres built where
// the grains are, and the block's load is reduced there; the block, moved on the host by that
// load, and the grains stay bitwise those of the host's loop.
TEST(DemResident, SpheresOntoAFreeBlock) {
    const std::string file = test::write_temp_case("resident_block", R"(
name = "resident_block"
dimensions = 3
[time]
end = 0.2
[output]
vtk = false
[domain]
min = [-0.01, -0.01, -0.06]
max = [0.21, 0.21, 0.4]
[dem]
safety = 0.1
)" + std::string(glass_box) + R"([[material]]
name = "steel"
density = 7800
kn = 2e5
restitution = 0.3
friction = 0.5
[[body]]
name = "block"
material = "steel"
shape = "box"
min = [0.07, 0.07, 0.0005]
max = [0.13, 0.13, 0.0605]
[rigid]
contact_spacing = 0.01
[[grains]]
name = "spheres"
material = "glass"
count = 300
seed = 3
diameter = 0.01
region = { shape = "box", min = [0.01, 0.01, 0.08], max = [0.19, 0.19, 0.16] }
[[probe]]
name = "block"
type = "body"
body = "block"
every = 0.005
)");
    const State s = check_resident(file, {}, 0.2, 0.01);
    // the block was struck: its probe's columns (time, then position, velocity, ...) moved
    const auto& rows = s.probes[0];
    ASSERT_GT(rows.size(), 2u);
    double moved = 0;
    for (std::size_t k = 1; k < rows.back().size(); ++k)
        moved = std::max(moved, std::abs(double(rows.back()[k] - rows.front()[k])));
    EXPECT_GT(moved, 0);
}

// A steel block falls through the open half of a floor into an outlet, with spheres raining
// after it, while a bed of spheres rests on the floor's other half: the outlet takes the
// grains where they are and the block on the host.
TEST(DemResident, BlockAndSpheresIntoAnOutlet) {
    const std::string file = test::write_temp_case("resident_block_outlet", R"(
name = "resident_block_outlet"
dimensions = 3
[time]
end = 0.3
[output]
vtk = false
[domain]
min = [-0.1, -0.1, -0.3]
max = [0.3, 0.3, 0.4]
[dem]
safety = 0.1
[[material]]
name = "glass"
density = 2500
kn = 2e4
restitution = 0.3
friction = 0.5
[[material]]
name = "steel"
density = 7800
kn = 2e5
restitution = 0.3
friction = 0.5
[[wall]]
name = "floor"
shape = "box"
material = "glass"
min = [-0.1, -0.1, -0.05]
max = [0.1, 0.3, 0]
[[body]]
name = "block"
material = "steel"
shape = "box"
min = [0.15, 0.05, 0.05]
max = [0.21, 0.11, 0.11]
[rigid]
contact_spacing = 0.01
[[grains]]
name = "bed"
material = "glass"
count = 150
seed = 3
diameter = 0.01
region = { shape = "box", min = [-0.08, 0.0, 0.01], max = [0.08, 0.2, 0.08] }
[[grains]]
name = "rain"
material = "glass"
count = 60
seed = 4
diameter = 0.01
region = { shape = "box", min = [0.13, 0.03, 0.13], max = [0.23, 0.13, 0.2] }
[[outlet]]
name = "sink"
min = [-0.1, -0.1, -0.3]
max = [0.3, 0.3, -0.1]
)");
    std::size_t at_end = 0;
    const State s = check_resident(file, {}, 0.3, 0.01, &at_end);
    EXPECT_EQ(s.bodies, 0u); // the block went through the outlet
    EXPECT_LT(at_end, 210u); // and spheres with it
}

// A rock feed releases mesh rocks (rigid bodies added during the run) into a box holding a bed
// of spheres, with spheres falling through the feed's region: the rocks are placed clear of the
// grains near the region, which come from where the grains are.
TEST(DemResident, RockFeedOntoABedOfSpheres) {
    const std::string src = DEBRISFLOW_SOURCE_DIR;
    const std::string file = test::write_temp_case("resident_rock_feed", fmt::format(R"(
name = "resident_rock_feed"
dimensions = 3
[time]
end = 0.3
[output]
vtk = false
[domain]
min = [-0.1, -0.1, -0.1]
max = [0.7, 0.5, 0.9]
[rigid]
dt = 1e-4
contact_spacing = 0.02
[[material]]
name = "rock"
law = "hertz_mindlin"
density = 2650
youngs_modulus = 5e7
poisson = 0.3
restitution = 0.3
friction = 0.4
[[wall]]
name = "box"
shape = "open_tank"
min = [0.0, 0.0, 0.0]
max = [0.6, 0.4, 0.8]
material = "rock"
[[grains]]
name = "bed"
material = "rock"
count = 300
seed = 3
diameter = 0.02
region = {{ shape = "box", min = [0.02, 0.02, 0.01], max = [0.58, 0.38, 0.1] }}
[[grains]]
name = "cloud"
material = "rock"
count = 40
seed = 4
diameter = 0.02
region = {{ shape = "box", min = [0.1, 0.1, 0.35], max = [0.5, 0.3, 0.7] }}
[[feed]]
name = "rocks"
material = "rock"
rocks = ["{0}/cases/shapes/rock_a.stl", "{0}/cases/shapes/rock_b.stl"]
min = [0.1, 0.1, 0.3]
max = [0.5, 0.3, 0.7]
discharge = 2e-3
size = {{ distribution = "lognormal", d50 = 0.06, sigma = 0.3, min = 0.03, max = 0.09 }}
)",
                                                                                     src));
    const State s = check_resident(file, {}, 0.3, 0.02);
    EXPECT_GT(s.bodies, 0u); // rocks were released
}

// A disc on a pendulum and a box joined by a spring fall into a bed of 150 discs (2D,
// Hertz-Mindlin): bodies with joints, body-wall and body-body contacts (on the host) and
// body-grain contacts (where the grains are).
TEST(DemResident, BodiesWithJointsIntoABedOfDiscs) {
    check_resident("tests/cli/inputs/restart_bodies_grains2d.toml", {"output.vtk=false"}, 0.2,
                   0.012);
}

// Clumps of grains (dem/clump_step_k.hpp): 200 two-disc clumps collapse from a column (2D,
// unsettled), each clump kicked, drifted and summed where the grains are; with the domain cut
// short, clumps run out through its x+ face and are removed whole on the host (a member still
// inside counted at the face its clump crossed), then the grains are taken over again.
TEST(DemResident, ClumpsCollapseAndLeaveTheDomain) {
    check_resident("cases/deposits/column_collapse2d_clumps.toml",
                   {"dem.settle=false", "time.end=0.3", "output.vtk=false"}, 0.3, 0.005);
    std::size_t at_end = 0;
    const State s = check_resident(
        "cases/deposits/column_collapse2d_clumps.toml",
        {"dem.settle=false", "time.end=0.3", "output.vtk=false", "domain.max=[0.14, 0, 0.6]"}, 0.3,
        0.005, &at_end);
    EXPECT_GT(s.left.count[1], 0);     // through x+
    EXPECT_EQ(s.left.count[1] % 2, 0); // whole clumps of two
    EXPECT_LT(at_end, 400u);
}

// Clumps and a grain feed: 100 two-disc clumps collapse while a feed drops single discs onto
// them (2D). The feed's new grains are appended where the grains are, their ids in no clump
// (the id maps widened there, as DemSolver::map_clumps widens them), and clumps and discs
// leave through the domain's cut x+ face.
TEST(DemResident, FeedOntoCollapsingClumps) {
    const std::string file = "tests/cli/inputs/clumps_feed2d.toml";
    std::size_t at_end = 0;
    const State s = check_resident(file, {}, 0.3, 0.005, &at_end);
    EXPECT_GT(at_end, 200u);       // the feed added discs to the clumps' members
    EXPECT_GT(s.left.count[1], 0); // and grains left through x+
}

// Spheres, two-sphere clumps and a free steel block onto a floor mapped by pressure panels:
// clumps, a body and a pressure map together.
TEST(DemResident, GrainsAndClumpsOnABodyAndAMappedFloor) {
    check_resident("cases/validation/grains_on_body_floor.toml", {"output.vtk=false"}, 0.23, 0.01);
}

// A hopper feed releasing grains onto baffles (structures of boxes): the grains near the
// hopper's region come to the host, where the new ones are placed clear of them, and the new
// ones are appended where the grains are.
// The same plate on the resident loop: the surface triangles' corners and the nodes'
// velocities uploaded at each evaluation, the contacts on them brought back and their impulse
// handed to the nodes in slot order (the FEM steps on the host). The plate's load (its fem_force
// probe) and its nodes' motion come out bitwise the host's.
TEST(DemResident, GrainsOnAnElasticPlate) {
    const State s = check_resident(plate_case(), {}, 0.02, 0.01);
    ASSERT_FALSE(s.probes.empty());
    double peak = 0; // |F| of the grains' load on the plate (time, fluid's 4, grains' 4, ...)
    for (const auto& row : s.probes[0]) peak = std::max(peak, row[8]);
    EXPECT_GT(peak, 0);
}

TEST(DemResident, HopperFeedOntoBaffles) {
    std::size_t at_end = 0;
    const State s = check_resident("cases/debris/baffles_hopper_dem.toml",
                                   {"time.end=0.3", "output.vtk=false"}, 0.3, 0.01, &at_end);
    EXPECT_GT(at_end, 0u);
    std::cout << "copies of the grains to the host: " << s.copies_to_host << "\n";
    // the probes that read grains sample every 0.01 s (31 times) and the end: the feed's
    // releases copy no grains
    EXPECT_LE(s.copies_to_host, 32);
}
