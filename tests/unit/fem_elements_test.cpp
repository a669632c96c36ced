// Solid elements: patch tests on distorted meshes, masses, rigid-body modes, bending without
// locking, structured meshers and the Gmsh reader.
#include "debrisflow/core/error.hpp"
#include "debrisflow/coupling/sph_fem.hpp"
#include "debrisflow/fem/element_matrices.hpp"
#include "debrisflow/fem/fem_mesh.hpp"
#include "debrisflow/fem/fem_solver.hpp"
#include "debrisflow/fem/fem_surface.hpp"
#include <algorithm>
#include <fmt/format.h>
#include <fstream>
#include <gtest/gtest.h>
#include <random>
#include <set>

using namespace debrisflow;
using namespace debrisflow::fem;

namespace {

FemMaterial steel() {
    FemMaterial m;
    m.name = "steel";
    m.density = 7850;
    m.youngs_modulus = 200e9;
    m.poisson = 0.3;
    return m;
}

// Interior nodes of a box mesh moved at random by up to 20 % of a cell (a distorted patch).
FemMesh distorted_box(ElementType t, int n) {
    FemMesh m = box_mesh(t, {0, 0, 0}, {1, 1, 1}, {n, n, n});
    const std::size_t corners =
        t == ElementType::tet10 ? std::size_t((n + 1) * (n + 1) * (n + 1)) : m.nodes.size();
    std::mt19937 rng(7);
    std::uniform_real_distribution<Real> u(-0.2 / n, 0.2 / n);
    const bool flat = t == ElementType::quad4;
    for (std::size_t i = 0; i < corners; ++i) {
        Vec3& p = m.nodes[i];
        bool interior = true;
        for (int k = 0; k < 3; ++k)
            if (!(flat && k == 1)) interior = interior && p[k] > 1e-9 && p[k] < 1 - 1e-9;
        if (!interior) continue;
        p.x += u(rng), p.z += u(rng);
        if (!flat) p.y += u(rng);
    }
    if (t == ElementType::tet10) // mid-edge nodes back to the middle of their (moved) edges
        for (std::size_t e = 0; e < m.elements(); ++e) {
            const std::int32_t* c = &m.conn[10 * e];
            const int edges[6][2] = {{0, 1}, {1, 2}, {0, 2}, {0, 3}, {1, 3}, {2, 3}};
            for (int k = 0; k < 6; ++k)
                m.nodes[std::size_t(c[4 + k])] = 0.5 * (m.nodes[std::size_t(c[edges[k][0]])] +
                                                        m.nodes[std::size_t(c[edges[k][1]])]);
        }
    return m;
}

} // namespace

// Patch test (Irons; Taylor, Beresford & Wilson 1976 for the incompatible modes): a linear
// displacement field u = A X + b imposed on the boundary of a distorted patch is reproduced at
// the interior nodes by the static solution, and every element reports the constant strain A,
// to 1e-10 (issue 6, validation 1).
class PatchTest : public ::testing::TestWithParam<ElementType> {};

TEST_P(PatchTest, ConstantStrainOnADistortedMesh) {
    const ElementType t = GetParam();
    const int dim = dim_of(t);
    FemMesh mesh = distorted_box(t, t == ElementType::tet10 ? 2 : 3);
    FemParams p;
    p.dim = dim;
    p.gravity = {};
    FemSolver fem(p, {steel()});
    fem.add_solid("patch", mesh, 0);
    fem.initialize();
    // Symmetric A (a pure stretch: the corotational frame stays the identity).
    const Real A[3][3] = {
        {1.0e-3, 0.4e-3, -0.3e-3}, {0.4e-3, -0.5e-3, 0.2e-3}, {-0.3e-3, 0.2e-3, 0.7e-3}};
    auto field = [&](Vec3 X) {
        Vec3 u{};
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) u[i] += A[i][j] * X[j];
        if (dim == 2) u.y = 0;
        return u + Vec3{2e-4, dim == 2 ? 0 : -1e-4, 3e-4};
    };
    const auto& X = fem.reference();
    std::vector<char> boundary(X.size(), 0);
    for (std::size_t i = 0; i < X.size(); ++i)
        for (int k = 0; k < 3; ++k)
            if (!(dim == 2 && k == 1) && (X[i][k] < 1e-9 || X[i][k] > 1 - 1e-9)) boundary[i] = 1;
    // Static solution: K_ii u_i = -K_ib u_b.
    const Eigen::MatrixXd K = fem.assemble_stiffness();
    std::vector<Eigen::Index> in, bd;
    for (std::size_t i = 0; i < X.size(); ++i)
        for (int k = 0; k < dim; ++k) (boundary[i] ? bd : in).push_back(Eigen::Index(i) * dim + k);
    ASSERT_FALSE(in.empty());
    auto comp = [&](Vec3 u, int k) { return u[dim == 3 ? k : 2 * k]; };
    Eigen::VectorXd ub(Eigen::Index(bd.size()));
    for (std::size_t r = 0; r < bd.size(); ++r)
        ub[Eigen::Index(r)] = comp(field(X[std::size_t(bd[r] / dim)]), int(bd[r] % dim));
    Eigen::MatrixXd Kii(in.size(), in.size()), Kib(in.size(), bd.size());
    for (std::size_t r = 0; r < in.size(); ++r) {
        for (std::size_t c = 0; c < in.size(); ++c)
            Kii(Eigen::Index(r), Eigen::Index(c)) = K(in[r], in[c]);
        for (std::size_t c = 0; c < bd.size(); ++c)
            Kib(Eigen::Index(r), Eigen::Index(c)) = K(in[r], bd[c]);
    }
    const Eigen::VectorXd ui = Kii.ldlt().solve(-Kib * ub);
    Real worst = 0;
    for (std::size_t r = 0; r < in.size(); ++r) {
        const Real exact = comp(field(X[std::size_t(in[r] / dim)]), int(in[r] % dim));
        worst = std::max(worst, std::fabs(ui[Eigen::Index(r)] - exact) / 1e-3);
    }
    EXPECT_LT(worst, 1e-10) << name_of(t);
    // Element strains with every node on the field (explicit internal forces: interior nodes in
    // equilibrium).
    for (std::size_t i = 0; i < X.size(); ++i) fem.positions()[i] = X[i] + field(X[i]);
    fem.advance(0); // no step: forces only
    Real strain_err = 0;
    for (std::size_t e = 0; e < fem.solids()[0].volume.size(); ++e) {
        const auto r = fem.element_result(0, e);
        const Real expect[6] = {A[0][0], A[1][1], A[2][2], A[0][1], A[1][2], A[0][2]};
        for (int k = 0; k < 6; ++k) {
            if (dim == 2 && (k == 1 || k == 3 || k == 4)) continue;
            strain_err =
                std::max(strain_err, std::fabs(r.strain[std::size_t(k)] - expect[k]) / 1e-3);
        }
    }
    EXPECT_LT(strain_err, 1e-10) << name_of(t);
    std::cout << fmt::format(
        "{}: interior displacement error {:.2e}, strain error {:.2e} (relative)\n", name_of(t),
        worst, strain_err);
}

INSTANTIATE_TEST_SUITE_P(Elements, PatchTest,
                         ::testing::Values(ElementType::hex8, ElementType::tet4, ElementType::tet10,
                                           ElementType::quad4),
                         [](const auto& info) { return std::string(name_of(info.param)); });

// Lumped masses add up to rho V; the element stiffness has exactly the rigid-body null space
// (6 zero eigenvalues in 3D, 3 in 2D) and is positive otherwise.
TEST(FemElements, MassAndRigidBodyModes) {
    const auto C3 = elasticity_matrix(200e9, 0.3, 3), C2 = elasticity_matrix(200e9, 0.3, 2);
    struct Case {
        ElementType t;
        std::vector<Vec3> X;
        Real volume;
    };
    const std::vector<Vec3> hex = {{0, 0, 0},   {2, 0, 0},     {2.2, 1, 0}, {0, 1.1, 0},
                                   {0, 0, 0.5}, {2, 0.1, 0.6}, {2, 1, 0.5}, {0.1, 1, 0.5}};
    const std::vector<Vec3> tet = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    std::vector<Vec3> tet10 = tet;
    for (auto [a, b] : {std::pair{0, 1}, {1, 2}, {0, 2}, {0, 3}, {1, 3}, {2, 3}})
        tet10.push_back(0.5 * (tet[std::size_t(a)] + tet[std::size_t(b)]));
    const std::vector<Vec3> quad = {{0, 0, 0}, {2, 0, 0}, {2, 0, 1}, {0, 0, 1}};
    for (const auto& [t, X, vol] : std::vector<Case>{{ElementType::tet4, tet, 1.0 / 6},
                                                     {ElementType::tet10, tet10, 1.0 / 6},
                                                     {ElementType::quad4, quad, 2.0},
                                                     {ElementType::hex8, hex, 0}}) {
        const int dim = dim_of(t);
        const auto m = element_matrices(t, X, dim == 3 ? C3 : C2, 1000);
        if (vol > 0) {
            EXPECT_NEAR(m.volume, vol, 1e-12);
        }
        EXPECT_NEAR(m.mass.sum(), 1000 * m.volume, 1e-9);
        EXPECT_GT(m.mass.minCoeff(), 0);
        Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(m.stiffness);
        const auto& ev = eig.eigenvalues();
        const int zeros = dim == 3 ? 6 : 3;
        for (int k = 0; k < zeros; ++k)
            EXPECT_LT(std::fabs(ev[k]), 1e-6 * ev.maxCoeff()) << name_of(t);
        EXPECT_GT(ev[zeros], 1e-4 * ev.maxCoeff()) << name_of(t);
    }
}

// A hex8 with incompatible modes is exact in pure bending of a rectangular element (no shear
// locking): the end rotation under a bending moment equals M L / (E I) of plane-stress beam
// theory with nu = 0.
TEST(FemElements, Hex8PureBendingWithoutLocking) {
    const Real L = 2, b = 0.1, h = 0.2, E = 1e9;
    const auto m = element_matrices(
        ElementType::hex8,
        {{0, 0, 0}, {L, 0, 0}, {L, b, 0}, {0, b, 0}, {0, 0, h}, {L, 0, h}, {L, b, h}, {0, b, h}},
        elasticity_matrix(E, 0, 3), 1000);
    // Curvature kappa: u_x = -kappa x (z - h/2), u_z = kappa x^2 / 2 (exact bending mode).
    const Real kappa = 1e-4;
    Eigen::VectorXd u(24);
    const Vec3 X[8] = {{0, 0, 0}, {L, 0, 0}, {L, b, 0}, {0, b, 0},
                       {0, 0, h}, {L, 0, h}, {L, b, h}, {0, b, h}};
    for (int a = 0; a < 8; ++a) {
        u[3 * a] = -kappa * X[a].x * (X[a].z - h / 2);
        u[3 * a + 1] = 0;
        u[3 * a + 2] = kappa * X[a].x * X[a].x / 2;
    }
    // Strain energy 1/2 u K u against the beam's 1/2 E I kappa^2 L (I = b h^3 / 12).
    const Real energy = 0.5 * u.dot(m.stiffness * u);
    const Real exact = 0.5 * E * b * h * h * h / 12 * kappa * kappa * L;
    EXPECT_NEAR(energy / exact, 1, 1e-9);
}

TEST(FemMeshes, TrapezoidVolumeAndNodeSets) {
    TrapezoidSpec s;
    s.base_width = 3, s.crest_width = 1, s.height = 4, s.upstream_offset = 0.5, s.length = 6;
    for (ElementType t : {ElementType::hex8, ElementType::tet4, ElementType::tet10}) {
        const FemMesh m = trapezoid_mesh(t, s, {3, 4, 5});
        FemParams p;
        FemSolver fem(p, {steel()});
        fem.add_solid("dam", m, 0);
        Real v = 0;
        for (Real dv : fem.solids()[0].volume) v += dv;
        EXPECT_NEAR(v, (3 + 1) / 2.0 * 4 * 6, 1e-9) << name_of(t);
        for (const char* set : {"base", "crest", "upstream", "downstream", "left", "right"})
            EXPECT_FALSE(m.node_sets.at(set).empty()) << set;
        for (auto n : m.node_sets.at("crest")) EXPECT_NEAR(m.nodes[std::size_t(n)].z, 4, 1e-12);
    }
    const FemMesh q = trapezoid_mesh(ElementType::quad4, s, {3, 1, 5});
    Real area = 0;
    FemParams p2;
    p2.dim = 2;
    FemSolver fem2(p2, {steel()});
    fem2.add_solid("dam", q, 0);
    for (Real dv : fem2.solids()[0].volume) area += dv;
    EXPECT_NEAR(area, 8, 1e-12);
}

// A Gmsh 4.1 file with two tet4 and a physical group on a face: nodes, elements, named set.
TEST(FemMeshes, ReadsGmsh41) {
    const std::string path = ::testing::TempDir() + "/two_tets.msh";
    std::ofstream(path) << R"($MeshFormat
4.1 0 8
$EndMeshFormat
$PhysicalNames
1
2 7 "base"
$EndPhysicalNames
$Entities
0 0 1 1
1 0 0 0 1 1 0 1 7 0
1 0 0 0 1 1 1 0 0
$EndEntities
$Nodes
2 5 1 5
2 1 0 3
1
2
3
0 0 0
1 0 0
0 1 0
3 1 0 2
4
5
0 0 1
0 0 -1
$EndNodes
$Elements
2 3 1 3
2 1 2 1
1 1 2 3
3 1 4 2
2 1 2 3 4
3 1 2 3 5
$EndElements
)";
    const FemMesh m = read_gmsh(path, ElementType::tet4);
    ASSERT_EQ(m.nodes.size(), 5u);
    ASSERT_EQ(m.elements(), 2u);
    EXPECT_EQ(m.node_sets.at("base").size(), 3u);
    FemParams p;
    FemSolver fem(p, {steel()});
    fem.add_solid("tets", m, 0); // both elements positive after reorientation
    EXPECT_NEAR(fem.solids()[0].volume[0] + fem.solids()[0].volume[1], 2.0 / 6, 1e-12);
    try {
        read_gmsh(path, ElementType::hex8);
        FAIL() << "expected an error";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("no hex8 elements"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("two_tets.msh"), std::string::npos) << e.what();
    }
}

// Mazars (1986) tension damage and erosion on one hex8 under uniaxial strain (nu = 0, so the
// principal strains are (e, 0, 0) and the equivalent strain is e): the damage follows
// D = 1 - k0 (1 - A) / e - A exp(-B (e - k0)), never heals when unloaded, and the element is
// eroded (no force, off the surface) once its largest principal strain passes the threshold.
TEST(FemMaterials, MazarsDamageAndErosion) {
    FemMaterial concrete;
    concrete.name = "concrete";
    concrete.model = "mazars";
    concrete.density = 2320;
    concrete.youngs_modulus = 32.5e9;
    concrete.poisson = 0;
    concrete.damage_threshold = 1e-4;
    concrete.damage_a = 0.9;
    concrete.damage_b = 8000;
    concrete.erosion_strain = 0.05;
    FemParams p;
    p.gravity = {};
    FemSolver fem(p, {concrete});
    fem.add_solid("cube", box_mesh(ElementType::hex8, {0, 0, 0}, {1, 1, 1}, {1, 1, 1}), 0);
    fem.initialize();
    const auto X = fem.reference();
    auto stretch = [&](Real e) {
        for (std::size_t i = 0; i < X.size(); ++i)
            fem.positions()[i] = X[i] + Vec3{e * X[i].x, 0, 0};
        fem.advance(0);
    };
    auto expected = [&](Real e) {
        return 1 - 1e-4 * (1 - 0.9) / e - 0.9 * std::exp(-8000 * (e - 1e-4));
    };
    stretch(5e-5);
    EXPECT_EQ(fem.element_result(0, 0).damage, 0); // below kappa_0
    for (Real e : {2e-4, 5e-4, 1e-3}) {
        stretch(e);
        EXPECT_NEAR(fem.element_result(0, 0).damage, expected(e), 1e-9) << e;
        // Stress is (1 - D) E e.
        EXPECT_NEAR(fem.element_result(0, 0).stress[0] / ((1 - expected(e)) * 32.5e9 * e), 1, 1e-6);
    }
    stretch(1e-4); // unloading keeps the damage of the largest strain reached
    EXPECT_NEAR(fem.element_result(0, 0).damage, expected(1e-3), 1e-9);
    EXPECT_EQ(boundary_facets(fem).size(), 12u);
    stretch(0.06);
    EXPECT_TRUE(fem.element_result(0, 0).eroded);
    EXPECT_EQ(fem.eroded_elements(), 1);
    EXPECT_TRUE(boundary_facets(fem).empty());
    Real f = 0;
    for (Real v : fem.solids()[0].force) f += std::fabs(v);
    EXPECT_EQ(f, 0);
}

// tet10 surface: each quadratic face becomes four flat triangles through its edge nodes, so the
// DEM surface follows the edge nodes and a grain's reaction reaches all six face nodes. On a
// unit cube (one hex split into tets): 6 sides x 2 faces x 4 = 48 triangles, outward, closed
// (area-weighted normals sum to zero), total area 6 m^2, and every edge node on the surface used.
TEST(FemSurface, Tet10FacesSplitThroughEdgeNodes) {
    FemParams p;
    p.gravity = {};
    FemSolver fem(p, {steel()});
    fem.add_solid("cube", box_mesh(ElementType::tet10, {0, 0, 0}, {1, 1, 1}, {1, 1, 1}), 0);
    fem.initialize();
    const auto facets = boundary_facets(fem);
    ASSERT_EQ(facets.size(), 48u);
    const auto& X = fem.reference();
    Real area = 0;
    Vec3 closure{};
    std::set<std::int32_t> used;
    for (const auto& f : facets) {
        const Vec3 a = X[std::size_t(f.nodes[0])], b = X[std::size_t(f.nodes[1])],
                   c = X[std::size_t(f.nodes[2])];
        const Vec3 an = Real(0.5) * cross(b - a, c - a);
        area += norm(an);
        closure += an;
        const Vec3 centre = (Real(1) / 3) * (a + b + c);
        EXPECT_GT(dot(facet_normal(f, X), centre - Vec3{0.5, 0.5, 0.5}), 0);
        used.insert(f.nodes.begin(), f.nodes.end());
    }
    EXPECT_NEAR(area, 6, 1e-12);
    EXPECT_NEAR(norm(closure), 0, 1e-12);
    // Surface nodes of the split cube: 8 corners, 12 cube-edge midpoints, 6 face-diagonal
    // midpoints (one per side).
    EXPECT_EQ(used.size(), 26u);
}

// SPH <-> FEM shell: boundary particles sit inside the solid within layers x dp of its surface,
// follow the elements, carry the fluid force back to the nodes with total force conserved,
// leave with their element when it erodes, and the surface the erosion exposes gets its layer.
TEST(FemSphShell, FollowsTheElementsAndLeavesWithErodedOnes) {
    FemMaterial m = steel();
    m.erosion_strain = 0.05;
    FemParams p;
    p.dim = 2;
    p.gravity = {};
    FemSolver fem(p, {m});
    fem.add_solid("plate", box_mesh(ElementType::quad4, {0, 0, 0}, {0.1, 0, 0.04}, {10, 1, 4}), 0);
    fem.initialize();
    particles::ParticleSet set;
    set.add({0.05, 0, 0.02}, {}, 1000, 0.1, particles::Kind::fluid, 0); // inside: removed
    set.add({0.05, 0, 0.08}, {}, 1000, 0.1, particles::Kind::fluid, 0); // outside: kept
    coupling::SphFemCoupling shell(fem, set, 0.005, 2, 1000, 2);
    EXPECT_EQ(set.count(particles::Kind::fluid), 1);
    // 2 layers of dp = 5 mm inside a 100 x 40 mm plate on a lattice offset by dp/2.
    EXPECT_EQ(shell.particles(), 20u * 8u - 16u * 4u);
    // A rigid translation of the nodes moves the particles with them.
    for (std::size_t i = 0; i < fem.nodes(); ++i)
        fem.positions()[i] = fem.reference()[i] + Vec3{0.01, 0, 0.002};
    const Real x0 = set.x[1];
    shell.move_particles(0);
    EXPECT_NEAR(set.x[1] - x0, 0.01, 1e-14);
    // Forces: every boundary particle pushed by 1 N along x: the nodes receive the total.
    for (Index i = 0; i < set.size(); ++i) set.ax[i] = set.kind[i] ? 1 / set.mass[i] : 0;
    std::vector<Vec3> f(fem.nodes());
    shell.collect_forces(f);
    Vec3 total{};
    for (const auto& v : f) total = total + v;
    EXPECT_NEAR(total.x, Real(shell.particles()), 1e-9);
    EXPECT_NEAR(shell.last_force().x, Real(shell.particles()), 1e-9);
    // Erode the corner element (stretch its top-right node far out): its particles go.
    EXPECT_TRUE(shell.eroded_keep_mask().empty());
    const auto corner = fem.node_set("plate.xmax");
    for (auto n : corner)
        if (fem.reference()[std::size_t(n)].z > 0.039) fem.positions()[std::size_t(n)].x += 0.01;
    fem.advance(0);
    ASSERT_EQ(fem.eroded_elements(), 1);
    const auto keep = shell.eroded_keep_mask();
    ASSERT_FALSE(keep.empty());
    const auto before = set.size();
    set.compact(keep);
    EXPECT_EQ(before - set.size(), 4); // the corner element held 2 x 2 particles
    // The exposed faces (x = 90 mm and z = 30 mm around the hole) get their boundary layer:
    // the inner neighbour's samples at (82.5, 27.5), (87.5, 27.5) and (87.5, 22.5) mm lie within
    // 2 dp of the new corner at (90, 30) mm; (82.5, 22.5) mm, 10.6 mm away, does not.
    EXPECT_EQ(shell.expose_new_surface(), 3u);
    EXPECT_EQ(shell.expose_new_surface(), 0u); // nothing new until the next erosion
    EXPECT_EQ(shell.particles(), 20u * 8u - 16u * 4u - 4u + 3u);
    shell.move_particles(0); // survivors are found again by id
    EXPECT_EQ(shell.eroded_keep_mask().size(), 0u);
    // The updated layer equals the one sampled from scratch on the eroded mesh: same positions,
    // wall normals and depths.
    particles::ParticleSet fresh_set;
    coupling::SphFemCoupling fresh(fem, fresh_set, 0.005, 2, 1000, 2);
    fresh.move_particles(0);
    auto layer = [](const particles::ParticleSet& s) {
        std::vector<std::array<Real, 5>> rows;
        for (Index i = 0; i < s.size(); ++i)
            if (s.kind[i] == std::uint8_t(particles::Kind::boundary))
                rows.push_back({s.x[i], s.z[i], s.wnx[i], s.wnz[i], s.wd[i]});
        std::sort(rows.begin(), rows.end());
        return rows;
    };
    const auto a = layer(set), b = layer(fresh_set);
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t k = 0; k < a.size(); ++k)
        for (int c = 0; c < 5; ++c) EXPECT_NEAR(a[k][std::size_t(c)], b[k][std::size_t(c)], 1e-12);
}
