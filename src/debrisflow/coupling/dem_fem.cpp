#include "debrisflow/coupling/dem_fem.hpp"
#include "debrisflow/fem/fem_surface.hpp"
#include "debrisflow/rigid/body_solver.hpp"

namespace debrisflow::coupling {

std::vector<Exchange> DemFemCoupling::exchanges() const {
    std::vector<Exchange> out{
        {"dem", "fem",
         "grains' contact impulse on the surface triangles (WallSet nodes' impulse) / dt, to "
         "the corners with barycentric weights",
         When::fem_step_loads},
        {"fem", "dem", "node positions and velocities, to the surface triangles' corners",
         When::fem_motion}};
    if (bodies_)
        out.push_back(
            {"rigid", "fem", "bodies' contact forces on the nodes (node_forces)", When::fem_loads});
    return out;
}

void DemFemCoupling::connect(const rigid::BodySolver* bodies) {
    bodies_ = bodies;
    fem_.add_step_source([this](std::vector<Vec3>& f, Real dt) {
        collect_grain_forces(f, dt);
        fem_.report_interface_force("grains", last_grain_force());
    });
    if (bodies_)
        fem_.add_load_source([this](std::vector<Vec3>& f) {
            add_body_forces(bodies_->node_forces(), f);
            Vec3 total{};
            for (const Vec3& v : bodies_->node_forces()) total += v;
            fem_.report_interface_force("bodies", total);
        });
    fem_.add_surface_mover([this](Real ahead) {
        if (ahead == 0) sync();
    });
}

DemFemCoupling::DemFemCoupling(fem::FemSolver& fem, dem::WallSet& walls,
                               const std::vector<int>& dem_material)
    : fem_(fem), walls_(walls) {
    auto& nodes = walls_.nodes();
    nodes.x = fem_.positions();
    nodes.v = fem_.velocities();
    nodes.impulse.assign(nodes.x.size(), Vec3{});
    const auto tris = triangles_per_solid();
    for (std::size_t s = 0; s < fem_.solids().size(); ++s) {
        dem::Wall w;
        w.name = fem_.solids()[s].name;
        w.material = dem_material[s];
        Vec3 c{};
        const auto& so = fem_.solids()[s];
        for (std::int32_t i = 0; i < so.nodes; ++i)
            c += fem_.positions()[std::size_t(so.first_node + i)];
        w.origin = (Real(1) / Real(so.nodes)) * c;
        walls_of_.push_back(walls_.add_nodal(w, tris[s]));
    }
    eroded_seen_ = fem_.eroded_elements();
}

std::vector<std::vector<dem::NodalCorners>> DemFemCoupling::triangles_per_solid() const {
    std::vector<std::vector<dem::NodalCorners>> out(fem_.solids().size());
    const Vec3 across{0, 1, 0}; // 2D: an edge is extruded 1 m to each side of y = 0
    for (const auto& f : fem::boundary_facets(fem_)) {
        auto& list = out[std::size_t(f.solid)];
        if (f.nodes[2] >= 0) {
            list.push_back({{f.nodes[0], f.nodes[1], f.nodes[2]}, {}});
            continue;
        }
        const std::int32_t a = f.nodes[0], b = f.nodes[1];
        list.push_back({{a, b, b}, {-1 * across, -1 * across, across}});
        list.push_back({{a, b, a}, {-1 * across, across, across}});
    }
    return out;
}

void DemFemCoupling::sync() {
    auto& nodes = walls_.nodes();
    nodes.x = fem_.positions();
    nodes.v = fem_.velocities();
    if (fem_.eroded_elements() != eroded_seen_) {
        eroded_seen_ = fem_.eroded_elements();
        const auto tris = triangles_per_solid();
        for (std::size_t s = 0; s < walls_of_.size(); ++s)
            walls_.replace_nodal(walls_of_[s], tris[s]);
    }
    walls_.place_nodal();
}

void DemFemCoupling::collect_grain_forces(std::vector<Vec3>& f, Real dt) {
    auto& j = walls_.nodes().impulse;
    Vec3 total{};
    if (dt > 0)
        for (std::size_t i = 0; i < j.size() && i < f.size(); ++i) {
            const Vec3 fi = (1 / dt) * j[i];
            f[i] += fi;
            total += fi;
            j[i] = {};
        }
    last_grain_force_ = total;
}

void DemFemCoupling::add_body_forces(const std::vector<Vec3>& node_forces, std::vector<Vec3>& f) {
    for (std::size_t i = 0; i < node_forces.size() && i < f.size(); ++i) f[i] += node_forces[i];
}

std::size_t DemFemCoupling::triangles() const {
    std::size_t n = 0;
    for (const auto& p : walls_.primitives()) n += p.corners >= 0 ? 1 : 0;
    return n;
}

} // namespace debrisflow::coupling
