#include "debrisflow/flow/fluid_inlet.hpp"
#include "debrisflow/exec/parallel.hpp"
#include "debrisflow/io/case_spec.hpp"
#include "debrisflow/sph/sph_params.hpp"
#include <cmath>

namespace debrisflow::flow {

FluidInlet::FluidInlet(const io::InletSpec& spec, const io::CaseSpec& c)
    : spec_(spec), q_{spec.times, spec.discharge}, eos_(c.sph.rho0, c.sph.c0, c.sph.gamma),
      dp_(c.dp), rho0_(c.sph.rho0), area_(spec.area(c.dim)),
      g_down_(c.sph.gravity.z < 0 ? -c.sph.gravity.z : 0), dim_(c.dim),
      group_(std::int16_t(spec.fluid)) {}

Real FluidInlet::density_at(Real z) const {
    // Hydrostatic below the buffer's top, as the initial fluid blocks (build_particles).
    const Real depth = spec_.max.z - z;
    return depth > 0 ? eos_.density(rho0_ * g_down_ * depth) : rho0_;
}

void FluidInlet::add_layer(particles::ParticleSet& set, Real along, Real t) {
    const int a = spec_.axis;
    int perp[2], np = 0;
    for (int k = 0; k < 3; ++k)
        if (k != a && !(dim_ == 2 && k == 1)) perp[np++] = k;
    const Real u = velocity(t);
    Vec3 vel{};
    vel[a] = spec_.sign * u;
    auto count = [&](int k) { return int(std::floor((spec_.max[k] - spec_.min[k]) / dp_ + 1e-9)); };
    const int n0 = count(perp[0]), n1 = np > 1 ? count(perp[1]) : 1;
    const Real cell = sph::lattice_volume(dp_, dim_);
    for (int i = 0; i < n0; ++i)
        for (int j = 0; j < n1; ++j) {
            Vec3 x{};
            x[a] = along;
            x[perp[0]] = spec_.min[perp[0]] + (i + Real(0.5)) * dp_;
            if (np > 1) x[perp[1]] = spec_.min[perp[1]] + (j + Real(0.5)) * dp_;
            const Real rho = density_at(x.z);
            set.add(x, vel, rho, rho * cell, particles::Kind::fluid, group_);
            mass_in_ += rho * cell;
            volume_in_ += cell * rho / rho0_;
        }
}

void FluidInlet::apply(particles::ParticleSet& set, Real t, Real dt) {
    const int a = spec_.axis;
    const Real u = velocity(t);
    // Prescribed state of the buffer particles.
    const Index n = set.size();
    const Vec3 lo = spec_.min, hi = spec_.max;
    const bool flat = dim_ == 2;
    const Real sign = Real(spec_.sign);
    Real* vs[3] = {set.vx.data(), set.vy.data(), set.vz.data()};
    const bool old_state = set.keeps_previous_state(); // Verlet only
    Real* vo[3] = {set.vx_old.data(), set.vy_old.data(), set.vz_old.data()};
    exec::for_each(n, [&](Index i) {
        if (set.kind[i] != std::uint8_t(particles::Kind::fluid)) return;
        const Real x[3] = {set.x[i], set.y[i], set.z[i]};
        bool inside = true;
        for (int k = 0; k < 3; ++k)
            if (!(flat && k == 1)) inside = inside && x[k] >= lo[k] && x[k] <= hi[k];
        if (!inside) return;
        for (int k = 0; k < 3; ++k) {
            vs[k][i] = k == a ? sign * u : 0;
            if (old_state) vo[k][i] = vs[k][i];
        }
        set.rho[i] = density_at(x[2]);
        if (old_state) set.rho_old[i] = set.rho[i];
    });
    // New layers behind the upstream one: it started at dp/2 inside the upstream face.
    advance_ += u * dt;
    const Real upstream = spec_.sign > 0 ? spec_.min[a] : spec_.max[a];
    while (advance_ >= dp_) {
        advance_ -= dp_;
        add_layer(set, upstream + sign * (Real(0.5) * dp_ + advance_), t);
    }
}

} // namespace debrisflow::flow
