#include "debrisflow/io/rigid_reader.hpp"
#include "debrisflow/io/dem_reader.hpp"
#include "debrisflow/io/named.hpp"
#include <algorithm>
#include <cmath>
#include <fmt/format.h>

namespace debrisflow::io {

namespace {

std::array<bool, 3> axes(const ConfigTable& t, const std::string& key) {
    std::array<bool, 3> out{false, false, false};
    if (!t.has(key)) return out;
    for (const auto& a : t.strings(key)) {
        if (a != "x" && a != "y" && a != "z") t.fail(key, "axes are \"x\", \"y\" or \"z\"");
        out[a[0] - 'x'] = true;
    }
    return out;
}

Vec3 row_vec(const std::vector<Real>& r) {
    return {r[0], r[1], r[2]};
}

BodySpec read_body(const ConfigTable& t, const CaseSpec& c) {
    BodySpec b;
    b.origin = t.origin();
    b.name = t.name("name");
    b.material = t.string("material");
    require_named(t, "material", c.dem.materials, b.material, "[[material]]");
    const dem::Material* mat = find_named(c.dem.materials, b.material);
    const std::string type = t.choice("shape", {"box", "sphere", "cylinder", "stl", "clump"});
    if (type == "sphere") {
        b.shape.type = "sphere";
        b.shape.center = t.vec3("center", c.dim);
        b.shape.radius = t.positive("radius");
    } else if (type == "clump") {
        b.shape.type = "clump";
        for (const auto& r : t.rows("spheres", 4)) {
            if (!(r[3] > 0)) t.fail("spheres", "radii (4th number) must be > 0");
            b.clump_centers.push_back(row_vec(r));
            b.clump_radii.push_back(r[3]);
        }
        if (b.clump_centers.empty()) t.fail("spheres", "a clump needs at least one sphere");
    } else {
        b.shape = read_shape(t, c.dim, {"box", "cylinder", "stl"});
        if (type == "stl" && c.dim == 2) t.fail("shape", "STL bodies need a 3D case");
    }
    b.density = t.positive("density", mat->density);
    if (t.has("mass")) b.mass = t.positive("mass");
    if (t.has("com_offset")) b.com_offset = t.vec3("com_offset", c.dim);
    if (t.has("inertia")) {
        const auto v = t.reals("inertia");
        if (v.size() != 6) t.fail("inertia", "expected [Ixx, Iyy, Izz, Ixy, Ixz, Iyz] (kg m^2)");
        b.inertia = std::array<Real, 6>{v[0], v[1], v[2], v[3], v[4], v[5]};
    }
    b.motion = t.choice("motion", {"free", "fixed", "prescribed"}, "free");
    b.velocity = t.vec3("velocity", c.dim, {});
    b.angular_velocity = t.vec3("angular_velocity", 3, {});
    if (t.has("motion_times")) {
        if (b.motion != "prescribed")
            t.fail("motion_times", "motion tables need motion = \"prescribed\"");
        b.motion_times = t.reals("motion_times");
        for (std::size_t k = 1; k < b.motion_times.size(); ++k)
            if (!(b.motion_times[k] > b.motion_times[k - 1]))
                t.fail("motion_times", "times must increase");
        const std::size_t n = b.motion_times.size();
        auto table = [&](const std::string& key) {
            std::vector<Vec3> out(n);
            if (!t.has(key)) return out;
            const auto rows = t.rows(key, 3);
            if (rows.size() != n)
                t.fail(key, fmt::format("needs one [x, y, z] row per time ({} rows)", n));
            for (std::size_t k = 0; k < n; ++k) out[k] = row_vec(rows[k]);
            return out;
        };
        b.motion_velocity = table("motion_velocity");
        b.motion_angular_velocity = table("motion_angular_velocity");
    }
    b.lock_translation = axes(t, "lock_translation");
    b.lock_rotation = axes(t, "lock_rotation");
    if (t.has("track_point")) b.track_point = t.vec3("track_point", c.dim);
    b.contact_radius = t.real("contact_radius", 0);
    if (b.contact_radius < 0) t.fail("contact_radius", "must be >= 0");
    if (!c.fluids.empty()) {
        b.layers = int(
            t.integer("layers", long(sph::kernel_layers(c.sph.h, c.dp)), 1, max_boundary_layers));
    }
    t.finish();
    return b;
}

JointSpec read_joint(const ConfigTable& t, const CaseSpec& c) {
    JointSpec j;
    j.name = t.name("name");
    j.type = t.choice("type", {"hinge", "ball", "fixed", "spring"});
    const auto bodies = t.strings("bodies");
    if (bodies.empty() || bodies.size() > 2)
        t.fail("bodies", "one body (joined to the ground) or two bodies");
    for (const auto& n : bodies)
        if (std::none_of(c.rigid.bodies.begin(), c.rigid.bodies.end(),
                         [&](const auto& b) { return b.name == n; }))
            t.fail("bodies", "no [[body]] named \"" + n + "\"");
    j.body_a = bodies[0];
    j.body_b = bodies.size() > 1 ? bodies[1] : "";
    if (j.body_a == j.body_b) t.fail("bodies", "a joint needs two different bodies");
    j.point = t.vec3("point", c.dim);
    if (j.type == "hinge") {
        j.axis = t.vec3("axis", c.dim, {0, 1, 0});
        if (c.dim == 2) j.axis = {0, 1, 0};
        if (norm(j.axis) == 0) t.fail("axis", "must be a non-zero vector");
        j.axis = (1 / norm(j.axis)) * j.axis;
    }
    if (j.type == "spring") {
        j.point_b = t.vec3("point_b", c.dim);
        j.stiffness = t.positive("stiffness");
        j.damping = t.real("damping", 0);
        if (j.damping < 0) t.fail("damping", "must be >= 0");
        if (t.has("rest_length")) {
            j.rest_length = t.real("rest_length");
            if (*j.rest_length < 0) t.fail("rest_length", "must be >= 0");
        }
    }
    t.finish();
    return j;
}

} // namespace

void read_rigid(const ConfigTable& root, CaseSpec& c) {
    for (const auto& t : root.tables("body")) {
        if (c.dem.materials.empty()) t.fail("material", "define a [[material]] first");
        c.rigid.bodies.push_back(read_body(t, c));
        for (std::size_t i = 0; i + 1 < c.rigid.bodies.size(); ++i)
            if (c.rigid.bodies[i].name == c.rigid.bodies.back().name)
                t.fail("name", "two bodies are named \"" + c.rigid.bodies.back().name + "\"");
    }
    for (const auto& t : root.tables("joint")) {
        if (c.rigid.bodies.empty()) t.fail("bodies", "joints need [[body]] blocks");
        c.rigid.joints.push_back(read_joint(t, c));
    }
    auto t = root.table("rigid");
    const bool alone = c.fluids.empty() && !c.has_dem;
    if (!t) {
        if (alone && c.has_bodies())
            root.fail("rigid", "a case with bodies only needs [rigid] dt (time step, s)");
        return;
    }
    if (!c.has_bodies()) t->fail("dt", "[rigid] given but no [[body]]");
    if (alone)
        c.rigid.dt = t->positive("dt");
    else if (t->has("dt"))
        c.rigid.dt = t->positive("dt");
    c.rigid.contact_spacing = t->positive("contact_spacing", c.dp > 0 ? c.dp : 0);
    c.rigid.joint_iterations = int(t->integer("joint_iterations", 30, 1, 100000));
    c.rigid.joint_stabilization = t->real("joint_stabilization", 0.2);
    if (c.rigid.joint_stabilization < 0 || c.rigid.joint_stabilization > 1)
        t->fail("joint_stabilization", "must be within [0, 1]");
    t->finish();
}

} // namespace debrisflow::io
