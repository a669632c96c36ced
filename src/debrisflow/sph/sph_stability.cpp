// The SphSolver's stable step (CFL, forces, viscosity; DualSPHysics's criteria) and its
// health check (a particle outside the domain, not finite, or a fluid particle compressed or
// expanded beyond max_density_change stops the run).
#include "debrisflow/core/error.hpp"
#include "debrisflow/exec/parallel.hpp"
#include "debrisflow/models/eos_tait_k.hpp"
#include "debrisflow/sph/sph_solver.hpp"
#include "debrisflow/sph/step_limit.hpp"
#include "debrisflow/sph/time_schemes_k.hpp"
#include <cmath>
#include <fmt/format.h>

namespace debrisflow::sph {

using particles::Kind;

time::DtLimit step_limit(const SphParams& p, const StepExtremes& e) {
    const Real h = p.h;
    time::DtLimit lim{p.cfl * h / std::max(e.cmax, p.c0), "cfl"};
    if (e.amax > 0) {
        const Real dtf = p.cfl * std::sqrt(h / e.amax);
        if (dtf < lim.dt) lim = {dtf, "force"};
    }
    if (e.nu > 0) {
        const Real dtv = Real(0.125) * h * h / e.nu; // Morris et al. 1997, eq. 19
        if (dtv < lim.dt) lim = {dtv, "viscous"};
    }
    return lim;
}

LowStep low_step(const SphParams& p, const time::DtLimit& lim, const StepExtremes& e) {
    if (lim.limiter == "cfl" && e.cmax > Real(1.5) * p.c0) return LowStep::signal;
    if (lim.limiter == "force" && e.amax > 100 * norm(p.gravity)) return LowStep::force;
    return LowStep::none;
}

std::string low_step_words(const ParticleState& s, Real rho0) {
    return fmt::format(" (fluid id {} at ({:.3g}, {:.3g}, {:.3g}) m: rho/rho0 {:.3f}, |v| {:.3g} "
                       "m/s, |a| {:.3g} m/s^2)",
                       s.id, s.x.x, s.x.y, s.x.z, s.rho / rho0, norm(s.v), norm(s.a));
}

std::string unhealthy_message(const ParticleState& s, Real t, const Domain& d, const SphParams& p) {
    const bool finite = std::isfinite(s.x.x) && std::isfinite(s.v.x) && std::isfinite(s.rho) &&
                        std::isfinite(s.x.z);
    bool inside = true;
    for (int k = 0; k < 3; ++k)
        if (!d.periodic[k] && (s.x[k] < d.lo[k] || s.x[k] > d.hi[k])) inside = false;
    const std::string where = fmt::format(
        "at t = {:.6g} s: particle id {} ({}) at ({:.4g}, {:.4g}, {:.4g}) m, velocity ({:.4g}, "
        "{:.4g}, {:.4g}) m/s, density {:.6g} kg/m^3",
        t, s.id, s.fluid ? "fluid" : "boundary", s.x.x, s.x.y, s.x.z, s.v.x, s.v.y, s.v.z, s.rho);
    if (!finite) return "non-finite state (NaN/Inf) " + where;
    if (!inside)
        return fmt::format("particle left the domain {}; domain is ({}, {}, {}) to ({}, {}, {}) "
                           "m{}",
                           where, d.lo.x, d.lo.y, d.lo.z, d.hi.x, d.hi.y, d.hi.z,
                           s.fluid ? " (domain.exit = \"remove\" takes fluid that leaves out of "
                                     "the run)"
                                   : "");
    return fmt::format(
        "fluid {} beyond the weakly-compressible range {} (rho/rho0 = {:.3f}, outside 1 +- {:g}; "
        "pressure {:.4g} Pa): the flow is too fast or too violent for the sound speed c0 = {:.4g} "
        "m/s (a weakly-compressible fluid needs c0 of at least 10 times its fastest speed: raise "
        "sph.c0 or sph.c0_coefficient), or the time step is too long (sph.cfl)",
        s.rho > p.rho0 ? "compressed" : "expanded", where, s.rho / p.rho0, max_density_change,
        models::TaitEos(p.rho0, p.c0, p.gamma).pressure(s.rho), p.c0);
}

namespace {
ParticleState state_of(const particles::ParticleSet& s, Index i) {
    return {s.id[i],
            {s.x[i], s.y[i], s.z[i]},
            {s.vx[i], s.vy[i], s.vz[i]},
            {s.ax[i], s.ay[i], s.az[i]},
            s.rho[i],
            s.kind[i] == std::uint8_t(Kind::fluid)};
}
} // namespace

time::DtLimit SphSolver::stable_dt() const {
    auto pv = const_cast<particles::ParticleSet&>(set_).view();
    const SignalSpeed signal{pv, eos_};
    const AccelerationNorm accel{pv};
    const StepExtremes e{exec::max_of(pv.n, signal), exec::max_of(pv.n, accel),
                         max_kinematic_viscosity()};
    time::DtLimit lim = step_limit(params_, e);
    // When one particle holds the step far below its nominal value, say which and why.
    const LowStep low = low_step(params_, lim, e);
    if (low == LowStep::none) return lim;
    for (Index i = 0; i < set_.size(); ++i)
        if ((low == LowStep::signal && signal(i) >= e.cmax) ||
            (low == LowStep::force && accel(i) >= e.amax)) {
            lim.limiter += low_step_words(state_of(set_, i), params_.rho0);
            break;
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
    // the first bad particle (n: none)
    const ParticleHealthy healthy = ParticleHealthy::of(
        const_cast<particles::ParticleSet&>(set_).view(), domain_, params_.rho0);
    const auto first_bad = [&](Index i, Index& bad) {
        if (!healthy(i) && i < bad) bad = i;
    };
    const Index bad = exec::reduce(n, n, first_bad, [](Index& b, Index v) { b = v < b ? v : b; });
    if (bad == n) return;
    throw InstabilityError(unhealthy_message(state_of(set_, bad), t, domain_, params_));
}

} // namespace debrisflow::sph
