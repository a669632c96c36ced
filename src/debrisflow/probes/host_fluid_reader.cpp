#include "debrisflow/probes/fluid_reader.hpp"
#include "debrisflow/sph/sph_solver.hpp"
#include <limits>

namespace debrisflow::probes {

namespace {
particles::ParticleView view_of(const sph::SphSolver& solver) {
    return const_cast<sph::SphSolver&>(solver).particles().view();
}

// f(x) at every point with the case's kernel: Sampler<Kernel>{particles, grid, kernel}.
template <template <class> class Sampler, class Out>
std::vector<Out> at_points(const sph::SphSolver& solver, const std::vector<Vec3>& points) {
    const auto pv = view_of(solver);
    return std::visit(
        [&](const auto& kernel) {
            using K = std::decay_t<decltype(kernel)>;
            const Sampler<K> f{pv, solver.grid().view(), kernel};
            std::vector<Out> out;
            out.reserve(points.size());
            for (const Vec3& x : points) out.push_back(f(x));
            return out;
        },
        solver.models().kernel);
}
} // namespace

std::vector<PointSample> HostFluidReader::samples(const std::vector<Vec3>& points) const {
    return at_points<ShepardSample, PointSample>(solver_, points);
}

std::vector<Real> HostFluidReader::filled(const std::vector<Vec3>& points) const {
    return at_points<FilledFraction, Real>(solver_, points);
}

Real HostFluidReader::front(int axis, Real sign) const {
    const Real lowest = -std::numeric_limits<Real>::max();
    const FrontCoordinate coordinate{view_of(solver_), axis, sign, lowest};
    Real m = lowest;
    for (Index i = 0; i < coordinate.pv.n; ++i) m = std::max(m, coordinate(i));
    return m;
}

Vec3 HostFluidReader::wall_load(int group) const {
    const WallParticleLoad load{view_of(solver_), group};
    Vec3 f;
    for (Index i = 0; i < load.pv.n; ++i)
        if (load.on_wall(i)) f += load(i); // the wall's particles, in index order
    return f;
}

std::vector<ParticleRow> HostFluidReader::select(const RowSelection& selection) const {
    const auto pv = view_of(solver_);
    const auto& id = solver_.particles().id;
    std::vector<ParticleRow> out;
    for (Index i = 0; i < pv.n; ++i) {
        if (selection(pv, i)) out.push_back(row_of(pv, id[std::size_t(i)], i));
    }
    return out;
}

} // namespace debrisflow::probes
