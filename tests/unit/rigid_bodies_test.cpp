// Rigid bodies: mass properties against closed forms, quaternion helpers, joints, locks,
// prescribed motion, body-body contact, and case-file errors.
#include "debrisflow/core/error.hpp"
#include "debrisflow/dem/box_faces.hpp"
#include "debrisflow/flow/outlet.hpp"
#include "rigid_rig.hpp"
#include "run_case.hpp"
#include <cmath>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>

using namespace debrisflow;

namespace {

constexpr Real pi = 3.14159265358979323846;

// Principal moments of a body, sorted.
std::array<Real, 3> moments(const rigid::BodyState& s) {
    std::array<Real, 3> m{1 / s.inv_inertia.x, 1 / s.inv_inertia.y, 1 / s.inv_inertia.z};
    std::sort(m.begin(), m.end());
    return m;
}

// A closed axis-aligned box [0, a] x [0, b] x [0, c] as 12 outward-facing triangles.
std::string write_box_stl(Real a, Real b, Real c) {
    const auto path = std::filesystem::temp_directory_path() / "debrisflow_box.stl";
    std::ofstream o(path);
    const Vec3 v[8] = {{0, 0, 0}, {a, 0, 0}, {a, b, 0}, {0, b, 0},
                       {0, 0, c}, {a, 0, c}, {a, b, c}, {0, b, c}};
    const int f[12][3] = {{0, 2, 1}, {0, 3, 2}, {4, 5, 6}, {4, 6, 7}, {0, 1, 5}, {0, 5, 4},
                          {2, 3, 7}, {2, 7, 6}, {1, 2, 6}, {1, 6, 5}, {0, 4, 7}, {0, 7, 3}};
    o << "solid box\n";
    for (const auto& t : f) {
        o << "facet normal 0 0 0\nouter loop\n";
        for (int k : t) o << "vertex " << v[k].x << " " << v[k].y << " " << v[k].z << "\n";
        o << "endloop\nendfacet\n";
    }
    o << "endsolid box\n";
    return path.string();
}

dem::WallPrimitive tri(Vec3 a, Vec3 b, Vec3 c) {
    return dem::wall_triangle(a, b, c);
}

} // namespace

TEST(RigidBodies, QuaternionEulerRoundTrip) {
    const Vec3 rpy{0.3, -0.7, 2.1};
    const Vec3 back = rigid::euler_zyx(rigid::from_euler_zyx(rpy));
    EXPECT_NEAR(back.x, rpy.x, 1e-12);
    EXPECT_NEAR(back.y, rpy.y, 1e-12);
    EXPECT_NEAR(back.z, rpy.z, 1e-12);
    const rigid::Quat q = rigid::axis_angle({0, 0, 1}, pi / 2);
    const Vec3 x = rigid::rotate(q, {1, 0, 0});
    EXPECT_NEAR(x.y, 1, 1e-15);
}

TEST(RigidBodies, MassPropertiesOfPrimitivesMatchClosedForms) {
    test::RigidRig rig;
    // box 0.3 x 0.2 x 0.1, rho 700: I = m/12 (b^2 + c^2, ...)
    rig.add(test::RigidRig::box("box", {0, 0, 0}, {0.3, 0.2, 0.1}), 700);
    const Real m = 700 * 0.006;
    EXPECT_NEAR(rig.bodies[0].mass, m, 1e-12);
    const auto mb = moments(rig.bodies[0]);
    EXPECT_NEAR(mb[0], m * (0.04 + 0.01) / 12, 1e-12);
    EXPECT_NEAR(mb[2], m * (0.09 + 0.04) / 12, 1e-12);
    // cylinder r = 0.1, L = 0.5 along (1,1,0)/sqrt2: I_axis = m r^2/2, I_perp = m(3r^2+L^2)/12
    io::BodySpec cyl;
    cyl.name = "cyl";
    cyl.shape.type = "cylinder";
    cyl.shape.center = {1, 1, 1};
    cyl.shape.axis = {1 / std::sqrt(2.0), 1 / std::sqrt(2.0), 0};
    cyl.shape.radius = 0.1;
    cyl.shape.length = 0.5;
    rig.add(cyl, 1000);
    const Real mc = 1000 * pi * 0.01 * 0.5;
    const auto mcyl = moments(rig.bodies[1]);
    EXPECT_NEAR(rig.bodies[1].mass, mc, 1e-9);
    EXPECT_NEAR(mcyl[0], 0.5 * mc * 0.01, 1e-10);
    EXPECT_NEAR(mcyl[2], mc * (0.03 + 0.25) / 12, 1e-10);
    EXPECT_NEAR(rig.bodies[1].pos.x, 1 + 0.25 / std::sqrt(2.0), 1e-12);
    // a closed STL box by signed tetrahedra: exact
    io::BodySpec mesh;
    mesh.name = "mesh";
    mesh.shape.type = "stl";
    mesh.shape.file = write_box_stl(0.3, 0.2, 0.1);
    rig.add(mesh, 700);
    EXPECT_NEAR(rig.bodies[2].mass, m, 1e-12);
    const auto mm = moments(rig.bodies[2]);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(mm[k] / mb[k], 1, 1e-12);
    EXPECT_NEAR(rig.bodies[2].pos.x, 0.15, 1e-12);
    EXPECT_EQ(rig.models[2].vertices.size(), 8u);
    // a one-sphere clump by lattice integration: within 1 % of 4/3 pi r^3 rho and 2/5 m r^2
    io::BodySpec clump;
    clump.name = "clump";
    clump.shape.type = "clump";
    clump.clump_centers = {{0, 0, 0}};
    clump.clump_radii = {0.05};
    rig.add(clump, 2650);
    const Real ms = 2650 * 4 * pi / 3 * 1.25e-4;
    EXPECT_NEAR(rig.bodies[3].mass / ms, 1, 0.01);
    EXPECT_NEAR(moments(rig.bodies[3])[0] / (0.4 * ms * 0.0025), 1, 0.01);
}

TEST(RigidBodies, PrescribedMassAndOffsetCentreFollowParallelAxisTheorem) {
    test::RigidRig rig;
    io::BodySpec b = test::RigidRig::box("container", {0, 0, 0}, {0.15, 0.06, 0.06});
    b.mass = 0.226;
    b.com_offset = Vec3{0.004, 0, 0};
    rig.add(b, 1);
    const auto& s = rig.bodies[0];
    EXPECT_NEAR(s.mass, 0.226, 1e-15);
    EXPECT_NEAR(s.pos.x, 0.079, 1e-15);
    // about the offset centre: I_yy = m (a^2 + c^2)/12 - m d^2 (d along x)
    const Real iyy = 0.226 * (0.0225 + 0.0036) / 12 - 0.226 * 0.004 * 0.004;
    const Real izz = 0.226 * (0.0225 + 0.0036) / 12 - 0.226 * 0.004 * 0.004;
    const Real ixx = 0.226 * (0.0036 + 0.0036) / 12;
    const auto m = moments(s);
    EXPECT_NEAR(m[0], ixx, 1e-15);
    EXPECT_NEAR(m[1], std::min(iyy, izz), 1e-15);
}

TEST(RigidBodies, LockedAndPrescribedMotion) {
    test::RigidRig rig;
    io::BodySpec a = test::RigidRig::box("slider", {0, 0, 0}, {0.1, 0.1, 0.1});
    a.lock_translation = {false, false, true};
    a.lock_rotation = {true, true, true};
    a.velocity = {1, 0, 0};
    a.angular_velocity = {0, 0, 3};
    rig.add(a, 1000);
    io::BodySpec p = test::RigidRig::box("gate", {1, 0, 0}, {1.1, 0.1, 0.5});
    p.motion = "prescribed";
    p.motion_times = {0, 1};
    p.motion_velocity = {{0, 0, 0}, {0, 0, 2}}; // v_z = 2 t: z(1) = 1
    rig.add(p, 1000);
    rig.models[1].times = p.motion_times;
    rig.models[1].velocity = p.motion_velocity;
    rig.models[1].angular_velocity = {{0, 0, 0}, {0, 0, 0}};
    rig.start({0, 0, -9.81});
    for (int k = 0; k < 1000; ++k) rig.solver->step(1e-3);
    EXPECT_NEAR(rig.body(0).pos.z, 0.05, 1e-15); // locked against gravity
    EXPECT_NEAR(rig.body(0).pos.x, 1.05, 1e-12);
    EXPECT_NEAR(norm(rig.body(0).omega()), 0, 1e-15);
    EXPECT_NEAR(rig.body(1).pos.z - 0.25, 1.0, 1e-9); // midpoint rule, exact for linear v
}

TEST(RigidBodies, FixedJointKeepsRelativePose) {
    // Two welded boxes, thrown spinning: they move as one body (relative pose constant) and
    // their joint centre of mass falls freely.
    test::RigidRig rig;
    const int a = rig.add(test::RigidRig::box("a", {0, 0, 0}, {0.2, 0.1, 0.1}), 1000);
    const int b = rig.add(test::RigidRig::box("b", {0.2, 0, 0}, {0.3, 0.3, 0.1}), 500);
    rigid::Joint weld;
    weld.type = rigid::JointType::fixed;
    weld.a = a;
    weld.b = b;
    const Vec3 p{0.2, 0.05, 0.05};
    weld.anchor_a = rigid::rotate_inverse(rig.bodies[a].q, p - rig.bodies[a].pos);
    weld.anchor_b = rigid::rotate_inverse(rig.bodies[b].q, p - rig.bodies[b].pos);
    weld.rel0 = rigid::conjugate(rig.bodies[a].q) * rig.bodies[b].q;
    rig.joints.joints().push_back(weld);
    const Real ma = rig.bodies[a].mass, mb = rig.bodies[b].mass;
    const Vec3 c0 = (1 / (ma + mb)) * (ma * rig.bodies[a].pos + mb * rig.bodies[b].pos);
    const Real d0 = norm(rig.bodies[a].pos - rig.bodies[b].pos);
    rig.start({0, 0, -9.81});
    // a small spin shared by both (consistent initial velocities)
    const Vec3 w{0, 0, 1};
    for (int k : {a, b}) {
        auto& s = rig.body(k);
        s.ang_mom = rigid::angular_momentum(s.q, w, s.inv_inertia);
        s.vel = cross(w, s.pos - c0);
    }
    const Real dt = 1e-4;
    for (int k = 0; k < 5000; ++k) rig.solver->step(dt);
    const Real d = norm(rig.body(a).pos - rig.body(b).pos);
    EXPECT_NEAR(d, d0, 1e-5);
    const Vec3 c = (1 / (ma + mb)) * (ma * rig.body(a).pos + mb * rig.body(b).pos);
    EXPECT_NEAR(c.z - c0.z, -0.5 * 9.81 * 0.25, 1e-4); // free fall over 0.5 s
    const rigid::Quat rel = rigid::conjugate(rig.body(a).q) * rig.body(b).q;
    EXPECT_NEAR(std::fabs(rel.w * weld.rel0.w + rel.x * weld.rel0.x + rel.y * weld.rel0.y +
                          rel.z * weld.rel0.z),
                1, 1e-8);
    EXPECT_GT(std::fabs(rigid::euler_zyx(rig.body(a).q).z), 0.4); // it did turn (~0.5 rad)
}

TEST(RigidBodies, SphereCollisionConservesMomentumWithRestitution) {
    // Two spheres (distributed samples are the exact spheres) collide head-on with a linear
    // law, e = 0.5: momentum is conserved and the relative speed reverses to e times itself.
    test::RigidRig rig;
    rig.materials[0].kn = 1e5;
    rig.materials[0].restitution = 0.5;
    rig.materials[0].friction = 0.3;
    io::BodySpec s1 = test::RigidRig::sphere("s1", {0, 0, 0}, 0.05);
    io::BodySpec s2 = test::RigidRig::sphere("s2", {0.2, 0, 0}, 0.04);
    s1.velocity = {1, 0, 0};
    s2.velocity = {-0.5, 0, 0};
    const int a = rig.add(s1, 1000), b = rig.add(s2, 2000);
    rig.start({0, 0, 0});
    const Real ma = rig.body(a).mass, mb = rig.body(b).mass;
    const Vec3 p0 = ma * rig.body(a).vel + mb * rig.body(b).vel;
    for (int k = 0; k < 20000; ++k) rig.solver->step(1e-5);
    const Vec3 p1 = ma * rig.body(a).vel + mb * rig.body(b).vel;
    EXPECT_LT(norm(p1 - p0), 1e-12);
    const Real rel = rig.body(b).vel.x - rig.body(a).vel.x;
    EXPECT_NEAR(rel / 1.5, 0.5, 0.005); // linear law: exact restitution
}

// An outlet takes a free body whose centre is in its box: counted once by mass, parked at
// rest, and gone from the contacts (the other sphere, which would have hit it head-on, flies
// on through its place at its own speed).
TEST(RigidBodies, BodyTakenByAnOutletStopsTouchingOthers) {
    test::RigidRig rig;
    rig.materials[0].kn = 1e5;
    rig.materials[0].restitution = 0.5;
    io::BodySpec s1 = test::RigidRig::sphere("s1", {0, 0, 0}, 0.05);
    io::BodySpec s2 = test::RigidRig::sphere("s2", {0.2, 0, 0}, 0.04);
    s1.velocity = {1, 0, 0};
    s2.velocity = {-0.5, 0, 0};
    const int a = rig.add(s1, 1000), b = rig.add(s2, 2000);
    rig.start({0, 0, 0});
    flow::Outlet outlet(io::OutletSpec{"sink", {0.1, -1, -1}, {0.5, 1, 1}, 0.01, {}}, 1000);
    std::vector<std::uint8_t> none;
    outlet.apply(nullptr, nullptr, rig.solver.get());
    ASSERT_TRUE(rig.solver->removed(b));
    EXPECT_FALSE(rig.solver->removed(a)); // its centre is outside the box
    EXPECT_EQ(outlet.bodies_removed(), 1);
    EXPECT_DOUBLE_EQ(outlet.body_mass(), rig.body(b).mass);
    EXPECT_FALSE(rig.solver->remove_body(b, none)); // once only
    const Vec3 parked = rig.body(b).pos;
    for (int k = 0; k < 40000; ++k) rig.solver->step(1e-5); // s1 travels 0.4 m through s2's place
    outlet.apply(nullptr, nullptr, rig.solver.get());       // s1 is in the box now: taken too
    EXPECT_EQ(outlet.bodies_removed(), 2);
    EXPECT_DOUBLE_EQ(outlet.body_mass(), rig.body(a).mass + rig.body(b).mass);
    EXPECT_EQ(rig.body(b).pos.x, parked.x);
    EXPECT_EQ(norm(rig.body(b).vel), 0);
    EXPECT_NEAR(rig.body(a).pos.x, 0.4, 1e-9) << "s1 was stopped by the removed body";
    EXPECT_EQ(rig.solver->contacts(), 0);
}

TEST(RigidBodies, CaseFileErrorsNameTheKey) {
    const std::string base = R"(
dimensions = 3
[time]
end = 0.1
[domain]
min = [-1, -1, -1]
max = [1, 1, 1]
[[material]]
name = "steel"
kn = 1e6
density = 7800
)";
    auto fails = [&](const std::string& extra, const std::string& what) {
        try {
            test::case_from_toml("rigid_errors", base + extra);
            ADD_FAILURE() << "accepted: " << extra;
        } catch (const InputError& e) {
            EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
        }
    };
    fails("[[body]]\nname = \"b\"\nmaterial = \"wood\"\nshape = \"sphere\"\ncenter = [0, 0, "
          "0]\nradius = 0.1\n[rigid]\ndt = 1e-4\n",
          "body.0.material");
    fails("[[body]]\nname = \"b\"\nmaterial = \"steel\"\nshape = \"sphere\"\ncenter = [0, 0, "
          "0]\nradius = 0.1\n",
          "[rigid] dt");
    fails("[[body]]\nname = \"b\"\nmaterial = \"steel\"\nshape = \"clump\"\nspheres = [[0, 0, "
          "0]]\n[rigid]\ndt = 1e-4\n",
          "body.0.spheres");
    fails("[[body]]\nname = \"b\"\nmaterial = \"steel\"\nshape = \"sphere\"\ncenter = [0, 0, "
          "0]\nradius = 0.1\n[rigid]\ndt = 1e-4\n[[joint]]\nname = \"j\"\ntype = "
          "\"hinge\"\nbodies = [\"b\", \"c\"]\npoint = [0, 0, 0]\n",
          "joint.0.bodies");
}

TEST(RigidBodies, BodyOnlyCaseRunsFromTheCaseFile) {
    // A sphere hanging from a spring to the ground settles at the static stretch m g / k.
    app::Simulation sim(test::case_from_toml("rigid_spring", R"(
dimensions = 3
[time]
end = 3.0
[domain]
min = [-1, -1, -2]
max = [1, 1, 1]
[[material]]
name = "steel"
kn = 1e6
density = 7800
[[body]]
name = "bob"
material = "steel"
shape = "sphere"
center = [0, 0, -0.5]
radius = 0.05
[[joint]]
name = "spring"
type = "spring"
bodies = ["bob"]
point = [0, 0, -0.5]
point_b = [0, 0, 0]
stiffness = 500
damping = 20
[rigid]
dt = 1e-4
[[probe]]
name = "bob"
type = "body"
body = "bob"
every = 0.01
)"));
    sim.run({"", true, 0, 0});
    const auto& s = sim.bodies().bodies()[0];
    const Real stretch = s.mass * 9.81 / 500;
    EXPECT_NEAR(s.pos.z, -0.5 - stretch, 1e-4);
    EXPECT_EQ(sim.probe("bob").columns().size(), 25u);
}

TEST(RigidBodies, GrainBodyCollisionConservesMomentum) {
    // A grain (r = 0.02 m) hits a free spherical body (r = 0.03 m) head-on, linear law with
    // e = 0.6: the body receives the grains' reaction (averaged over the DEM steps), so the
    // total momentum is conserved and the relative velocity reverses to -e times itself.
    app::Simulation sim(test::case_from_toml("rigid_grain", R"(
dimensions = 3
[time]
end = 0.2
[physics]
gravity = [0, 0, 0]
[domain]
min = [-1, -1, -1]
max = [1, 1, 1]
[[material]]
name = "glass"
kn = 2e4
density = 2500
restitution = 0.6
friction = 0.3
[[grains]]
name = "g"
material = "glass"
packing = "single"
diameter = 0.04
position = [-0.1, 0, 0]
velocity = [2, 0, 0]
[dem]
safety = 0.02
[[body]]
name = "ball"
material = "glass"
shape = "sphere"
center = [0.0, 0.0, 0.0]
radius = 0.03
[rigid]
dt = 1e-3
)"));
    const Real mg = sim.grains().grains().mass[0];
    const Real mb = sim.bodies().bodies()[0].mass;
    sim.run({"", true, 0, 0});
    const Vec3 vg = sim.grains().grains().vel[0], vb = sim.bodies().bodies()[0].vel;
    const Real p0 = mg * 2;
    EXPECT_NEAR((mg * vg.x + mb * vb.x) / p0, 1, 1e-9);
    EXPECT_NEAR((vb.x - vg.x) / 2, 0.6, 0.006);    // 1 % on e
    EXPECT_GT(sim.grains().grains().pos[0].x, -1); // stayed in the domain
}

TEST(RigidBodies, VertexInsideAConvexEdgeLeavesByTheNearerFace) {
    // A cube's corner sits inside the upstream edge of a slit post (x in [0, 0.05], y >= 0):
    // 1 mm behind the upstream face x = 0 and 3 mm behind the slit face y = 0, with the cube's
    // centre upstream and in the slit, so both faces see it. The way out is the nearer face:
    // the contact pushes along -x with the 1 mm overlap (a linear spring: |F| = k_n delta per
    // vertex), not along -y with 3 mm (which threw rocks across slit posts).
    test::RigidRig rig;
    rig.materials[0].kn = 1e5;
    rig.materials[0].restitution = 1.0;
    rig.materials[0].friction = 0;
    const Vec3 centre{-0.019, -0.017, 0.15};
    rig.add(test::RigidRig::box("rock", centre - Vec3{0.02, 0.02, 0.02},
                                centre + Vec3{0.02, 0.02, 0.02}),
            2650);
    dem::Wall post;
    post.name = "post";
    rig.walls.add(post, {tri({0, 0, 0}, {0, 0.2, 0.3}, {0, 0.2, 0}), // upstream face, n = -x
                         tri({0, 0, 0}, {0, 0, 0.3}, {0, 0.2, 0.3}),
                         tri({0, 0, 0}, {0.05, 0, 0}, {0.05, 0, 0.3}), // slit face, n = -y
                         tri({0, 0, 0}, {0.05, 0, 0.3}, {0, 0, 0.3})});
    rig.start({0, 0, 0});
    const Vec3 f = rig.solver->wall_force(0); // the rock's push on the post
    EXPECT_EQ(rig.solver->contacts(), 2);     // the two corners at x = 0.001
    EXPECT_NEAR(f.x, 2 * 1e5 * 0.001, 1e-6 * 1e5 * 0.001);
    EXPECT_NEAR(f.y, 0, 1e-9);
}

TEST(RigidBodies, BodyLeavingTheDomainIsReportedWithWhatThrewIt) {
    // A cube released 5 mm into a floor (linear springs, k_n = 1e5 N/m per corner: 500 N each)
    // is thrown up and out of a 0.3 m high domain. The message names the body, the largest
    // contact load (the four corners, 2000 N) and the wall that gave it.
    test::RigidRig rig;
    rig.spec.domain.hi.z = 0.3;
    rig.materials[0].kn = 1e5;
    rig.materials[0].restitution = 1.0;
    rig.materials[0].friction = 0;
    rig.add(test::RigidRig::box("rock", {-0.02, -0.02, -0.005}, {0.02, 0.02, 0.035}), 2650);
    dem::Wall floor;
    floor.name = "floor";
    rig.walls.add(floor,
                  {dem::WallPrimitive{{0, 0, 0}, {}, {}, {0, 0, 1}, dem::PrimitiveType::plane, 0}});
    rig.start({0, 0, -9.81});
    std::string message;
    try {
        for (int k = 0; k < 100000; ++k) {
            rig.solver->step(1e-5);
            rig.solver->check_health(1e-5 * (k + 1));
        }
    } catch (const InstabilityError& e) {
        message = e.what();
    }
    EXPECT_NE(message.find("body left the domain"), std::string::npos) << message;
    EXPECT_NE(message.find("contacts 2000 N at t = 0 s"), std::string::npos) << message;
    EXPECT_NE(message.find("500 N, overlap 5 mm, with wall 'floor'"), std::string::npos) << message;
    EXPECT_NE(message.find("fluid 0 N"), std::string::npos) << message;
    // What the rigid phase adds to an instability another phase raised (a shell particle of
    // the rock leaving the domain is caught by the SPH phase first).
    const std::string d = rig.solver->diagnose();
    EXPECT_NE(d.find("fastest body 'rock'"), std::string::npos) << d;
    EXPECT_NE(d.find("contacts 2000 N at t = 0 s"), std::string::npos) << d;
}

TEST(RigidBodies, VertexInFrontOfAPostKeepsItsSideWhenTheCentrePassesTheFace) {
    // A cube tilted 50 degrees about y rests over the upstream edge of a post (x in [0, 0.05],
    // top z = 0.3): its lowest corners hang 2 mm below the top, 2.5 mm upstream of the centre.
    // With the centre 1 mm in front of the upstream face x = 0 the corners are 3.5 mm in front
    // of it (within the 4 mm contact reach): no contact. Moved 2 mm downstream, the centre is
    // past the face but the corners are still 1.5 mm in front, outside the post: still no
    // contact (the centre's side of the face threw rocks out of the check dam). Moved 3 mm
    // further, the corners are 1.5 mm inside the post through its upstream face, and the
    // contact pushes them back upstream (linear springs: 2 x k_n x 1.5 mm on the post).
    test::RigidRig rig;
    rig.materials[0].kn = 1e5;
    rig.materials[0].restitution = 1.0;
    rig.materials[0].friction = 0;
    const Real a = 0.02, angle = 50 * 3.14159265358979 / 180;
    const Real drop = a * (std::cos(angle) + std::sin(angle)); // centre to lowest corner in z
    const Real lead = a * (std::cos(angle) - std::sin(angle)); // and in x (< 0: upstream)
    const Vec3 centre{-0.001, 0.1, 0.298 + drop};
    rig.add(test::RigidRig::box("rock", centre - Vec3{a, a, a}, centre + Vec3{a, a, a}), 2650);
    rig.bodies[0].q = rigid::from_rotation_vector(Vec3{0, angle, 0});
    dem::Wall post;
    post.name = "post";
    rig.walls.add(post, {tri({0, 0, 0}, {0, 0.2, 0.3}, {0, 0.2, 0}), // upstream face, n = -x
                         tri({0, 0, 0}, {0, 0, 0.3}, {0, 0.2, 0.3}),
                         tri({0, 0, 0.3}, {0.05, 0, 0.3}, {0.05, 0.2, 0.3}), // top, n = +z
                         tri({0, 0, 0.3}, {0.05, 0.2, 0.3}, {0, 0.2, 0.3})});
    rig.start({0, 0, 0});
    ASSERT_NEAR(rig.body(0).to_world(Vec3{a, a, -a}).x, -0.001 + lead, 1e-9); // a lowest corner
    EXPECT_NEAR(lead, -0.00246, 1e-5);
    EXPECT_EQ(rig.solver->contacts(), 0);
    rig.body(0).pos.x += 0.002; // centre past the face, corners still in front
    rig.solver->compute_forces();
    EXPECT_EQ(rig.solver->contacts(), 0);
    EXPECT_NEAR(norm(rig.solver->wall_force(0)), 0, 1e-12);
    rig.body(0).pos.x += 0.003; // corners 1.5 mm into the post through its upstream face
    rig.solver->compute_forces();
    const Real depth = 0.004 + lead;
    EXPECT_EQ(rig.solver->contacts(), 2);
    EXPECT_NEAR(rig.solver->wall_force(0).x, 2 * 1e5 * depth, 1e-6);
    EXPECT_NEAR(rig.solver->wall_force(0).z, 0, 1e-9);
}

TEST(RigidBodies, FastBodySeesAnImpactComingFromBeyondItsContactReach) {
    // A 40 mm cube falls corner-first at 10 m/s onto a floor triangle. The contact search
    // skips primitives out of every feature's reach (BodyContacts' bound-radius cull), but a
    // primitive the body closes on within the horizon (3 ms before the first step: 30 mm)
    // must stay in: with the lowest corner 20 mm above the floor (centre to floor 20 mm more
    // than the bound radius, five times the 4 mm vertex reach) the step is cut for the impact;
    // 50 mm above, the impact is beyond the horizon and the step is not cut.
    for (const Real gap : {0.02, 0.05}) {
        test::RigidRig rig;
        rig.materials[0].kn = 1e5;
        const Real a = 0.02, bound = a * std::sqrt(Real(3));
        rig.add(test::RigidRig::box("rock", Vec3{-a, -a, -a}, Vec3{a, a, a}), 2650);
        // Corner (1, 1, 1) turned to point straight down.
        const Vec3 diag = (1 / std::sqrt(Real(3))) * Vec3{1, 1, 1}, down{0, 0, -1};
        const Vec3 axis = cross(diag, down);
        rig.bodies[0].q =
            rigid::from_rotation_vector(std::acos(dot(diag, down)) / norm(axis) * axis);
        rig.bodies[0].pos = {0, 0, bound + gap};
        rig.bodies[0].vel = {0, 0, -10};
        dem::Wall floor;
        floor.name = "floor";
        rig.walls.add(floor, {tri({-1, -1, 0}, {1, -1, 0}, {0, 1, 0})});
        rig.start({0, 0, 0});
        ASSERT_NEAR(rig.body(0).to_world(Vec3{a, a, a}).z, gap, 1e-9); // the corner's height
        EXPECT_EQ(rig.solver->contacts(), 0);
        EXPECT_EQ(rig.solver->stable_dt().limiter, gap < 0.03 ? "impact" : "none") << gap;
    }
}
