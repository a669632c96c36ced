// The SphSolver's stable step (CFL, forces, viscosity; DualSPHysics's criteria) and its
// health check (a particle outside the domain or not finite stops the run).
#include "debrisflow/core/error.hpp"
#include "debrisflow/exec/parallel.hpp"
#include "debrisflow/sph/sph_solver.hpp"
#include "debrisflow/sph/time_schemes_k.hpp"
#include <cmath>
#include <fmt/format.h>

namespace debrisflow::sph {

using particles::Kind;

time::DtLimit SphSolver::stable_dt() const {
    auto pv = const_cast<particles::ParticleSet&>(set_).view();
    const SignalSpeed signal{pv, eos_};
    const AccelerationNorm accel{pv};
    const Real cmax = exec::max_of(pv.n, signal);
    const Real amax = exec::max_of(pv.n, accel);
    const Real h = params_.h;
    time::DtLimit lim{params_.cfl * h / std::max(cmax, params_.c0), "cfl"};
    if (amax > 0) {
        const Real dtf = params_.cfl * std::sqrt(h / amax);
        if (dtf < lim.dt) lim = {dtf, "force"};
    }
    // When one particle holds the step far below its nominal value, say which and why.
    const bool cfl_low = lim.limiter == "cfl" && cmax > Real(1.5) * params_.c0;
    const bool force_low = lim.limiter == "force" && amax > 100 * norm(params_.gravity);
    if (cfl_low || force_low) {
        const auto& s = set_;
        Index worst = -1;
        for (Index i = 0; i < s.size(); ++i) {
            if ((cfl_low && signal(i) >= cmax) || (force_low && accel(i) >= amax)) {
                worst = i;
                break;
            }
        }
        if (worst >= 0)
            lim.limiter += fmt::format(
                " (fluid id {} at ({:.3g}, {:.3g}, {:.3g}) m: rho/rho0 {:.3f}, |v| {:.3g} m/s, "
                "|a| {:.3g} m/s^2)",
                s.id[worst], s.x[worst], s.y[worst], s.z[worst], s.rho[worst] / params_.rho0,
                std::sqrt(s.vx[worst] * s.vx[worst] + s.vy[worst] * s.vy[worst] +
                          s.vz[worst] * s.vz[worst]),
                std::sqrt(s.ax[worst] * s.ax[worst] + s.ay[worst] * s.ay[worst] +
                          s.az[worst] * s.az[worst]));
    }
    const Real nu = max_kinematic_viscosity();
    if (nu > 0) {
        const Real dtv = Real(0.125) * h * h / nu; // Morris et al. 1997, eq. 19
        if (dtv < lim.dt) lim = {dtv, "viscous"};
    }
    return lim;
}

time::DtLimit SphSolver::initial_dt() const {
    const Real h = params_.h;
    time::DtLimit lim{params_.cfl * h / params_.c0, "cfl"};
    const Real g = norm(params_.gravity);
    if (g > 0 && params_.cfl * std::sqrt(h / g) < lim.dt)
        lim = {params_.cfl * std::sqrt(h / g), "force"};
    const Real nu =
        std::visit([](const auto& v) { return v.kinematic_viscosity(); }, models_.viscosity);
    if (nu > 0 && Real(0.125) * h * h / nu < lim.dt) lim = {Real(0.125) * h * h / nu, "viscous"};
    return lim;
}

void SphSolver::check_health(Real t) const {
    const Index n = set_.size();
    const Domain d = domain_;
    const auto& s = set_;
    // the first bad particle (n: none)
    const ParticleHealthy healthy{const_cast<particles::ParticleSet&>(s).view(), d};
    const auto first_bad = [&](Index i, Index& bad) {
        if (!healthy(i) && i < bad) bad = i;
    };
    const Index bad = exec::reduce(n, n, first_bad, [](Index& b, Index v) { b = v < b ? v : b; });
    if (bad == n) return;
    const bool finite = std::isfinite(s.x[bad]) && std::isfinite(s.vx[bad]) &&
                        std::isfinite(s.rho[bad]) && std::isfinite(s.z[bad]);
    throw InstabilityError(fmt::format(
        "{} at t = {:.6g} s: particle id {} ({}) at ({:.4g}, {:.4g}, {:.4g}) m, velocity "
        "({:.4g}, {:.4g}, {:.4g}) m/s, density {:.6g} kg/m^3{}",
        finite ? "particle left the domain" : "non-finite state (NaN/Inf)", t, s.id[bad],
        s.kind[bad] == std::uint8_t(Kind::fluid) ? "fluid" : "boundary", s.x[bad], s.y[bad],
        s.z[bad], s.vx[bad], s.vy[bad], s.vz[bad], s.rho[bad],
        finite ? fmt::format("; domain is ({}, {}, {}) to ({}, {}, {}) m{}", d.lo.x, d.lo.y, d.lo.z,
                             d.hi.x, d.hi.y, d.hi.z,
                             s.kind[bad] == std::uint8_t(Kind::fluid)
                                 ? " (domain.exit = \"remove\" takes fluid that leaves out of "
                                   "the run)"
                                 : "")
               : std::string()));
}

} // namespace debrisflow::sph
