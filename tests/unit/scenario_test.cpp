// Particle building: shapes fill the volume they describe, STL (ASCII and binary) agree,
// walls carry their normal and depth, a gate is removed at its time.
#include "debrisflow/scenario/stl_mesh.hpp"
#include "run_case.hpp"
#include <cstdint>
#include <fmt/format.h>
#include <fstream>
#include <gtest/gtest.h>

using namespace debrisflow;

namespace {

// Unit cube [0,1]^3 scaled by `s`, outward normals, as 12 triangles.
std::vector<scenario::Triangle> cube(double s) {
    const Vec3 v[8] = {{0, 0, 0}, {s, 0, 0}, {s, s, 0}, {0, s, 0},
                       {0, 0, s}, {s, 0, s}, {s, s, s}, {0, s, s}};
    const int f[12][3] = {{0, 2, 1}, {0, 3, 2}, {4, 5, 6}, {4, 6, 7}, {0, 1, 5}, {0, 5, 4},
                          {1, 2, 6}, {1, 6, 5}, {2, 3, 7}, {2, 7, 6}, {3, 0, 4}, {3, 4, 7}};
    std::vector<scenario::Triangle> t;
    for (const auto& k : f) t.push_back({v[k[0]], v[k[1]], v[k[2]]});
    return t;
}

std::string write_ascii_stl(const std::string& path, const std::vector<scenario::Triangle>& tris) {
    std::ofstream o(path);
    o << "solid cube\n";
    for (const auto& t : tris) {
        const Vec3 n = t.normal();
        o << fmt::format("facet normal {} {} {}\n outer loop\n", n.x, n.y, n.z);
        for (const Vec3& p : {t.a, t.b, t.c})
            o << fmt::format("  vertex {} {} {}\n", p.x, p.y, p.z);
        o << " endloop\nendfacet\n";
    }
    o << "endsolid cube\n";
    return path;
}

std::string write_binary_stl(const std::string& path, const std::vector<scenario::Triangle>& tris) {
    std::ofstream o(path, std::ios::binary);
    char header[80] = {};
    o.write(header, 80);
    const std::uint32_t n = std::uint32_t(tris.size());
    o.write(reinterpret_cast<const char*>(&n), 4);
    for (const auto& t : tris) {
        const Vec3 nn = t.normal();
        const float v[12] = {float(nn.x),  float(nn.y),  float(nn.z),  float(t.a.x),
                             float(t.a.y), float(t.a.z), float(t.b.x), float(t.b.y),
                             float(t.b.z), float(t.c.x), float(t.c.y), float(t.c.z)};
        o.write(reinterpret_cast<const char*>(v), sizeof v);
        const std::uint16_t attr = 0;
        o.write(reinterpret_cast<const char*>(&attr), 2);
    }
    return path;
}

std::string base_case(int dim, const std::string& fluid, const std::string& walls = "") {
    return fmt::format(R"(dimensions = {}
dp = 0.01
[time]
end = 0.01
[output]
vtk = false
[domain]
min = [-0.2, -0.2, -0.2]
max = [0.4, 0.4, 0.4]
[sph]
c0 = 20
[[fluid]]
name = "f"
{}
{})",
                       dim, fluid, walls);
}

} // namespace

TEST(Scenario, StlAsciiAndBinaryAgreeAndFillTheCube) {
    const auto dir = std::filesystem::temp_directory_path() / "debrisflow_tests";
    std::filesystem::create_directories(dir);
    const auto a = write_ascii_stl((dir / "cube_ascii.stl").string(), cube(0.1));
    const auto b = write_binary_stl((dir / "cube_binary.stl").string(), cube(0.1));
    const auto ma = scenario::TriangleMesh::read_stl(a, 1, {});
    const auto mb = scenario::TriangleMesh::read_stl(b, 1, {});
    ASSERT_EQ(ma.triangles.size(), 12u);
    ASSERT_EQ(mb.triangles.size(), 12u);
    EXPECT_TRUE(ma.contains({0.05, 0.05, 0.05}));
    EXPECT_FALSE(ma.contains({0.15, 0.05, 0.05}));
    for (const auto& file : {a, b}) {
        app::Simulation sim(test::case_from_toml(
            "stl_fill", base_case(3, fmt::format("shape = \"stl\"\nfile = \"{}\"", file))));
        EXPECT_EQ(sim.particles().count(particles::Kind::fluid), 1000); // (0.1 / 0.01)^3
    }
}

TEST(Scenario, StlWallHasLayersBehindTheSurface) {
    const auto dir = std::filesystem::temp_directory_path() / "debrisflow_tests";
    const auto a = write_ascii_stl((dir / "cube_wall.stl").string(), cube(0.1));
    app::Simulation sim(test::case_from_toml(
        "stl_wall", base_case(3, "shape = \"box\"\nmin = [0.2, 0.2, 0.2]\nmax = [0.25, 0.25, 0.25]",
                              fmt::format("[[wall]]\nname = \"w\"\nshape = \"stl\"\nfile = "
                                          "\"{}\"\nlayers = 2\n",
                                          a))));
    const auto& s = sim.particles();
    int n = 0;
    for (Index i = 0; i < s.size(); ++i) {
        if (s.kind[i] != 1) continue;
        ++n;
        // inside the cube (behind its outward surface), depth below 2 dp
        EXPECT_GT(s.wd[i], 0);
        EXPECT_LT(s.wd[i], 0.02);
        EXPECT_GE(s.x[i], -1e-9);
        EXPECT_LE(s.x[i], 0.1 + 1e-9);
    }
    EXPECT_GT(n, 6 * 100); // two layers over six faces of 10 x 10 samples, thinned at edges
}

TEST(Scenario, CylinderVolume) {
    app::Simulation sim3(test::case_from_toml(
        "cyl3", base_case(3, "shape = \"cylinder\"\ncenter = [0, 0, 0]\naxis = [0, 0, 1]\n"
                             "radius = 0.1\nlength = 0.2")));
    const double v3 = 3.14159265358979 * 0.01 * 0.2 / 1e-6;
    EXPECT_NEAR(sim3.particles().count(particles::Kind::fluid), v3, 0.03 * v3);
    app::Simulation sim2(test::case_from_toml(
        "cyl2", base_case(2, "shape = \"cylinder\"\ncenter = [0, 0]\nradius = 0.1")));
    const double v2 = 3.14159265358979 * 0.01 / 1e-4;
    EXPECT_NEAR(sim2.particles().count(particles::Kind::fluid), v2, 0.03 * v2);
}

TEST(Scenario, PlaneAndTankWallsCarryNormalAndDepth) {
    app::Simulation sim(test::case_from_toml(
        "plane", base_case(2, "shape = \"box\"\nmin = [0, 0]\nmax = [0.1, 0.1]",
                           "[[wall]]\nname = \"floor\"\nshape = \"plane\"\npoint = [0, 0]\n"
                           "normal = [0, 1]\nlayers = 3\n")));
    const auto& s = sim.particles();
    for (Index i = 0; i < s.size(); ++i) {
        if (s.kind[i] != 1) continue;
        EXPECT_NEAR(s.wnz[i], 1, 1e-12);
        EXPECT_NEAR(s.wd[i], -s.z[i], 1e-12);
        EXPECT_LT(s.wd[i], 0.03);
    }
}

// A gate holds the column until it is removed; the front must not move before.
TEST(Scenario, GateIsRemovedAtItsTime) {
    app::Simulation sim(test::case_from_toml(
        "gate",
        base_case(2, "shape = \"box\"\nmin = [0, 0]\nmax = [0.1, 0.1]",
                  "[[wall]]\nname = \"tank\"\nshape = \"open_tank\"\nmin = [0, 0]\n"
                  "max = [0.35, 0.2]\n[[wall]]\nname = \"gate\"\nshape = \"box\"\n"
                  "min = [0.1, 0]\nmax = [0.13, 0.2]\nremove_at = 0.05\n[[probe]]\n"
                  "name = \"front\"\ntype = \"front\"\n") +
            "",
        {"time.end=0.1"}));
    const long gate_particles = sim.particles().count(particles::Kind::boundary);
    sim.run({"", true, 0, 0.045});
    EXPECT_LT(sim.probe("front").finals()[0], 0.1);
    sim.run({"", true, 0});
    EXPECT_LT(sim.particles().count(particles::Kind::boundary), gate_particles);
    EXPECT_GT(sim.probe("front").finals()[0], 0.11);
}
