// Grains: sizes, packing, settling and saved states; contact history across neighbour
// rebuilds and reordering; walls made of triangles push once; moving walls; input errors.
#include "debrisflow/core/error.hpp"
#include "debrisflow/dem/law_overlap.hpp"
#include "debrisflow/dem/materials.hpp"
#include "dem_rig.hpp"
#include "run_case.hpp"
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>

using namespace debrisflow;

namespace {

std::string grains_case(const std::string& grains, const std::string& extra = "") {
    return R"(dimensions = 3
[time]
end = 0.01
[output]
vtk = false
[domain]
min = [-0.01, -0.01, -0.01]
max = [0.11, 0.11, 0.3]
[[material]]
name = "glass"
density = 2500
kn = 1e5
restitution = 0.5
friction = 0.5
[[wall]]
name = "tank"
shape = "open_tank"
min = [0, 0, 0]
max = [0.1, 0.1, 0.3]
)" + grains +
           extra;
}

std::string error_of(const std::string& toml) {
    return test::input_error_of("dem_errors", toml);
}

// Smallest gap between any two grains: negative where they overlap.
Real smallest_gap(const dem::GrainSet& g) {
    Real gap = 1e30;
    for (Index i = 0; i < g.size(); ++i)
        for (Index j = i + 1; j < g.size(); ++j) {
            const std::size_t a = std::size_t(i), b = std::size_t(j);
            const Real dx = g.pos[a].x - g.pos[b].x, dy = g.pos[a].y - g.pos[b].y,
                       dz = g.pos[a].z - g.pos[b].z;
            gap = std::min(gap, std::sqrt(dx * dx + dy * dy + dz * dz) - g.radius[a] - g.radius[b]);
        }
    return gap;
}

} // namespace

// Random insertion places the requested count without overlaps; a log-normal sample has its
// median at d50 (3 % for 2000 grains) and respects the cut-offs.
TEST(DemGrains, RandomInsertionLognormalSizesDoNotOverlap) {
    app::Simulation sim(test::case_from_toml("dem_random", grains_case(R"([[grains]]
name = "pile"
material = "glass"
count = 2000
size = { distribution = "lognormal", d50 = 0.004, sigma = 0.2, min = 0.003, max = 0.006 }
region = { shape = "box", min = [0, 0, 0], max = [0.1, 0.1, 0.25] }
)")));
    const auto& g = sim.grains().grains();
    ASSERT_EQ(g.size(), 2000);
    std::vector<Real> d;
    for (Index i = 0; i < g.size(); ++i) d.push_back(2 * g.radius[std::size_t(i)]);
    std::sort(d.begin(), d.end());
    EXPECT_NEAR(d[1000] / 0.004, 1, 0.03);
    EXPECT_GE(d.front(), 0.003);
    EXPECT_LE(d.back(), 0.006);
    EXPECT_GE(smallest_gap(g), -1e-12);
}

// A wide gradation built in two blocks, coarse first: the fine block's random insertion fills
// the room the coarse grains leave, without touching them, and its own sizes (2 mm to 12 mm;
// five size classes of the insertion grid with the coarse grains) do not overlap either.
TEST(DemGrains, RandomBlockFillsAroundEarlierBlocks) {
    app::Simulation sim(test::case_from_toml("dem_two_blocks", grains_case(R"([[grains]]
name = "coarse"
material = "glass"
count = 40
seed = 3
diameter = 0.02
region = { shape = "box", min = [0, 0, 0], max = [0.1, 0.1, 0.25] }
[[grains]]
name = "fine"
material = "glass"
count = 6000
seed = 5
size = { distribution = "lognormal", d50 = 0.003, sigma = 0.4, min = 0.002, max = 0.012 }
region = { shape = "box", min = [0, 0, 0], max = [0.1, 0.1, 0.25] }
)")));
    const auto& g = sim.grains().grains();
    ASSERT_EQ(g.size(), 6040);
    EXPECT_GE(smallest_gap(g), -1e-12);
}

// A lattice laid over grains of an earlier block is refused, naming the block and a grain.
TEST(DemGrains, LatticeOverEarlierBlockIsRefused) {
    const std::string e = error_of(grains_case(R"([[grains]]
name = "loose"
material = "glass"
count = 200
diameter = 0.005
region = { shape = "box", min = [0, 0, 0], max = [0.1, 0.1, 0.1] }
[[grains]]
name = "stack"
packing = "lattice"
material = "glass"
diameter = 0.005
region = { shape = "box", min = [0, 0, 0], max = [0.1, 0.1, 0.1] }
)"));
    EXPECT_NE(e.find("grains 'stack': the grain of diameter 0.005 m at ("), std::string::npos) << e;
    EXPECT_NE(e.find("overlaps a grain of an earlier [[grains]] block"), std::string::npos) << e;
}

// A sieve curve is mass passing: the mass fraction finer than the middle sieve size matches
// the curve (tolerance 3 % of the total for ~20 kg-scale samples of 3000 grains).
TEST(DemGrains, SieveCurveReproducesMassPassing) {
    app::Simulation sim(test::case_from_toml("dem_sieve", grains_case(R"([[grains]]
name = "pile"
material = "glass"
mass = 0.25
seed = 7
size = { distribution = "sieve", sizes = [0.002, 0.004, 0.006], passing = [0, 50, 100] }
region = { shape = "box", min = [0, 0, 0], max = [0.1, 0.1, 0.29] }
)")));
    const auto& g = sim.grains().grains();
    Real fine = 0;
    for (Index i = 0; i < g.size(); ++i)
        if (2 * g.radius[std::size_t(i)] <= 0.004) fine += g.mass[std::size_t(i)];
    EXPECT_GE(g.total_mass(), 0.25);
    EXPECT_NEAR(fine / g.total_mass(), 0.5, 0.03);
}

// Settling stops at PFC's criterion; the saved state reloads grain for grain.
TEST(DemGrains, SettlesBelowUnbalancedRatioAndReloads) {
    const std::string dir = (std::filesystem::temp_directory_path() / "dem_settle").string();
    std::filesystem::remove_all(dir);
    io::CaseSpec spec = test::case_from_toml("dem_settle", grains_case(R"([[grains]]
name = "pile"
material = "glass"
count = 300
diameter = 0.008
region = { shape = "box", min = [0, 0, 0], max = [0.1, 0.1, 0.1] }
[dem]
settle = true
)"));
    app::Simulation sim(spec);
    sim.grains().measure_contact_force(true); // for the ratio after the run
    app::RunOptions opt;
    opt.out_dir = dir;
    opt.quiet = true;
    sim.run(opt);
    ASSERT_TRUE(std::filesystem::exists(dir + "/grains_settled.csv"));
    auto reload = test::case_from_toml("dem_reload", grains_case(R"([[grains]]
name = "pile"
material = "glass"
packing = "file"
file = ")" + dir + R"(/grains_settled.csv"
)"));
    app::Simulation again(reload);
    EXPECT_EQ(again.grains().grains().size(), 300);
    EXPECT_NEAR(again.grains().grains().total_mass(), sim.grains().grains().total_mass(), 1e-12);
    // Settled: every grain rests in the lower part of the tank, at rest.
    const auto& g = again.grains().grains();
    Real top = 0, vmax = 0;
    for (Index i = 0; i < g.size(); ++i) {
        top = std::max(top, g.pos[std::size_t(i)].z);
        vmax = std::max(vmax, std::fabs(g.vel[std::size_t(i)].z));
    }
    EXPECT_LT(top, 0.06); // 300 grains of 8 mm fill ~3 layers of the 0.1 x 0.1 m floor
    EXPECT_EQ(vmax, 0);
    EXPECT_LT(sim.grains().unbalanced_ratio(), 0.05); // still near equilibrium after the run
    // The saved state with overrides: a region keeps the grains whose centre lies in it, a
    // velocity applies to all of them, and their material stays the file's.
    auto subset = test::case_from_toml("dem_reload_subset", grains_case(R"([[grains]]
name = "bottom"
packing = "file"
file = ")" + dir + R"(/grains_settled.csv"
velocity = [0.1, 0, 0]
region = { shape = "box", min = [-1, -1, -1], max = [1, 1, 0.006] }
)"));
    app::Simulation part(subset);
    long low = 0;
    for (Index i = 0; i < g.size(); ++i) low += g.pos[std::size_t(i)].z <= 0.006;
    const auto& b = part.grains().grains();
    EXPECT_GT(low, 0);
    EXPECT_LT(low, 300);
    EXPECT_EQ(b.size(), low);
    for (Index i = 0; i < b.size(); ++i) {
        EXPECT_EQ(b.vel[std::size_t(i)].x, 0.1);
        EXPECT_LE(b.pos[std::size_t(i)].z, 0.006);
        EXPECT_EQ(b.material[std::size_t(i)], 0);
    }
}

// Grains resting on a 20 degree incline with friction 0.5 and elastic-plastic rolling
// resistance 0.6 (> tan 20 deg, so they neither slide nor roll) are held by their tangential
// and rolling springs; were the history lost at a neighbour rebuild or a reordering, they
// would move. Rebuilds with reordering are forced every 20 steps.
TEST(DemGrains, TangentialHistorySurvivesRebuildsAndReordering) {
    test::DemRig rig;
    dem::Material m;
    m.name = "glass";
    m.density = 2500;
    m.kn = m.kt = 1e5;
    m.restitution = 0.3;
    m.friction = 0.5;
    m.rolling_friction = 0.6;
    const Real r = 0.005, th = 20 * M_PI / 180;
    for (int k = 0; k < 3; ++k) rig.add_sphere({0.05 * k, 0, r}, {}, r, m.density, 0);
    rig.add_sphere({0.05 * 3 + 2 * r, 0, r}, {}, r, m.density, 0); // touching the third
    rig.add_plane("incline", {0, 0, 0}, {0, 0, 1}, -1);
    dem::DemParams p;
    p.gravity = {9.81 * std::sin(th), 0, -9.81 * std::cos(th)};
    p.rolling = "epsd";
    rig.start(p, {m}, {-1, -1, -1}, {1, 1, 1});
    for (int s = 0; s < 5000; ++s) rig.solver->advance(rig.solver->dt()); // load the springs
    const std::vector<Vec3> x0 = rig.grains.pos;
    const std::vector<std::uint32_t> id0 = rig.grains.id;
    for (int s = 0; s < 20000; ++s) {
        rig.solver->advance(rig.solver->dt());
        if (s % 20 == 0) rig.solver->rebuild_now();
    }
    for (std::size_t a = 0; a < x0.size(); ++a) {
        const auto b = std::size_t(std::find(rig.grains.id.begin(), rig.grains.id.end(), id0[a]) -
                                   rig.grains.id.begin());
        EXPECT_NEAR(rig.grains.pos[b].x, x0[a].x, 1e-6) << "grain " << id0[a];
    }
}

// A sphere resting on the shared diagonal of a box floor (two triangles) is pushed once:
// the floor pushes through one contact, not two (the overlap is m g / k_n).
TEST(DemGrains, TriangleEdgeContactCountedOnce) {
    app::Simulation sim(test::case_from_toml("dem_edge", grains_case(R"([[grains]]
name = "one"
material = "glass"
packing = "single"
diameter = 0.01
position = [0.05, 0.05, 0.005]
)")));
    app::RunOptions opt;
    opt.quiet = true;
    sim.run(opt);
    // At rest the floor carries the weight whatever the contact count; the overlap shows how
    // many springs carry it: m g / k_n for one contact.
    const auto& g = sim.grains().grains();
    const Real overlap = g.radius[0] - g.pos[0].z, one_spring = g.mass[0] * 9.81 / 1e5;
    EXPECT_NEAR(overlap / one_spring, 1, 0.02);
}

// A wall moving at 0.2 m/s carries a grain resting on it (friction), and the grain's vertical
// velocity follows a floor moving up.
TEST(DemGrains, MovingWallCarriesGrain) {
    app::Simulation sim(test::case_from_toml("dem_moving", R"(dimensions = 3
[time]
end = 0.3
[output]
vtk = false
[domain]
min = [-0.1, -0.1, -0.1]
max = [0.2, 0.1, 0.2]
[[material]]
name = "glass"
density = 2500
kn = 1e5
restitution = 0.3
friction = 0.5
[[grains]]
name = "one"
material = "glass"
packing = "single"
diameter = 0.01
position = [0, 0, 0.005]
[[wall]]
name = "belt"
shape = "plane"
point = [0, 0, 0]
normal = [0, 0, 1]
velocity = [0.2, 0, 0.05]
)"));
    app::RunOptions opt;
    opt.quiet = true;
    sim.run(opt);
    const auto& g = sim.grains().grains();
    EXPECT_NEAR(g.vel[0].z, 0.05, 1e-3);
    // Rolling without slip on a belt: the centre moves at 2/7 of the belt speed (solid sphere).
    EXPECT_NEAR(g.vel[0].x / 0.2, 2.0 / 7.0, 0.01);
}

TEST(DemGrains, InputErrorsNameTheKey) {
    const std::string base = grains_case(R"([[grains]]
name = "pile"
material = "sand"
count = 10
diameter = 0.01
region = { shape = "box", min = [0, 0, 0], max = [0.1, 0.1, 0.1] }
)");
    const std::string e = error_of(base);
    EXPECT_NE(e.find("material"), std::string::npos) << e;
    EXPECT_NE(e.find("sand"), std::string::npos) << e;
    const std::string dt = error_of(grains_case(R"([[grains]]
name = "pile"
material = "glass"
count = 10
diameter = 0.01
region = { shape = "box", min = [0, 0, 0], max = [0.1, 0.1, 0.1] }
[dem]
dt = 1e-3
)"));
    EXPECT_NE(dt.find("exceeds the stable step"), std::string::npos) << dt;
    const std::string full = error_of(grains_case(R"([[grains]]
name = "pile"
material = "glass"
count = 100000
diameter = 0.01
region = { shape = "box", min = [0, 0, 0], max = [0.1, 0.1, 0.1] }
)"));
    EXPECT_NE(full.find("no room"), std::string::npos) << full;
}

// Mixed contact laws: a pair of materials with different laws needs a [[contact]] naming its
// law (no default would be right), and dcdem has no restitution (its damping is damping_cn).
TEST(DemGrains, MixedContactLawsNeedAContactTable) {
    const std::string pile = R"([[grains]]
name = "pile"
material = "glass"
count = 10
diameter = 0.01
region = { shape = "box", min = [0, 0, 0], max = [0.1, 0.1, 0.1] }
)";
    const std::string rock = R"([[material]]
name = "rock"
law = "dcdem"
density = 2650
youngs_modulus = 5e7
)";
    const std::string mixed = error_of(grains_case(pile + rock));
    EXPECT_NE(mixed.find("material.1.law"), std::string::npos) << mixed;
    EXPECT_NE(mixed.find("different contact laws"), std::string::npos) << mixed;
    const std::string no_e = error_of(grains_case(pile + rock + R"([[contact]]
materials = ["glass", "rock"]
law = "linear"
)"));
    EXPECT_NE(no_e.find("restitution"), std::string::npos) << no_e;
    EXPECT_NE(no_e.find("dcdem material has no restitution"), std::string::npos) << no_e;
    EXPECT_EQ(error_of(grains_case(pile + rock + R"([[contact]]
materials = ["glass", "rock"]
law = "linear"
restitution = 0.2
)")),
              "");
    const std::string dcdem_e = error_of(grains_case(pile + rock + "restitution = 0.3\n"));
    EXPECT_NE(dcdem_e.find("not a parameter of the dcdem law"), std::string::npos) << dcdem_e;
}

// An STL floor made of a fan of eight triangles around a vertex: a sphere resting exactly on
// the shared vertex, and one on a shared edge, each rest on a single contact.
TEST(DemGrains, StlWallSharedVertexAndEdgeCountedOnce) {
    const auto dir = std::filesystem::temp_directory_path() / "debrisflow_tests";
    std::filesystem::create_directories(dir);
    const auto stl = (dir / "fan.stl").string();
    {
        std::ofstream out(stl);
        out << "solid fan\n";
        const double c = 0.05, pi = 3.14159265358979;
        for (int k = 0; k < 8; ++k) {
            const double a0 = k * pi / 4, a1 = (k + 1) * pi / 4, R = 0.07;
            out << "facet normal 0 0 1\n outer loop\n";
            out << "  vertex " << c << " " << c << " 0\n";
            out << "  vertex " << c + R * std::cos(a0) << " " << c + R * std::sin(a0) << " 0\n";
            out << "  vertex " << c + R * std::cos(a1) << " " << c + R * std::sin(a1) << " 0\n";
            out << " endloop\nendfacet\n";
        }
        out << "endsolid fan\n";
    }
    for (const char* pos : {"[0.05, 0.05, 0.005]", "[0.08, 0.05, 0.005]"}) {
        app::Simulation sim(test::case_from_toml("dem_stl", std::string(R"(dimensions = 3
[time]
end = 0.05
[output]
vtk = false
[domain]
min = [-0.05, -0.05, -0.05]
max = [0.15, 0.15, 0.15]
[[material]]
name = "glass"
density = 2500
kn = 1e5
restitution = 0.5
friction = 0.5
[[grains]]
name = "one"
material = "glass"
packing = "single"
diameter = 0.01
position = )") + pos + R"(
[[wall]]
name = "fan"
shape = "stl"
file = ")" + stl + R"("
)"));
        app::RunOptions opt;
        opt.quiet = true;
        sim.run(opt);
        const auto& g = sim.grains().grains();
        const Real overlap = g.radius[0] - g.pos[0].z, one_spring = g.mass[0] * 9.81 / 1e5;
        EXPECT_NEAR(overlap / one_spring, 1, 0.02) << pos; // one contact, not several
    }
}

// A simple-cubic column of ten 10 mm spheres on the floor: the bed-load estimate of
// scenario/grain_bed_load.hpp is the floor contact's force, 10 m g, exactly (closed form:
// overlap 10 m g / k_n, linear law, floor of the grains' material), and the column, left to
// come to rest, sits on the floor at that overlap (tolerance 1 %: the column's residual
// oscillation after 0.3 s). A column ten times softer than the refusal's 10 % of the radius is
// refused with the stiffness that keeps it at 1 %.
TEST(DemGrains, BedOverlapEstimateIsTheRestingColumnsOverlap) {
    const std::string column = R"([[grains]]
name = "column"
packing = "lattice"
material = "glass"
diameter = 0.01
region = { shape = "box", min = [0, 0, 0], max = [0.0101, 0.0101, 0.1001] }
)";
    const std::string dir = (std::filesystem::temp_directory_path() / "dem_bed_column").string();
    std::filesystem::remove_all(dir);
    io::CaseSpec spec = test::case_from_toml("dem_bed_column", grains_case(column),
                                             {"time.end=0.3", "material.0.restitution=0.1"});
    app::Simulation sim(spec);
    const auto& g = sim.grains().grains();
    ASSERT_EQ(g.size(), 10);
    const Real pi = 3.14159265358979323846, r = 0.005;
    const Real m = 2500 * 4 / 3.0 * pi * r * r * r, k = 1e5;
    const Real expected = 10 * m * 9.81 / k; // 1.284e-6 m
    EXPECT_NEAR(sim.bed_overlap().force, 10 * m * 9.81, 1e-12);
    EXPECT_NEAR(sim.bed_overlap().overlap, expected, 1e-9 * expected);
    EXPECT_NE(sim.bed_overlap().where.find("glass-"), std::string::npos);
    app::RunOptions opt;
    opt.out_dir = dir;
    opt.quiet = true;
    sim.run(opt);
    Real bottom = 1;
    for (Index i = 0; i < g.size(); ++i) bottom = std::min(bottom, g.pos[std::size_t(i)].z);
    EXPECT_NEAR(r - bottom, expected, 0.01 * expected) << "floor overlap at rest";

    // k_n = 1 N/m: 10 m g / k_n = 0.128 m, 26 radii; 1 % of r needs 10 m g / 5e-5 = 2.57e3.
    const std::string e = error_of(grains_case(column) + "\n");
    EXPECT_EQ(e, "");
    io::CaseSpec soft =
        test::case_from_toml("dem_bed_soft", grains_case(column), {"material.0.kn=1"});
    try {
        app::Simulation refused(soft);
        ADD_FAILURE() << "a column sinking 26 radii into its contacts was accepted";
    } catch (const InputError& x) {
        const std::string w = x.what();
        EXPECT_NE(w.find("too soft to rest on their contacts"), std::string::npos) << w;
        EXPECT_NE(w.find("'material.0.kn' = 1 to about 2.57e+03 for 1 %"), std::string::npos) << w;
    }
}

// The law-generic overlaps of dem/law_overlap.hpp (used by the checks of a case's stiffness)
// against the closed forms: linear, F = k delta and an impact's largest overlap v sqrt(m/k);
// Hertz (Johnson 1985, eqs. 4.23 and 11.23 undamped), delta = (3 F / (4 E* sqrt(R)))^(2/3) and
// delta_max = (15 m v^2 / (16 E* sqrt(R)))^(2/5). Tolerance 1e-6 relative (Simpson's rule on
// Hertz's delta^1.5: 1e-5 of the work, a fifth of that in the overlap).
TEST(DemLawOverlap, StaticAndImpactOverlapsMatchClosedForms) {
    dem::Material linear;
    linear.name = "a";
    linear.kn = 2e5;
    linear.kt = 2e5;
    dem::Material hertz;
    hertz.name = "b";
    hertz.law = "hertz_mindlin";
    hertz.youngs_modulus = 5e7;
    hertz.poisson = 0.3;
    const auto table = dem::build_pair_table({linear, hertz}, {}, "none");
    const dem::PairParams &lin = table[0], &hm = table[3];
    const Real r = 0.005, m = 1.4e-3, v = 3, force = 0.2;
    EXPECT_NEAR(dem::overlap_carrying(lin, r, force, 2 * r), force / 2e5, 1e-12 * r);
    EXPECT_NEAR(dem::overlap_absorbing(lin, r, 0.5 * m * v * v, 2 * r), v * std::sqrt(m / 2e5),
                1e-6 * v * std::sqrt(m / 2e5));
    const Real e_star = 5e7 / (2 * (1 - 0.09));
    const Real hertz_static = std::pow(3 * force / (4 * e_star * std::sqrt(r)), 2.0 / 3);
    const Real hertz_impact = std::pow(15 * m * v * v / (16 * e_star * std::sqrt(r)), 0.4);
    EXPECT_NEAR(dem::overlap_carrying(hm, r, force, 2 * r), hertz_static, 1e-9 * hertz_static);
    EXPECT_NEAR(dem::overlap_absorbing(hm, r, 0.5 * m * v * v, 2 * r), hertz_impact,
                1e-6 * hertz_impact);
    // beyond the search range: the range's end
    EXPECT_EQ(dem::overlap_carrying(lin, r, 1e9, 2 * r), 2 * r);
    EXPECT_EQ(dem::overlap_absorbing(lin, r, 1e9, 2 * r), 2 * r);
}
