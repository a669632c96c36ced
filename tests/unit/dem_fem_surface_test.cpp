// DEM <-> FEM contact surface (issue #6): the solids' boundary facets as DEM walls on moving
// nodes, the velocity blend, the reaction split and the surface update after erosion.
#include "debrisflow/coupling/dem_fem.hpp"
#include "debrisflow/fem/fem_mesh.hpp"
#include <gtest/gtest.h>

using namespace debrisflow;

namespace {

fem::FemMaterial concrete() {
    fem::FemMaterial m;
    m.name = "c40";
    m.density = 2320;
    m.youngs_modulus = 32.5e9;
    m.poisson = 0.2;
    m.erosion_strain = 0.05;
    return m;
}

} // namespace

// A column of two hex8 (1 x 1 x 2 m): 10 boundary quads -> 20 triangles on its nodes; when the
// top element erodes, the surface is rebuilt from what remains (6 quads, top at z = 1) and the
// DEM sees the new layout.
TEST(DemFemSurface, TrianglesFollowNodesAndErosion) {
    fem::FemParams p;
    p.gravity = {};
    fem::FemSolver solver(p, {concrete()});
    solver.add_solid("column",
                     fem::box_mesh(fem::ElementType::hex8, {0, 0, 0}, {1, 1, 2}, {1, 1, 2}), 0);
    solver.initialize();
    dem::WallSet walls;
    coupling::DemFemCoupling coupling(solver, walls, {-1});
    EXPECT_EQ(coupling.triangles(), 20u);
    EXPECT_EQ(walls.walls()[std::size_t(coupling.wall_of(0))].name, "column");
    // Nodes moved by the FEM carry the triangles after sync().
    for (std::size_t i = 0; i < solver.nodes(); ++i)
        solver.positions()[i] = solver.reference()[i] + Vec3{0.001, 0, 0};
    coupling.sync();
    for (const auto& pr : walls.primitives())
        EXPECT_GE(std::min({pr.a.x, pr.b.x, pr.c.x}), 0.001 - 1e-15);
    // Erode the top element by stretching its top face 0.2 m (strain 0.2 > 0.05).
    const auto layout = walls.layout();
    for (auto n : solver.node_set("column.zmax")) solver.positions()[std::size_t(n)].z += 0.2;
    solver.advance(0);
    ASSERT_EQ(solver.eroded_elements(), 1);
    coupling.sync();
    EXPECT_NE(walls.layout(), layout);
    EXPECT_EQ(coupling.triangles(), 12u);
    Real top = -1;
    for (const auto& pr : walls.primitives()) top = std::max({top, pr.a.z, pr.b.z, pr.c.z});
    EXPECT_NEAR(top, 1.0, 1e-12);
}

// 2D: a quad4 plate's edges become pairs of triangles extruded across y = 0; a contact point's
// wall velocity is the barycentric blend of the corner nodes' velocities (linear along the
// edge) and the weights sum to one.
TEST(DemFemSurface, EdgesExtrudeIn2DAndBlendNodeVelocities) {
    fem::FemParams p;
    p.dim = 2;
    p.gravity = {};
    fem::FemSolver solver(p, {concrete()});
    solver.add_solid("plate",
                     fem::box_mesh(fem::ElementType::quad4, {0, 0, 0}, {1, 0, 0.1}, {1, 1, 1}), 0);
    solver.initialize();
    dem::WallSet walls;
    coupling::DemFemCoupling coupling(solver, walls, {-1});
    EXPECT_EQ(coupling.triangles(), 8u); // 4 edges x 2
    // Top edge nodes (z = 0.1): x = 0 at rest, x = 1 moving up at 2 m/s.
    for (std::size_t i = 0; i < solver.nodes(); ++i)
        if (solver.reference()[i].x > 0.5) solver.velocities()[i] = {0, 0, 2};
    coupling.sync();
    const Vec3 q{0.25, 0, 0.1}; // a quarter along the top edge, on the y = 0 plane
    bool found = false;
    for (const auto& pr : walls.primitives()) {
        if (std::fabs(pr.n.z) < 0.99 || pr.a.z < 0.05) continue; // the top edge's triangles
        if (!dem::lies_on_triangle(pr, q, 1e-9)) continue;
        const Vec3 w = dem::barycentric(q, pr.a, pr.b, pr.c);
        EXPECT_NEAR(w.x + w.y + w.z, 1, 1e-14);
        const auto& c = walls.corners()[std::size_t(pr.corners)];
        Vec3 v{};
        for (int k = 0; k < 3; ++k)
            v += w[k] * walls.nodes().v[std::size_t(c.node[std::size_t(k)])];
        EXPECT_NEAR(v.z, 0.5, 1e-12); // linear along the edge
        found = true;
    }
    EXPECT_TRUE(found);
}
