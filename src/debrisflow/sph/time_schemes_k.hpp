#pragma once
// The SPH phase's per-particle updates, written once for the host loop (exec::for_each) and a
// device loop (a CUDA kernel; exec/cuda_instantiations.cu compiles them with nvcc): the
// pressures of the equation of state, both time schemes, and the per-particle quantities that
// the stable step and the health check reduce over.
#include "debrisflow/core/domain.hpp"
#include "debrisflow/models/eos_tait_k.hpp"
#include "debrisflow/particles/particle_set.hpp"
#include <cmath>
#include <type_traits>

namespace debrisflow::sph {

// Folds a coordinate back into a periodic direction.
DF_HD inline Real wrap_periodic(Real v, Real lo, Real hi) {
    const Real len = hi - lo;
    if (v >= hi)
        v -= len;
    else if (v < lo)
        v += len;
    return v;
}

// A [[wall]]'s particles (group >= 0; a body's and an FEM surface's are -1 and moved by their
// phases) translate with the wall's prescribed velocity: x = x_from + dt v, wrapped through
// periodic sides. A fixed wall's particles (v = 0) stay where they are.
DF_HD inline void translate_wall_particle(const particles::ParticleView& pv, Index i,
                                          const Real (&from)[3], Real dt, const Domain& d) {
    if (pv.group[i] < 0) return;
    const Real v[3] = {pv.vx[i], pv.vy[i], pv.vz[i]};
    if (v[0] == 0 && v[1] == 0 && v[2] == 0) return;
    Real* xs[3] = {pv.x, pv.y, pv.z};
    for (int k = 0; k < 3; ++k) {
        const Real x = from[k] + dt * v[k];
        xs[k][i] = d.periodic[k] ? wrap_periodic(x, d.lo[k], d.hi[k]) : x;
    }
}

// Pressure from the Tait equation of state, p_i = B [(rho_i/rho0)^gamma - 1] (eos_tait_k.hpp).
struct TaitPressure {
    particles::ParticleView pv;
    models::TaitEos eos;
    DF_HD void operator()(Index i) const { pv.p[i] = eos.pressure(pv.rho[i]); }
};

// The pressure and what the half list's pair loop reads per particle: p / rho^2, the sound
// speed and the volume m / rho.
struct TaitPressureArrays {
    particles::ParticleView pv;
    models::TaitEos eos;
    Real *prho, *cs, *vol;
    DF_HD void operator()(Index i) const {
        const Real p = eos.pressure(pv.rho[i]);
        pv.p[i] = p;
        prho[i] = p / (pv.rho[i] * pv.rho[i]);
        cs[i] = eos.sound_speed(pv.rho[i]);
        vol[i] = pv.mass[i] / pv.rho[i];
    }
};

// The state at t_n that the symplectic corrector starts from.
struct StepStart {
    Real *x, *y, *z, *vx, *vy, *vz, *rho;
};

// Symplectic predictor (DualSPHysics, Dominguez et al. 2022): half a step from t_n,
//   rho_n+1/2 = rho_n + dt/2 D_n,  x_n+1/2 = x_n + dt/2 v_n,  v_n+1/2 = v_n + dt/2 a_n;
// boundary particles keep rho >= rho_ref (DBC: never below the wall's reference density) and
// move only with their wall. Saves the state at t_n in `start`.
struct SymplecticPredictor {
    particles::ParticleView pv;
    StepStart start;
    Real half_dt, rho_ref;
    Domain d;
    DF_HD void operator()(Index i) const {
        start.x[i] = pv.x[i], start.y[i] = pv.y[i], start.z[i] = pv.z[i];
        start.vx[i] = pv.vx[i], start.vy[i] = pv.vy[i], start.vz[i] = pv.vz[i];
        start.rho[i] = pv.rho[i];
        pv.rho[i] += half_dt * pv.drho[i];
        if (!pv.is_fluid(i)) {
            if (pv.rho[i] < rho_ref) pv.rho[i] = rho_ref;
            translate_wall_particle(pv, i, {start.x[i], start.y[i], start.z[i]}, half_dt, d);
            return;
        }
        Real* xs[3] = {pv.x, pv.y, pv.z};
        const Real vs[3] = {pv.vx[i], pv.vy[i], pv.vz[i]};
        for (int k = 0; k < 3; ++k) {
            const Real v = xs[k][i] + half_dt * vs[k];
            xs[k][i] = d.periodic[k] ? wrap_periodic(v, d.lo[k], d.hi[k]) : v;
        }
        pv.vx[i] += half_dt * pv.ax[i];
        pv.vy[i] += half_dt * pv.ay[i];
        pv.vz[i] += half_dt * pv.az[i];
    }
};

// Symplectic corrector with the derivatives at t_n+1/2 (DualSPHysics, Dominguez et al. 2022):
//   rho_n+1 = rho_n (2 - eps) / (2 + eps), eps = -dt D_n+1/2 / rho_n+1/2;
//   v_n+1 = v_n + dt a_n+1/2;  x_n+1 = x_n + dt (v_n + v_n+1) / 2.
struct SymplecticCorrector {
    particles::ParticleView pv;
    StepStart start;
    Real dt, rho_ref;
    Domain d;
    DF_HD void operator()(Index i) const {
        const Real eps = -dt * pv.drho[i] / pv.rho[i];
        pv.rho[i] = start.rho[i] * (2 - eps) / (2 + eps);
        if (!pv.is_fluid(i)) {
            if (pv.rho[i] < rho_ref) pv.rho[i] = rho_ref;
            translate_wall_particle(pv, i, {start.x[i], start.y[i], start.z[i]}, dt, d);
            return;
        }
        const Real vn[3] = {start.vx[i], start.vy[i], start.vz[i]};
        const Real xn[3] = {start.x[i], start.y[i], start.z[i]};
        Real* vs[3] = {pv.vx, pv.vy, pv.vz};
        Real* xs[3] = {pv.x, pv.y, pv.z};
        const Real as[3] = {pv.ax[i], pv.ay[i], pv.az[i]};
        for (int k = 0; k < 3; ++k) {
            const Real v1 = vn[k] + dt * as[k];
            vs[k][i] = v1;
            const Real x = xn[k] + Real(0.5) * dt * (vn[k] + v1);
            xs[k][i] = d.periodic[k] ? wrap_periodic(x, d.lo[k], d.hi[k]) : x;
        }
    }
};

// The state at t_n-1 that the Verlet scheme keeps.
struct PreviousState {
    Real *vx, *vy, *vz, *rho;
};

// Verlet (DualSPHysics, Dominguez et al. 2022 eqs. 17-19):
//   x_n+1 = x_n + dt v_n + dt^2/2 a_n,  v_n+1 = v_n-1 + 2 dt a_n,  rho_n+1 = rho_n-1 + 2 dt D_n
// and, on an `euler` step, v_n+1 = v_n + dt a_n, rho_n+1 = rho_n + dt D_n.
struct VerletUpdate {
    particles::ParticleView pv;
    PreviousState old;
    Real dt, rho_ref;
    bool euler;
    Domain d;
    DF_HD void operator()(Index i) const {
        const Real r_new = (euler ? pv.rho[i] : old.rho[i]) + (euler ? dt : 2 * dt) * pv.drho[i];
        old.rho[i] = pv.rho[i];
        pv.rho[i] = pv.is_fluid(i) || r_new >= rho_ref ? r_new : rho_ref;
        if (!pv.is_fluid(i)) {
            translate_wall_particle(pv, i, {pv.x[i], pv.y[i], pv.z[i]}, dt, d);
            return;
        }
        Real* xs[3] = {pv.x, pv.y, pv.z};
        Real* vs[3] = {pv.vx, pv.vy, pv.vz};
        Real* vo[3] = {old.vx, old.vy, old.vz};
        const Real as[3] = {pv.ax[i], pv.ay[i], pv.az[i]};
        const Real hdt2 = Real(0.5) * dt * dt;
        for (int k = 0; k < 3; ++k) {
            const Real v = vs[k][i];
            const Real x = xs[k][i] + dt * v + hdt2 * as[k];
            xs[k][i] = d.periodic[k] ? wrap_periodic(x, d.lo[k], d.hi[k]) : x;
            vs[k][i] = (euler ? v : vo[k][i]) + (euler ? dt : 2 * dt) * as[k];
            vo[k][i] = v;
        }
    }
};

// Fastest signal of a fluid particle, c_i + |v_i| (the CFL limit, Monaghan 1992; 0 for walls).
struct SignalSpeed {
    particles::ParticleView pv;
    models::TaitEos eos;
    DF_HD Real operator()(Index i) const {
        if (!pv.is_fluid(i)) return Real(0);
        return eos.sound_speed(pv.rho[i]) +
               std::sqrt(pv.vx[i] * pv.vx[i] + pv.vy[i] * pv.vy[i] + pv.vz[i] * pv.vz[i]);
    }
};

// |a_i| of a fluid particle (the force limit dt <= cfl sqrt(h / |a|); 0 for walls).
struct AccelerationNorm {
    particles::ParticleView pv;
    DF_HD Real operator()(Index i) const {
        if (!pv.is_fluid(i)) return Real(0);
        return std::sqrt(pv.ax[i] * pv.ax[i] + pv.ay[i] * pv.ay[i] + pv.az[i] * pv.az[i]);
    }
};

// How far a weakly-compressible fluid particle's density may leave rho0 before the run stops:
// 30 % (DualSPHysics's default RhopOut range for water, 700-1300 kg/m^3). By Tait's law that is
// a pressure of 0.75 rho0 c0^2, the water hammer of a flow at 3/4 of c0: the fluid is no longer
// the nearly incompressible one the method stands for (c0 >= 10 |v| keeps it within ~1 %).
inline constexpr Real max_density_change = Real(0.3);

// Whether particle i is fit to go on: position, velocity and density finite, inside every
// closed side of the domain, and (fluid) its density within max_density_change of rho0 (the
// health check stops the run at the first that is not).
struct ParticleHealthy {
    particles::ParticleView pv;
    Domain d;
    Real rho_min = 0, rho_max = 0; // a fluid particle's density bounds

    static ParticleHealthy of(particles::ParticleView pv, const Domain& d, Real rho0) {
        return {pv, d, (1 - max_density_change) * rho0, (1 + max_density_change) * rho0};
    }
    DF_HD bool operator()(Index i) const {
        const Real v[7] = {pv.x[i], pv.y[i], pv.z[i], pv.vx[i], pv.vy[i], pv.vz[i], pv.rho[i]};
        bool ok = true;
        for (Real q : v) ok = ok && std::isfinite(q);
        for (int k = 0; k < 3 && ok; ++k) {
            const Real c = v[k];
            if (!d.periodic[k] && (c < d.lo[k] || c > d.hi[k])) ok = false;
        }
        if (ok && pv.is_fluid(i)) ok = pv.rho[i] >= rho_min && pv.rho[i] <= rho_max;
        return ok;
    }
};

static_assert(std::is_trivially_copyable_v<SymplecticPredictor>);
static_assert(std::is_trivially_copyable_v<SymplecticCorrector>);
static_assert(std::is_trivially_copyable_v<VerletUpdate>);

} // namespace debrisflow::sph
