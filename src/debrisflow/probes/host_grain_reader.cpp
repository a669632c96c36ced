#include "debrisflow/dem/dem_solver.hpp"
#include "debrisflow/exec/host_space.hpp"
#include "debrisflow/probes/grain_reader.hpp"

namespace debrisflow::probes {

namespace {
GrainsRead grains_of(const dem::DemSolver& solver) {
    const dem::GrainSet& g = solver.grains();
    const auto& clump_of = solver.clump_of_ids();
    return {g.pos.data(),      g.vel.data(),  g.spin.data(),
            g.radius.data(),   g.mass.data(), g.inv_inertia.data(),
            g.material.data(), g.id.data(),   clump_of.empty() ? nullptr : clump_of.data(),
            g.size()};
}

std::vector<Real> densities(const dem::DemSolver& solver) {
    std::vector<Real> rho;
    for (const auto& m : solver.materials()) rho.push_back(m.density);
    return rho;
}
} // namespace

GrainSums HostGrainReader::sums(const GrainBox& box) const {
    using Space = exec::HostSpace;
    const auto& cl = solver_.grains().clumps;
    const ClumpsRead clumps{
        cl.pos.data(),    cl.vel.data(),  cl.ang_mom.data(), cl.inv_inertia.data(),
        cl.orient.data(), cl.mass.data(), cl.size()};
    const std::vector<Real> rho = densities(solver_);
    GrainSums s = Space::fold<GrainSums>(clumps.n, ClumpEnergy{clumps, box});
    const GrainsRead g = grains_of(solver_);
    GrainSums::combine(s, Space::fold<GrainSums>(g.n, GrainSumsIn{g, rho.data(), box}));
    return s;
}

Real HostGrainReader::runup(int wall, Real bed) const {
    std::vector<dem::WallPrimitive> faces;
    for (const auto& w : solver_.walls().primitives())
        if (w.wall == wall) faces.push_back(w);
    const GrainsRead g = grains_of(solver_);
    const GrainTopOnWall top{g, faces.data(), Index(faces.size()), bed, 0};
    return exec::HostSpace::max_from(g.n, top, 0);
}

int HostGrainReader::add_plane(const CrossingPlane& plane) {
    planes_.push_back(plane);
    last_.emplace_back();
    return int(planes_.size()) - 1;
}

GrainSums HostGrainReader::cross(int plane) {
    using Space = exec::HostSpace;
    const GrainsRead g = grains_of(solver_);
    std::vector<Real>& last = last_[std::size_t(plane)];
    const Real top = Space::max_from(g.n, GrainIdOf{g.id}, -1);
    if (Real(last.size()) < top + 1) last.resize(std::size_t(top + 1), unseen_distance);
    const std::vector<Real> rho = densities(solver_);
    return Space::fold<GrainSums>(
        g.n, GrainCrossing{g, rho.data(), planes_[std::size_t(plane)], last.data()});
}

std::vector<GrainRow> HostGrainReader::select(const GrainBox& box) const {
    const GrainsRead g = grains_of(solver_);
    const std::vector<Real> rho = densities(solver_);
    std::vector<Index> flag(std::size_t(g.n)), at(std::size_t(g.n));
    Index m = 0;
    for (Index i = 0; i < g.n; ++i) {
        FlagGrainsIn{g, box, flag.data()}(i);
        at[std::size_t(i)] = m;
        m += flag[std::size_t(i)];
    }
    std::vector<GrainRow> rows(static_cast<std::size_t>(m));
    const GatherGrainRows gather{g, rho.data(), flag.data(), at.data(), rows.data()};
    for (Index i = 0; i < g.n; ++i) gather(i);
    return rows;
}

} // namespace debrisflow::probes
