#include "debrisflow/scenario/build_fem.hpp"
#include "debrisflow/core/error.hpp"
#include "debrisflow/io/named.hpp"
#include <algorithm>
#include <fmt/format.h>

namespace debrisflow::scenario {

namespace {

fem::ElementType element_type(const std::string& name) {
    if (name == "tet4") return fem::ElementType::tet4;
    if (name == "tet10") return fem::ElementType::tet10;
    if (name == "quad4") return fem::ElementType::quad4;
    return fem::ElementType::hex8;
}

} // namespace

fem::FemMesh build_fem_mesh(const io::FemSolidSpec& s, const io::CaseSpec& c) {
    const fem::ElementType t = element_type(s.element);
    fem::FemMesh m;
    if (s.mesh == "box")
        m = fem::box_mesh(t, s.min, s.max, s.divisions);
    else if (s.mesh == "trapezoid")
        m = fem::trapezoid_mesh(t, s.trapezoid, s.divisions);
    else
        m = fem::read_gmsh(s.file, t);
    Vec3 lo = m.nodes.front(), hi = lo;
    for (const Vec3& p : m.nodes)
        for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], p[k]), hi[k] = std::max(hi[k], p[k]);
    const Real tol = 1e-6 * norm(hi - lo);
    for (const auto& ns : c.fem.node_sets) {
        if (ns.solid != s.name) continue;
        Vec3 a = ns.min, b = ns.max;
        if (c.dim == 2) a.y = -1, b.y = 1;
        auto nodes = m.nodes_in(a, b, tol);
        if (nodes.empty())
            throw InputError(fmt::format("{}: node set '{}' holds no node of solid '{}'", c.file,
                                         ns.name, s.name));
        m.node_sets[ns.name] = std::move(nodes);
    }
    return m;
}

std::unique_ptr<fem::FemSolver> make_fem_solver(const io::CaseSpec& c) {
    fem::FemParams p = c.fem.params;
    if (c.fluids.empty() && !c.has_dem && !c.has_bodies() && p.max_subcycles == 0)
        p.max_subcycles = 1;
    auto solver = std::make_unique<fem::FemSolver>(p, c.fem.materials);
    for (const auto& s : c.fem.solids) {
        const fem::FemMesh mesh = build_fem_mesh(s, c);
        try {
            solver->add_solid(s.name, mesh, io::index_named(c.fem.materials, s.material));
            for (const auto& f : s.fixed)
                solver->fix(solver->node_set(s.name + "." + f), {true, true, true});
        } catch (const InputError& e) {
            throw InputError(c.file + ": " + e.what());
        }
    }
    for (const auto& l : c.fem.loads) {
        try {
            solver->add_load({solver->node_set(l.set), l.force, l.times, l.scale});
        } catch (const InputError& e) {
            throw InputError(c.file + ": [[fem_load]]: " + e.what());
        }
    }
    solver->initialize();
    return solver;
}

} // namespace debrisflow::scenario
