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
    return std::make_unique<GaugeProbe>(s.name(), s.every(), x, Real(0.25) * c.dp, c.domain.lo.z,
                                        c.domain.hi.z);
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

std::vector<Real> PressureProbe::sample_fluid(const FluidReader& fluid) const {
    return {fluid.samples({x_})[0].p};
}

std::vector<Real> VelocityProbe::sample_fluid(const FluidReader& fluid) const {
    const PointSample s = fluid.samples({x_})[0];
    return {s.v.x, s.v.y, s.v.z, norm(s.v)};
}

// The kernel sum of the volume of fluid and boundary particles (FilledFraction) downward from
// the domain's top, so that the thin under-filled layer DBC leaves between fluid and wall
// cannot pass for the surface; the first level filled to 0.5 is the surface. Solids count as
// filled, so that a film on the bed raises the reading from the bed's elevation by its
// thickness instead of staying dry until it is a kernel deep. The levels are read in batches
// (one evaluation where the particles are per batch).
std::vector<Real> GaugeProbe::sample_fluid(const FluidReader& fluid) const {
    constexpr int batch = 32;
    Real prev_w = 0;
    Real z = top_;
    while (z >= bottom_) {
        std::vector<Vec3> levels;
        for (Real l = z; l >= bottom_ && levels.size() < batch; l -= dz_)
            levels.push_back({x_.x, x_.y, l});
        const std::vector<Real> w = fluid.filled(levels);
        for (std::size_t k = 0; k < levels.size(); ++k) {
            const Real level = levels[k].z;
            if (w[k] >= 0.5) {
                if (level == top_) return {level};
                // linear interpolation of the 0.5 crossing between the level and the one above
                const Real f = (w[k] - Real(0.5)) / (w[k] - prev_w);
                return {level + f * dz_};
            }
            prev_w = w[k];
        }
        z = levels.back().z - dz_;
    }
    return {bottom_};
}

std::vector<Real> FrontProbe::sample_fluid(const FluidReader& fluid) const {
    return {sign_ * fluid.front(axis_, sign_)};
}

} // namespace debrisflow::probes
