#include "debrisflow/io/fem_reader.hpp"
#include "debrisflow/io/named.hpp"
#include <algorithm>
#include <filesystem>
#include <fmt/format.h>

namespace debrisflow::io {

namespace {

fem::FemMaterial read_fem_material(const ConfigTable& t) {
    fem::FemMaterial m;
    m.name = t.name("name");
    m.model = t.choice("model", {"linear_elastic", "mazars"}, "linear_elastic");
    m.density = t.positive("density");
    m.youngs_modulus = t.positive("youngs_modulus");
    m.poisson = t.real("poisson", 0.25);
    if (!(m.poisson >= 0 && m.poisson < 0.5)) t.fail("poisson", "must be in [0, 0.5)");
    if (m.model == "mazars") {
        m.damage_threshold = t.positive("damage_threshold");
        m.damage_a = t.real("damage_a", 1);
        if (!(m.damage_a >= 0 && m.damage_a <= 1)) t.fail("damage_a", "must be in [0, 1]");
        m.damage_b = t.positive("damage_b", 10000);
    }
    m.erosion_strain = t.real("erosion_strain", 0);
    if (m.erosion_strain < 0) t.fail("erosion_strain", "must be >= 0 (0: no erosion)");
    t.finish();
    return m;
}

std::array<int, 3> read_divisions(const ConfigTable& t, int dim) {
    const auto d = t.reals("divisions");
    if (d.size() != std::size_t(dim))
        t.fail("divisions", fmt::format("needs {} integers (elements along {})", dim,
                                        dim == 3 ? "x, y, z" : "x, z"));
    for (Real v : d)
        if (!(v >= 1) || v != std::floor(v) || v > 100000)
            t.fail("divisions", "must be integers within 1..100000");
    return dim == 3 ? std::array<int, 3>{int(d[0]), int(d[1]), int(d[2])}
                    : std::array<int, 3>{int(d[0]), 1, int(d[1])};
}

FemSolidSpec read_solid(const ConfigTable& t, const CaseSpec& c) {
    FemSolidSpec s;
    s.origin = t.origin();
    s.name = t.name("name");
    s.material = t.string("material");
    require_named(t, "material", c.fem.materials, s.material, "[[fem_material]]");
    s.element = c.dim == 2 ? t.choice("element", {"quad4"}, "quad4")
                           : t.choice("element", {"hex8", "tet4", "tet10"}, "hex8");
    s.mesh = t.choice("mesh", {"box", "trapezoid", "gmsh"}, "box");
    if (s.mesh == "box") {
        s.min = t.vec3("min", c.dim);
        s.max = t.vec3("max", c.dim);
        for (int k = 0; k < 3; ++k)
            if (!(c.dim == 2 && k == 1) && !(s.max[k] > s.min[k]))
                t.fail("max", fmt::format("must exceed min in {}", "xyz"[k]));
        s.divisions = read_divisions(t, c.dim);
    } else if (s.mesh == "trapezoid") {
        auto& z = s.trapezoid;
        const Vec3 o = t.vec3("origin", c.dim);
        z.x0 = o.x, z.y0 = o.y, z.z0 = o.z;
        z.base_width = t.positive("base_width");
        z.crest_width = t.positive("crest_width");
        z.height = t.positive("height");
        z.upstream_offset = t.real("upstream_offset", 0);
        z.length = c.dim == 3 ? t.positive("length") : 1;
        s.divisions = read_divisions(t, c.dim);
    } else {
        std::filesystem::path p(t.string("file"));
        if (p.is_relative()) p = std::filesystem::path(t.file()).parent_path() / p;
        if (!std::filesystem::exists(p)) t.fail("file", "mesh file not found: " + p.string());
        s.file = p.string();
    }
    if (t.has("fixed")) s.fixed = t.strings("fixed");
    if (t.has("dem_material")) {
        s.dem_material = t.string("dem_material");
        require_named(t, "dem_material", c.dem.materials, s.dem_material, "DEM [[material]]");
    }
    t.finish();
    return s;
}

} // namespace

void read_fem(const ConfigTable& root, CaseSpec& c, Vec3 gravity) {
    for (const auto& t : root.tables("fem_material")) {
        c.fem.materials.push_back(read_fem_material(t));
        for (std::size_t i = 0; i + 1 < c.fem.materials.size(); ++i)
            if (c.fem.materials[i].name == c.fem.materials.back().name)
                t.fail("name", "two FEM materials are named \"" + c.fem.materials[i].name + "\"");
    }
    for (const auto& t : root.tables("solid")) {
        c.fem.solids.push_back(read_solid(t, c));
        for (std::size_t i = 0; i + 1 < c.fem.solids.size(); ++i)
            if (c.fem.solids[i].name == c.fem.solids.back().name)
                t.fail("name", "two solids are named \"" + c.fem.solids[i].name + "\"");
    }
    auto solid_exists = [&](const std::string& name) {
        return std::any_of(c.fem.solids.begin(), c.fem.solids.end(),
                           [&](const auto& s) { return s.name == name; });
    };
    for (const auto& t : root.tables("node_set")) {
        FemNodeSetSpec n;
        n.name = t.name("name");
        n.solid = t.string("solid");
        if (!solid_exists(n.solid)) t.fail("solid", "no [[solid]] named \"" + n.solid + "\"");
        n.min = t.vec3("min", c.dim);
        n.max = t.vec3("max", c.dim);
        t.finish();
        c.fem.node_sets.push_back(n);
    }
    for (const auto& t : root.tables("fem_load")) {
        FemLoadSpec l;
        l.set = t.string("set");
        if (l.set.find('.') == std::string::npos || !solid_exists(l.set.substr(0, l.set.find('.'))))
            t.fail("set", "name a node set as \"<solid>.<set>\" (e.g. \"beam.xmax\")");
        l.force = t.vec3("force", c.dim);
        if (t.has("times")) {
            l.times = t.reals("times");
            l.scale = t.reals("scale");
            if (l.times.size() != l.scale.size() || l.times.empty())
                t.fail("scale", "needs one value per entry of 'times'");
            for (std::size_t k = 1; k < l.times.size(); ++k)
                if (!(l.times[k] > l.times[k - 1])) t.fail("times", "must increase");
        }
        t.finish();
        c.fem.loads.push_back(l);
    }
    auto& p = c.fem.params;
    p.dim = c.dim;
    p.gravity = gravity;
    p.domain_min = c.domain.lo;
    p.domain_max = c.domain.hi;
    auto t = root.table("fem");
    if (!t) return;
    if (!c.has_fem()) t->fail("cfl", "[fem] given but no [[solid]]");
    p.cfl = t->positive("cfl", p.cfl);
    if (p.cfl > 1) t->fail("cfl", "must be <= 1 (fraction of the critical step)");
    p.alpha = t->real("damping_alpha", 0);
    p.beta = t->real("damping_beta", 0);
    if (p.alpha < 0) t->fail("damping_alpha", "must be >= 0 [1/s]");
    if (p.beta < 0) t->fail("damping_beta", "must be >= 0 [s]");
    p.max_subcycles = int(t->integer("max_subcycles", 0, 0, 100000000)); // 0: no limit
    c.fem.layers = int(t->integer("layers", 0, 0, max_boundary_layers)); // 0: ceil(2h/dp)
    t->finish();
}

} // namespace debrisflow::io
