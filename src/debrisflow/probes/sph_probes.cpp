#include "debrisflow/probes/sph_probes.hpp"
#include "debrisflow/sph/sph_solver.hpp"
#include <cmath>
#include <limits>

namespace debrisflow::probes {

std::unique_ptr<Probe> PressureProbe::from_config(const ProbeSetup& s) {
    s.require(!s.c.fluids.empty(), "a fluid");
    return std::make_unique<PressureProbe>(s.name(), s.every(), s.point_in_domain("position"));
}

std::unique_ptr<Probe> VelocityProbe::from_config(const ProbeSetup& s) {
    s.require(!s.c.fluids.empty(), "a fluid");
    return std::make_unique<VelocityProbe>(s.name(), s.every(), s.point_in_domain("position"));
}

std::unique_ptr<Probe> GaugeProbe::from_config(const ProbeSetup& s) {
    s.require(!s.c.fluids.empty(), "a fluid");
    // A gauge stands at a plan position: (x, y) in 3D, (x) in 2D; a vertical coordinate, if
    // given, is ignored (the gauge scans the whole height of the domain).
    const auto& c = s.c;
    const auto v = s.t.reals("position");
    const std::size_t plan = c.dim == 3 ? 2 : 1;
    if (v.size() != plan && v.size() != plan + 1)
        s.t.fail("position", c.dim == 3 ? "expected [x, y] (or [x, y, z], z ignored)"
                                        : "expected [x] (or [x, z], z ignored)");
    const Vec3 x = c.dim == 3 ? Vec3{v[0], v[1], c.domain.lo.z} : Vec3{v[0], 0, c.domain.lo.z};
    s.require_in_domain("position", x);
    return std::make_unique<GaugeProbe>(s.name(), s.every(), x, Real(0.25) * c.dp);
}

std::unique_ptr<Probe> FrontProbe::from_config(const ProbeSetup& s) {
    s.require(!s.c.fluids.empty(), "a fluid");
    // "+x" (or "x"): the largest x of the fluid; "-x": the smallest (a surge running towards -x)
    const std::string a =
        s.t.choice("axis", {"x", "y", "z", "+x", "+y", "+z", "-x", "-y", "-z"}, "x");
    const int axis = a.back() == 'x' ? 0 : (a.back() == 'y' ? 1 : 2);
    if (s.c.dim == 2 && axis == 1) s.t.fail("axis", "2D cases flow in the x-z plane");
    return std::make_unique<FrontProbe>(s.name(), s.every(), axis, a.front() == '-' ? -1 : 1);
}

PointSample interpolate(const sph::SphSolver& solver, Vec3 x) {
    auto pv = const_cast<sph::SphSolver&>(solver).particles().view();
    return std::visit(
        [&](const auto& kernel) {
            using K = std::decay_t<decltype(kernel)>;
            return ShepardSample<K>{pv, solver.grid().view(), kernel}(x);
        },
        solver.models().kernel);
}

std::vector<Real> PressureProbe::sample_fluid(const sph::SphSolver& solver) const {
    return {interpolate(solver, x_).p};
}

std::vector<Real> VelocityProbe::sample_fluid(const sph::SphSolver& solver) const {
    const PointSample s = interpolate(solver, x_);
    return {s.v.x, s.v.y, s.v.z, norm(s.v)};
}

// Kernel sum of the volume of fluid and boundary particles at x (FilledFraction): solids count
// as filled, so that a film on the bed raises the reading from the bed's elevation by its
// thickness instead of staying dry until it is a kernel deep.
Real filled_fraction(const sph::SphSolver& solver, Vec3 x) {
    auto pv = const_cast<sph::SphSolver&>(solver).particles().view();
    return std::visit(
        [&](const auto& kernel) {
            using K = std::decay_t<decltype(kernel)>;
            return FilledFraction<K>{pv, solver.grid().view(), kernel}(x);
        },
        solver.models().kernel);
}

std::vector<Real> GaugeProbe::sample_fluid(const sph::SphSolver& solver) const {
    // Downward from the domain's top, so that the thin under-filled layer DBC leaves between
    // fluid and wall cannot pass for the surface; the first level filled to 0.5 is the surface.
    const auto& d = solver.domain();
    Real prev_w = 0;
    for (Real z = d.hi.z; z >= d.lo.z; z -= dz_) {
        const Real w = filled_fraction(solver, {x_.x, x_.y, z});
        if (w >= 0.5) {
            if (z == d.hi.z) return {z};
            // linear interpolation of the 0.5 crossing between z and z + dz
            const Real f = (w - Real(0.5)) / (w - prev_w);
            return {z + f * dz_};
        }
        prev_w = w;
    }
    return {d.lo.z};
}

std::vector<Real> FrontProbe::sample_fluid(const sph::SphSolver& solver) const {
    auto pv = const_cast<sph::SphSolver&>(solver).particles().view();
    const Real lowest = -std::numeric_limits<Real>::max();
    const FrontCoordinate coordinate{pv, axis_, sign_, lowest};
    Real m = lowest; // the largest of sign * coordinate
    for (Index i = 0; i < pv.n; ++i) m = std::max(m, coordinate(i));
    return {sign_ * m};
}

Vec3 fluid_wall_force(const sph::SphSolver& solver, int group) {
    const WallParticleLoad load{const_cast<sph::SphSolver&>(solver).particles().view(), group};
    Vec3 f;
    for (Index i = 0; i < load.pv.n; ++i)
        if (load.on_wall(i)) f += load(i); // the wall's particles, in index order
    return f;
}

} // namespace debrisflow::probes
