#include "debrisflow/dem/critical_dt.hpp"
#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <limits>

namespace debrisflow::dem {

time::DtLimit critical_dt(const GrainSet& grains, const std::vector<int>& wall_materials,
                          const std::vector<Material>& materials,
                          const std::vector<PairParams>& table, const DemParams& params,
                          const sph::Domain& domain, Real safety) {
    const Index n = grains.size();
    const int nm = int(materials.size());
    if (n == 0) return {std::numeric_limits<Real>::max(), "no grains"};
    std::vector<Real> mmin(std::size_t(nm), std::numeric_limits<Real>::max()), rmin = mmin;
    Real vmax = 0;
    for (Index i = 0; i < n; ++i) {
        const std::size_t m = grains.material[std::size_t(i)];
        mmin[m] = std::min(mmin[m], grains.mass[std::size_t(i)]);
        rmin[m] = std::min(rmin[m], grains.radius[std::size_t(i)]);
        vmax = std::max(vmax, norm(grains.vel[std::size_t(i)]));
    }
    Real vref = params.reference_velocity;
    if (vref <= 0) {
        const Real height = domain.hi.z - domain.lo.z;
        vref = std::max({vmax, std::sqrt(2 * norm(params.gravity) * height), Real(1)});
    }
    const Real pi = 3.14159265358979323846;
    time::DtLimit best{std::numeric_limits<Real>::max(), ""};
    auto consider = [&](Real dt, std::string why) {
        if (dt < best.dt) best = {dt, std::move(why)};
    };
    std::vector<int> partners; // grain materials, wall materials, and "own" (-1)
    for (int a = 0; a < nm; ++a)
        if (mmin[std::size_t(a)] < std::numeric_limits<Real>::max()) partners.push_back(a);
    const std::size_t grain_partners = partners.size();
    for (int m : wall_materials) partners.push_back(m);
    for (int a = 0; a < nm; ++a) {
        if (mmin[std::size_t(a)] == std::numeric_limits<Real>::max()) continue;
        const Material& ma = materials[std::size_t(a)];
        for (std::size_t k = 0; k < partners.size(); ++k) {
            const int b = partners[k] < 0 ? a : partners[k];
            const bool wall = k >= grain_partners;
            const PairParams& p = table[std::size_t(a * nm + b)];
            const Real m1 = mmin[std::size_t(a)], r1 = rmin[std::size_t(a)];
            const Real meff = wall ? m1 : m1 * mmin[std::size_t(b)] / (m1 + mmin[std::size_t(b)]);
            const Real reff = wall ? r1 : r1 * rmin[std::size_t(b)] / (r1 + rmin[std::size_t(b)]);
            const std::string pair =
                ma.name + "-" + (wall ? "wall" : materials[std::size_t(b)].name);
            if (p.law == LawId::linear) {
                // Contact duration of the damped linear oscillator: pi / (w0 sqrt(1 - zeta^2)).
                const Real w0 = std::sqrt(std::max(p.kn, p.kt) / meff);
                consider(safety * pi / (w0 * std::sqrt(1 - p.damping * p.damping)),
                         fmt::format("{} x linear contact time ({})", safety, pair));
            } else {
                // Hertz contact time 2.868 (m*^2 / (E*^2 R* v))^(1/5) (Johnson 1985).
                const Real tc =
                    2.868 * std::pow(meff * meff / (p.e_star * p.e_star * reff * vref), Real(0.2));
                consider(safety * tc, fmt::format("{} x Hertz contact time at {:.3g} m/s ({})",
                                                  safety, vref, pair));
                // Rayleigh time pi r sqrt(rho/G) / (0.1631 nu + 0.8766) of the grain material.
                if (!ma.rigid && ma.youngs_modulus > 0) {
                    const Real g = ma.youngs_modulus / (2 * (1 + ma.poisson));
                    const Real tr =
                        pi * r1 * std::sqrt(ma.density / g) / (0.1631 * ma.poisson + 0.8766);
                    consider(0.2 * tr, fmt::format("0.2 x Rayleigh time ({})", ma.name));
                }
            }
        }
    }
    return best;
}

} // namespace debrisflow::dem
