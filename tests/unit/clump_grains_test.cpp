// Clumps of grains: the template's mass properties, how a clump is laid out in the grain set,
// random insertion without overlap, clumps leaving whole, and input errors.
#include "debrisflow/core/error.hpp"
#include "debrisflow/scenario/clump_template.hpp"
#include "run_case.hpp"
#include <cmath>
#include <gtest/gtest.h>

using namespace debrisflow;

namespace {

constexpr Real pi = 3.14159265358979323846;

std::string clump_case(const std::string& grains) {
    return R"(dimensions = 3
[time]
end = 0.002
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
)" + grains;
}

std::string error_of(const std::string& toml) {
    return test::input_error_of("clump_errors", toml);
}

} // namespace

// Two touching equal spheres: the union's volume is 2 (4/3) pi r^3, so at unit
// volume-equivalent diameter r = 16^(-1/3); principal moments per unit density
// 2 (2/5) m r^2 about the axis and 2 (2/5 m r^2 + m r^2) across it (m = (4/3) pi r^3).
// Lattice integration of the union: 1 % (as for [[body]] clumps); lengths are scaled by the
// integrated volume, so they carry a third of its error (0.34 %).
TEST(ClumpGrains, TemplateOfTwoTouchingSpheres) {
    io::CaseSpec c = test::case_from_toml("clump_template", clump_case(R"([[grains]]
name = "dimers"
material = "glass"
packing = "single"
position = [0.05, 0.05, 0.05]
diameter = 0.01
clump = [[-1, 0, 0, 1], [1, 0, 0, 1]]
)"));
    const auto t = scenario::ClumpTemplate::from(c.dem.grains[0], c);
    const Real r = std::cbrt(1.0 / 16), m = 4.0 / 3 * pi * r * r * r;
    EXPECT_NEAR(t.volume / (2 * m), 1, 0.01);
    ASSERT_EQ(t.radii.size(), 2u);
    EXPECT_NEAR(t.radii[0] / r, 1, 0.0034);
    EXPECT_NEAR(norm(t.centers[0] - t.centers[1]) / (2 * r), 1, 0.0034);
    EXPECT_NEAR(t.radii[0] / t.radii[1], 1, 1e-12);
    EXPECT_NEAR(norm(t.centers[0] + t.centers[1]), 0, 0.01 * r); // centre of mass between
    const Real axial = 2 * 0.4 * m * r * r, across = 2 * (0.4 * m * r * r + m * r * r);
    std::vector<Real> moments = {t.inertia.x, t.inertia.y, t.inertia.z};
    std::sort(moments.begin(), moments.end());
    EXPECT_NEAR(moments[0] / axial, 1, 0.01);
    EXPECT_NEAR(moments[1] / across, 1, 0.01);
    EXPECT_NEAR(moments[2] / across, 1, 0.01);
    EXPECT_NEAR(t.reach / (2 * r), 1, 0.0034);
}

// A clump in the grain set: its members' masses sum to rho V d^3, they sit at the scaled
// offsets from its centre of mass, they move with it (v + w x lever), and random insertion
// keeps the clumps' bounding spheres apart.
TEST(ClumpGrains, MembersCarryTheMassAndMoveWithTheClump) {
    app::Simulation sim(test::case_from_toml("clump_members", clump_case(R"([[grains]]
name = "dimers"
material = "glass"
count = 200
diameter = 0.006
seed = 4
clump = [[-1, 0, 0, 1], [1, 0, 0, 1]]
velocity = [0.1, 0, 0]
angular_velocity = [0, 0, 5]
region = { shape = "box", min = [0, 0, 0], max = [0.1, 0.1, 0.25] }
)")));
    const auto& g = sim.grains().grains();
    const auto& cl = g.clumps;
    ASSERT_EQ(cl.size(), 200);
    ASSERT_EQ(g.size(), 400);
    const Real v_eq = pi / 6 * 0.006 * 0.006 * 0.006;
    EXPECT_NEAR(cl.mass[0] / (2500 * v_eq), 1, 1e-12);
    EXPECT_NEAR(g.total_mass() / cl.total_mass(), 1, 1e-12);
    std::vector<Index> where(g.next_id());
    for (Index i = 0; i < g.size(); ++i) where[g.id[std::size_t(i)]] = i;
    Real closest = 1e9;
    for (Index c = 0; c < cl.size(); ++c) {
        const std::size_t k = std::size_t(c);
        const Vec3 w = cl.spin(c);
        EXPECT_NEAR(norm(w - Vec3{0, 0, 5}), 0, 1e-9);
        for (std::size_t m = cl.first[k]; m < cl.first[k + 1]; ++m) {
            const std::size_t i = std::size_t(where[cl.member_id[m]]);
            const Vec3 lever = g.pos[i] - cl.pos[k];
            EXPECT_NEAR(norm(lever), norm(cl.offset[m]), 1e-12);
            EXPECT_NEAR(norm(g.vel[i] - (cl.vel[k] + cross(w, lever))), 0, 1e-9);
        }
        for (Index d = c + 1; d < cl.size(); ++d)
            closest = std::min(closest, norm(cl.pos[k] - cl.pos[std::size_t(d)]));
    }
    // bounding radius of each clump: 2 r at unit size (0.34 % as above)
    const Real reach = 0.006 * std::cbrt(1.0 / 16) * 2;
    EXPECT_GE(closest, 2 * reach * (1 - 0.0034));
}

TEST(ClumpGrains, InputErrorsNameTheKey) {
    auto block = [](const std::string& extra) {
        return clump_case("[[grains]]\nname = \"c\"\nmaterial = \"glass\"\ncount = 10\n"
                          "diameter = 0.006\nregion = { shape = \"box\", min = [0, 0, 0], max = "
                          "[0.1, 0.1, 0.25] }\n" +
                          extra);
    };
    EXPECT_NE(error_of(block("clump = [[0, 0, 0, 1]]\n")).find("key 'grains.0.clump'"),
              std::string::npos);
    EXPECT_NE(error_of(block("clump = [[0, 0, 0, 1], [1, 0, 0, 0]]\n")).find("must be > 0"),
              std::string::npos);
    EXPECT_NE(error_of(block("clump = [[0, 0, 0, 1], [1, 0, 0]]\n")).find("4 numbers"),
              std::string::npos);
    EXPECT_NE(error_of(block("clump = [[0, 0, 0, 1], [1, 0, 0, 1]]\norientation = \"up\"\n"))
                  .find("key 'grains.0.orientation'"),
              std::string::npos);
    const std::string file = clump_case("[[grains]]\nname = \"c\"\npacking = \"file\"\nfile = "
                                        "\"x.csv\"\nclump = [[0, 0, 0, 1], [1, 0, 0, 1]]\n");
    EXPECT_NE(error_of(file).find("spheres only"), std::string::npos) << error_of(file);
}
